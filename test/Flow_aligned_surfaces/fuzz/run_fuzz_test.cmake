# The ctest fuzz_readers: builds the libFuzzer targets of this folder with clang++ and runs each
# for a bounded number of inputs on a seed corpus: only committed files (fuzz/corpus/<reader>/ and
# the test data files of its format in SEED_DIRS), so that a run does not depend on what other
# tests or users left in a temporary folder.  Fails on a crash,
# a sanitizer report or a timeout, naming the input saved in <WORK_DIR>/artifacts/.  Prints
# FUZZ_SKIPPED (a skip for ctest) when clang++ or libFuzzer is missing, or fails under FUZZ_REQUIRED.
# Run as: cmake -DFUZZ_SOURCE_DIR=... -DWORK_DIR=... -P run_fuzz_test.cmake
# Optional: -DFUZZ_CXX_COMPILER=clang++, -DSEED_DIRS="dir;dir",
#           -DFUZZ_RUNS=10000, -DFUZZ_MAX_TIME=20 (seconds per target), -DFUZZ_JOBS=2,
#           -DFUZZ_SEED=1 (libFuzzer's random seed: the same inputs in the same order every run),
#           -DFUZZ_REQUIRED=ON (a missing clang++ or libFuzzer is a failure, not a skip: CI=true)
cmake_minimum_required(VERSION 3.16)

foreach(var IN ITEMS FUZZ_SOURCE_DIR WORK_DIR)
  if(NOT DEFINED ${var} OR "${${var}}" STREQUAL "")
    message(FATAL_ERROR "run_fuzz_test.cmake: -D${var}=... is required")
  endif()
endforeach()
if(NOT FUZZ_RUNS)
  set(FUZZ_RUNS 10000)
endif()
if(NOT FUZZ_MAX_TIME)
  set(FUZZ_MAX_TIME 20)
endif()
if(NOT FUZZ_JOBS)
  set(FUZZ_JOBS 2)
endif()
if(NOT FUZZ_SEED)
  set(FUZZ_SEED 1)
endif()

# clang++ with libFuzzer, or a visible skip.
if(NOT FUZZ_CXX_COMPILER)
  find_program(FUZZ_CXX_COMPILER NAMES clang++ clang++-19 clang++-18 clang++-17 clang++-16 clang++-15 clang++-14)
endif()
# Without a fuzzer: a visible skip, or under FUZZ_REQUIRED a failure that says what to install.
function(skip_or_fail reason)
  if(FUZZ_REQUIRED)
    message(FATAL_ERROR "fuzz test: ${reason} (FUZZ_REQUIRED: a missing tool fails; "
                        "scripts/install-deps.sh installs clang from Debian's packages)")
  endif()
  message(STATUS "FUZZ_SKIPPED: ${reason}")
endfunction()
if(NOT FUZZ_CXX_COMPILER)
  skip_or_fail("no clang++ found; the libFuzzer targets were not built or run")
  return()
endif()
file(MAKE_DIRECTORY "${WORK_DIR}")
file(WRITE "${WORK_DIR}/probe.cpp"
  "#include <cstddef>\n#include <cstdint>\nextern \"C\" int LLVMFuzzerTestOneInput(const std::uint8_t*, std::size_t) { return 0; }\n")
execute_process(COMMAND "${FUZZ_CXX_COMPILER}" -fsanitize=fuzzer,address,undefined "${WORK_DIR}/probe.cpp"
                        -o "${WORK_DIR}/probe"
  RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE output)
if(NOT result EQUAL 0)
  skip_or_fail("${FUZZ_CXX_COMPILER} cannot link -fsanitize=fuzzer,address,undefined "
               "(libFuzzer or the sanitizer runtimes are missing):\n${output}")
  return()
endif()

# Runs one step; on failure stops with the step's name, command and the end of its output.
function(run_step name)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE output)
  if(NOT result EQUAL 0)
    string(REPLACE ";" " " command "${ARGN}")
    string(LENGTH "${output}" length)
    if(length GREATER 12000)
      math(EXPR start "${length} - 12000")
      string(SUBSTRING "${output}" ${start} -1 output)
    endif()
    message(FATAL_ERROR "fuzz test: step '${name}' failed (exit code: ${result})\n"
                        "command: ${command}\n--- output (end) ---\n${output}")
  endif()
  set(step_output "${output}" PARENT_SCOPE)
endfunction()

string(TIMESTAMP t0 "%s")
set(build "${WORK_DIR}/build")
run_step("configure" "${CMAKE_COMMAND}" -S "${FUZZ_SOURCE_DIR}" -B "${build}"
         "-DCMAKE_CXX_COMPILER=${FUZZ_CXX_COMPILER}" -DCMAKE_BUILD_TYPE=)
run_step("build" "${CMAKE_COMMAND}" --build "${build}" -j ${FUZZ_JOBS})
string(TIMESTAMP t1 "%s")
math(EXPR build_seconds "${t1} - ${t0}")
message(STATUS "fuzz test: built the targets in ${build_seconds} s")

# reader -> the file name patterns of its seeds
set(patterns_VTK_legacy "*.vtk")
set(patterns_AmiraMesh "*.am")
set(patterns_NRRD "*.nrrd;*.nhdr")
set(patterns_VTK_XML "*.vti;*.vtu;*.vts;*.vtr;*.pvd")
file(REMOVE_RECURSE "${WORK_DIR}/artifacts")
file(MAKE_DIRECTORY "${WORK_DIR}/artifacts")
foreach(reader IN ITEMS VTK_legacy AmiraMesh NRRD VTK_XML)
  set(corpus "${WORK_DIR}/corpus/${reader}")
  file(REMOVE_RECURSE "${corpus}")
  file(MAKE_DIRECTORY "${corpus}")
  file(GLOB seeds "${FUZZ_SOURCE_DIR}/corpus/${reader}/*")
  foreach(dir IN LISTS SEED_DIRS)
    foreach(pattern IN LISTS patterns_${reader})
      file(GLOB more "${dir}/${pattern}")
      list(APPEND seeds ${more})
    endforeach()
  endforeach()
  set(copied 0)
  foreach(seed IN LISTS seeds)
    file(SIZE "${seed}" size)
    if(size LESS 65536 AND NOT IS_DIRECTORY "${seed}")
      file(COPY "${seed}" DESTINATION "${corpus}")
      math(EXPR copied "${copied} + 1")
    endif()
  endforeach()
  string(TIMESTAMP t0 "%s")
  run_step("run fuzz_read_${reader}" "${build}/fuzz_read_${reader}"
           -seed=${FUZZ_SEED} -runs=${FUZZ_RUNS} -max_total_time=${FUZZ_MAX_TIME} -timeout=5 -rss_limit_mb=2048 -max_len=4096
           "-artifact_prefix=${WORK_DIR}/artifacts/${reader}-" "${corpus}")
  string(TIMESTAMP t1 "%s")
  math(EXPR seconds "${t1} - ${t0}")
  string(REGEX MATCH "Done [0-9]+ runs in [0-9]+ second" done "${step_output}")
  message(STATUS "fuzz test: fuzz_read_${reader}: ${copied} seeds, ${done}(s), ${seconds} s, no crash")
endforeach()
