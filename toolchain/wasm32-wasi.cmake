# WebAssembly for the web playground (web/): Debian's clang 14 targeting wasm32-wasi, with Debian's
# wasi-libc, libc++-14-dev-wasm32 and libclang-rt-14-dev-wasm32 as the sysroot (no emscripten, no
# download). Programs are WASI commands (.wasm) that web/wasi.js runs in the browser.
set(CMAKE_SYSTEM_NAME Generic)
set(CMAKE_SYSTEM_PROCESSOR wasm32)
find_program(HIDER_WASM_CLANG NAMES clang-14 clang REQUIRED)
find_program(HIDER_WASM_CLANGXX NAMES clang++-14 clang++ REQUIRED)
set(CMAKE_C_COMPILER ${HIDER_WASM_CLANG})
set(CMAKE_CXX_COMPILER ${HIDER_WASM_CLANGXX})
set(CMAKE_C_COMPILER_TARGET wasm32-wasi)
set(CMAKE_CXX_COMPILER_TARGET wasm32-wasi)
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)
