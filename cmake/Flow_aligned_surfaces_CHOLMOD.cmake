# Finds CHOLMOD (SuiteSparse) and defines the imported target FAS::CHOLMOD.
# Sets FAS_CHOLMOD_FOUND. Debian's SuiteSparse 5 ships no CMake package, so look by hand.
if(TARGET FAS::CHOLMOD)
  set(FAS_CHOLMOD_FOUND TRUE)
  return()
endif()
find_path(FAS_CHOLMOD_INCLUDE_DIR cholmod.h PATH_SUFFIXES suitesparse)
find_library(FAS_CHOLMOD_LIBRARY cholmod)
if(FAS_CHOLMOD_INCLUDE_DIR AND FAS_CHOLMOD_LIBRARY)
  set(FAS_CHOLMOD_FOUND TRUE)
  add_library(FAS::CHOLMOD INTERFACE IMPORTED)
  set_target_properties(FAS::CHOLMOD PROPERTIES
    INTERFACE_INCLUDE_DIRECTORIES "${FAS_CHOLMOD_INCLUDE_DIR}"
    INTERFACE_LINK_LIBRARIES "${FAS_CHOLMOD_LIBRARY}"
    INTERFACE_COMPILE_DEFINITIONS "CGAL_FLOW_ALIGNED_SURFACES_USE_CHOLMOD")
  if(NOT Flow_aligned_surfaces_FIND_QUIETLY)
    message(STATUS "CHOLMOD found: ${FAS_CHOLMOD_LIBRARY} (sparse Cholesky: CHOLMOD, supernodal or simplicial factorization, simplicial LDL^T solves)")
  endif()
else()
  set(FAS_CHOLMOD_FOUND FALSE)
  message(STATUS "CHOLMOD not found: sparse Cholesky falls back to Eigen::SimplicialLDLT")
endif()
