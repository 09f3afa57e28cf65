# STRIDE_COVERAGE: the whole build (libraries, FMUs, tests, CLI) instrumented with gcov (GCC
# --coverage), so that running the test suite leaves .gcda counters next to the objects; FMUs
# unpacked elsewhere still write there, the object paths are absolute. scripts/coverage.sh
# configures it, runs the suite and reports with gcovr.
option(STRIDE_COVERAGE "Build with gcov instrumentation (GCC) for scripts/coverage.sh" OFF)
# -Og: the suite runs as fast as at -O1 (at -O0 five times slower) and it compiles faster than
# -O1; it inlines less, so the counts stay closer to the source. -DSTRIDE_COVERAGE_OPTIMIZATION=
# overrides it (to compare levels).
if(NOT DEFINED STRIDE_COVERAGE_OPTIMIZATION)
  set(STRIDE_COVERAGE_OPTIMIZATION -Og)
endif()
if(STRIDE_COVERAGE)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "GNU" OR NOT CMAKE_C_COMPILER_ID STREQUAL "GNU")
    message(FATAL_ERROR "STRIDE_COVERAGE needs GCC for C and C++ (gcov's data format)")
  endif()
  if(STRIDE_SANITIZE)
    message(FATAL_ERROR "STRIDE_COVERAGE and STRIDE_SANITIZE exclude each other")
  endif()
  # target options come after the build type's flags, so this level wins over theirs; atomic
  # counters, since components step on threads and racing increments corrupt gcov's arc counts
  # (negative branch counts that gcovr refuses)
  add_compile_options(${STRIDE_COVERAGE_OPTIMIZATION} -g --coverage -fprofile-update=atomic)
  add_link_options(--coverage)
endif()
