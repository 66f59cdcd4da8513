# install_package.cmake - `cmake --install` of the kernel and the model as static libraries with
# their headers, an exported CMake package (find_package(torusrt): torusrt::kernel,
# torusrt::core, torusrt::model) and a pkg-config file (torusrt.pc).
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

# Installed names that cannot clash with other packages' libraries.
set_target_properties(rtkernel PROPERTIES EXPORT_NAME kernel OUTPUT_NAME torusrt_kernel)
set_target_properties(rtcore PROPERTIES EXPORT_NAME core OUTPUT_NAME torusrt_core)
set_target_properties(rtmodel PROPERTIES EXPORT_NAME model OUTPUT_NAME torusrt_model)

file(GLOB KERNEL_HEADERS CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/include/*.h)
set(TORUSRT_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/torusrt)
install(TARGETS rtkernel rtcore rtmodel EXPORT torusrtTargets ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(FILES ${KERNEL_HEADERS} ${CORE_HEADERS} ${MODEL_HEADERS} DESTINATION include/torusrt)
install(EXPORT torusrtTargets NAMESPACE torusrt:: DESTINATION ${TORUSRT_CMAKE_DIR})

configure_package_config_file(${CMAKE_SOURCE_DIR}/cmake/torusrtConfig.cmake.in
                              ${CMAKE_BINARY_DIR}/torusrtConfig.cmake INSTALL_DESTINATION ${TORUSRT_CMAKE_DIR})
write_basic_package_version_file(${CMAKE_BINARY_DIR}/torusrtConfigVersion.cmake COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_BINARY_DIR}/torusrtConfig.cmake ${CMAKE_BINARY_DIR}/torusrtConfigVersion.cmake
        DESTINATION ${TORUSRT_CMAKE_DIR})

# pkg-config: paths relative to the file, so `cmake --install --prefix` anywhere works.
file(RELATIVE_PATH TORUSRT_PC_TO_PREFIX ${CMAKE_INSTALL_PREFIX}/${CMAKE_INSTALL_LIBDIR}/pkgconfig
     ${CMAKE_INSTALL_PREFIX})
configure_file(${CMAKE_SOURCE_DIR}/cmake/torusrt.pc.in ${CMAKE_BINARY_DIR}/torusrt.pc @ONLY)
install(FILES ${CMAKE_BINARY_DIR}/torusrt.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
