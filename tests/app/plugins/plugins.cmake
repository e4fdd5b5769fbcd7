# Plugins for the command-line tests (materials/registry/plugin.h), built like a user's
# (cmake/scatterlabPlugin.cmake): the example's model (examples/own-bsdf), models that misbehave
# at run time, and libraries the loader must refuse. Their paths are compiled into app_tests.
include(${PROJECT_SOURCE_DIR}/cmake/scatterlabPlugin.cmake)

scatterlab_add_plugin(example_phong ${PROJECT_SOURCE_DIR}/examples/own-bsdf/plugin.cpp)
target_link_libraries(example_phong PRIVATE scatterlab::fitting)
scatterlab_add_plugin(test_plugin_models ${CMAKE_CURRENT_LIST_DIR}/test_plugin_models.cpp)
target_include_directories(test_plugin_models PRIVATE ${PROJECT_SOURCE_DIR}/examples/own-bsdf)
set(test_plugins example_phong test_plugin_models)
foreach(variant WRONG_ABI DUPLICATE NO_DEFAULT THROWS NOT_A_PLUGIN NO_REGISTER)
  string(TOLOWER "bad_plugin_${variant}" name)
  scatterlab_add_plugin(${name} ${CMAKE_CURRENT_LIST_DIR}/bad_plugin.cpp)
  target_compile_definitions(${name} PRIVATE BAD_PLUGIN_${variant})
  list(APPEND test_plugins ${name})
endforeach()

add_dependencies(app_tests ${test_plugins})
foreach(plugin ${test_plugins})
  string(TOUPPER "${plugin}" upper)
  target_compile_definitions(app_tests PRIVATE SCATTERLAB_PLUGIN_${upper}="$<TARGET_FILE:${plugin}>")
endforeach()
