# Installation and the package configuration, for consumers that call
# find_package(Advancing_front_mesh_2 [COMPONENTS Poisson]), against an
# installed tree or against this build tree.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(AFM_CONFIG_DESTINATION ${CMAKE_INSTALL_DATADIR}/Advancing_front_mesh_2/cmake)

install(DIRECTORY include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(FILES package_info/Advancing_front_mesh_2/license.txt package_info/Advancing_front_mesh_2/copyright
        DESTINATION ${CMAKE_INSTALL_DATADIR}/Advancing_front_mesh_2)

install(TARGETS Advancing_front_mesh_2 EXPORT Advancing_front_mesh_2Targets)
install(EXPORT Advancing_front_mesh_2Targets NAMESPACE CGAL:: DESTINATION ${AFM_CONFIG_DESTINATION})
export(EXPORT Advancing_front_mesh_2Targets NAMESPACE CGAL::
       FILE ${CMAKE_CURRENT_BINARY_DIR}/Advancing_front_mesh_2Targets.cmake)
# its own file: the configuration includes it only for COMPONENTS Poisson
# with Eigen found
install(TARGETS Advancing_front_mesh_2_Poisson EXPORT Advancing_front_mesh_2PoissonTargets)
install(EXPORT Advancing_front_mesh_2PoissonTargets NAMESPACE CGAL:: DESTINATION ${AFM_CONFIG_DESTINATION})
export(EXPORT Advancing_front_mesh_2PoissonTargets NAMESPACE CGAL::
       FILE ${CMAKE_CURRENT_BINARY_DIR}/Advancing_front_mesh_2PoissonTargets.cmake)

write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/Advancing_front_mesh_2ConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion ARCH_INDEPENDENT)
# the same configuration serves both: the installed one, and the build
# tree's, which its Targets files place beside it
configure_package_config_file(cmake/Advancing_front_mesh_2Config.cmake.in
                              ${CMAKE_CURRENT_BINARY_DIR}/Advancing_front_mesh_2Config.cmake
                              INSTALL_DESTINATION ${AFM_CONFIG_DESTINATION})
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/Advancing_front_mesh_2Config.cmake
              ${CMAKE_CURRENT_BINARY_DIR}/Advancing_front_mesh_2ConfigVersion.cmake
        DESTINATION ${AFM_CONFIG_DESTINATION})
