// The Model Exchange settings of a component on a worker, as they travel in its instantiate
// request: a value block in the request's `data`. Strings: "model-exchange", the solver, the
// method; reals: rtol, atol, max_step; Booleans: which of the three are set. An empty block is
// a Co-Simulation instance.
#pragma once

#include <optional>

#include "stride/cosim/component.hpp"
#include "stride/cosim/model_exchange.hpp"

namespace stride::remote {

cosim::value_block model_exchange_to_wire(const std::optional<cosim::model_exchange_options>& o);

/// \throws std::runtime_error naming what is wrong when the block is not such settings.
std::optional<cosim::model_exchange_options> model_exchange_from_wire(const cosim::value_block& v);

}  // namespace stride::remote
