# Install the libraries, headers and an exported CMake package so that users can
# write find_package(moorsph) and link moorsph::moorsph_fluid etc.
include(CMakePackageConfigHelpers)
set(MOORSPH_EXPORTED_TARGETS moorsph_fluid moorsph_io)
if(MOORSPH_WITH_BODIES)
  list(APPEND MOORSPH_EXPORTED_TARGETS moorsph_bodies moorsph_coupling)
endif()
install(TARGETS ${MOORSPH_EXPORTED_TARGETS} EXPORT moorsphTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
foreach(layer fluid bodies coupling io)
  if(EXISTS ${CMAKE_SOURCE_DIR}/${layer}/include/moorsph)
    install(DIRECTORY ${CMAKE_SOURCE_DIR}/${layer}/include/moorsph DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
  endif()
endforeach()
install(EXPORT moorsphTargets NAMESPACE moorsph:: DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/moorsph)
configure_package_config_file(${CMAKE_SOURCE_DIR}/cmake/moorsphConfig.cmake.in
  ${CMAKE_BINARY_DIR}/moorsphConfig.cmake INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/moorsph)
write_basic_package_version_file(${CMAKE_BINARY_DIR}/moorsphConfigVersion.cmake COMPATIBILITY SameMajorVersion)
install(FILES ${CMAKE_BINARY_DIR}/moorsphConfig.cmake ${CMAKE_BINARY_DIR}/moorsphConfigVersion.cmake
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/moorsph)
