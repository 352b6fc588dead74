# SuiteSparse's sparse direct solvers (CHOLMOD, UMFPACK) for the implicit solver, as one imported
# target SuiteSparse::direct. Debian 12's libsuitesparse-dev 5.12 ships no CMake config for them,
# so find the header and the libraries (SuiteSparse >= 7 has its own config: SuiteSparse::CHOLMOD,
# ...). Used by abut's build and by its installed package (abutConfig.cmake, solver component).
if(NOT TARGET SuiteSparse::direct)
  find_path(SUITESPARSE_INCLUDE_DIR cholmod.h PATH_SUFFIXES suitesparse)
  set(suitesparse_libraries)
  set(suitesparse_missing)
  if(NOT SUITESPARSE_INCLUDE_DIR OR NOT EXISTS ${SUITESPARSE_INCLUDE_DIR}/umfpack.h)
    list(APPEND suitesparse_missing cholmod.h umfpack.h)
  endif()
  foreach(lib umfpack cholmod amd colamd suitesparseconfig)
    find_library(SUITESPARSE_${lib}_LIBRARY ${lib})
    if(NOT SUITESPARSE_${lib}_LIBRARY)
      list(APPEND suitesparse_missing lib${lib})
    endif()
    list(APPEND suitesparse_libraries ${SUITESPARSE_${lib}_LIBRARY})
  endforeach()
  if(suitesparse_missing)
    list(JOIN suitesparse_missing ", " suitesparse_missing)
    message(FATAL_ERROR "SuiteSparse not found (missing: ${suitesparse_missing}). Install the "
      "Debian package libsuitesparse-dev (apt-get install libsuitesparse-dev; see "
      "deps/debian-packages.txt).")
  endif()
  add_library(SuiteSparse::direct INTERFACE IMPORTED)
  set_target_properties(SuiteSparse::direct PROPERTIES
    INTERFACE_INCLUDE_DIRECTORIES ${SUITESPARSE_INCLUDE_DIR}
    INTERFACE_LINK_LIBRARIES "${suitesparse_libraries}")
endif()
