# Runs a libFuzzer binary for SECONDS on a fresh copy of the SEEDS corpus (WORK/corpus: the seeds are
# never modified) and fails on any finding. cmake -DFUZZER=... -DSEEDS=... -DWORK=... -DSECONDS=... -P run_fuzz.cmake
foreach(var FUZZER SEEDS WORK SECONDS)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "run_fuzz.cmake: ${var} not set")
  endif()
endforeach()
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK}/corpus ${WORK}/artifacts)
execute_process(
  # -timeout: a hang, not a slow input (tests/data/obj/newell_cycles_fuzz.obj once took over 20 s beside other tests).
  COMMAND ${FUZZER} -max_total_time=${SECONDS} -timeout=60 -rss_limit_mb=2048 -print_final_stats=1
          -artifact_prefix=${WORK}/artifacts/ ${WORK}/corpus ${SEEDS}
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
string(REGEX MATCH "stat::number_of_executed_units: *[0-9]+" runs "${err}")
string(REGEX MATCH "stat::average_exec_per_sec: *[0-9]+" speed "${err}")
string(REGEX MATCHALL "cov: [0-9]+ ft: [0-9]+ corp: [0-9/]+[a-zA-Z]*" covs "${err}")
set(cov "no coverage line")
if(covs)
  list(GET covs -1 cov)
endif()
message(STATUS "${FUZZER}: ${runs}, ${speed}, at the end ${cov}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the fuzzer found a failure (exit ${rc}); the input is in ${WORK}/artifacts/, replay it with "
                      "${FUZZER} FILE\n${out}${err}")
endif()
