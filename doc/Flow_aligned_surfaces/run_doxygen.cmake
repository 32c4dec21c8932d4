# Runs Doxygen on the package's Doxyfile, copies MathJax into the HTML, and fails when
# Doxygen fails or writes anything to its warning log (WARN_LOGFILE): a manual with unresolved
# references, undocumented public names or malformed commands does not pass; nor does one
# whose pages load a script, a style sheet or an image from the network.
#
#   cmake -DDOXYGEN_EXECUTABLE=doxygen -DDOXYFILE=<build>/Doxyfile -DWARN_LOG=<log> \
#         -DHTML_DIR=<build>/html -DMATHJAX_DIR=/usr/share/javascript/mathjax -P run_doxygen.cmake

cmake_minimum_required(VERSION 3.16) # IN_LIST

foreach(var DOXYGEN_EXECUTABLE DOXYFILE WARN_LOG HTML_DIR MATHJAX_DIR)
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

# The manual's own MathJax (MATHJAX_RELPATH = mathjax): what Doxygen's MathJax 2 configuration
# loads (TeX input, HTML-CSS output with the TeX web fonts, the menu and zoom extensions), about
# 7 MB of the 54 MB that Debian installs.
set(mathjax_copy "${HTML_DIR}/mathjax")
if(NOT EXISTS "${MATHJAX_DIR}/MathJax.js")
  message(FATAL_ERROR "No MathJax.js in MATHJAX_DIR=${MATHJAX_DIR}")
endif()
file(COPY "${MATHJAX_DIR}/MathJax.js" "${MATHJAX_DIR}/extensions" DESTINATION "${mathjax_copy}")
file(COPY "${MATHJAX_DIR}/jax/element" DESTINATION "${mathjax_copy}/jax")
file(COPY "${MATHJAX_DIR}/jax/input/TeX" DESTINATION "${mathjax_copy}/jax/input")
file(COPY "${MATHJAX_DIR}/jax/output/HTML-CSS" DESTINATION "${mathjax_copy}/jax/output")
file(COPY "${MATHJAX_DIR}/fonts/HTML-CSS/TeX" DESTINATION "${mathjax_copy}/fonts/HTML-CSS")

# Offline: no page may fetch anything from the network (links to other sites are fine).
file(GLOB_RECURSE pages "${HTML_DIR}/*.html")
list(FILTER pages EXCLUDE REGEX "/mathjax/")
set(remote_fetches "")
foreach(page IN LISTS pages)
  file(STRINGS "${page}" fetches REGEX "(src|<link[^>]* href)=[\"']?https?:")
  foreach(fetch IN LISTS fetches)
    string(STRIP "${fetch}" fetch)
    string(APPEND remote_fetches "${page}: ${fetch}\n")
  endforeach()
endforeach()
if(NOT remote_fetches STREQUAL "")
  message(FATAL_ERROR "Pages of the manual load from the network; it must read offline:\n"
                      "${remote_fetches}")
endif()

# The navigation tree: no two entries of the same title, which a reader could not tell apart.
file(READ "${HTML_DIR}/navtreedata.js" navtree)
# Each entry is [ "title", "link", children ]; brackets would group CMake's list elements.
string(REPLACE "[ \"" "@@" navtree "${navtree}")
string(REPLACE "[" "" navtree "${navtree}")
string(REPLACE "]" "" navtree "${navtree}")
string(REGEX MATCHALL "@@[^\"]+" entries "${navtree}")
set(seen "")
set(repeated "")
foreach(entry IN LISTS entries)
  string(SUBSTRING "${entry}" 2 -1 title)
  if(title IN_LIST seen AND NOT title IN_LIST repeated)
    list(APPEND repeated "${title}")
  endif()
  list(APPEND seen "${title}")
endforeach()
if(repeated)
  string(REPLACE ";" "', '" repeated "${repeated}")
  message(FATAL_ERROR "The navigation tree has several entries titled '${repeated}' (${HTML_DIR}/navtreedata.js)")
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
message(STATUS "Doxygen built the manual without warnings; it reads offline")
