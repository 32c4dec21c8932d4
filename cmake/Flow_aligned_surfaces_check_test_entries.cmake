# cmake -DEXECUTABLE=... -DFILTER=a.*:b.* -P Flow_aligned_surfaces_check_test_entries.cmake
# Fails when the GoogleTest executable holds test cases that the per-file ctest entries do not
# run, i.e. that `--gtest_filter=-FILTER` still lists.
execute_process(COMMAND "${EXECUTABLE}" --gtest_list_tests "--gtest_filter=-${FILTER}"
                OUTPUT_VARIABLE listing RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "${EXECUTABLE} --gtest_list_tests failed (${status}):\n${listing}")
endif()
# The listing is "Suite.\n  Case\n" per suite; any indented line is a test case left out.
string(REGEX MATCHALL "\n  [^\n]+" left_out "\n${listing}")
if(left_out)
  message(FATAL_ERROR "test cases that no per-file ctest entry runs (their suite was not found "
                      "in a test file by cmake/Flow_aligned_surfaces_test_entries.cmake):\n${listing}")
endif()
message(STATUS "every test case of ${EXECUTABLE} is run by a per-file entry")
