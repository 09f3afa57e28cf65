#include "stride/suite/results.hpp"

#include <cmath>
#include <fstream>
#include <stdexcept>

#include "stride/common/text.hpp"

namespace stride::suite {

namespace fs = std::filesystem;

namespace {

std::optional<double> number(const std::string& field) {
  return text::parse_double(field);
}

}  // namespace

std::optional<std::size_t> recorded_signals::column(const std::string& name) const {
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (names[i] == name) return i;
  }
  return std::nullopt;
}

recorded_signals read_recorded_signals(const fs::path& file) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error(file.string() + ": cannot read (was it recorded?)");
  recorded_signals r;
  r.file = file;
  std::string line;
  if (!std::getline(in, line)) throw std::runtime_error(file.string() + ": empty");
  const auto header = text::csv_fields(line);
  if (header.empty() || header[0] != "time") {
    throw std::runtime_error(file.string() + ":1: the first column must be 'time'");
  }
  r.names.assign(header.begin() + 1, header.end());
  r.values.assign(r.names.size(), {});
  r.is_text.assign(r.names.size(), false);
  for (int line_no = 2; std::getline(in, line); ++line_no) {
    if (line.empty() || line == "\r") continue;
    const auto fields = text::csv_fields(line);
    const std::string where = file.string() + ":" + std::to_string(line_no) + ": ";
    if (fields.size() != header.size()) {
      throw std::runtime_error(where + std::to_string(fields.size()) + " fields, the header has " +
                               std::to_string(header.size()));
    }
    const auto t = number(fields[0]);
    if (!t) throw std::runtime_error(where + "time '" + fields[0] + "' is not a number");
    r.time.push_back(*t);
    for (std::size_t c = 0; c < r.names.size(); ++c) {
      const auto v = number(fields[c + 1]);
      if (!v) r.is_text[c] = true;
      r.values[c].push_back(v ? *v : std::nan(""));
    }
  }
  for (std::size_t c = 0; c < r.names.size(); ++c) {
    if (r.is_text[c]) r.values[c].clear();
  }
  return r;
}

}  // namespace stride::suite
