// The fmi3_kinds test FMU (data/fmi3_kinds) for the FMI 3.0 import tests: its packaged archive,
// variants of it written at test time, and port lookup by name.
#ifndef STRIDE_TESTS_ORCHESTRATOR_FMI3_FIXTURE_HPP
#define STRIDE_TESTS_ORCHESTRATOR_FMI3_FIXTURE_HPP

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "stride/cosim/archive.hpp"
#include "stride/cosim/component.hpp"
#include "stride/cosim/fmu.hpp"
#include "stride/cosim/log.hpp"
#include "zip_writer.hpp"

namespace stride::cosim::test {

inline const std::filesystem::path k_fmi3_kinds = FMI3_KINDS_FMU;

inline std::string read_whole(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// Import options extracting below `dir`.
inline fmu_import_options extract_into(const std::filesystem::path& dir) {
  fmu_import_options o;
  o.extract_root = dir;
  return o;
}

/// The test FMU's modelDescription.xml.
inline std::string fmi3_kinds_xml() {
  return read_whole(FMI3_KINDS_MODEL_DESCRIPTION);
}

/// Writes `file` as the test FMU with `xml` for its model description (same binary).
inline void write_fmi3_kinds_variant(const std::filesystem::path& file, const std::string& xml) {
  write_zip(file, {{"modelDescription.xml", xml},
                   {"binaries/x86_64-linux/fmi3_kinds.so", read_whole(FMI3_KINDS_BINARY)}});
}

/// `text` with the first `from` replaced by `to` (the test fails if `from` is missing).
inline std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  if (at == std::string::npos) throw std::runtime_error("no \"" + from + "\" in the text");
  return text.replace(at, from.size(), to);
}

/// The Stride port reference of `name` in `c`.
inline value_reference ref(const component& c, const std::string& name) {
  const auto* v = c.model_description().find(name);
  if (v == nullptr) throw std::runtime_error("no port " + name);
  return v->reference;
}

/// A batch of one port of each listed channel, by name.
struct batch {
  variable_refs refs;
  value_block values;
  batch& real(const component& c, const std::string& name, double v) {
    refs.reals.push_back(ref(c, name));
    values.reals.push_back(v);
    return *this;
  }
  batch& integer(const component& c, const std::string& name, int v) {
    refs.integers.push_back(ref(c, name));
    values.integers.push_back(v);
    return *this;
  }
  batch& boolean(const component& c, const std::string& name, bool v) {
    refs.booleans.push_back(ref(c, name));
    values.booleans.push_back(v);
    return *this;
  }
  batch& string(const component& c, const std::string& name, const std::string& v) {
    refs.strings.push_back(ref(c, name));
    values.strings.push_back(v);
    return *this;
  }
};

struct log_lines {
  std::vector<std::string> lines;
  log_sink sink() {
    return [this](log_level level, std::string_view source, std::string_view,
                  std::string_view message) {
      lines.push_back(std::string(to_string(level)) + " " + std::string(source) + ": " +
                      std::string(message));
    };
  }
};

/// An instance of the test FMU in step mode (start 0, no stop time).
inline std::unique_ptr<component> stepping_fmi3_kinds(const std::shared_ptr<fmu>& f,
                                                      const instance_options& options = {}) {
  auto c = f->instantiate("k", options);
  c->setup(time_point{}, std::nullopt);
  c->enter_initialization();
  c->exit_initialization();
  return c;
}

}  // namespace stride::cosim::test

#endif  // STRIDE_TESTS_ORCHESTRATOR_FMI3_FIXTURE_HPP
