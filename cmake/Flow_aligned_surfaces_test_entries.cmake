# fas_add_test_file_entries(EXECUTABLE target SOURCES file... [LABELS label...] [ENVIRONMENT var=value...])
#
# One ctest entry per GoogleTest source file, named after the file, that runs the file's suites
# in one process (`--gtest_filter=SuiteA.*:SuiteB.*`), instead of one process per test case:
# every process of an executable that links VTK or runs under ASan pays a start-up of 0.2-1.4 s,
# and the suite has ~370 test cases.  A failure still names the file, and GoogleTest's output
# names the test case.
#
# The suites are read from the file (`TEST(Suite, ...)`, `TEST_F`, `TYPED_TEST`, ...); a suite
# used in two files of one executable would run twice, so that is refused at configure time.  The entry
# `<target>_every_test_case_has_an_entry` fails when the executable holds a test case that no
# entry's filter selects (a suite defined by a macro the pattern does not see).
function(fas_add_test_file_entries)
  cmake_parse_arguments(ARG "" "EXECUTABLE" "SOURCES;LABELS;ENVIRONMENT" ${ARGN})
  set(all_filters "")
  foreach(source IN LISTS ARG_SOURCES)
    get_filename_component(stem "${source}" NAME_WE)
    file(STRINGS "${source}" lines REGEX "^[ \t]*(TEST|TEST_F|TEST_P|TYPED_TEST|TYPED_TEST_P)\\(")
    set(suites "")
    foreach(line IN LISTS lines)
      string(REGEX REPLACE "^[ \t]*[A-Z_]+\\([ \t]*([A-Za-z0-9_]+).*" "\\1" suite "${line}")
      list(APPEND suites "${suite}")
    endforeach()
    list(REMOVE_DUPLICATES suites)
    if(NOT suites)
      message(FATAL_ERROR "${source}: no GoogleTest suite found (TEST(Suite, Name) at the start of a line)")
    endif()
    set(filter "")
    foreach(suite IN LISTS suites)
      get_property(owner GLOBAL PROPERTY FAS_TEST_SUITE_${ARG_EXECUTABLE}_${suite})
      if(owner)
        message(FATAL_ERROR "GoogleTest suite ${suite} is defined in ${owner} and in ${source}: "
                            "give it a name of its own, or its test cases run in both entries")
      endif()
      set_property(GLOBAL PROPERTY FAS_TEST_SUITE_${ARG_EXECUTABLE}_${suite} "${source}")
      # Typed suites are named Suite/0, Suite/1, ...
      list(APPEND filter "${suite}.*" "${suite}/*")
    endforeach()
    string(JOIN ":" filter ${filter})
    list(APPEND all_filters "${filter}")
    add_test(NAME ${stem} COMMAND ${ARG_EXECUTABLE} "--gtest_filter=${filter}" --gtest_brief=1
             WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
    # Scratch files (GoogleTest's TempDir()) go to a folder of the entry's own in the build
    # folder: entries running side by side cannot collide, and nothing is left in /tmp.
    set(scratch "${CMAKE_CURRENT_BINARY_DIR}/scratch/${stem}/")
    file(MAKE_DIRECTORY "${scratch}")
    set(environment "TEST_TMPDIR=${scratch}" ${ARG_ENVIRONMENT})
    set_tests_properties(${stem} PROPERTIES TIMEOUT 1500 LABELS "${ARG_LABELS}" ENVIRONMENT "${environment}")
  endforeach()
  string(JOIN ":" all_filters ${all_filters})
  add_test(NAME ${ARG_EXECUTABLE}_every_test_case_has_an_entry
    COMMAND ${CMAKE_COMMAND} "-DEXECUTABLE=$<TARGET_FILE:${ARG_EXECUTABLE}>" "-DFILTER=${all_filters}"
            -P ${PROJECT_SOURCE_DIR}/cmake/Flow_aligned_surfaces_check_test_entries.cmake)
  set_tests_properties(${ARG_EXECUTABLE}_every_test_case_has_an_entry PROPERTIES LABELS "${ARG_LABELS}")
endfunction()
