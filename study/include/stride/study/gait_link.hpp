// What ties the learner to the DARwIn-OP gait in the study's systems: the grid of a learner is
// a set of gait parameters (checked against their valid ranges before a run), and the best state
// of a learn run, applied to the gait's settings, is a ROBOTIS config.ini (written after it).
#ifndef STRIDE_STUDY_GAIT_LINK_HPP
#define STRIDE_STUDY_GAIT_LINK_HPP

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "stride/cosim/system_structure.hpp"
#include "stride/learner/grid.hpp"

namespace stride::study {

/// Whether a component is a learner: its FMU is the bundled "learner" or a learner.fmu file.
bool is_learner(const cosim::component_spec& c);

/// Checks both ends of every grid dimension that names a gait ([Walking Config]) parameter
/// against that parameter's valid range. \throws learner::learner_error naming the parameter.
void check_grid_against_gait(const learner::state_grid& grid, const std::string& what = "grid");

/// Checks the grid and evaluation point of every learner of `system` against the gait's ranges.
/// \throws cosim::validation_error naming the file, line and parameter.
void check_learner_grids(const cosim::system_structure& system);

/// Writes a ROBOTIS config.ini to `out`: the framework defaults, then `settings` ([Walking Config]
/// keys, e.g. the gait component's parameters in the system), then the grid dimensions that are
/// gait parameters set to `values`, by the gait core's INI writer.
void write_best_config(const std::filesystem::path& out,
                       const std::vector<std::pair<std::string, double>>& settings,
                       const learner::state_grid& grid, const std::vector<double>& values);

/// After a run of `system` (as run: placeholders substituted): for every learner in learn mode
/// with a V table in its output folder, writes config.ini there with the best state applied to
/// the settings of the gait component its value[i] outputs drive. Returns the files written.
std::vector<std::filesystem::path> write_best_configs(const cosim::system_structure& system);

}  // namespace stride::study

#endif  // STRIDE_STUDY_GAIT_LINK_HPP
