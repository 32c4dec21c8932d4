# Finds liblz4 and liblzma and defines the imported targets FAS::LZ4 and FAS::LZMA, which carry
# the macros CGAL_FLOW_ALIGNED_SURFACES_USE_LZ4 / _USE_LZMA: the VTK XML reader then decompresses
# arrays written with vtkLZ4DataCompressor / vtkLZMADataCompressor.  Sets FAS_LZ4_FOUND and
# FAS_LZMA_FOUND.  Debian's liblz4 ships no CMake package, so both are looked for by hand.
foreach(codec IN ITEMS LZ4 LZMA)
  string(TOLOWER "${codec}" name)
  if(TARGET FAS::${codec})
    set(FAS_${codec}_FOUND TRUE)
    continue()
  endif()
  find_path(FAS_${codec}_INCLUDE_DIR ${name}.h)
  find_library(FAS_${codec}_LIBRARY ${name})
  if(FAS_${codec}_INCLUDE_DIR AND FAS_${codec}_LIBRARY)
    set(FAS_${codec}_FOUND TRUE)
    add_library(FAS::${codec} INTERFACE IMPORTED)
    set_target_properties(FAS::${codec} PROPERTIES
      INTERFACE_INCLUDE_DIRECTORIES "${FAS_${codec}_INCLUDE_DIR}"
      INTERFACE_LINK_LIBRARIES "${FAS_${codec}_LIBRARY}"
      INTERFACE_COMPILE_DEFINITIONS "CGAL_FLOW_ALIGNED_SURFACES_USE_${codec}")
    if(NOT Flow_aligned_surfaces_FIND_QUIETLY)
      message(STATUS "lib${name} found: VTK XML arrays compressed with ${codec} can be read")
    endif()
  else()
    set(FAS_${codec}_FOUND FALSE)
    message(STATUS "lib${name} not found: VTK XML arrays compressed with ${codec} are refused (Debian: lib${name}-dev)")
  endif()
endforeach()
