# Compile flags of hider's own code, kept PRIVATE to hider's own targets: the
# INTERFACE of hider::hider carries only the include directory and C++17, never these.
#
#   hider_target_flags(<target>...)   every hider target (library checks, ports, tools, tests,
#                                     firmware, web) calls this once after creating the target.
#
# A new target in hider's tree adopts the flags with one line, e.g. `hider_target_flags(hider-bsp)`,
# instead of `target_compile_options(<target> PRIVATE ${HIDER_WARNINGS})` (warnings only: the
# language flags would be missing). The ctest hider.own_flags (cmake/check_compile_flags.cmake)
# fails when a compile command of a file under lib/, port/, tools/, tests/, firmware/ or web/
# lacks any flag of HIDER_CXX_FLAGS.
include_guard(GLOBAL)

# Warnings alone (also used by cmake/firmware.cmake for host programs built by custom commands).
set(HIDER_WARNINGS -Wall -Wextra -Wshadow -Wdouble-promotion -Werror=double-promotion)
# Everything a hider C++ file compiles with.
set(HIDER_CXX_FLAGS ${HIDER_WARNINGS} -fno-exceptions -fno-rtti)
# The function reads them from a global property, so it works from any directory scope (for example
# web/, which adds hider as a subdirectory of its own project).
set_property(GLOBAL PROPERTY HIDER_CXX_FLAGS "${HIDER_CXX_FLAGS}")

function(hider_target_flags)
  get_property(flags GLOBAL PROPERTY HIDER_CXX_FLAGS)
  foreach(target IN LISTS ARGN)
    get_target_property(type ${target} TYPE)
    if(type STREQUAL "INTERFACE_LIBRARY")
      message(FATAL_ERROR "hider_target_flags(${target}): an INTERFACE target would pass the flags to its users")
    endif()
    target_compile_options(${target} PRIVATE $<$<COMPILE_LANGUAGE:CXX>:${flags}>)
  endforeach()
endfunction()
