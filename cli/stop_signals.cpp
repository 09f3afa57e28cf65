#include "stop_signals.hpp"

#include <csignal>

namespace stride::cli {

namespace {

std::atomic<bool> g_stop{false};
std::atomic<int> g_signal{0};

extern "C" void request_stop(int signal) {
  g_signal.store(signal);
  g_stop.store(true);
}

}  // namespace

const std::atomic<bool>& catch_stop_signals() {
  struct sigaction sa {};
  sa.sa_handler = request_stop;
  sa.sa_flags = SA_RESETHAND;  // the second signal is handled as usual
  sigemptyset(&sa.sa_mask);
  sigaction(SIGINT, &sa, nullptr);
  sigaction(SIGTERM, &sa, nullptr);
  return g_stop;
}

int caught_stop_signal() {
  return g_signal.load();
}

}  // namespace stride::cli
