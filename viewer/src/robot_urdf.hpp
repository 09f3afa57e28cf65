// The URDF a run's robot was loaded from, found the way the plant finds it: the component's
// `urdf` parameter (a path, or a file in the FMU's resources/), and without one the URDF the
// FMU ships in resources/.
#ifndef STRIDE_VIEWER_ROBOT_URDF_HPP
#define STRIDE_VIEWER_ROBOT_URDF_HPP

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace stride::viewer {

struct urdf_source {
  std::string text;   ///< the URDF document
  std::string label;  ///< where it came from, for messages and the page
};

/// The URDF of component `component` in the run folder `run_dir` (its system.xml).
/// \throws cosim::validation_error naming the component, the parameter or the FMU.
urdf_source find_run_urdf(const std::filesystem::path& run_dir, const std::string& component);

/// The parameters the run's system sets on components other than `component`, as
/// "comp.var = value" (the gait parameters in force, for the page's panel).
std::vector<std::string> other_parameters(const std::filesystem::path& run_dir,
                                          const std::string& component);

/// The target of every connection of the run's system whose source is one variable ("comp.var" →
/// "comp.var").
std::map<std::string, std::string> connection_targets(const std::filesystem::path& run_dir);

}  // namespace stride::viewer

#endif  // STRIDE_VIEWER_ROBOT_URDF_HPP
