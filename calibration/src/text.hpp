// The calibration readers use the shared text helpers as detail::…
#pragma once

#include "stride/common/text.hpp"

namespace stride::calibration::detail {
using namespace ::stride::text;
}  // namespace stride::calibration::detail
