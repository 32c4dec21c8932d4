# The example replay_session as a test: replays the shipped sessions twice into two folders,
# then checks that both runs wrote the same CSV files byte for byte (the replay is
# deterministic), the saved surfaces, and the plot (a PNG file).  SESSIONS and EXPECTED_FILES
# are lists separated by '|'.
string(REPLACE "|" ";" SESSIONS "${SESSIONS}")
string(REPLACE "|" ";" EXPECTED_FILES "${EXPECTED_FILES}")
foreach(run 1 2)
  execute_process(
    COMMAND "${REPLAY}" --overwrite --output "${WORK_DIR}/run${run}" ${SESSIONS}
    RESULT_VARIABLE status)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "replay_session failed (run ${run}): ${status}")
  endif()
endforeach()
foreach(session ${SESSIONS})
  get_filename_component(stem "${session}" NAME_WE)
  execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files
    "${WORK_DIR}/run1/${stem}.csv" "${WORK_DIR}/run2/${stem}.csv" RESULT_VARIABLE differ)
  if(NOT differ EQUAL 0)
    message(FATAL_ERROR "two replays of ${session} wrote different CSV files")
  endif()
endforeach()
foreach(file ${EXPECTED_FILES})
  if(NOT EXISTS "${WORK_DIR}/run1/${file}")
    message(FATAL_ERROR "replay_session did not write ${file}")
  endif()
endforeach()
file(READ "${WORK_DIR}/run1/flux.png" signature LIMIT 4 HEX)
if(NOT signature STREQUAL "89504e47")
  message(FATAL_ERROR "flux.png is not a PNG file (it starts with ${signature})")
endif()
message(STATUS "two replays agree; surfaces and flux.png written to ${WORK_DIR}/run1")
