# fas_check_imported_targets(): names the Debian package to install when a target that the
# project links needs an imported target that no find_package() created.
#
# ParaView's and VTK's CMake packages import their modules with link interfaces that name other
# packages' targets (VTK::freetype names Freetype::Freetype, for one) without finding those
# packages, and paraview-dev does not depend on all of them.  CMake only notices at the end of
# the configuration ("The link interface of target "VTK::freetype" contains: Freetype::Freetype
# but the target was not found"), which says nothing of the package to install.  This walks the
# link interfaces from every target of the project through the imported targets they link, and
# stops the configuration with the Debian package instead; under FAS_REQUIRE_ALL_TOOLS (CI=true) it is an
# error, otherwise a warning before CMake's own error.

# The Debian package (bookworm) that provides each imported target ParaView's and VTK's packages
# may name; a target not listed is named alone.
set(fas_debian_package_of_Freetype "libfreetype-dev")
set(fas_debian_package_of_EXPAT "libexpat1-dev")
set(fas_debian_package_of_LZ4 "liblz4-dev")
set(fas_debian_package_of_LibLZMA "liblzma-dev")
set(fas_debian_package_of_ZLIB "zlib1g-dev")
set(fas_debian_package_of_PNG "libpng-dev")
set(fas_debian_package_of_JPEG "libjpeg-dev")
set(fas_debian_package_of_TIFF "libtiff-dev")
set(fas_debian_package_of_GLEW "libglew-dev")
set(fas_debian_package_of_OpenGL "libgl-dev")
set(fas_debian_package_of_X11 "libx11-dev")
set(fas_debian_package_of_double-conversion "libdouble-conversion-dev")
set(fas_debian_package_of_utf8cpp "libutfcpp-dev")
set(fas_debian_package_of_FFMPEG "libavcodec-dev libavformat-dev libavutil-dev libswscale-dev libswresample-dev")
set(fas_debian_package_of_MPI "libopenmpi-dev")
set(fas_debian_package_of_Python3 "python3-dev")
set(fas_debian_package_of_Qt5 "qtbase5-dev libqt5opengl5-dev")
set(fas_debian_package_of_Threads "libc6-dev")
set(fas_debian_package_of_LibXml2 "libxml2-dev")
set(fas_debian_package_of_hdf5 "libhdf5-dev")
set(fas_debian_package_of_NetCDF "libnetcdf-dev")

# The targets of `directory` and of its subdirectories, into `out`.
function(fas_targets_of_directory directory out)
  get_property(targets DIRECTORY "${directory}" PROPERTY BUILDSYSTEM_TARGETS)
  get_property(subdirectories DIRECTORY "${directory}" PROPERTY SUBDIRECTORIES)
  foreach(subdirectory IN LISTS subdirectories)
    fas_targets_of_directory("${subdirectory}" more)
    list(APPEND targets ${more})
  endforeach()
  set(${out} ${targets} PARENT_SCOPE)
endfunction()

# The names of the form A::B in `items` (link items, generator expressions included), into `out`.
function(fas_namespaced_names items out)
  string(REGEX MATCHALL "[A-Za-z0-9_.+-]+::[A-Za-z0-9_.+-]+" names "${items}")
  list(REMOVE_DUPLICATES names)
  set(${out} ${names} PARENT_SCOPE)
endfunction()

function(fas_check_imported_targets)
  fas_targets_of_directory("${PROJECT_SOURCE_DIR}" todo)
  set(seen "")
  set(missing "")
  while(todo)
    list(POP_FRONT todo target)
    if(target IN_LIST seen)
      continue()
    endif()
    list(APPEND seen ${target})
    get_target_property(type ${target} TYPE)
    set(items "")
    foreach(property IN ITEMS LINK_LIBRARIES INTERFACE_LINK_LIBRARIES)
      if(type STREQUAL "INTERFACE_LIBRARY" AND property STREQUAL "LINK_LIBRARIES")
        continue()
      endif()
      get_target_property(value ${target} ${property})
      if(value)
        list(APPEND items ${value})
      endif()
    endforeach()
    fas_namespaced_names("${items}" names)
    # The project's own targets may link targets imported in their own directory, which are
    # not visible here: only the link interfaces of imported targets are checked.
    get_target_property(imported ${target} IMPORTED)
    foreach(name IN LISTS names)
      if(TARGET ${name})
        list(APPEND todo ${name})
      elseif(imported AND NOT "${name} (needed by ${target})" IN_LIST missing)
        list(APPEND missing "${name} (needed by ${target})")
      endif()
    endforeach()
  endwhile()
  if(NOT missing)
    return()
  endif()
  set(packages "")
  foreach(entry IN LISTS missing)
    string(REGEX REPLACE "::.*" "" namespace "${entry}")
    if(DEFINED fas_debian_package_of_${namespace})
      list(APPEND packages ${fas_debian_package_of_${namespace}})
    else()
      string(REGEX REPLACE " .*" "" name "${entry}")
      list(APPEND packages "<the package that provides ${name}>")
    endif()
  endforeach()
  list(REMOVE_DUPLICATES packages)
  string(JOIN " " packages ${packages})
  string(JOIN "; " missing ${missing})
  set(text "ParaView's or VTK's CMake package needs imported targets that were not found: "
           "${missing}.  Install the Debian packages: ${packages} "
           "(scripts/install-deps.sh installs them, scripts/install-deps.sh --check lists what is missing)")
  if(FAS_REQUIRE_ALL_TOOLS)
    message(FATAL_ERROR ${text})
  else()
    message(WARNING ${text})
  endif()
endfunction()
