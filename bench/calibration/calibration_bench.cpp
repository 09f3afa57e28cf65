// Full calibrations, from reading nothing but the target (already parsed) to the report:
//  - joint mode: the walk-ready pose (page 9, all 20 servos) with all seven offsets, a noisy
//    synthetic posture with six offsets, and the 27-posture plan with all seven; target < 100 ms
//    per fit;
//  - plant mode: torso pitch 0 (one offset), and pitch + height + CoM over the support polygon
//    (three offsets) through gait.fmu + robot.fmu; target < 60 s per fit on one core.
// Run: calibration_bench --benchmark_repetitions=5 (medians are reported with the aggregates).
#include <benchmark/benchmark.h>

#include <random>
#include <string>

#include "stride/calibration/calibrate.hpp"
#include "stride/gait/walking.hpp"
#include "stride/robot/darwin.hpp"

namespace {

using namespace stride;
using namespace stride::calibration;

calibration::joint_target walk_ready() {
  std::string csv = "id,count\n";
  for (int i = 0; i < gait::servo_total; ++i)
    csv += std::to_string(i + 1) + "," +
           std::to_string(robot::darwin::k_walk_ready_counts[static_cast<std::size_t>(i)]) + "\n";
  return parse_joint_target(csv, "walk_ready.csv");
}

gait::walking_params synthetic_truth() {
  gait::walking_params p;
  p.x_offset = -7.3;
  p.y_offset = 8.1;
  p.z_offset = 25.4;
  p.roll_offset = 1.7;
  p.yaw_offset = 3.1;
  p.hip_pitch_offset = 10.6;
  return p;
}

// the leg servos of `p` moved by each delta of `plan`, whole counts with -1/0/+1 count noise
calibration::joint_target noisy_synthetic(gait::ik_mode mode,
                                          const std::vector<offset_values>& plan = {{}}) {
  std::mt19937 rng(1);
  std::string csv;
  for (const offset_info& o : offset_table()) csv += "delta_" + std::string(o.key) + ",";
  csv += "id,count\n";
  for (const offset_values& delta : plan) {
    gait::walking_params p = synthetic_truth();
    offset_values v = get_offsets(p);
    std::string prefix;
    for (std::size_t k = 0; k < offset_count; ++k) {
      v[k] += delta[k];
      prefix += std::to_string(delta[k]) + ",";
    }
    set_offsets(p, v);
    std::array<double, gait::servo_total> c;
    gait::standing_servo_counts(gait::standing_params<double>::from(p), mode, c);
    for (int id = 7; id <= 18; ++id)
      csv += prefix + std::to_string(id) + "," +
             std::to_string(std::lround(c[static_cast<std::size_t>(id - 1)]) +
                            static_cast<long>(rng() % 3) - 1) +
             "\n";
  }
  return parse_joint_target(csv, "synthetic.csv");
}

void joint_fit(benchmark::State& state, const calibration::joint_target& target, fit_options o) {
  for (auto _ : state) {
    const calibration_report r = fit_joint_posture(target, gait::walking_params{}, o);
    benchmark::DoNotOptimize(r.final_cost);
    state.counters["iterations"] = r.iterations;
  }
}

void joint_walk_ready_all_seven(benchmark::State& state) {
  joint_fit(state, walk_ready(), fit_options{});
}

void joint_synthetic_six_darwin(benchmark::State& state) {
  fit_options o;
  o.fit =
      parse_offset_selection("x_offset,y_offset,z_offset,roll_offset,yaw_offset,hip_pitch_offset");
  joint_fit(state, noisy_synthetic(gait::ik_mode::darwin), o);
}

void joint_synthetic_six_geometric(benchmark::State& state) {
  fit_options o;
  o.ik = gait::ik_mode::geometric;
  o.fit =
      parse_offset_selection("x_offset,y_offset,z_offset,roll_offset,yaw_offset,hip_pitch_offset");
  joint_fit(state, noisy_synthetic(gait::ik_mode::geometric), o);
}

void joint_posture_plan_all_seven_darwin(benchmark::State& state) {
  joint_fit(state, noisy_synthetic(gait::ik_mode::darwin, recommended_posture_plan()),
            fit_options{});
}

void plant_fit(benchmark::State& state, const char* target_text) {
  const plant_target target = parse_plant_target(target_text, "bench.ini");
  plant_options p;
  p.fmu_search_path = {STRIDE_FMU_DIR};
  for (auto _ : state) {
    const calibration_report r =
        fit_plant_posture(target, gait::walking_params{}, fit_options{}, p);
    benchmark::DoNotOptimize(r.final_cost);
    state.counters["settles"] = static_cast<double>(r.evaluations);
    state.counters["iterations"] = r.iterations;
  }
}

void plant_pitch_zero(benchmark::State& state) {
  plant_fit(state, "[Plant Target]\npitch_deg = 0\n");
}

void plant_pitch_height_com(benchmark::State& state) {
  plant_fit(state, "[Plant Target]\npitch_deg = 5\nheight_m = 0.31\ncom_over_support = true\n");
}

}  // namespace

BENCHMARK(joint_walk_ready_all_seven)->Unit(benchmark::kMillisecond);
BENCHMARK(joint_synthetic_six_darwin)->Unit(benchmark::kMillisecond);
BENCHMARK(joint_synthetic_six_geometric)->Unit(benchmark::kMillisecond);
BENCHMARK(joint_posture_plan_all_seven_darwin)->Unit(benchmark::kMillisecond);
BENCHMARK(plant_pitch_zero)->Unit(benchmark::kSecond)->Iterations(1);
BENCHMARK(plant_pitch_height_com)->Unit(benchmark::kSecond)->Iterations(1);
