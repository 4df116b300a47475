# hider.asserts_active: runs PROBE (tests/port/assert_probe.cpp) and passes when it failed with the
# hook's message naming lib/hider/base.hpp and a line, i.e. HIDER_ASSERT is live in this build.
execute_process(COMMAND ${PROBE} RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(result EQUAL 0)
  message(FATAL_ERROR "the probe returned 0: HIDER_ASSERT is compiled out")
endif()
if(NOT err MATCHES "hider: assertion failed at [^\n]*hider/base\\.hpp:[0-9]+")
  message(FATAL_ERROR "the probe failed (${result}) without the hook's message:\n${out}${err}")
endif()
message(STATUS "HIDER_ASSERT live: ${err}")
