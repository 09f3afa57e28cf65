#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <sstream>

#include "stride/calibration/calibrate.hpp"
#include "stride/gait/config_ini.hpp"

namespace stride::calibration {

namespace {

std::string line(const char* format, ...) __attribute__((format(printf, 1, 2)));
std::string line(const char* format, ...) {
  char buf[512];
  va_list args;
  va_start(args, format);
  std::vsnprintf(buf, sizeof buf, format, args);
  va_end(args);
  return std::string(buf) + "\n";
}

const char* servo_names[] = {"r_sho_pitch", "l_sho_pitch", "r_sho_roll",  "l_sho_roll",
                             "r_el",        "l_el",        "r_hip_yaw",   "l_hip_yaw",
                             "r_hip_roll",  "l_hip_roll",  "r_hip_pitch", "l_hip_pitch",
                             "r_knee",      "l_knee",      "r_ank_pitch", "l_ank_pitch",
                             "r_ank_roll",  "l_ank_roll",  "head_pan",    "head_tilt"};

}  // namespace

std::string format_report(const calibration_report& r) {
  std::ostringstream out;
  out << "stride calibrate: " << r.mode << " mode, target " << r.target_source << ", IK "
      << (r.ik == gait::ik_mode::darwin ? "darwin" : "geometric") << "\n";
  out << line("solver: %d iterations, %s (%s)", r.iterations,
              r.converged ? "converged" : "NOT converged", r.termination.c_str());
  out << line("cost: %.6g -> %.6g (1/2 sum of %s squared residuals)", r.initial_cost, r.final_cost,
              r.mode == "joints" ? "robust" : "scaled");
  if (r.mode == "plant") out << line("plant settles: %lld", static_cast<long long>(r.evaluations));

  out << "\n"
      << line("%-17s %-4s %11s %11s %10s %10s  %s", "offset", "unit", "before", "after", "change",
              "1-sigma", "status");
  for (const offset_result& o : r.offsets) {
    const offset_info& info = offset_table()[o.index];
    std::string sigma = "-";
    std::string status = "fixed";
    if (o.fitted) {
      char buf[32];
      if (o.identifiable && std::isfinite(o.stddev)) {
        std::snprintf(buf, sizeof buf, "%.4f", o.stddev);
        sigma = buf;
        status = o.at_bound ? "fitted, AT BOUND" : "fitted";
      } else {
        sigma = "n/a";
        status = "NOT IDENTIFIABLE: " + o.note;
      }
    }
    out << line("%-17s %-4s %11.4f %11.4f %+10.4f %10s  %s", std::string(info.key).c_str(),
                std::string(info.unit).c_str(), o.before, o.after, o.after - o.before,
                sigma.c_str(), status.c_str());
  }

  const bool several = r.postures.size() > 1;
  if (several) {
    out << "\n"
        << line("%zu postures (target = gait output at the offsets + these deltas):",
                r.postures.size());
    for (std::size_t p = 0; p < r.postures.size(); ++p) {
      std::string deltas;
      for (std::size_t k = 0; k < offset_count; ++k) {
        const double d = r.postures[p].delta[k];
        if (d == 0.0) continue;
        char buf[64];
        std::snprintf(buf, sizeof buf, "%s%s %+g %s", deltas.empty() ? "" : ", ",
                      std::string(offset_table()[k].key).c_str(), d,
                      std::string(offset_table()[k].unit).c_str());
        deltas += buf;
      }
      out << line("  P%-3zu from line %-5d %s", p + 1, r.postures[p].line,
                  deltas.empty() ? "(no delta)" : deltas.c_str());
    }
  }

  if (!r.joints.empty()) {
    out << "\n"
        << line("%-22s %9s %9s %8s %9s %8s  %s", "joint (counts)", "target", "before", "resid",
                "after", "resid", "");
    double sum_before = 0, sum_after = 0;
    int fitted = 0;
    for (const joint_result& j : r.joints) {
      std::string flag;
      if (!j.fitted) flag = "not fitted (no offset moves it)";
      if (j.outlier) flag = "outlier";
      char name[40];
      if (several)
        std::snprintf(name, sizeof name, "P%-3d %2d %s", j.posture + 1, j.id,
                      servo_names[j.id - 1]);
      else
        std::snprintf(name, sizeof name, "%2d %s", j.id, servo_names[j.id - 1]);
      out << line("%-22s %9.1f %9.2f %+8.2f %9.2f %+8.2f  %s", name, j.target, j.model_before,
                  j.residual_before(), j.model_after, j.residual_after(), flag.c_str());
      if (j.fitted) {
        sum_before += j.residual_before() * j.residual_before();
        sum_after += j.residual_after() * j.residual_after();
        ++fitted;
      }
    }
    if (fitted > 0)
      out << line("rms residual of the %d fitted joints: %.3f -> %.3f counts (%.4f -> %.4f deg)",
                  fitted, std::sqrt(sum_before / fitted), std::sqrt(sum_after / fitted),
                  std::sqrt(sum_before / fitted) * gait::degrees_per_count,
                  std::sqrt(sum_after / fitted) * gait::degrees_per_count);
  }

  if (!r.plant.empty()) {
    out << "\n"
        << line("%-10s %10s %10s %10s %10s %8s", "target", "goal", "before", "after", "sigma",
                "off/sig");
    for (const plant_result& p : r.plant)
      out << line("%-10s %10.4f %10.4f %10.4f %10.4f %+8.2f", p.name.c_str(), p.target, p.before,
                  p.after, p.sigma, (p.after - p.target) / p.sigma);
  }

  if (!r.warnings.empty()) {
    out << "\nwarnings:\n";
    for (const std::string& w : r.warnings) out << "  - " << w << "\n";
  }
  return out.str();
}

void write_fitted_config(const std::filesystem::path& input, const std::filesystem::path& output,
                         const calibration_report& report) {
  gait::ini_document doc = gait::ini_document::load(input);
  for (const offset_result& o : report.offsets) {
    if (!o.fitted) continue;
    const gait::param_info* info = gait::find_param(offset_table()[o.index].key);
    doc.set(gait::walking_config_section, info->key,
            gait::format_param_value(*info, report.fitted));
  }
  doc.save(output);
}

}  // namespace stride::calibration
