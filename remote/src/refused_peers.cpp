#include "stride/remote/refused_peers.hpp"

#include <dds/dds.h>
#include <dds/ddsrt/log.h>

#include <cstdio>

namespace stride::remote {

namespace {

std::string_view between(std::string_view text, std::string_view from, std::string_view to) {
  const auto start = text.find(from);
  if (start == std::string_view::npos) return {};
  const auto rest = text.substr(start + from.size());
  return rest.substr(0, rest.find(to));
}

void sink(void* self, const dds_log_data_t* data) {
  const std::string_view message(data->message, data->size);
  const std::string line = static_cast<refused_peer_log*>(self)->refusal(message);
  // Cyclone's trace (stderr unless configured otherwise) also has every handshake failure; the
  // other messages are written as the default sink would
  if (line.empty() && message.find("handshake") == std::string_view::npos) {
    std::fwrite(data->message, 1, data->size, stderr);
    if (!message.ends_with('\n')) std::fputc('\n', stderr);
    std::fflush(stderr);
  }
}

}  // namespace

refused_peer_log::refused_peer_log(std::function<void(const std::string&)> log)
    : log_(std::move(log)) {
  dds_set_log_sink(&sink, this);
}

refused_peer_log::~refused_peer_log() {
  dds_set_log_sink(nullptr, nullptr);
}

std::string refused_peer_log::refusal(std::string_view message) {
  // Cyclone: "fsm: Begin handshake reply failed: REASON; subject: SUBJECT(code: N)"
  if (message.find("handshake") == std::string_view::npos ||
      message.find("failed") == std::string_view::npos) {
    return "";
  }
  std::string_view subject = between(message, "subject: ", "(code:");
  std::string_view reason = between(message, "failed: ", "; subject:");
  if (reason.starts_with("Certificate not valid: error: ")) reason.remove_prefix(30);
  if (subject.empty()) subject = "(subject unknown)";
  const std::string line = "refused peer " + std::string(subject) + ": " + std::string(reason) +
                           " (DDS Security handshake)";
  {
    std::lock_guard lock(mutex_);
    if (!seen_.insert(line).second) return "";
  }
  log_(line);
  return line;
}

}  // namespace stride::remote
