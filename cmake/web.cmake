# The web playground (web/) in the host build (-DHIDER_WEB=ON, on in the `host` preset): web/ is a
# project of its own for WebAssembly, built here as an ExternalProject with toolchain/wasm32-wasi.cmake
# into ${CMAKE_BINARY_DIR}/web/site, and tested in Debian's headless Chromium against this build's
# hider-render (web/test_browser.py). Needs the packages of `bash scripts/install-deps.sh all`.
include(ExternalProject)
find_program(HIDER_PYTHON3 NAMES python3 REQUIRED)
find_program(HIDER_CHROMIUM NAMES chromium chromium-browser)
if(NOT HIDER_CHROMIUM)
  message(FATAL_ERROR "HIDER_WEB: Debian's chromium is needed for the browser test (bash scripts/install-deps.sh all)")
endif()

ExternalProject_Add(hider_web
  SOURCE_DIR ${PROJECT_SOURCE_DIR}/web
  BINARY_DIR ${CMAKE_BINARY_DIR}/web
  CMAKE_GENERATOR ${CMAKE_GENERATOR}
  CMAKE_ARGS -DCMAKE_TOOLCHAIN_FILE=${PROJECT_SOURCE_DIR}/toolchain/wasm32-wasi.cmake -DCMAKE_BUILD_TYPE=Release
  BUILD_COMMAND ${CMAKE_COMMAND} --build <BINARY_DIR> -j 2
  BUILD_ALWAYS TRUE
  INSTALL_COMMAND "")

add_test(NAME web.browser
  COMMAND ${HIDER_PYTHON3} ${PROJECT_SOURCE_DIR}/web/test_browser.py --site ${CMAKE_BINARY_DIR}/web/site
          --hider-render $<TARGET_FILE:hider-render> --models ${PROJECT_SOURCE_DIR}/tests/data/models
          --work ${CMAKE_BINARY_DIR}/web-test --chromium ${HIDER_CHROMIUM})
set_tests_properties(web.browser PROPERTIES TIMEOUT 600 LABELS web)
# The wasm build's compile commands carry hider's flags too (hider_target_flags in web/CMakeLists.txt).
add_test(NAME web.own_flags
  COMMAND ${CMAKE_COMMAND} -DCOMPILE_COMMANDS=${CMAKE_BINARY_DIR}/web/compile_commands.json
          -DSOURCE_DIR=${PROJECT_SOURCE_DIR} -DMODE=own "-DFLAGS=${HIDER_CXX_FLAGS}"
          -P ${PROJECT_SOURCE_DIR}/cmake/check_compile_flags.cmake)
set_tests_properties(web.own_flags PROPERTIES TIMEOUT 60 LABELS web)
