# Each tests/python/test_*.py is one CTest test, python.<name>: Debian's pytest on the package as
# the build tree lays it out (PYTHONPATH=BUILD/python), with the scatterlab executable, the data
# directory and a scratch directory passed in the environment.
file(GLOB PYTHON_TEST_FILES CONFIGURE_DEPENDS ${CMAKE_CURRENT_LIST_DIR}/test_*.py)
set(PYTHON_TEST_ENVIRONMENT
    PYTHONPATH=${PROJECT_BINARY_DIR}/python
    PYTHONDONTWRITEBYTECODE=1
    SCATTERLAB_EXE=$<TARGET_FILE:scatterlab>
    SCATTERLAB_DATA_DIR=${SCATTERLAB_DATA_DIR}
    SCATTERLAB_TEST_OUTPUT_DIR=${CMAKE_CURRENT_BINARY_DIR}/output/python)
foreach(file ${PYTHON_TEST_FILES})
  get_filename_component(name ${file} NAME_WE)
  string(REGEX REPLACE "^test_" "" name ${name})
  add_test(NAME python.${name} COMMAND /usr/bin/python3 -m pytest -q -p no:cacheprovider ${file})
  set_tests_properties(python.${name} PROPERTIES ENVIRONMENT "${PYTHON_TEST_ENVIRONMENT}" TIMEOUT 900)
endforeach()
# The kit on numpy objects takes minutes (docs/python.md, "The kit on any object"): a high COST
# makes CTest start it first, so it overlaps the short tests instead of running alone at the end
# of a fresh build's suite (CTest orders by COST when it has no timings yet).
set_tests_properties(python.check PROPERTIES COST 10000)

# examples/notebook.py, the package's walk-through, runs as it is and writes its figure into the
# test output; the script asserts its own checks, the test that the PNG is there.
add_test(NAME python.notebook_example
         COMMAND /usr/bin/python3 -c
                 "import pathlib, runpy, sys; out = pathlib.Path(sys.argv[2]); out.mkdir(parents=True, exist_ok=True); sys.argv = sys.argv[1:]; runpy.run_path(sys.argv[0], run_name='__main__'); assert (out / 'notebook.png').stat().st_size > 0"
                 ${PROJECT_SOURCE_DIR}/examples/notebook.py ${CMAKE_CURRENT_BINARY_DIR}/output/python/notebook_example)
set_tests_properties(python.notebook_example PROPERTIES ENVIRONMENT "${PYTHON_TEST_ENVIRONMENT}" TIMEOUT 900
                                                         COST 5000)
