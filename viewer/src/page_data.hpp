// The page's data as JSON: the robot model (bodies with their collision shapes, joints with
// their servo IDs, link frames) and the recorded frames, in the layout fk.js and viewer.js read.
#ifndef STRIDE_VIEWER_PAGE_DATA_HPP
#define STRIDE_VIEWER_PAGE_DATA_HPP

#include <string>
#include <vector>

#include "recorded_frames.hpp"
#include "stride/robot/robot_model.hpp"

namespace stride::viewer {

/// One span of the run the user can pick in the page (a learner's episode or RL step).
struct episode {
  std::string label;
  double from = 0;
  double to = 0;
};

struct page_content {
  std::string title;
  std::vector<std::string> parameters;  ///< "comp.var = value"
  std::vector<episode> episodes;
};

/// The model as JSON: {"fixed_base", "bodies": [{"link", "shapes": [{"type", "size",
/// "origin"}]}], "joints": [{"name", "type", "parent", "child", "origin", "axis", "servo"}],
/// "links": [{"name", "body", "in_body"}]}; a pose is {"R": row-major 3x3, "p": [x, y, z]}.
std::string model_json(const robot::robot_model& model);

/// Everything the page reads: {"title", "model", "frames", "falls", "parameters", "state",
/// "episodes"}.
std::string page_json(const robot::robot_model& model, const recorded_frames& frames,
                      const page_content& content);

}  // namespace stride::viewer

#endif  // STRIDE_VIEWER_PAGE_DATA_HPP
