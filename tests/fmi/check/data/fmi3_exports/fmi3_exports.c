/* The dynamic symbols of an FMI 3.0 binary and nothing more: one stub per function of the C API
   (STRIDE_FMI3_FUNCTIONS), so that the checker's reading of .dynsym is tested on a real shared
   object. Only the names and the symbol type matter to that check, so each stub is a bare
   `ret` written in assembly rather than a C definition with the prototype's signature. A
   variant compiled with -Dfmi3DoStep=<other name> lacks fmi3DoStep. */
#include "stride/fmi3/fmi3_api.h"

#define STRIDE_FMI3_STUB(name)                                                       \
  __asm__(".pushsection .text\n.globl " #name "\n.type " #name ", @function\n" #name \
          ":\n  ret\n.popsection");
/* one more level, so that a name defined as a macro is replaced before it is quoted */
#define STRIDE_FMI3_STUB_NAMED(name) STRIDE_FMI3_STUB(name)

STRIDE_FMI3_FUNCTIONS(STRIDE_FMI3_STUB_NAMED)
