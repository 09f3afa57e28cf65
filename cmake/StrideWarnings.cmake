# stride_set_warnings(target): the project's warning flags, errors when STRIDE_WERROR is on.
function(stride_set_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic
                                           $<$<BOOL:${STRIDE_WERROR}>:-Werror>)
endfunction()

# GCC 12 at -O3 reports false -Wrestrict errors inside std::string's operator+ (GCC bug 105329)
function(stride_no_false_restrict target)
  if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND CMAKE_CXX_COMPILER_VERSION VERSION_LESS 13)
    target_compile_options(${target} PRIVATE -Wno-restrict)
  endif()
endfunction()
