# Runs Doxygen on the package's Doxyfile and fails when Doxygen fails or writes anything
# to its warning log (WARN_LOGFILE): a manual with unresolved references, undocumented
# public names or malformed commands does not pass.
#
#   cmake -DDOXYGEN_EXECUTABLE=doxygen -DDOXYFILE=<build>/Doxyfile -DWARN_LOG=<log> -P run_doxygen.cmake

foreach(var DOXYGEN_EXECUTABLE DOXYFILE WARN_LOG)
  if(NOT DEFINED ${var} OR "${${var}}" STREQUAL "")
    message(FATAL_ERROR "run_doxygen.cmake: -D${var}=... is required")
  endif()
endforeach()

# A log left over from an earlier run must not decide this one.
file(REMOVE "${WARN_LOG}")

execute_process(
  COMMAND "${DOXYGEN_EXECUTABLE}" "${DOXYFILE}"
  RESULT_VARIABLE doxygen_result
  OUTPUT_VARIABLE doxygen_stdout
  ERROR_VARIABLE doxygen_stderr)

if(NOT doxygen_result EQUAL 0)
  message(FATAL_ERROR "Doxygen failed (exit status ${doxygen_result}) on ${DOXYFILE}\n"
                      "${doxygen_stdout}\n${doxygen_stderr}")
endif()
if(NOT EXISTS "${WARN_LOG}")
  message(FATAL_ERROR "Doxygen wrote no warning log ${WARN_LOG}: is WARN_LOGFILE set in ${DOXYFILE}?")
endif()

# Doxygen is run with QUIET = YES, so anything on stderr is worth showing, but only the
# warning log decides: graphviz and fontconfig may print harmless notes of their own.
string(STRIP "${doxygen_stderr}" doxygen_stderr)
if(NOT doxygen_stderr STREQUAL "")
  message(STATUS "Doxygen printed on stderr:\n${doxygen_stderr}")
endif()

file(READ "${WARN_LOG}" warnings)
string(STRIP "${warnings}" warnings)
if(NOT warnings STREQUAL "")
  string(REGEX MATCHALL "(warning|error): " warning_markers "${warnings}")
  list(LENGTH warning_markers number_of_warnings)
  # NOTICE prints the log verbatim; FATAL_ERROR would reflow its lines.
  message(NOTICE "${warnings}\n")
  message(FATAL_ERROR "Doxygen reported ${number_of_warnings} warning(s), listed above "
                      "(log: ${WARN_LOG})")
endif()
message(STATUS "Doxygen built the manual without warnings")
