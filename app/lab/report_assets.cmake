# The lab report's static files, compiled into the executable (app/lab/embedded_assets.h): the
# report is self-contained and `scatterlab lab` reads nothing from the source tree or from
# node_modules at run time. Chart.js comes from node_modules, which scripts/setup fills with
# `npm ci` from the pinned package-lock.json at the repository's root.
set(LAB_CHART_JS_DIR ${PROJECT_SOURCE_DIR}/node_modules/chart.js)
if(NOT EXISTS ${LAB_CHART_JS_DIR}/dist/chart.umd.min.js)
  message(FATAL_ERROR "Chart.js is missing (${LAB_CHART_JS_DIR}): run scripts/setup, which runs `npm ci` on "
                      "package-lock.json")
endif()
file(READ ${LAB_CHART_JS_DIR}/package.json LAB_CHART_JS_PACKAGE)
string(JSON LAB_CHART_JS_VERSION GET "${LAB_CHART_JS_PACKAGE}" version)

# NAME PATH pairs. report/NAME is copied into every report's assets/ folder; explorer/NAME is the
# explorer's page (app/explorer/explorer_page.h), its WebAssembly module made by
# explorer/wasm_module.cmake.
set(EXPLORER_PAGE_DIR ${PROJECT_SOURCE_DIR}/explorer/page)
set(LAB_ASSET_SOURCES
  report/chart.umd.min.js ${LAB_CHART_JS_DIR}/dist/chart.umd.min.js
  report/chart.js-LICENSE.md ${LAB_CHART_JS_DIR}/LICENSE.md
  report/report.js ${CMAKE_CURRENT_LIST_DIR}/assets/report.js
  report/report.css ${CMAKE_CURRENT_LIST_DIR}/assets/report.css
  explorer/index.html ${EXPLORER_PAGE_DIR}/index.html
  explorer/scatterlab-api.js ${EXPLORER_PAGE_DIR}/scatterlab-api.js
  explorer/explorer-plots.js ${EXPLORER_PAGE_DIR}/explorer-plots.js
  explorer/explorer.js ${EXPLORER_PAGE_DIR}/explorer.js
  explorer/explorer.css ${EXPLORER_PAGE_DIR}/explorer.css
  explorer/scatterlab-wasm.js ${SCATTERLAB_EXPLORER_WASM_JS})
set(LAB_ASSET_FILES "")
set(LAB_ASSET_ARGUMENT "")
while(LAB_ASSET_SOURCES)
  list(POP_FRONT LAB_ASSET_SOURCES name path)
  list(APPEND LAB_ASSET_FILES ${path})
  string(APPEND LAB_ASSET_ARGUMENT "|${name}=${path}")
endwhile()
string(SUBSTRING "${LAB_ASSET_ARGUMENT}" 1 -1 LAB_ASSET_ARGUMENT)

set(LAB_ASSETS_CPP ${CMAKE_CURRENT_BINARY_DIR}/lab_embedded_assets.cpp)
add_custom_command(
  OUTPUT ${LAB_ASSETS_CPP}
  COMMAND ${CMAKE_COMMAND} -DOUTPUT=${LAB_ASSETS_CPP} "-DFILES=${LAB_ASSET_ARGUMENT}"
          -P ${CMAKE_CURRENT_LIST_DIR}/embed_files.cmake
  DEPENDS ${LAB_ASSET_FILES} ${CMAKE_CURRENT_LIST_DIR}/embed_files.cmake
  COMMENT "Embedding the lab report's assets (Chart.js ${LAB_CHART_JS_VERSION}) and the explorer"
  VERBATIM)
target_sources(scatterlab_app PRIVATE ${LAB_ASSETS_CPP})
add_dependencies(scatterlab_app explorer_wasm)
set_source_files_properties(${LAB_ASSETS_CPP} PROPERTIES SKIP_PRECOMPILE_HEADERS ON)
target_compile_definitions(scatterlab_app PRIVATE SCATTERLAB_CHART_JS_VERSION="${LAB_CHART_JS_VERSION}")
