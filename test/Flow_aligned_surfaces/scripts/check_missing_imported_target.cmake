# cmake -DSOURCE_DIR=... -DMODULE_DIR=... -DWORK_DIR=... -P check_missing_imported_target.cmake
# Configures missing_imported_target/ under FAS_REQUIRE_ALL_TOOLS: the configuration must stop
# naming the missing target, the target that needs it and the Debian package, and must not name
# what no target of the project links.
file(REMOVE_RECURSE "${WORK_DIR}")
execute_process(
  COMMAND ${CMAKE_COMMAND} -S "${SOURCE_DIR}/missing_imported_target" -B "${WORK_DIR}"
          -DFAS_REQUIRE_ALL_TOOLS=ON "-DFAS_CMAKE_MODULE_DIR=${MODULE_DIR}"
  RESULT_VARIABLE status OUTPUT_VARIABLE output ERROR_VARIABLE output)
string(REGEX REPLACE "[ \n]+" " " output "${output}")
if(status EQUAL 0)
  message(FATAL_ERROR "the configuration passed although Freetype::Freetype is missing: ${output}")
endif()
foreach(expected IN ITEMS "Freetype::Freetype (needed by VTK::freetype)" "Install the Debian packages: libfreetype-dev")
  string(FIND "${output}" "${expected}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "the message lacks '${expected}': ${output}")
  endif()
endforeach()
string(FIND "${output}" "GLEW" at)
if(NOT at EQUAL -1)
  message(FATAL_ERROR "the message names GLEW, which no target of the project links: ${output}")
endif()
message(STATUS "a missing imported target is reported with its Debian package")
