# The native build's step that makes the explorer's WebAssembly module: the root CMakeLists.txt
# configured again with Emscripten's toolchain (which then builds materials/ and
# explorer_api.cpp only, explorer/CMakeLists.txt) in BINARY_DIR/explorer-wasm, built on every
# build (a no-op when nothing changed). Sets SCATTERLAB_EXPLORER_WASM_JS to the module's path
# for app/explorer_assets.cmake, which embeds it into the executable.
#
# Emscripten and node-acorn are Debian packages (scripts/setup). Debian 12's emcc 3.1.6 runs its
# JavaScript optimizer with node, which finds acorn only through NODE_PATH=/usr/share/nodejs.
include(ExternalProject)
find_program(SCATTERLAB_EMCC emcc)
find_file(SCATTERLAB_EMSCRIPTEN_TOOLCHAIN Emscripten.cmake
          PATHS /usr/share/emscripten/cmake/Modules/Platform /usr/lib/emscripten/cmake/Modules/Platform)
if(NOT SCATTERLAB_EMCC OR NOT SCATTERLAB_EMSCRIPTEN_TOOLCHAIN)
  message(FATAL_ERROR "Emscripten is missing (emcc and its CMake toolchain Emscripten.cmake): run scripts/setup, "
                      "which installs Debian's emscripten and node-acorn")
endif()

# The module does not depend on the parent build's compiler or flags, so builds may share one
# sub-build: the asan-ubsan preset points this at the release build's (CI builds release first,
# so the sanitizer pass finds the module built and does not compile materials/ with emcc again).
# Its configure and build steps hold a lock on DIR.lock (flock, util-linux), so parent builds
# sharing it may run at the same time: one waits while the other configures or builds it.
set(SCATTERLAB_EXPLORER_WASM_DIR ${CMAKE_BINARY_DIR}/explorer-wasm
    CACHE PATH "Build directory of the explorer's WebAssembly module (a sub-build, configured with Emscripten)")
set(SCATTERLAB_EXPLORER_WASM_JS ${SCATTERLAB_EXPLORER_WASM_DIR}/explorer/scatterlab-wasm.js)
find_program(SCATTERLAB_FLOCK flock REQUIRED)
set(EMSCRIPTEN_ENVIRONMENT ${SCATTERLAB_FLOCK} ${SCATTERLAB_EXPLORER_WASM_DIR}.lock ${CMAKE_COMMAND} -E env
                           NODE_PATH=/usr/share/nodejs)
# A compiler launcher (ccache) of the native build serves this one too.
set(EMSCRIPTEN_LAUNCHER "")
if(CMAKE_CXX_COMPILER_LAUNCHER)
  set(EMSCRIPTEN_LAUNCHER -DCMAKE_CXX_COMPILER_LAUNCHER=${CMAKE_CXX_COMPILER_LAUNCHER})
endif()
# At most 2 compile jobs (the machines this runs on have 2 cores; the parent build's jobs run
# beside them).
ExternalProject_Add(explorer_wasm
  SOURCE_DIR ${PROJECT_SOURCE_DIR}
  BINARY_DIR ${SCATTERLAB_EXPLORER_WASM_DIR}
  CMAKE_GENERATOR Ninja
  CMAKE_COMMAND ${EMSCRIPTEN_ENVIRONMENT} ${CMAKE_COMMAND}
  CMAKE_ARGS -DCMAKE_TOOLCHAIN_FILE=${SCATTERLAB_EMSCRIPTEN_TOOLCHAIN} -DCMAKE_BUILD_TYPE=Release ${EMSCRIPTEN_LAUNCHER}
  BUILD_COMMAND ${EMSCRIPTEN_ENVIRONMENT} ${CMAKE_COMMAND} --build ${SCATTERLAB_EXPLORER_WASM_DIR}
                --target scatterlab_explorer --parallel 2
  BUILD_ALWAYS ON
  BUILD_BYPRODUCTS ${SCATTERLAB_EXPLORER_WASM_JS}
  INSTALL_COMMAND ""
  TEST_COMMAND "")
