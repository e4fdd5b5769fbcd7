# End-to-end tests of the scatterlab executable (exit codes, messages): app_tests runs the real
# binary, so it is built first and its path is compiled into the tests.
add_dependencies(app_tests scatterlab)
target_compile_definitions(app_tests PRIVATE SCATTERLAB_EXE="$<TARGET_FILE:scatterlab>")

include(${CMAKE_CURRENT_LIST_DIR}/plugins/plugins.cmake)
