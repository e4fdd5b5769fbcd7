# scatterlab_add_plugin(NAME SOURCES...): a plugin (materials/registry/plugin.h) that
# `scatterlab COMMAND --plugin $<TARGET_FILE:NAME>` loads: a shared module linked to
# scatterlab::materials, its symbols hidden but for the two entry points SCATTERLAB_PLUGIN
# exports, so that its copy of scatterlab::materials never meets the executable's.
function(scatterlab_add_plugin name)
  add_library(${name} MODULE ${ARGN})
  target_link_libraries(${name} PRIVATE scatterlab::materials)
  set_target_properties(${name} PROPERTIES CXX_VISIBILITY_PRESET hidden VISIBILITY_INLINES_HIDDEN ON)
endfunction()
