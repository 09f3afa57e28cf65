# STRIDE_SANITIZE: the whole build (libraries, FMUs, tests, CLI) with AddressSanitizer and
# UndefinedBehaviorSanitizer, every UB report fatal, and the fuzz targets under fuzz/ (which add
# libFuzzer's coverage instrumentation to the libraries they fuzz). Clang only.
# scripts/sanitize.sh configures and runs it.
option(STRIDE_SANITIZE "Build with ASan + UBSan (Clang) and build the libFuzzer targets" OFF)
if(STRIDE_SANITIZE)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang" OR NOT CMAKE_C_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "STRIDE_SANITIZE needs Clang for C and C++ (CC=clang CXX=clang++)")
  endif()
  add_compile_options(-fsanitize=address,undefined -fno-sanitize-recover=all
                      -fno-omit-frame-pointer)
  add_link_options(-fsanitize=address,undefined)
endif()
