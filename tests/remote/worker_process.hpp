// A `stride worker` process for tests: started, waited for until it says it is ready, stopped
// (SIGTERM) or killed on purpose, always reaped.
#ifndef STRIDE_TESTS_REMOTE_WORKER_PROCESS_HPP
#define STRIDE_TESTS_REMOTE_WORKER_PROCESS_HPP

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "../orchestrator/process.hpp"

namespace stride::remote::test {

using cosim::test::spawn;

class worker_process {
 public:
  /// Starts `stride worker --name NAME --domain DOMAIN EXTRA...`, its output into `log`;
  /// `environment` (NAME=VALUE, through env(1)) is added to its environment.
  worker_process(const std::string& stride, const std::string& name, int domain,
                 std::filesystem::path log, const std::vector<std::string>& extra = {},
                 const std::vector<std::string>& environment = {})
      : log_(std::move(log)),
        pid_(spawn(command(stride, name, domain, extra, environment), log_)) {}
  ~worker_process() {
    if (pid_ > 0) {
      ::kill(pid_, SIGKILL);
      ::waitpid(pid_, nullptr, 0);
    }
  }
  worker_process(const worker_process&) = delete;
  worker_process& operator=(const worker_process&) = delete;

  /// What it printed so far.
  std::string output() const {
    std::ifstream in(log_);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
  }
  /// Waits until its output holds `text` (or it exits, or `timeout` passes).
  bool wait_for(const std::string& text,
                std::chrono::milliseconds timeout = std::chrono::seconds(20)) const {
    const auto until = std::chrono::steady_clock::now() + timeout;
    while (std::chrono::steady_clock::now() < until) {
      if (output().find(text) != std::string::npos) return true;
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    return false;
  }
  bool ready() const { return pid_ > 0 && wait_for(" ready on DDS domain "); }

  /// Sends `signal` and reaps it; returns its exit code, or 128 + the signal that ended it.
  int stop(int signal) {
    if (pid_ <= 0) return -1;
    ::kill(pid_, signal);
    int status = 0;
    ::waitpid(pid_, &status, 0);
    pid_ = 0;
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  }
  /// Waits for it to exit by itself; its exit code.
  int wait_exit() {
    int status = 0;
    ::waitpid(pid_, &status, 0);
    pid_ = 0;
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  }

 private:
  static std::vector<std::string> command(const std::string& stride, const std::string& name,
                                          int domain, const std::vector<std::string>& extra,
                                          const std::vector<std::string>& environment) {
    std::vector<std::string> args;
    if (!environment.empty()) {
      args.push_back("/usr/bin/env");
      args.insert(args.end(), environment.begin(), environment.end());
    }
    for (const std::string& a : {stride, std::string("worker"), std::string("--name"), name,
                                 std::string("--domain"), std::to_string(domain)}) {
      args.push_back(a);
    }
    args.insert(args.end(), extra.begin(), extra.end());
    return args;
  }

  std::filesystem::path log_;
  pid_t pid_ = 0;
};

}  // namespace stride::remote::test

#endif  // STRIDE_TESTS_REMOTE_WORKER_PROCESS_HPP
