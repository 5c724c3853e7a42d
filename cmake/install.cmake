# `cmake --install BUILD [--prefix PREFIX]` (docs/INSTALL.md):
#   bin/                          plantfield, plantbench, physics_bench, lsys
#   share/plantfield/data/        plants, meshes, scenes (found from bin/: tools/data_dir.h)
#   lib/libplantfield_lsystem_*.a the L-system libraries, one per concern (no Vulkan)
#   include/plantfield/lsystem/   their headers, included as "lsystem/rewriting/rewriter.h"
#   lib/cmake/plantfield/         find_package(plantfield COMPONENTS lsystem): plantfield::lsystem, all of them
#   lib/pkgconfig/plantfield-lsystem.pc
# The tree is relocatable: nothing installed names the prefix it was configured for.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(PLANTFIELD_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/plantfield)

install(TARGETS plantfield plantbench physics_bench lsys RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
get_property(_plantfield_lsystem_libraries GLOBAL PROPERTY PLANTFIELD_LSYSTEM_LIBRARIES) # lsystem/CMakeLists.txt
install(TARGETS lsystem ${_plantfield_lsystem_libraries} EXPORT plantfieldTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/lsystem/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/plantfield/lsystem
        FILES_MATCHING PATTERN "*.h")
install(DIRECTORY ${PROJECT_SOURCE_DIR}/data/ DESTINATION ${CMAKE_INSTALL_DATADIR}/plantfield/data)
install(FILES ${PROJECT_SOURCE_DIR}/LICENSE ${PROJECT_SOURCE_DIR}/README.md ${PROJECT_SOURCE_DIR}/docs/INSTALL.md
        DESTINATION ${CMAKE_INSTALL_DOCDIR})

# The CMake package.
install(EXPORT plantfieldTargets NAMESPACE plantfield:: FILE plantfieldTargets.cmake
        DESTINATION ${PLANTFIELD_INSTALL_CMAKEDIR})
configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/plantfieldConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/install/plantfieldConfig.cmake
                              INSTALL_DESTINATION ${PLANTFIELD_INSTALL_CMAKEDIR})
# 0.x: a minor version may change the interface.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/install/plantfieldConfigVersion.cmake
                                 VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/install/plantfieldConfig.cmake
              ${PROJECT_BINARY_DIR}/install/plantfieldConfigVersion.cmake
        DESTINATION ${PLANTFIELD_INSTALL_CMAKEDIR})

# The pkg-config file. Its prefix is found from the file's own place
# (${pcfiledir}), so an installed tree can be moved or installed with --prefix.
if(IS_ABSOLUTE "${CMAKE_INSTALL_LIBDIR}")
  set(PLANTFIELD_PC_PREFIX "${CMAKE_INSTALL_PREFIX}")
else()
  file(RELATIVE_PATH _plantfield_pc_up /prefix/${CMAKE_INSTALL_LIBDIR}/pkgconfig /prefix)
  string(REGEX REPLACE "/$" "" _plantfield_pc_up "${_plantfield_pc_up}")
  set(PLANTFIELD_PC_PREFIX "\${pcfiledir}/${_plantfield_pc_up}")
endif()
foreach(dir LIBDIR INCLUDEDIR)
  if(IS_ABSOLUTE "${CMAKE_INSTALL_${dir}}")
    set(PLANTFIELD_PC_${dir} "${CMAKE_INSTALL_${dir}}")
  else()
    set(PLANTFIELD_PC_${dir} "\${prefix}/${CMAKE_INSTALL_${dir}}")
  endif()
endforeach()
# Libs: every L-system library, each before those it uses (lsystem/CMakeLists.txt
# defines them in the opposite order), as a static link needs them.
set(PLANTFIELD_PC_LIBS)
foreach(library ${_plantfield_lsystem_libraries})
  get_target_property(_plantfield_output_name ${library} OUTPUT_NAME)
  list(PREPEND PLANTFIELD_PC_LIBS -l${_plantfield_output_name})
endforeach()
list(JOIN PLANTFIELD_PC_LIBS " " PLANTFIELD_PC_LIBS)
configure_file(${CMAKE_CURRENT_LIST_DIR}/plantfield-lsystem.pc.in ${PROJECT_BINARY_DIR}/install/plantfield-lsystem.pc @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/install/plantfield-lsystem.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
