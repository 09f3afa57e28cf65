# The component SDK: the variable table, modelDescription generation and the FMI glue. Installed
# and exported (see cmake/StrideInstall.cmake) as Stride::sdk, Stride::sdk_glue (FMI 2.0),
# Stride::sdk_glue3 (FMI 3.0) and Stride::sdk_generator, so components build against an installed
# Stride exactly as in-tree.
add_library(stride_sdk STATIC
  src/types.cpp
  src/variable_table.cpp
  src/start_value.cpp
  src/guid.cpp
  src/model_description.cpp
  src/model_description3.cpp
  src/fmi3_variables.cpp
  src/lifecycle.cpp
  src/logger.cpp
  src/glue_common.cpp
  src/buffer_model.cpp
  src/resources.cpp)
target_include_directories(stride_sdk
  PUBLIC "$<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include>" "$<INSTALL_INTERFACE:include>"
  PRIVATE src)
target_link_libraries(stride_sdk PUBLIC stride_fmi_api)
# header-only helpers (stride/common/bytes.hpp, used by the public state headers, is installed
# beside the SDK's headers); BUILD_INTERFACE keeps the target out of the export
target_link_libraries(stride_sdk PUBLIC $<BUILD_INTERFACE:stride_common>)
# the public headers use std::span: whoever includes them compiles as C++20 at least
target_compile_features(stride_sdk PUBLIC cxx_std_20)
# components are shared libraries; the SDK goes into them whatever the including project sets
set_target_properties(stride_sdk PROPERTIES CXX_VISIBILITY_PRESET hidden VISIBILITY_INLINES_HIDDEN ON
                                            POSITION_INDEPENDENT_CODE ON EXPORT_NAME sdk)
stride_set_warnings(stride_sdk)
# a coverage build's SDK calls gcov's runtime: whatever links it, out of tree through the
# installed package too, links that runtime
if(STRIDE_COVERAGE)
  target_link_options(stride_sdk INTERFACE --coverage)
endif()
add_library(stride::sdk ALIAS stride_sdk)
add_library(Stride::sdk ALIAS stride_sdk)

# The FMI functions; compiled once, linked into every FMU as objects (a static library would
# drop them, since nothing inside the FMU references them).
add_library(stride_sdk_glue OBJECT src/glue.cpp)
target_include_directories(stride_sdk_glue PRIVATE src)
target_link_libraries(stride_sdk_glue PUBLIC stride_sdk)
target_compile_definitions(stride_sdk_glue PRIVATE STRIDE_FMI2_BUILDING_FMU)
set_target_properties(stride_sdk_glue PROPERTIES CXX_VISIBILITY_PRESET hidden VISIBILITY_INLINES_HIDDEN ON
                                                 POSITION_INDEPENDENT_CODE ON EXPORT_NAME sdk_glue)
stride_set_warnings(stride_sdk_glue)
add_library(Stride::sdk_glue ALIAS stride_sdk_glue)

# The FMI 3.0 functions, the same way: an FMU's FMI 3.0 binary links these instead of the 2.0 ones.
add_library(stride_sdk_glue3 OBJECT src/glue3.cpp src/glue3_values.cpp src/glue3_state.cpp
                                    src/glue3_not_offered.cpp)
target_include_directories(stride_sdk_glue3 PRIVATE src)
target_link_libraries(stride_sdk_glue3 PUBLIC stride_sdk)
target_compile_definitions(stride_sdk_glue3 PRIVATE STRIDE_FMI3_BUILDING_FMU)
set_target_properties(stride_sdk_glue3 PROPERTIES CXX_VISIBILITY_PRESET hidden
                      VISIBILITY_INLINES_HIDDEN ON POSITION_INDEPENDENT_CODE ON
                      EXPORT_NAME sdk_glue3)
stride_set_warnings(stride_sdk_glue3)
add_library(Stride::sdk_glue3 ALIAS stride_sdk_glue3)

# main() of the build-time modelDescription.xml generator, linked with each component's objects.
add_library(stride_sdk_generator OBJECT src/model_description_main.cpp)
target_link_libraries(stride_sdk_generator PUBLIC stride_sdk)
set_target_properties(stride_sdk_generator PROPERTIES EXPORT_NAME sdk_generator)
stride_set_warnings(stride_sdk_generator)
add_library(Stride::sdk_generator ALIAS stride_sdk_generator)
