#include "robot_fmu.hpp"

#include <cstdio>
#include <filesystem>

#include "stride/cosim/system_builder.hpp"

namespace stride::cli {

namespace fs = std::filesystem;

namespace {

// the plant FMU this Stride was built with: its binaries serve every generated plant
std::string built_plant_fmu() {
  for (const fs::path& dir : cosim::default_fmu_search_path()) {
    const fs::path candidate = dir / "robot.fmu";
    if (fs::is_regular_file(candidate)) return candidate.string();
  }
  throw std::runtime_error(
      "robot.fmu (whose binaries a plant FMU is made of) is not in $STRIDE_FMU_PATH or the "
      "bundled FMU folder; give it with --binaries-from");
}

}  // namespace

CLI::App* add_robot_fmu_command(CLI::App& app, robot_fmu_arguments& a) {
  CLI::App* c = app.add_subcommand(
      "robot-fmu",
      "Generate the FMI 2.0 co-simulation plant FMU of a URDF robot: joints, IMU, base pose, "
      "contact forces, simulated on ODE as its plant profile says (docs/plant-profile.md)");
  c->add_option("urdf", a.request.urdf, "URDF of the robot")->required()->check(CLI::ExistingFile);
  c->add_option("--profile", a.request.profile,
                "Plant profile (XML): servos, passive and welded joints, initial pose, contacts, "
                "physics step, fall rule, IMU and board outputs (default: every setting guessed, "
                "each guess reported)")
      ->check(CLI::ExistingFile);
  c->add_option("-o,--output", a.request.output, "The FMU to write (NAME.fmu)")->required();
  c->add_option("--name", a.request.model_name,
                "Model name; its C identifier names the binary (default: the output's name)");
  c->add_option("--description", a.request.description, "Model description");
  c->add_option("--package-path", a.request.package_path,
                "Folder for package:// URIs: a package folder or a folder of packages "
                "(repeatable; $ROS_PACKAGE_PATH is searched too)");
  c->add_option("--binaries-from", a.request.binaries_from,
                "Plant FMU whose binaries are packaged (default: the robot.fmu built with this "
                "Stride)")
      ->check(CLI::ExistingFile);
  c->add_flag("--quiet,-q", a.quiet, "Only warnings and errors");
  return c;
}

int robot_fmu(robot_fmu_arguments a) {
  if (a.request.binaries_from.empty()) a.request.binaries_from = built_plant_fmu();
  const robot::plant_fmu_result r = robot::write_plant_fmu(a.request);
  for (const std::string& w : r.warnings) {
    std::fprintf(stderr, "stride robot-fmu: warning: %s\n", w.c_str());
  }
  if (!a.quiet) {
    std::printf("%s: %zu joints, %zu variables, GUID %s\n", a.request.output.c_str(), r.joints,
                r.variables, r.guid.c_str());
  }
  return 0;
}

}  // namespace stride::cli
