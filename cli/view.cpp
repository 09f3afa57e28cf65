#include "view.hpp"

#include <cstdio>
#include <cstdlib>
#include <string>

namespace stride::cli {

namespace fs = std::filesystem;

CLI::App* add_view_command(CLI::App& app, view_arguments& args) {
  auto* view = app.add_subcommand(
      "view",
      "Write one self-contained HTML page (no server, no network) that replays a run's robot "
      "in 3-D: links from the URDF the run used, posed from the recorded base pose and joint "
      "angles; floor, path, falls on the timeline. Record with `stride run SYSTEM "
      "--record-view` (docs/viewer.md)");
  view->add_option("run_dir", args.options.run_dir, "Output folder of the run")
      ->required()
      ->check(CLI::ExistingDirectory);
  view->add_option("--output,-o", args.options.output,
                   "The page to write (default RUN_DIR/view.html)");
  view->add_flag("--open", args.open, "Open the page in the desktop's browser (xdg-open)");
  view->add_option("--from", args.options.from, "Start of the window to replay, s");
  view->add_option("--to", args.options.to, "End of the window to replay, s");
  view->add_option("--fps", args.options.fps,
                   "Frames kept per simulated second at most; longer recordings are decimated "
                   "(0: every recorded row)")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 1000.0));
  view->add_option("--robot", args.options.robot,
                   "The component whose pose to show when several are recorded (default: the "
                   "first)");
  view->add_option("--urdf", args.options.urdf,
                   "Draw this URDF instead of the one the run used (system.xml, the FMU)")
      ->check(CLI::ExistingFile);
  view->add_option("--max-frames", args.options.max_frames,
                   "Frames in the page at most; a longer window is thinned evenly (0: no limit)")
      ->capture_default_str();
  view->add_option("--episodes", args.options.episodes,
                   "A column whose runs of equal values the page offers to replay one by one "
                   "(default: a column named *.episode, e.g. learner.episode; or "
                   "learner.rl_step)");
  view->add_option("--episode", args.options.episode,
                   "Replay only the rows at which the --episodes column has this value");
  view->add_option("--state", args.options.state,
                   "Columns shown in the panel as they change: patterns with * and ? (default: "
                   "*.episode, *.rl_step, *.value[*], a learner's state)")
      ->allow_extra_args(false);
  view->add_flag("--quiet,-q", args.quiet, "Print nothing");
  return view;
}

int view(const view_arguments& args) {
  const viewer::view_report r = viewer::write_view(args.options);
  if (!args.quiet) {
    std::printf("view: %s (%zu frames of %s from %s, robot %s, %.1f MB)\n",
                r.output.string().c_str(), r.frames, r.robot.c_str(),
                r.results.filename().string().c_str(), r.urdf.string().c_str(),
                static_cast<double>(r.bytes) / 1e6);
    if (r.episodes > 0) std::printf("%zu episodes to choose from\n", r.episodes);
    for (const double t : r.falls) std::printf("fall at t = %g s\n", t);
  }
  if (args.open) {
    const std::string url = "file://" + fs::absolute(r.output).lexically_normal().string();
    const std::string command = "xdg-open '" + url + "' >/dev/null 2>&1";
    if (std::system(command.c_str()) != 0) {
      std::fprintf(stderr, "stride: could not open a browser; open %s\n", url.c_str());
    }
  }
  return 0;
}

}  // namespace stride::cli
