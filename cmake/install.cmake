# `cmake --install build --prefix P` puts abut under P: the program (bin/abut), the layers' static
# libraries, their headers and a CMake package (lib/cmake/abut) in two components of one package:
#   find_package(abut REQUIRED COMPONENTS contact)  -> abut::contact, abut::core
#   find_package(abut REQUIRED COMPONENTS solver)   -> abut::solver, abut::io, ... as well
# (cmake/abutConfig.cmake.in). The contact component is self-contained: its headers include
# nothing from the solver's layers.
include(CMakePackageConfigHelpers)
set(abut_package_dir ${CMAKE_INSTALL_LIBDIR}/cmake/abut)

install(TARGETS ${contact_layers} EXPORT abutContactTargets
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(DIRECTORY include/abut/core include/abut/contact DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/abut)
install(FILES include/abut/abut_contact.h DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/abut)
install(EXPORT abutContactTargets NAMESPACE abut:: DESTINATION ${abut_package_dir})

if(ABUT_BUILD_SOLVER)
  install(TARGETS ${solver_layers} EXPORT abutSolverTargets
    ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
  install(DIRECTORY include/abut/linalg include/abut/mesh include/abut/material
    include/abut/element include/abut/model include/abut/solver include/abut/io
    DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/abut)
  install(EXPORT abutSolverTargets NAMESPACE abut:: DESTINATION ${abut_package_dir})
  install(FILES cmake/abutSuiteSparse.cmake cmake/abutGmsh.cmake DESTINATION ${abut_package_dir})
  install(TARGETS abut RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
endif()

configure_package_config_file(cmake/abutConfig.cmake.in
  ${PROJECT_BINARY_DIR}/abutConfig.cmake INSTALL_DESTINATION ${abut_package_dir})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/abutConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/abutConfig.cmake ${PROJECT_BINARY_DIR}/abutConfigVersion.cmake
  DESTINATION ${abut_package_dir})
