# Cross-build helpers for firmware/. Needs a toolchain file from toolchain/.
#   hider_add_firmware()        builds <name>.elf, checks symbols/size/stack, runs it under QEMU (ctest)
#   hider_add_host_program()    builds a host program with the host C++ compiler (reference outputs)
#   hider_compare_with_host()   ctest: the firmware's semihosted files == the host program's, byte for byte
#   hider_add_insncount_test()  ctest: instruction count of bench_begin..bench_end is nonzero and repeatable
#   hider_add_insncount_budget() ctest: an instruction count (or a ratio of two) within a met target
include_guard(GLOBAL)

if(NOT DEFINED HIDER_ARCH OR NOT DEFINED HIDER_QEMU_BIG OR NOT DEFINED HIDER_QEMU_SMALL)
  message(FATAL_ERROR "cmake/firmware.cmake needs a toolchain file from toolchain/ (use --preset cm0plus, cm3 or rv32imac)")
endif()

find_program(HIDER_SIZE NAMES ${HIDER_TRIPLE}-size REQUIRED)
find_program(HIDER_OBJDUMP NAMES ${HIDER_TRIPLE}-objdump REQUIRED)
find_program(HIDER_TIMEOUT NAMES timeout REQUIRED)
find_program(HIDER_HOST_CC NAMES cc gcc clang REQUIRED)
find_program(HIDER_HOST_CXX NAMES c++ g++ clang++ REQUIRED)
list(GET HIDER_QEMU_BIG 0 _hider_qemu_big)
list(GET HIDER_QEMU_SMALL 0 _hider_qemu_small)
find_program(HIDER_QEMU_BIG_EXECUTABLE NAMES ${_hider_qemu_big} REQUIRED)
find_program(HIDER_QEMU_SMALL_EXECUTABLE NAMES ${_hider_qemu_small} REQUIRED)
if(NOT CMAKE_NM)
  message(FATAL_ERROR "CMAKE_NM not found for ${HIDER_TRIPLE}")
endif()

# The insncount TCG plugin is a host shared object.
set(HIDER_INSNCOUNT_DIR ${PROJECT_SOURCE_DIR}/tools/qemu-insncount CACHE INTERNAL "")
set(HIDER_INSNCOUNT_PLUGIN ${CMAKE_BINARY_DIR}/tools/qemu-insncount/libinsncount.so CACHE INTERNAL "")
add_custom_command(OUTPUT ${HIDER_INSNCOUNT_PLUGIN}
  COMMAND ${HIDER_HOST_CC} -O2 -shared -fPIC -Wall -Wextra -o ${HIDER_INSNCOUNT_PLUGIN} ${HIDER_INSNCOUNT_DIR}/insncount.c
  DEPENDS ${HIDER_INSNCOUNT_DIR}/insncount.c ${HIDER_INSNCOUNT_DIR}/arm_cycles.h
  COMMENT "Building QEMU plugin libinsncount.so with the host C compiler" VERBATIM)
add_custom_target(qemu_insncount ALL DEPENDS ${HIDER_INSNCOUNT_PLUGIN})

# Linker memory map of MACHINE (big|small) for the current target, as --defsym assignments.
function(_hider_memory_map machine out_var)
  if(machine STREQUAL "big")
    set(flash ${MCU_FLASH_SIZE})
    set(ram ${MCU_RAM_SIZE})
  else()
    set(flash ${MCU_SMALL_FLASH_SIZE})
    set(ram ${MCU_SMALL_RAM_SIZE})
  endif()
  if(HIDER_ARCH STREQUAL "arm")  # FLASH at 0, RAM at 0x20000000 on mps2-an385 and microbit
    set(map __flash_size=${flash} __ram_size=${ram})
  elseif(machine STREQUAL "big")  # virt: image at the start of DRAM, RAM 1 MB above
    set(map __rom=0x80000000 __rom_size=${flash} __ram=0x80100000 __ram_size=${ram})
  else()  # sifive_e: XIP flash from 0x20400000 (reset vector), 16 KB DTIM at 0x80000000
    set(map __rom=0x20400000 __rom_size=${flash} __ram=0x80000000 __ram_size=${ram})
  endif()
  set(${out_var} ${map} PARENT_SCOPE)
endfunction()

# hider_add_firmware(NAME <name> SOURCES <src>... MACHINE <big|small>
#                    [RAM_BUDGET <ld size>] [STACK_SIZE <ld size, default 4K>] [STACK_LIMIT <bytes>]
#                    [TIMEOUT <seconds, default 60>] [LIBRARIES <target>...] [NOT_POINTERS <object glob>...]
#                    [RUNTIME <target>] [FLAGS <flag>...] [EMULATOR <command>...]
#                    [NO_SYMBOL_CHECK] [NO_TEST])
# Builds <name>.elf for the current target with the runtime (startup, mem*, bench markers,
# semihosting) and hider::hider. After linking: the nm check (fails the build on float, heap,
# exceptions or RTTI), `size`, and the -fstack-usage report (fails above STACK_LIMIT if given).
# RAM_BUDGET caps data+bss+stack at link time. The ctest <name>.run runs the ELF on MACHINE under
# `timeout`, in the working directory ${CMAKE_BINARY_DIR}/frames/<name>, where its semihosted files
# land; it passes on exit status 0 and is the fixture <name>.run for comparisons. The ctest
# <name>.stack_bound requires hider-stack's static worst-case stack (from the reset entry, every path)
# to fit STACK_SIZE less the 32 bytes the start-up requires untouched; NOT_POINTERS names data objects whose words are not function pointers (baked
# data that holds integers equal to code addresses).
# RUNTIME replaces hider_fw_runtime (a variant built for other CPU flags), FLAGS are added to the
# firmware's compile and link flags (after the toolchain's: a later -march wins, and the link picks
# libgcc's matching multilib), EMULATOR replaces the machine's QEMU command line (ending in -kernel) for
# the ctest run (the <name>_insncount target keeps tools/qemu-insncount/run.sh's machine).
# Also adds the target <name>_insncount (not in ALL): prints the bench_begin..bench_end count.
function(hider_add_firmware)
  cmake_parse_arguments(PARSE_ARGV 0 FW "NO_SYMBOL_CHECK;NO_TEST"
    "NAME;MACHINE;RAM_BUDGET;STACK_SIZE;STACK_LIMIT;TIMEOUT;RUNTIME" "SOURCES;LIBRARIES;NOT_POINTERS;FLAGS;EMULATOR")
  if(NOT FW_NAME OR NOT FW_SOURCES)
    message(FATAL_ERROR "hider_add_firmware: NAME and SOURCES are required")
  endif()
  if(NOT FW_MACHINE MATCHES "^(big|small)$")
    message(FATAL_ERROR "hider_add_firmware(${FW_NAME}): MACHINE must be big or small, got '${FW_MACHINE}'")
  endif()
  if(FW_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "hider_add_firmware(${FW_NAME}): unknown arguments ${FW_UNPARSED_ARGUMENTS}")
  endif()
  if(NOT FW_STACK_SIZE)
    set(FW_STACK_SIZE 4K)
  endif()
  if(NOT FW_STACK_LIMIT)
    set(FW_STACK_LIMIT 0)
  endif()
  if(NOT FW_TIMEOUT)
    set(FW_TIMEOUT 60)
  endif()
  if(NOT FW_RUNTIME)
    set(FW_RUNTIME hider_fw_runtime)
  endif()
  string(TOUPPER ${FW_MACHINE} machine_upper)
  if(NOT FW_EMULATOR)
    set(FW_EMULATOR ${HIDER_QEMU_${machine_upper}})
  endif()
  set(common ${CMAKE_CURRENT_FUNCTION_LIST_DIR}/../firmware/common)
  cmake_path(NORMAL_PATH common)
  if(HIDER_ARCH STREQUAL "arm")
    set(script ${common}/cortex_m.ld)
  else()
    set(script ${common}/riscv.ld)
  endif()

  add_executable(${FW_NAME} ${FW_SOURCES})
  target_link_libraries(${FW_NAME} PRIVATE ${FW_RUNTIME} hider::hider hider_port_display ${FW_LIBRARIES})
  hider_target_flags(${FW_NAME})
  if(FW_FLAGS)
    target_compile_options(${FW_NAME} PRIVATE ${FW_FLAGS})
    target_link_options(${FW_NAME} PRIVATE ${FW_FLAGS})
  endif()

  _hider_memory_map(${FW_MACHINE} defsyms)
  list(APPEND defsyms __stack_size=${FW_STACK_SIZE})
  if(FW_RAM_BUDGET)
    list(APPEND defsyms __ram_budget=${FW_RAM_BUDGET})
  endif()
  list(TRANSFORM defsyms PREPEND "LINKER:--defsym=")
  target_link_options(${FW_NAME} PRIVATE -T${script} ${defsyms} LINKER:-Map=${CMAKE_CURRENT_BINARY_DIR}/${FW_NAME}.map)
  set_property(TARGET ${FW_NAME} APPEND PROPERTY LINK_DEPENDS ${script})

  set(scripts ${CMAKE_CURRENT_FUNCTION_LIST_DIR})
  get_target_property(runtime_dir ${FW_RUNTIME} BINARY_DIR)
  get_target_property(semihost_dir hider_port_semihost BINARY_DIR)
  set(post_build)
  if(NOT FW_NO_SYMBOL_CHECK)
    list(APPEND post_build COMMAND sh ${scripts}/check_firmware_symbols.sh ${CMAKE_NM} $<TARGET_FILE:${FW_NAME}> --delete-on-failure)
  endif()
  list(APPEND post_build
    COMMAND ${HIDER_SIZE} $<TARGET_FILE:${FW_NAME}>
    COMMAND sh ${scripts}/check_firmware_stack.sh ${FW_NAME} ${PROJECT_SOURCE_DIR}/lib ${FW_STACK_LIMIT}
            ${CMAKE_CURRENT_BINARY_DIR}/CMakeFiles/${FW_NAME}.dir ${runtime_dir}/CMakeFiles/${FW_RUNTIME}.dir
            ${semihost_dir}/CMakeFiles/hider_port_semihost.dir)
  add_custom_command(TARGET ${FW_NAME} POST_BUILD ${post_build} VERBATIM)

  set(frames ${CMAKE_BINARY_DIR}/frames/${FW_NAME})
  file(MAKE_DIRECTORY ${frames})
  set_target_properties(${FW_NAME} PROPERTIES
    SUFFIX .elf
    CROSSCOMPILING_EMULATOR "${HIDER_TIMEOUT};--kill-after=5;${FW_TIMEOUT};${FW_EMULATOR}"
    HIDER_FRAMES_DIR ${frames}
    HIDER_MACHINE ${FW_MACHINE})

  # The static stack bound against the reserved stack (ld sizes: bytes or <n>K).
  if(FW_STACK_SIZE MATCHES "^([0-9]+)K$")
    math(EXPR stack_bytes "${CMAKE_MATCH_1} * 1024")
  elseif(FW_STACK_SIZE MATCHES "^[0-9]+$")
    set(stack_bytes ${FW_STACK_SIZE})
  else()
    message(FATAL_ERROR "hider_add_firmware(${FW_NAME}): STACK_SIZE '${FW_STACK_SIZE}' is not <bytes> or <n>K")
  endif()
  if(HIDER_ARCH STREQUAL "arm")  # entry: the reset handler; the fault handler ends a run, it is no callee
    set(bound_args --entry hider_reset --handler hider_fault_from_frame --not-pointers hider_vectors)
  else()
    set(bound_args --entry _start --handler hider_trap_handler)
  endif()
  foreach(object IN LISTS FW_NOT_POINTERS)
    list(APPEND bound_args --not-pointers ${object})
  endforeach()
  math(EXPR bound_limit "${stack_bytes} - 32")  # the start-up fails a run leaving fewer than 32 bytes untouched
  get_target_property(hider_stack host_hider-stack HIDER_HOST_PROGRAM)
  if(FW_NO_TEST)
    set(measured -)
  else()
    set(measured ${frames}/stack.txt)
  endif()
  add_test(NAME ${FW_NAME}.stack_bound
    COMMAND sh ${scripts}/check_stack_bound.sh ${HIDER_OBJDUMP} ${hider_stack} $<TARGET_FILE:${FW_NAME}>
            ${CMAKE_CURRENT_BINARY_DIR}/${FW_NAME}.dump ${bound_limit} ${measured} ${bound_args})
  set_tests_properties(${FW_NAME}.stack_bound PROPERTIES TIMEOUT 60 LABELS "firmware;stack;${HIDER_TARGET}")
  if(NOT FW_NO_TEST)
    set_tests_properties(${FW_NAME}.stack_bound PROPERTIES FIXTURES_REQUIRED ${FW_NAME}.run)
  endif()

  if(NOT FW_NO_TEST)
    add_test(NAME ${FW_NAME}.run COMMAND ${FW_NAME} WORKING_DIRECTORY ${frames})
    math(EXPR ctest_timeout "${FW_TIMEOUT} + 15")
    set_tests_properties(${FW_NAME}.run PROPERTIES
      TIMEOUT ${ctest_timeout} FIXTURES_SETUP ${FW_NAME}.run LABELS "firmware;${HIDER_TARGET}")
  endif()

  set(count_dir ${CMAKE_BINARY_DIR}/insncount/${FW_NAME})
  add_custom_target(${FW_NAME}_insncount
    COMMAND ${CMAKE_COMMAND} -E make_directory ${count_dir}
    COMMAND ${CMAKE_COMMAND} -E chdir ${count_dir} ${CMAKE_COMMAND} -E env INSNCOUNT_PLUGIN=${HIDER_INSNCOUNT_PLUGIN}
            NM=${CMAKE_NM} sh ${HIDER_INSNCOUNT_DIR}/run.sh ${HIDER_TARGET} $<TARGET_FILE:${FW_NAME}>
            ${count_dir}/counts.txt ${FW_MACHINE}
    DEPENDS ${FW_NAME} qemu_insncount
    COMMENT "Counting instructions of ${FW_NAME} (bench_begin..bench_end) on ${FW_MACHINE}"
    USES_TERMINAL VERBATIM)
endfunction()

# hider_add_host_program(NAME <name> SOURCES <src>... [INCLUDE_DIRECTORIES <dir>...] [COMPILE_OPTIONS <flag>...])
# Compiles and links ${CMAKE_BINARY_DIR}/host/<name> with the HOST C++ compiler (HIDER_HOST_CXX,
# C++17, -O2, hider warnings); include path: lib/, firmware/, port/ plus INCLUDE_DIRECTORIES.
# Header dependencies are tracked (depfiles). Built by the target host_<name> (in ALL).
function(hider_add_host_program)
  cmake_parse_arguments(PARSE_ARGV 0 HP "" "NAME" "SOURCES;INCLUDE_DIRECTORIES;COMPILE_OPTIONS")
  if(NOT HP_NAME OR NOT HP_SOURCES)
    message(FATAL_ERROR "hider_add_host_program: NAME and SOURCES are required")
  endif()
  set(out ${CMAKE_BINARY_DIR}/host/${HP_NAME})
  set(obj_dir ${CMAKE_BINARY_DIR}/host/${HP_NAME}.dir)
  file(MAKE_DIRECTORY ${obj_dir})
  set(flags -std=c++17 -O2 ${HIDER_WARNINGS} ${HP_COMPILE_OPTIONS})
  foreach(dir IN LISTS HP_INCLUDE_DIRECTORIES ITEMS ${PROJECT_SOURCE_DIR}/lib ${PROJECT_SOURCE_DIR}/firmware ${PROJECT_SOURCE_DIR}/port)
    get_filename_component(dir ${dir} ABSOLUTE BASE_DIR ${CMAKE_CURRENT_SOURCE_DIR})
    list(APPEND flags -I${dir})
  endforeach()
  set(objects)
  set(index 0)
  foreach(src IN LISTS HP_SOURCES)
    get_filename_component(src ${src} ABSOLUTE BASE_DIR ${CMAKE_CURRENT_SOURCE_DIR})
    get_filename_component(base ${src} NAME)
    set(obj ${obj_dir}/${index}_${base}.o)
    add_custom_command(OUTPUT ${obj}
      COMMAND ${HIDER_HOST_CXX} ${flags} -MD -MF ${obj}.d -MT ${obj} -c ${src} -o ${obj}
      DEPENDS ${src} DEPFILE ${obj}.d
      COMMENT "Host C++ ${base} (${HP_NAME})" VERBATIM)
    list(APPEND objects ${obj})
    math(EXPR index "${index} + 1")
  endforeach()
  add_custom_command(OUTPUT ${out}
    COMMAND ${HIDER_HOST_CXX} -o ${out} ${objects}
    DEPENDS ${objects}
    COMMENT "Linking host program ${HP_NAME}" VERBATIM)
  add_custom_target(host_${HP_NAME} ALL DEPENDS ${out})
  set_target_properties(host_${HP_NAME} PROPERTIES HIDER_HOST_PROGRAM ${out})
endfunction()

# hider-stack (tools/hider-stack), the static stack bound of every firmware's <name>.stack_bound test.
hider_add_host_program(NAME hider-stack SOURCES ${PROJECT_SOURCE_DIR}/tools/hider-stack/main.cpp
                       ${PROJECT_SOURCE_DIR}/tools/hider-stack/stack_bound.cpp)

# hider_compare_with_host(FIRMWARE <fw> OUTPUTS <file>...
#                         HOST_PROGRAM <name> [HOST_ARGS <arg>...] | HOST_COMMAND <cmd>...)
# ctest <fw>.matches_host, after <fw>.run: runs the host program (from hider_add_host_program) or
# HOST_COMMAND in an emptied ${CMAKE_BINARY_DIR}/reference/<fw>, which must write each OUTPUTS file
# there, then compares them byte for byte with the firmware's files in its frames directory.
function(hider_compare_with_host)
  cmake_parse_arguments(PARSE_ARGV 0 CMP "" "FIRMWARE;HOST_PROGRAM;TIMEOUT" "OUTPUTS;HOST_ARGS;HOST_COMMAND")
  if(NOT CMP_FIRMWARE OR NOT CMP_OUTPUTS OR (NOT CMP_HOST_PROGRAM AND NOT CMP_HOST_COMMAND))
    message(FATAL_ERROR "hider_compare_with_host: FIRMWARE, OUTPUTS and HOST_PROGRAM or HOST_COMMAND are required")
  endif()
  if(CMP_HOST_PROGRAM)
    get_target_property(program host_${CMP_HOST_PROGRAM} HIDER_HOST_PROGRAM)
    set(command ${program} ${CMP_HOST_ARGS})
  else()
    set(command ${CMP_HOST_COMMAND})
  endif()
  if(NOT CMP_TIMEOUT)
    set(CMP_TIMEOUT 120)
  endif()
  get_target_property(frames ${CMP_FIRMWARE} HIDER_FRAMES_DIR)
  add_test(NAME ${CMP_FIRMWARE}.matches_host
    COMMAND sh ${CMAKE_CURRENT_FUNCTION_LIST_DIR}/check_firmware_outputs.sh ${frames}
            ${CMAKE_BINARY_DIR}/reference/${CMP_FIRMWARE} $<TARGET_FILE:${CMP_FIRMWARE}> ${CMP_OUTPUTS} -- ${command})
  set_tests_properties(${CMP_FIRMWARE}.matches_host PROPERTIES
    FIXTURES_REQUIRED ${CMP_FIRMWARE}.run TIMEOUT ${CMP_TIMEOUT} LABELS "firmware;${HIDER_TARGET}")
endfunction()

# hider_add_insncount_test(FIRMWARE <fw>)
# ctest <fw>.insncount_deterministic: two plugin runs give identical counts, and the
# bench_begin..bench_end region is nonzero. Prints the counts (ctest -V or --output-on-failure).
function(hider_add_insncount_test)
  cmake_parse_arguments(PARSE_ARGV 0 IC "" "FIRMWARE" "")
  get_target_property(machine ${IC_FIRMWARE} HIDER_MACHINE)
  add_test(NAME ${IC_FIRMWARE}.insncount_deterministic
    COMMAND ${CMAKE_COMMAND} -E env INSNCOUNT_PLUGIN=${HIDER_INSNCOUNT_PLUGIN} NM=${CMAKE_NM}
            sh ${HIDER_INSNCOUNT_DIR}/check_deterministic.sh ${HIDER_TARGET} $<TARGET_FILE:${IC_FIRMWARE}>
            ${CMAKE_BINARY_DIR}/insncount/${IC_FIRMWARE}.test ${machine})
  set_tests_properties(${IC_FIRMWARE}.insncount_deterministic PROPERTIES
    TIMEOUT 120 PASS_REGULAR_EXPRESSION "deterministic, region=[1-9]" LABELS "firmware;${HIDER_TARGET}")
endfunction()

# hider_add_insncount_budget(NAME <test> FIRMWARE <fw> FIELD region|pair0 NUM <n> [DEN <d>]
#                            [AGAINST <fw2> AGAINST_FIELD region|pair0])
# ctest <test>: the firmware's instruction count (bench region, or its first pair) times DEN is at
# most NUM, or at most NUM times the count of AGAINST (a ratio NUM / DEN): an issue's met target kept
# under test (tools/qemu-insncount/check_budget.sh). Each firmware runs on its own machine.
function(hider_add_insncount_budget)
  cmake_parse_arguments(PARSE_ARGV 0 IB "" "NAME;FIRMWARE;FIELD;NUM;DEN;AGAINST;AGAINST_FIELD" "")
  if(IB_UNPARSED_ARGUMENTS OR NOT IB_NAME OR NOT IB_FIRMWARE OR NOT IB_NUM OR NOT IB_FIELD MATCHES "^(region|pair0)$"
     OR (IB_AGAINST AND NOT IB_AGAINST_FIELD MATCHES "^(region|pair0)$") OR (IB_AGAINST_FIELD AND NOT IB_AGAINST))
    message(FATAL_ERROR "hider_add_insncount_budget(${ARGV}): needs NAME, FIRMWARE, FIELD region|pair0, NUM, "
                        "optional DEN and AGAINST with AGAINST_FIELD region|pair0; unknown: ${IB_UNPARSED_ARGUMENTS}")
  endif()
  if(NOT IB_DEN)
    set(IB_DEN 1)
  endif()
  get_target_property(machine ${IB_FIRMWARE} HIDER_MACHINE)
  set(args $<TARGET_FILE:${IB_FIRMWARE}> ${machine} ${IB_FIELD})
  if(IB_AGAINST)
    get_target_property(machine_b ${IB_AGAINST} HIDER_MACHINE)
    list(APPEND args $<TARGET_FILE:${IB_AGAINST}> ${machine_b} ${IB_AGAINST_FIELD})
  endif()
  add_test(NAME ${IB_NAME}
    COMMAND ${CMAKE_COMMAND} -E env INSNCOUNT_PLUGIN=${HIDER_INSNCOUNT_PLUGIN} NM=${CMAKE_NM}
            sh ${HIDER_INSNCOUNT_DIR}/check_budget.sh ${HIDER_TARGET} ${CMAKE_BINARY_DIR}/insncount/${IB_NAME}
            ${IB_NUM} ${IB_DEN} ${args})
  set_tests_properties(${IB_NAME} PROPERTIES TIMEOUT 180 LABELS "firmware;${HIDER_TARGET};budget")
endfunction()
