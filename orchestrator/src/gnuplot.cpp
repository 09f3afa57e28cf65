#include "stride/cosim/gnuplot.hpp"

#include <sys/wait.h>

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "stride/common/files.hpp"

namespace stride::cosim::gnuplot {

namespace fs = std::filesystem;

std::string num(double v) {
  if (std::isnan(v)) return "NaN";
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

std::string quote(const std::string& s) {
  std::string out = "'";
  for (char c : s) {
    if (c == '\'') {
      out += "''";
    } else {
      out += c;
    }
  }
  return out + "'";
}

void write_text(const fs::path& file, const std::string& text) {
  common::write_file_atomically(file, text);
}

void run(const fs::path& script) {
  const fs::path err = script.string() + ".err";
  const std::string cmd = "gnuplot " + quote(script.string()) + " 2> " + quote(err.string());
  const int status = std::system(cmd.c_str());
  if (status == -1 || !WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    std::ifstream in(err);
    std::stringstream text;
    text << in.rdbuf();
    if (WIFEXITED(status) && WEXITSTATUS(status) == 127) {
      throw std::runtime_error(
          "gnuplot not found: install the Debian package gnuplot-nox (scripts/install-deps.sh)");
    }
    throw std::runtime_error("gnuplot failed on " + script.string() + ": " + text.str());
  }
  fs::remove(err);
}

}  // namespace stride::cosim::gnuplot
