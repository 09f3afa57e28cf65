// The study's assertion kinds for `stride test`: where a learner's best state lies, and V at a
// state, read from the learner's V table in the case's output folder.
#ifndef STRIDE_STUDY_SUITE_ASSERTIONS_HPP
#define STRIDE_STUDY_SUITE_ASSERTIONS_HPP

#include "stride/suite/assertions.hpp"

namespace stride::study {

/// `best_state region="period_time=555..615, swing_right_left=21..29" [folder="sub"]` and
/// `value_at state="period_time=600, swing_right_left=21" min=".." max=".." [folder="sub"]`.
suite::assertion_registry learner_assertions();

}  // namespace stride::study

#endif  // STRIDE_STUDY_SUITE_ASSERTIONS_HPP
