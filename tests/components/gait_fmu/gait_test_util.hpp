// Helpers shared by the gait core tests: golden CSV reading and a scripted driver.
#pragma once

#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "stride/gait/walking.hpp"

namespace gait_test {

inline std::string data_path(const std::string& name) {
  return std::string(STRIDE_TEST_DATA_DIR) + "/" + name;
}

/// A CSV file as header + rows of doubles.
struct csv {
  std::vector<std::string> header;
  std::vector<std::vector<double>> rows;
};

inline csv read_csv(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot open " + path);
  csv out;
  std::string line;
  bool first = true;
  while (std::getline(in, line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty()) continue;
    std::stringstream ss(line);
    std::string cell;
    if (first) {
      while (std::getline(ss, cell, ',')) out.header.push_back(cell);
      first = false;
      continue;
    }
    std::vector<double> row;
    while (std::getline(ss, cell, ',')) row.push_back(std::stod(cell));
    out.rows.push_back(std::move(row));
  }
  return out;
}

/// Servo values of one tick as a vector (for readable gtest diffs).
inline std::vector<int> servos(const stride::gait::walking_state& s) {
  return std::vector<int>(std::begin(s.servo_count), std::end(s.servo_count));
}

}  // namespace gait_test
