# Gmsh's library (Debian libgmsh-dev, Gmsh 4.8) as the imported target Gmsh::gmsh: the io layer
# meshes .geo, STEP and BREP files with it (src/io/gmsh/gmsh_cad.cpp). Debian ships no CMake
# config for it, so find the header and the library. Used by abut's build and by its installed
# package (abutConfig.cmake, solver component).
if(NOT TARGET Gmsh::gmsh)
  find_path(GMSH_INCLUDE_DIR gmsh.h)
  find_library(GMSH_LIBRARY gmsh)
  if(NOT GMSH_INCLUDE_DIR OR NOT GMSH_LIBRARY)
    message(FATAL_ERROR "Gmsh's library not found (gmsh.h, libgmsh). Install the Debian package "
      "libgmsh-dev (apt-get install libgmsh-dev; see deps/debian-packages.txt).")
  endif()
  add_library(Gmsh::gmsh INTERFACE IMPORTED)
  set_target_properties(Gmsh::gmsh PROPERTIES
    INTERFACE_INCLUDE_DIRECTORIES ${GMSH_INCLUDE_DIR}
    INTERFACE_LINK_LIBRARIES ${GMSH_LIBRARY})
endif()
