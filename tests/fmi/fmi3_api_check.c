/* Compile-only check of stride/fmi3/fmi3_api.h: nothing here runs or links.
 *
 * Each prototype is written out twice in the header, once with parameter names and once as a
 * fmi3XxxTYPE function type for importers. Taking the address of every prototype through its
 * function type makes any difference between the two a compile error, and the X-macro that
 * drives it must name exactly the 75 functions of the standard. The static assertions pin the
 * sizes and enumerator values that are the binary interface.
 */
#include "stride/fmi3/fmi3_api.h"

/* plain C only warns about incompatible function pointers; here that is the defect sought */
#pragma GCC diagnostic error "-Wincompatible-pointer-types"

#define STRIDE_CHECK_MEMBER(name) name##TYPE* name;
#define STRIDE_CHECK_ADDRESS(name) .name = &name,
#define STRIDE_CHECK_COUNT(name) +1

struct stride_fmi3_api_check {
  STRIDE_FMI3_FUNCTIONS(STRIDE_CHECK_MEMBER)
};

/* external linkage, so that no unused-variable warning hides a missing entry */
const struct stride_fmi3_api_check stride_fmi3_api_check_table = {
    STRIDE_FMI3_FUNCTIONS(STRIDE_CHECK_ADDRESS)};

/* 61 common + 10 Model Exchange + 3 Co-Simulation + 1 Scheduled Execution */
enum { stride_fmi3_function_count = 0 STRIDE_FMI3_FUNCTIONS(STRIDE_CHECK_COUNT) };
_Static_assert(stride_fmi3_function_count == 75, "fmi3 function list incomplete");

/* fixed-width platform types */
_Static_assert(sizeof(fmi3ValueReference) == 4, "fmi3ValueReference is uint32_t");
_Static_assert(sizeof(fmi3Float32) == 4 && sizeof(fmi3Float64) == 8, "float widths");
_Static_assert(sizeof(fmi3Int8) == 1 && sizeof(fmi3UInt8) == 1, "8-bit integers");
_Static_assert(sizeof(fmi3Int16) == 2 && sizeof(fmi3UInt16) == 2, "16-bit integers");
_Static_assert(sizeof(fmi3Int32) == 4 && sizeof(fmi3UInt32) == 4, "32-bit integers");
_Static_assert(sizeof(fmi3Int64) == 8 && sizeof(fmi3UInt64) == 8, "64-bit integers");
_Static_assert(sizeof(fmi3Byte) == 1, "fmi3Byte is uint8_t");
_Static_assert(sizeof(fmi3Boolean) == sizeof(bool) && sizeof(fmi3Clock) == sizeof(bool),
               "fmi3Boolean and fmi3Clock are bool");
_Static_assert(fmi3True == 1 && fmi3False == 0, "boolean values");
_Static_assert(fmi3ClockActive == 1 && fmi3ClockInactive == 0, "clock values");

/* enumerator values */
_Static_assert(fmi3OK == 0 && fmi3Warning == 1 && fmi3Discard == 2 && fmi3Error == 3 &&
                   fmi3Fatal == 4,
               "fmi3Status");
_Static_assert(fmi3Independent == 0 && fmi3Constant == 1 && fmi3Fixed == 2 && fmi3Tunable == 3 &&
                   fmi3Discrete == 4 && fmi3Dependent == 5,
               "fmi3DependencyKind");
_Static_assert(fmi3IntervalNotYetKnown == 0 && fmi3IntervalUnchanged == 1 &&
                   fmi3IntervalChanged == 2,
               "fmi3IntervalQualifier");
