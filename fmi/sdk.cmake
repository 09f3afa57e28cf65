# The component SDK: the variable table, modelDescription generation and the FMI glue.
set(STRIDE_SDK_DIR "${CMAKE_CURRENT_SOURCE_DIR}" CACHE INTERNAL "")

add_library(stride_sdk STATIC
  src/types.cpp
  src/variable_table.cpp
  src/start_value.cpp
  src/guid.cpp
  src/model_description.cpp
  src/lifecycle.cpp
  src/logger.cpp
  src/resources.cpp)
target_include_directories(stride_sdk PUBLIC include PRIVATE src)
target_link_libraries(stride_sdk PUBLIC stride_fmi_api)
set_target_properties(stride_sdk PROPERTIES CXX_VISIBILITY_PRESET hidden VISIBILITY_INLINES_HIDDEN ON)
stride_set_warnings(stride_sdk)
add_library(stride::sdk ALIAS stride_sdk)

# The FMI functions; compiled once, linked into every FMU as objects (a static library would
# drop them, since nothing inside the FMU references them).
add_library(stride_sdk_glue OBJECT src/glue.cpp)
target_include_directories(stride_sdk_glue PRIVATE src)
target_link_libraries(stride_sdk_glue PUBLIC stride_sdk)
target_compile_definitions(stride_sdk_glue PRIVATE STRIDE_FMI2_BUILDING_FMU)
set_target_properties(stride_sdk_glue PROPERTIES CXX_VISIBILITY_PRESET hidden VISIBILITY_INLINES_HIDDEN ON)
stride_set_warnings(stride_sdk_glue)
