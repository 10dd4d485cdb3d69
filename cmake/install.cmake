# Install rules and the exported CMake package: after `cmake --install build --prefix P`, a
# project with CMAKE_PREFIX_PATH=P calls find_package(lbdem) and links lbdem::<target>
# (docs/developer.md, "Using the installed package"; tested by install_find_package).
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(lbdem_install_targets
    lbdem_geometry lbdem_scene lbdem_output lbdem_coupling lbdem_app coupler_lib
    fluid_lattice fluid_kernel fluid_parallel fluid_boundary fluid_solver fluid_forcing fluid_hlbm
    fluid_analytic fluid_output fluid_validation fluid_stability fluid_run fluid_coupling
    fluid_core fluid_app clump_gen)
set(lbdem_header_dirs coupler_lib fluid_app)
if(LBDEM_WITH_LAMMPS)
  list(APPEND lbdem_install_targets dem_contact dem_lubrication dem_loads dem_setup dem_engine
                                    dem_output dem_run dem_coupling dem_core dem_app)
  list(APPEND lbdem_header_dirs dem_app)
endif()

install(TARGETS ${lbdem_install_targets} EXPORT lbdemTargets
        RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR}
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
foreach(dir IN LISTS lbdem_header_dirs)
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/${dir} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
          FILES_MATCHING PATTERN "*.hpp")
endforeach()

set(lbdem_cmake_dir ${CMAKE_INSTALL_LIBDIR}/cmake/lbdem)
install(EXPORT lbdemTargets NAMESPACE lbdem:: DESTINATION ${lbdem_cmake_dir})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/lbdemConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/lbdemConfig.cmake
                              INSTALL_DESTINATION ${lbdem_cmake_dir})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/lbdemConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/lbdemConfig.cmake ${PROJECT_BINARY_DIR}/lbdemConfigVersion.cmake
        DESTINATION ${lbdem_cmake_dir})
