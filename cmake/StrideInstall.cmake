# `cmake --install build --prefix P` lays Stride out like a Debian package:
#   P/bin/stride, P/bin/stride-fmu-check
#   P/share/stride/fmus/*.fmu        bundled components (stride_add_fmu(... INSTALL))
#   P/share/stride/models/           robot models and example systems
#   P/share/stride/examples/         components built against the package (docs/tutorial.md)
#   P/include/stride/{sdk,fmi2,fmi3}/ the component SDK headers (and stride/common/bytes.hpp)
#   P/lib/libstride_sdk.a, P/lib/stride/objects/  the SDK library and its two object sets
#   P/lib/stride/libstride_dds_auth.so  the wrapper of Cyclone's authentication plugin (distributed.md)
#   P/lib/cmake/Stride/              StrideConfig.cmake, StrideConfigVersion.cmake, StrideFmu.cmake
# An installed `stride` finds the bundled FMUs and models through its own location
# (bin/../share/stride), so no STRIDE_FMU_PATH is needed.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(STRIDE_INSTALL_CMAKE_DIR "${CMAKE_INSTALL_LIBDIR}/cmake/Stride")
set(STRIDE_INSTALL_FMU_DIR "${CMAKE_INSTALL_DATADIR}/stride/fmus")

install(TARGETS stride RUNTIME DESTINATION "${CMAKE_INSTALL_BINDIR}")
if(TARGET stride-fmu-check)
  install(TARGETS stride-fmu-check RUNTIME DESTINATION "${CMAKE_INSTALL_BINDIR}")
endif()
install(DIRECTORY "${PROJECT_SOURCE_DIR}/models/" DESTINATION "${CMAKE_INSTALL_DATADIR}/stride/models")
install(DIRECTORY "${PROJECT_SOURCE_DIR}/examples/" DESTINATION "${CMAKE_INSTALL_DATADIR}/stride/examples"
        PATTERN build EXCLUDE)

install(TARGETS stride_fmi_api stride_sdk stride_sdk_glue stride_sdk_glue3 stride_sdk_generator
  EXPORT StrideTargets
  ARCHIVE DESTINATION "${CMAKE_INSTALL_LIBDIR}"
  OBJECTS DESTINATION "${CMAKE_INSTALL_LIBDIR}/stride/objects")
install(DIRECTORY "${PROJECT_SOURCE_DIR}/fmi/include/stride/sdk"
                  "${PROJECT_SOURCE_DIR}/fmi/include/stride/fmi2"
                  "${PROJECT_SOURCE_DIR}/fmi/include/stride/fmi3"
        DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}/stride")
# the byte encoding of state images, used by the SDK's public headers
install(FILES "${PROJECT_SOURCE_DIR}/common/include/stride/common/bytes.hpp"
        DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}/stride/common")
install(EXPORT StrideTargets NAMESPACE Stride:: DESTINATION "${STRIDE_INSTALL_CMAKE_DIR}")

configure_package_config_file("${CMAKE_CURRENT_LIST_DIR}/StrideConfig.cmake.in"
  "${PROJECT_BINARY_DIR}/StrideConfig.cmake"
  INSTALL_DESTINATION "${STRIDE_INSTALL_CMAKE_DIR}"
  PATH_VARS CMAKE_INSTALL_BINDIR STRIDE_INSTALL_FMU_DIR)
# 0.x: a minor version may change the SDK
write_basic_package_version_file("${PROJECT_BINARY_DIR}/StrideConfigVersion.cmake"
  COMPATIBILITY SameMinorVersion)
install(FILES "${PROJECT_BINARY_DIR}/StrideConfig.cmake"
              "${PROJECT_BINARY_DIR}/StrideConfigVersion.cmake"
              "${CMAKE_CURRENT_LIST_DIR}/StrideFmu.cmake"
              "${CMAKE_CURRENT_LIST_DIR}/StrideBundleDependencies.cmake"
              "${CMAKE_CURRENT_LIST_DIR}/fmu_exports.map"
              "${CMAKE_CURRENT_LIST_DIR}/fmu3_exports.map"
        DESTINATION "${STRIDE_INSTALL_CMAKE_DIR}")
