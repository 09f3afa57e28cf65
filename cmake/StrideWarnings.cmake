# stride_set_warnings(target): the project's warning flags, errors when STRIDE_WERROR is on.
function(stride_set_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic
                                           $<$<BOOL:${STRIDE_WERROR}>:-Werror>)
endfunction()
