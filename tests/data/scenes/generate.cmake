# The generated test scenes committed in tests/data/scenes/, from tools/common/gen_scenes.cpp through
# hider-scenes (the same generator the tests call in memory). Each line: "<file>|<hider-scenes name>".
#   cmake -DSCENES=<hider-scenes> -DSOURCE_DIR=<repo> -DOUT_DIR=<dir> -DMODE=check|update -P generate.cmake
# check: regenerates into OUT_DIR and fails if an OBJ or cameras.txt differs from the committed one
#        (ctest scenes.up_to_date); update: copies them over the committed files (review the diff).
# cameras.txt holds hider-render's camera options for each scene, as hider-scenes prints them.
set(HIDER_GENERATED_SCENES
  "cyclic_bars.obj|cyclic-bars"
  "piercing.obj|piercing"
  "city-1-16-16-street.obj|city-1-16-16-street"
  "city-1-12-12-above.obj|city-1-12-12-above")
foreach(var SCENES SOURCE_DIR OUT_DIR MODE)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "generate.cmake: -D${var}=... is required")
  endif()
endforeach()
set(committed ${SOURCE_DIR}/tests/data/scenes)
file(MAKE_DIRECTORY ${OUT_DIR})
set(cameras "# hider-render camera options of the generated scenes (tests/data/scenes/generate.cmake)\n")
set(files cameras.txt)
foreach(entry IN LISTS HIDER_GENERATED_SCENES)
  string(REPLACE "|" ";" fields "${entry}")
  list(GET fields 0 file)
  list(GET fields 1 name)
  execute_process(COMMAND ${SCENES} ${name} -o ${OUT_DIR}/${file} RESULT_VARIABLE rc OUTPUT_VARIABLE camera
                  OUTPUT_STRIP_TRAILING_WHITESPACE)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "hider-scenes failed for ${name} (exit ${rc})")
  endif()
  string(APPEND cameras "${file}: ${camera}\n")
  list(APPEND files ${file})
endforeach()
file(WRITE ${OUT_DIR}/cameras.txt "${cameras}")
set(stale)
foreach(file IN LISTS files)
  if(MODE STREQUAL "update")
    file(COPY_FILE ${OUT_DIR}/${file} ${committed}/${file} ONLY_IF_DIFFERENT)
    message(STATUS "wrote ${committed}/${file}")
  else()
    execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${OUT_DIR}/${file} ${committed}/${file} RESULT_VARIABLE same)
    if(NOT same EQUAL 0)
      list(APPEND stale ${file})
    endif()
  endif()
endforeach()
if(stale)
  message(FATAL_ERROR "committed scenes differ from a fresh generation: ${stale}\n"
          "If the change is intended: cmake --build <host build> --target generate_scenes, then review the diff.")
endif()
