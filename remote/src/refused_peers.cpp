#include "stride/remote/refused_peers.hpp"

#include <dds/dds.h>
#include <dds/ddsrt/log.h>

#include <cstdio>

#include "dds_security.hpp"

namespace stride::remote {

namespace {

// Cyclone's handshake messages say again and again what the listener says once (without the
// wrapper they are all there is, and pass); the others are written as the default sink would
void sink(void*, const dds_log_data_t* data) {
  const std::string_view message(data->message, data->size);
  if (dds::handshakes_watched() && message.find("andshake") != std::string_view::npos) return;
  std::fwrite(data->message, 1, data->size, stderr);
  if (!message.ends_with('\n')) std::fputc('\n', stderr);
  std::fflush(stderr);
}

void listener(void* self, stride_handshake_event event, std::int64_t peer, const char* subject,
              const char* ca_subject, const char* detail) {
  static constexpr handshake_event events[] = {handshake_event::requested,
                                               handshake_event::authenticated,
                                               handshake_event::failed, handshake_event::ended};
  if (event < STRIDE_HANDSHAKE_REQUESTED || event > STRIDE_HANDSHAKE_ENDED) return;
  static_cast<refused_peer_log*>(self)->on_event(events[event - STRIDE_HANDSHAKE_REQUESTED], peer,
                                                 subject, ca_subject, detail);
}

std::string named(std::string_view subject) {
  return subject.empty() ? "(subject unknown)" : std::string(subject);
}

}  // namespace

refused_peer_log::refused_peer_log(std::function<void(const std::string&)> log,
                                   std::chrono::milliseconds answer_within)
    : log_(std::move(log)), answer_within_(answer_within) {
  watching_ = dds::watch_handshakes(&listener, this);
  if (!watching_) return;  // Cyclone then says what happens, in its own words
  dds_set_log_sink(&sink, nullptr);
}

refused_peer_log::~refused_peer_log() {
  if (watching_) dds::stop_watching_handshakes();
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  if (timer_.joinable()) timer_.join();
  // the last check, for a peer that had its time to answer since the timer last looked
  std::lock_guard lock(mutex_);
  say_unanswered(clock::now() - answer_within_);
  if (watching_) dds_set_log_sink(nullptr, nullptr);
}

void refused_peer_log::start_timer() {
  timer_ = std::thread([this] {
    std::unique_lock lock(mutex_);
    while (!wake_.wait_for(lock, std::chrono::milliseconds(250), [this] { return stopping_; })) {
      say_unanswered(clock::now() - answer_within_);
    }
  });
}

void refused_peer_log::on_event(handshake_event event, std::int64_t peer, std::string_view subject,
                                std::string_view ca_subject, std::string_view detail) {
  std::lock_guard lock(mutex_);
  switch (event) {
    case handshake_event::requested:
      asked_.try_emplace(peer, asked{std::string(subject), std::string(ca_subject), clock::now()});
      if (!timer_.joinable()) start_timer();  // only a process that asks has answers to await
      break;
    case handshake_event::authenticated:
      asked_.erase(peer);
      break;
    case handshake_event::failed: {
      asked_.erase(peer);
      // Cyclone: "Certificate not valid: error: REASON; subject: SUBJECT"
      std::string_view reason = detail;
      if (reason.starts_with("Certificate not valid: error: ")) reason.remove_prefix(30);
      if (const auto at = reason.find("; subject: "); at != std::string_view::npos) {
        subject = reason.substr(at + 11);
        reason = reason.substr(0, at);
      }
      say(peer, "refused peer " + named(subject) + ": " + std::string(reason) +
                    " (DDS Security handshake)");
      break;
    }
    case handshake_event::ended:
      // the peer left (or its run gave up) before it answered; one that leaves sooner than it
      // had to answer may just have been quick (a `stride workers` listing)
      if (const auto it = asked_.find(peer); it != asked_.end()) {
        if (clock::now() - it->second.since >= answer_within_) unanswered(peer, it->second);
        asked_.erase(it);
      }
      break;
  }
}

void refused_peer_log::check_unanswered(clock::time_point now) {
  std::lock_guard lock(mutex_);
  say_unanswered(now - answer_within_);
}

void refused_peer_log::say_unanswered(clock::time_point asked_before) {
  for (auto it = asked_.begin(); it != asked_.end();) {
    if (it->second.since > asked_before) {
      ++it;
      continue;
    }
    unanswered(it->first, it->second);
    it = asked_.erase(it);
  }
}

void refused_peer_log::unanswered(std::int64_t peer, const asked& a) {
  const std::string ca = a.ca_subject.empty() ? "" : " (its CA: " + a.ca_subject + ")";
  say(peer, "refused peer " + named(a.subject) + ca +
                ": it did not answer the DDS Security handshake, so it does not trust this "
                "identity (identities trust each other only when they come from one keystore)");
}

void refused_peer_log::say(std::int64_t peer, const std::string& line) {
  if (!said_.insert(peer).second) return;
  log_(line);
}

}  // namespace stride::remote
