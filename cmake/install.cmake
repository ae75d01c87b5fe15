# cmake --install: headers, the runtime's static libraries, the CMake package
# (ScalableFXConfig.cmake, its version file, the exported targets), scalablefx.pc and the
# sfx/sfxc tools. The libraries carry compiled shaders; nothing of glslang, SPIRV-Tools or
# SPIRV-Cross is installed or needed by a host (tests/consumer/run_consumer.sh checks it).
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(SFX_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/ScalableFX)

# sfx_warnings is link-only on the libraries (no flags reach a host); it travels in the export
# set because CMake names every PRIVATE link item of a static library there.
install(TARGETS ${SFX_PACKAGE_TARGETS} sfx_warnings
        EXPORT ScalableFXTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
set_target_properties(sfx_warnings PROPERTIES EXPORT_NAME internal_warnings)

# Public headers. sdk/include/sfx/reference (the CPU references) belongs to the tests and tools.
install(DIRECTORY ${PROJECT_SOURCE_DIR}/sdk/include/sfx DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
        PATTERN reference EXCLUDE)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/tiers/include/sfx ${PROJECT_SOURCE_DIR}/backends/include/sfx
                  ${PROJECT_SOURCE_DIR}/backends/null/include/sfx
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
if(TARGET sfx_backend_vulkan)
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/backends/vulkan/include/sfx DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
endif()
if(TARGET sfx_backend_gl)
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/backends/gl/include/sfx DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
endif()
# The constants shared by shaders and C++ (sfx_core's include path names this folder). The
# GLSL-only shader bodies stay out: sfxc compiled them into the libraries and they are no C++.
install(DIRECTORY ${PROJECT_SOURCE_DIR}/shader_src/include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/sfx/shader_include
        PATTERN sfx_shared_oit_ao.h EXCLUDE PATTERN sfx_shared_oit_resolve.h EXCLUDE PATTERN sfx_ao_*_pass.h EXCLUDE)
install(FILES ${PROJECT_BINARY_DIR}/generated/sfx_shaders/sfx_shaders.hpp DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})

install(EXPORT ScalableFXTargets NAMESPACE ScalableFX:: DESTINATION ${SFX_CMAKE_DIR})
set(SFX_CONFIG_HAS_VULKAN OFF)
set(SFX_CONFIG_HAS_GL OFF)
if(TARGET sfx_backend_vulkan)
  set(SFX_CONFIG_HAS_VULKAN ON)
endif()
if(TARGET sfx_backend_gl)
  set(SFX_CONFIG_HAS_GL ON)
endif()
configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/ScalableFXConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/ScalableFXConfig.cmake
                              INSTALL_DESTINATION ${SFX_CMAKE_DIR})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/ScalableFXConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/ScalableFXConfig.cmake ${PROJECT_BINARY_DIR}/ScalableFXConfigVersion.cmake
        DESTINATION ${SFX_CMAKE_DIR})

# pkg-config: the same libraries in link order, for builds that do not use CMake.
set(SFX_PC_LIBS "-lsfx_backends")
set(SFX_PC_REQUIRES "")
if(TARGET sfx_backend_vulkan)
  string(APPEND SFX_PC_LIBS " -lsfx_backend_vulkan")
endif()
if(TARGET sfx_backend_gl)
  string(APPEND SFX_PC_LIBS " -lsfx_backend_gl")
  set(SFX_PC_REQUIRES "egl")  # libOSMesa is opened at run time
endif()
list(TRANSFORM CMAKE_DL_LIBS PREPEND "-l" OUTPUT_VARIABLE SFX_PC_DL)
list(JOIN SFX_PC_DL " " SFX_PC_DL)
string(APPEND SFX_PC_LIBS " -lsfx_backend_null -lsfx_tiers -lsfx_budget -lsfx -lsfx_shaders -lsfx_core ${SFX_PC_DL}")
# Relocatable: the prefix is found from the .pc file's own folder, so `cmake --install --prefix`
# anywhere gives a working file.
file(RELATIVE_PATH SFX_PC_TO_PREFIX /${CMAKE_INSTALL_LIBDIR}/pkgconfig /)
configure_file(${CMAKE_CURRENT_LIST_DIR}/scalablefx.pc.in ${PROJECT_BINARY_DIR}/scalablefx.pc @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/scalablefx.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)

if(TARGET sfxc AND NOT SFX_SFXC_EXECUTABLE)
  install(TARGETS sfxc RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
endif()
if(TARGET sfx_cli)
  install(TARGETS sfx_cli RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
endif()
