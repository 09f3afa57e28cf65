// The parameter table and the INI reader use the shared text helpers as detail::…
#pragma once

#include "stride/common/text.hpp"

namespace stride::gait::detail {
using namespace ::stride::text;
}  // namespace stride::gait::detail
