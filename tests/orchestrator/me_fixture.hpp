// The Model Exchange test FMUs of me_fmus/ packed at test time, and the driving helpers the
// runner's tests share (FMI 2.0 in me_component_test, FMI 3.0 in fmi3_me_component_test).
#ifndef STRIDE_TESTS_ORCHESTRATOR_ME_FIXTURE_HPP
#define STRIDE_TESTS_ORCHESTRATOR_ME_FIXTURE_HPP

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "stride/cosim/archive.hpp"
#include "stride/cosim/fmu.hpp"
#include "zip_writer.hpp"

namespace stride::cosim::test {

inline std::string read_text(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

enum class standard { fmi2, fmi3 };

class me_fixture : public ::testing::Test {
 protected:
  // packs me_fmus/<model>.xml (<model>3.xml for 3.0) and the built library into an FMU;
  // `edit` replaces its first string by its second in the model description (when non-empty)
  std::shared_ptr<fmu> load(const std::string& model, const std::string& library,
                            const std::pair<std::string, std::string>& edit = {},
                            standard s = standard::fmi2) {
    return fmu::load(pack(model, library, edit, s));
  }
  std::filesystem::path pack(const std::string& model, const std::string& library,
                             const std::pair<std::string, std::string>& edit = {},
                             standard s = standard::fmi2) {
    const bool three = s == standard::fmi3;
    std::string description = read_text(std::filesystem::path(STRIDE_ME_FMU_SOURCES) /
                                        (model + (three ? "3" : "") + ".xml"));
    if (!edit.first.empty()) {
      const auto at = description.find(edit.first);
      EXPECT_NE(at, std::string::npos) << edit.first;
      if (at != std::string::npos) description.replace(at, edit.first.size(), edit.second);
    }
    const std::string binary = three ? "binaries/x86_64-linux/me3_" + model + ".so"
                                     : "binaries/linux64/me_" + model + ".so";
    const auto file = dir_.path() / (model + std::to_string(++loaded_) + ".fmu");
    write_zip(file, {{"modelDescription.xml", description}, {binary, read_text(library)}});
    return file;
  }
  std::shared_ptr<fmu> load3(const std::string& model, const std::string& library,
                             const std::pair<std::string, std::string>& edit = {}) {
    return load(model, library, edit, standard::fmi3);
  }

  temp_dir dir_{"stride-me-test-"};
  int loaded_ = 0;
};

struct run_trace {
  std::vector<double> t;
  std::vector<value_block> outputs;
};

inline void initialise(component& c, double stop) {
  c.setup(time_from_seconds(0), time_from_seconds(stop));
  c.enter_initialization();
  c.exit_initialization();
}

// `steps` communication steps of `dt` from `from`, reading `outs` after each
inline run_trace advance(component& c, const variable_refs& outs, double from, double dt,
                         int steps) {
  c.expose({}, outs);
  run_trace trace;
  for (int i = 0; i < steps; ++i) {
    const time_point t = time_from_seconds(from) + i * duration_from_seconds(dt);
    value_block out;
    out.resize_for(outs);
    EXPECT_EQ(c.step(t, duration_from_seconds(dt), {}, out), step_result::complete);
    trace.t.push_back(to_seconds(t + duration_from_seconds(dt)));
    trace.outputs.push_back(out);
  }
  return trace;
}

inline model_exchange_options cvode(double rtol) {
  model_exchange_options o;
  o.rtol = rtol;
  o.atol = rtol * 1e-3;
  return o;
}

inline std::unique_ptr<component> make(fmu& f, const std::string& name, model_exchange_options o) {
  instance_options io;
  io.model_exchange = o;
  return f.instantiate(name, io);
}

}  // namespace stride::cosim::test

#endif  // STRIDE_TESTS_ORCHESTRATOR_ME_FIXTURE_HPP
