// Runs a command line for the CLI tests and collects exit code, stdout and stderr.
#ifndef STRIDE_TESTS_ORCHESTRATOR_PROCESS_HPP
#define STRIDE_TESTS_ORCHESTRATOR_PROCESS_HPP

#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace stride::cosim::test {

struct process_result {
  int exit_code = -1;
  std::string out;
  std::string err;
};

/// Runs `command` through the shell; stderr is collected through a file in `scratch`.
inline process_result run_command(const std::string& command,
                                  const std::filesystem::path& scratch) {
  const auto err_file = scratch / "stderr.txt";
  process_result r;
  FILE* pipe = ::popen((command + " 2> '" + err_file.string() + "'").c_str(), "r");
  if (pipe == nullptr) return r;
  char buffer[4096];
  std::size_t n;
  while ((n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0) r.out.append(buffer, n);
  const int status = ::pclose(pipe);
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  std::ifstream in(err_file);
  std::stringstream text;
  text << in.rdbuf();
  r.err = text.str();
  return r;
}

inline std::string quoted(const std::filesystem::path& p) {
  return "'" + p.string() + "'";
}

}  // namespace stride::cosim::test

#endif  // STRIDE_TESTS_ORCHESTRATOR_PROCESS_HPP
