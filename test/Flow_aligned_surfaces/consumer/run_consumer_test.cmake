# Checks that the package installed the header-only way works for an outside project:
#   (1) cmake -S <PACKAGE_SOURCE_DIR> -B <WORK_DIR>/package (nothing built, ParaView found or not),
#       then cmake --install <WORK_DIR>/package --prefix <WORK_DIR>/prefix
#   (2) configure the consumer project with CMAKE_PREFIX_PATH=<prefix>
#   (3) build it
#   (4) run it (it returns nonzero when the alignment misses its flux)
# Run as: cmake -DPACKAGE_SOURCE_DIR=... -DCONSUMER_SOURCE_DIR=... -DWORK_DIR=... -P run_consumer_test.cmake
# Optional: -DCONSUMER_GENERATOR=..., -DCONSUMER_CXX_COMPILER=..., -DCONSUMER_BUILD_TYPE=... (default: none),
#           -DCONSUMER_COMPILER_LAUNCHER=... (ccache: the consumer's own compilations only),
#           -DEXPECT_CHOLMOD=ON|OFF (checks that the CHOLMOD usage requirement reached the consumer),
#           -DEXPECT_ZLIB=ON|OFF (likewise for zlib: the consumer then reads a gzip NRRD file),
#           -DWITH_PARAVIEW_VTK=ON (also the component VTK after ParaView: consumer_VTK must run with
#           ParaView's VTK, PARAVIEW_VTK_VERSION).
cmake_minimum_required(VERSION 3.16)

foreach(var IN ITEMS PACKAGE_SOURCE_DIR CONSUMER_SOURCE_DIR WORK_DIR)
  if(NOT DEFINED ${var} OR "${${var}}" STREQUAL "")
    message(FATAL_ERROR "run_consumer_test.cmake: -D${var}=... is required")
  endif()
endforeach()
if(NOT EXISTS "${PACKAGE_SOURCE_DIR}/CMakeLists.txt")
  message(FATAL_ERROR "run_consumer_test.cmake: no CMakeLists.txt in ${PACKAGE_SOURCE_DIR}")
endif()
if(NOT EXISTS "${CONSUMER_SOURCE_DIR}/CMakeLists.txt")
  message(FATAL_ERROR "run_consumer_test.cmake: no CMakeLists.txt in ${CONSUMER_SOURCE_DIR}")
endif()
# By default the consumer is configured without a build type, as an outside project that sets
# none: no optimization and assertions on.  What it checks (the package found, the exported targets'
# usage requirements, GCC compiling the headers, the run's results) needs no optimization, and GCC
# compiles consumer.cpp without it in about four fifths of the CPU time of -O3 (-g would add back
# most of the difference, hence no Debug).
if(NOT DEFINED CONSUMER_BUILD_TYPE)
  set(CONSUMER_BUILD_TYPE "")
endif()

set(package "${WORK_DIR}/package")
set(prefix "${WORK_DIR}/prefix")
set(build "${WORK_DIR}/build")
file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")

# Runs one step; on failure stops with the step's name, command and output.
function(run_step name)
  execute_process(COMMAND ${ARGN}
    RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE error)
  if(NOT result EQUAL 0)
    string(REPLACE ";" " " command "${ARGN}")
    message(FATAL_ERROR "consumer test: step '${name}' failed (exit code: ${result})\n"
                        "command: ${command}\n--- stdout ---\n${output}\n--- stderr ---\n${error}")
  endif()
  set(step_output "${output}" PARENT_SCOPE)
  message(STATUS "consumer test: step '${name}' done")
endfunction()

# The arguments of a configuration of `source` in `binary`, with the test's generator and compiler.
function(configure_args variable source binary)
  set(args -S "${source}" -B "${binary}")
  if(NOT CONSUMER_BUILD_TYPE STREQUAL "")
    list(APPEND args "-DCMAKE_BUILD_TYPE=${CONSUMER_BUILD_TYPE}")
  endif()
  if(CONSUMER_GENERATOR)
    list(APPEND args -G "${CONSUMER_GENERATOR}")
  endif()
  if(CONSUMER_CXX_COMPILER)
    list(APPEND args "-DCMAKE_CXX_COMPILER=${CONSUMER_CXX_COMPILER}")
  endif()
  if(CONSUMER_COMPILER_LAUNCHER)
    list(APPEND args "-DCMAKE_CXX_COMPILER_LAUNCHER=${CONSUMER_COMPILER_LAUNCHER}")
  endif()
  set(${variable} ${args} PARENT_SCOPE)
endfunction()

# (1) Configure the package and install it without building anything.
configure_args(package_args "${PACKAGE_SOURCE_DIR}" "${package}")
run_step("1/4 configure the package" "${CMAKE_COMMAND}" ${package_args})
run_step("1/4 install" "${CMAKE_COMMAND}" --install "${package}" --prefix "${prefix}")
# A plugin that was not built is not installed (it installs, component paraview_plugin, once built).
file(GLOB_RECURSE plugin_files "${prefix}/lib/*FlowAlignedSurfaces*")
if(plugin_files)
  message(FATAL_ERROR "consumer test: step '1/4 install' installed files of a plugin that was not built: ${plugin_files}")
endif()
foreach(file IN ITEMS
    include/CGAL/Flow_aligned_surfaces/Flow_aligned_deformation.h
    include/CGAL/Flow_aligned_surfaces/align_to_flow.h
    include/CGAL/Flow_aligned_surfaces/internal/Poisson_operators.h
    share/cmake/Flow_aligned_surfaces/Flow_aligned_surfacesConfig.cmake
    share/cmake/Flow_aligned_surfaces/Flow_aligned_surfacesConfigVersion.cmake
    share/cmake/Flow_aligned_surfaces/Flow_aligned_surfacesTargets.cmake)
  if(NOT EXISTS "${prefix}/${file}")
    message(FATAL_ERROR "consumer test: step '1/4 install' did not install ${file} under ${prefix}")
  endif()
endforeach()

# (2) Configure: only the fresh prefix may provide the package (no package registry).
configure_args(configure_args "${CONSUMER_SOURCE_DIR}" "${build}")
list(APPEND configure_args "-DCMAKE_PREFIX_PATH=${prefix}"
     -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF -DCMAKE_FIND_PACKAGE_NO_PACKAGE_REGISTRY=ON)
if(WITH_PARAVIEW_VTK)
  list(APPEND configure_args -DCONSUMER_WITH_PARAVIEW_VTK=ON)
endif()
run_step("2/4 configure" "${CMAKE_COMMAND}" ${configure_args})
file(STRINGS "${build}/CMakeCache.txt" found_dir REGEX "^Flow_aligned_surfaces_DIR:")
string(REGEX REPLACE "^[^=]*=" "" found_dir "${found_dir}")
file(REAL_PATH "${prefix}" real_prefix)
if(EXISTS "${found_dir}")
  file(REAL_PATH "${found_dir}" found_dir)
endif()
string(FIND "${found_dir}" "${real_prefix}/" position)
if(NOT position EQUAL 0)
  message(FATAL_ERROR "consumer test: step '2/4 configure' found the package in '${found_dir}', "
                      "not in the installed prefix ${real_prefix}")
endif()

# (3) Build.
# A multi-configuration generator builds Debug when given no configuration.
set(config "${CONSUMER_BUILD_TYPE}")
if(config STREQUAL "")
  set(config Debug)
endif()
run_step("3/4 build" "${CMAKE_COMMAND}" --build "${build}" --config "${config}")

# (4) Run.
set(executable "${build}/consumer")
if(NOT EXISTS "${executable}" AND EXISTS "${build}/${config}/consumer")
  set(executable "${build}/${config}/consumer")
endif()
run_step("4/4 run" "${executable}" "${build}") # the consumer writes its scratch file there
message(STATUS "consumer output:\n${step_output}")
if(NOT step_output MATCHES "normalized flux after: ")
  message(FATAL_ERROR "consumer test: step '4/4 run' printed no flux:\n${step_output}")
endif()
if(DEFINED EXPECT_CHOLMOD AND NOT "${EXPECT_CHOLMOD}" STREQUAL "")
  if(EXPECT_CHOLMOD AND NOT step_output MATCHES "sparse solver: CHOLMOD")
    message(FATAL_ERROR "consumer test: the package was built with CHOLMOD but the consumer did not "
                        "get CGAL_FLOW_ALIGNED_SURFACES_USE_CHOLMOD from the exported target:\n${step_output}")
  endif()
  if(NOT EXPECT_CHOLMOD AND step_output MATCHES "sparse solver: CHOLMOD")
    message(FATAL_ERROR "consumer test: the package was built without CHOLMOD but the consumer uses it")
  endif()
endif()
if(DEFINED EXPECT_ZLIB AND NOT "${EXPECT_ZLIB}" STREQUAL "")
  if(EXPECT_ZLIB AND NOT step_output MATCHES "zlib: gzip NRRD read")
    message(FATAL_ERROR "consumer test: the package was built with zlib but the consumer did not "
                        "get CGAL_FLOW_ALIGNED_SURFACES_USE_ZLIB from the exported target:\n${step_output}")
  endif()
  if(NOT EXPECT_ZLIB AND step_output MATCHES "zlib: ")
    message(FATAL_ERROR "consumer test: the package was built without zlib but the consumer uses it")
  endif()
endif()
if(WITH_PARAVIEW_VTK)
  run_step("4/4 run consumer_VTK" "${build}/consumer_VTK")
  message(STATUS "consumer_VTK output:\n${step_output}")
  if(NOT step_output MATCHES "VTK version: ${PARAVIEW_VTK_VERSION}")
    message(FATAL_ERROR "consumer test: consumer_VTK does not run with ParaView's VTK ${PARAVIEW_VTK_VERSION}:\n${step_output}")
  endif()
endif()
