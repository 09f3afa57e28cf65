#include "calibrate.hpp"

#include <cstdio>
#include <fstream>
#include <stdexcept>

#include "stride/calibration/calibrate.hpp"
#include "stride/common/files.hpp"
#include "stride/cosim/log.hpp"
#include "stride/cosim/system_import.hpp"
#include "stride/cosim/system_structure.hpp"
#include "stride/gait/config_ini.hpp"

namespace stride::cli {

namespace {

// an argument error, named after its option
[[noreturn]] void bad_option(const std::string& option, const std::exception& e) {
  throw std::invalid_argument(option + ": " + e.what());
}

}  // namespace

CLI::App* add_calibrate_command(CLI::App& app, calibrate_arguments& a) {
  CLI::App* c = app.add_subcommand(
      "calibrate",
      "Fit the gait's offsets (x/y/z/roll/pitch/yaw/hip_pitch_offset) to a static posture with "
      "Ceres and write the config.ini with the fitted values (docs/calibration.md)");
  c->add_option("--target", a.target,
                "Target posture: joints mode a CSV (id + count|deg|rad; delta_<offset> "
                "columns for several postures), plant mode an INI ([Plant Target] pitch_deg, "
                "roll_deg, height_m, com_over_support)")
      ->required()
      ->check(CLI::ExistingFile);
  c->add_option("--config", a.config, "Input config.ini ([Walking Config]): the start values")
      ->required()
      ->check(CLI::ExistingFile);
  c->add_option("--output", a.output,
                "Output config.ini: the input with the fitted offsets (other keys, comments and "
                "order kept)")
      ->required();
  c->add_option("--fit", a.fit,
                "Offsets to fit, comma-separated, or 'all' (default: joints all seven; plant the "
                "offsets that drive the targets)");
  c->add_option("--mode", a.mode, "joints (standing joint posture) or plant (settled robot)")
      ->check(CLI::IsMember({"joints", "plant"}))
      ->capture_default_str();
  c->add_option("--ik", a.ik, "Leg IK of the gait: darwin (framework) or geometric")
      ->check(CLI::IsMember({"darwin", "geometric"}))
      ->capture_default_str();
  c->add_option("--bound", a.bounds, "Fit bounds of an offset: OFFSET=LO:HI (repeatable)")
      ->allow_extra_args(false);
  c->add_option("--loss-scale", a.loss_scale,
                "Joints mode: Cauchy loss scale in servo counts; larger residuals are treated as "
                "outliers")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  c->add_option("--system", a.system,
                "Plant mode: system XML with components 'gait' and 'robot' (default: the built-in "
                "standing system)")
      ->check(CLI::ExistingFile);
  c->add_option("--report", a.report, "Also write the report to this file");
  c->add_flag("--quiet,-q", a.quiet, "No report on stdout; warnings go to stderr");
  return c;
}

int calibrate(const calibrate_arguments& a) {
  namespace cal = stride::calibration;
  cal::fit_options options;
  try {
    if (!a.fit.empty()) options.fit = cal::parse_offset_selection(a.fit);
  } catch (const std::invalid_argument& e) {
    bad_option("--fit", e);
  }
  try {
    for (const std::string& b : a.bounds) cal::apply_bound(options.bounds, b);
  } catch (const std::invalid_argument& e) {
    bad_option("--bound", e);
  }
  options.ik = a.ik == "geometric" ? gait::ik_mode::geometric : gait::ik_mode::darwin;
  options.loss_scale = a.loss_scale;

  std::vector<std::string> config_warnings;
  const gait::walking_params start = gait::read_walking_config(
      std::filesystem::path(a.config), gait::walking_params{}, &config_warnings);
  for (const std::string& w : config_warnings)
    std::fprintf(stderr, "stride: warning: %s\n", w.c_str());

  cal::calibration_report report;
  if (a.mode == "plant") {
    const cal::plant_target target = cal::read_plant_target(a.target);
    cal::plant_options plant;
    if (!a.system.empty()) plant.system = cosim::load_system_file(a.system);
    plant.log = cosim::stderr_log_sink(cosim::log_level::warning);
    report = cal::fit_plant_posture(target, start, options, plant);
  } else {
    const cal::joint_target target = cal::read_joint_target(a.target);
    report = cal::fit_joint_posture(target, start, options);
  }
  cal::write_fitted_config(a.config, a.output, report);

  const std::string text = cal::format_report(report) + "\nwritten: " + a.output + "\n";
  if (!a.report.empty()) common::write_file_atomically(a.report, text);
  if (a.quiet) {
    for (const std::string& w : report.warnings)
      std::fprintf(stderr, "stride: warning: %s\n", w.c_str());
  } else {
    std::fputs(text.c_str(), stdout);
  }
  return report.converged ? 0 : calibrate_not_converged;
}

}  // namespace stride::cli
