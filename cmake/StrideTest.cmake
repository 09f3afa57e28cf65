# stride_add_test(NAME SOURCES src... [LIBS lib...] [DATA_DIR dir])
#
# One line per test executable: builds it against GoogleTest, registers every TEST with CTest and
# hands the test its data directory (STRIDE_TEST_DATA_DIR) and the folder of built FMUs
# (STRIDE_FMU_DIR) as compile definitions.
function(stride_add_test name)
  cmake_parse_arguments(arg "" "DATA_DIR;TIMEOUT" "SOURCES;LIBS;DEPENDS" ${ARGN})
  add_executable(${name} ${arg_SOURCES})
  stride_set_warnings(${name})
  target_link_libraries(${name} PRIVATE GTest::gtest_main GTest::gmock ${arg_LIBS})
  if(arg_DATA_DIR)
    target_compile_definitions(${name} PRIVATE STRIDE_TEST_DATA_DIR="${arg_DATA_DIR}")
  endif()
  target_compile_definitions(${name} PRIVATE STRIDE_FMU_DIR="${STRIDE_FMU_OUTPUT_DIR}"
                                             STRIDE_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
  if(arg_DEPENDS)
    add_dependencies(${name} ${arg_DEPENDS})
  endif()
  if(NOT arg_TIMEOUT)
    set(arg_TIMEOUT 300)
  endif()
  gtest_discover_tests(${name} DISCOVERY_TIMEOUT 60 PROPERTIES TIMEOUT ${arg_TIMEOUT})
endfunction()
