#include "client.hpp"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <random>
#include <stdexcept>
#include <thread>

#include "stride/cosim/deferred_work.hpp"
#include "stride/cosim/error.hpp"
#include "stride/remote/identity.hpp"

namespace stride::remote {

namespace {

// a run id no other run on the network will have: host, process and 64 random bits
std::string new_run_id() {
  char host[64] = {};
  ::gethostname(host, sizeof host - 1);
  std::random_device rd;
  const std::uint64_t r = (std::uint64_t{rd()} << 32) ^ rd();
  char buf[160];
  std::snprintf(buf, sizeof buf, "%s-%ld-%016llx", host, static_cast<long>(::getpid()),
                static_cast<unsigned long long>(r));
  return buf;
}

reply_data copy_reply(const stride_remote_reply& r) {
  reply_data out;
  out.result = static_cast<status>(r.status);
  out.message = r.message != nullptr ? r.message : "";
  copy_values(r.data, out.values);
  out.blob = get_blob(r.blob);
  for (std::uint32_t i = 0; i < r.log._length; ++i) {
    const auto& l = r.log._buffer[i];
    const int level = std::clamp(l.level, 0, static_cast<int>(cosim::log_level::error));
    out.log.push_back({static_cast<cosim::log_level>(level), l.source ? l.source : "",
                       l.category ? l.category : "", l.message ? l.message : ""});
  }
  out.outputs.resize(r.outputs._length);
  for (std::uint32_t i = 0; i < r.outputs._length; ++i)
    copy_values(r.outputs._buffer[i], out.outputs[i]);
  out.ended = r.ended;
  out.busy = std::chrono::nanoseconds(r.busy_ns);
  return out;
}

}  // namespace

client::client(const dds_settings& settings, const timeouts& limits)
    : settings_(settings),
      limits_(limits),
      run_(new_run_id()),
      participant_(dds::make_participant(settings)),
      topics_(participant_.get()) {
  dds_qos_t* qos = dds::announcement_qos(std::chrono::milliseconds(0));
  announcements_ = dds::entity(
      dds::check(dds_create_reader(participant_.get(), topics_.worker_info.get(), qos, nullptr),
                 "worker announcements reader"));
  dds_delete_qos(qos);
  reply_subscriber_ = dds::make_subscriber(participant_.get(), run_partition(run_));
  qos = dds::reliable_qos();
  // replies are handed over on DDS's receive thread: one thread switch less per call than a
  // waitset
  dds_listener_t* listener = dds_create_listener(this);
  dds_lset_data_available_arg(
      listener, [](dds_entity_t, void* self) { static_cast<client*>(self)->take_replies(); }, this,
      true);
  replies_ = dds::entity(
      dds::check(dds_create_reader(reply_subscriber_.get(), topics_.reply.get(), qos, listener),
                 "reply reader"));
  dds_delete_listener(listener);
  dds_delete_qos(qos);
}

client::~client() {
  stride_remote_request r{};
  r.op = static_cast<std::int32_t>(op::end_run);
  r.run = const_cast<char*>(run_.c_str());
  r.component = const_cast<char*>("");
  r.text = const_cast<char*>("");
  for (auto& [name, endpoints] : workers_) {
    r.seq = ++next_seq_;
    dds_write(endpoints.second.get(), &r);  // best effort: the writer lingers until delivered
  }
  replies_.reset();  // no listener call after this
}

dds_instance_handle_t client::announcement_of(const std::string& worker) {
  dds_instance_handle_t writer = 0;
  dds::read_all<stride_remote_worker_info>(
      announcements_.get(), [&](const stride_remote_worker_info& w, const dds_sample_info_t& i) {
        if (i.valid_data && w.name != nullptr && worker == w.name &&
            i.instance_state == DDS_IST_ALIVE) {
          writer = i.publication_handle;
        }
      });
  return writer;
}

bool client::alive(const std::string& worker) {
  return announcement_of(worker) != 0;
}

dds_entity_t client::connect(const std::string& worker) {
  if (const auto it = workers_.find(worker); it != workers_.end()) return it->second.second.get();
  using clock = std::chrono::steady_clock;
  const auto until = clock::now() + limits_.connect;
  const auto seconds = std::to_string(limits_.connect.count() / 1000.0);
  while (announcement_of(worker) == 0) {
    if (clock::now() >= until) {
      // a worker behind DDS Security is invisible to a run it does not trust, and the other way
      const std::filesystem::path identity = effective_identity(settings_);
      const std::string security =
          identity.empty()
              ? "; a worker with --security is out of reach of a run without it"
              : "; a worker is out of reach of this run's identity " + identity.string() +
                    " unless its own comes from the same keystore, the one whose CA is " +
                    identity_files{identity}.identity_ca().string() +
                    " (give the worker one: `stride security add " +
                    identity.parent_path().string() + " " + worker + "`)";
      throw std::runtime_error("worker '" + worker + "' did not appear on DDS domain " +
                               std::to_string(settings_.domain) + " within " +
                               seconds.substr(0, seconds.find('.') + 2) +
                               " s (start it with `stride worker --name " + worker + " --domain " +
                               std::to_string(settings_.domain) + "`" + security + ")");
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  dds::entity publisher = dds::make_publisher(participant_.get(), worker_partition(worker));
  dds_qos_t* qos = dds::reliable_qos();
  dds::entity writer(
      dds::check(dds_create_writer(publisher.get(), topics_.request.get(), qos, nullptr),
                 "request writer for worker '" + worker + "'"));
  dds_delete_qos(qos);
  const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(until - clock::now());
  if (!dds::wait_for_reader(writer.get(), std::max(left, std::chrono::milliseconds(1000)))) {
    throw std::runtime_error("worker '" + worker + "' is announced on DDS domain " +
                             std::to_string(settings_.domain) + " but does not take requests");
  }
  // Requests sent before the worker's reader has matched this writer, and replies sent before
  // the run's reply writer on the worker has matched our reader, are lost (volatile data): a
  // hello is repeated until one is answered, and then both directions are open.
  for (auto wait = std::chrono::milliseconds(2);; wait = std::min(2 * wait, limits_.poll)) {
    stride_remote_request hello{};
    hello.op = static_cast<std::int32_t>(op::hello);
    hello.component = const_cast<char*>("");
    hello.text = const_cast<char*>("");
    const std::uint64_t seen = arrivals_.load(std::memory_order_acquire);
    const std::uint64_t seq = send(writer.get(), worker, hello);
    if (wait_reply(seq, seen, worker, clock::now() + wait)) break;
    if (clock::now() >= until + std::chrono::milliseconds(1000)) {
      throw std::runtime_error("worker '" + worker + "' is announced on DDS domain " +
                               std::to_string(settings_.domain) + " but does not answer");
    }
  }
  const dds_entity_t w = writer.get();
  workers_.emplace(worker, std::make_pair(std::move(publisher), std::move(writer)));
  return w;
}

void client::take_replies() {
  std::map<std::uint64_t, reply_data> got;
  dds::take_all<stride_remote_reply>(replies_.get(),
                                     [&](const stride_remote_reply& r, const dds_sample_info_t&) {
                                       // the partition keeps other runs out; the check keeps out a
                                       // run with a reused name
                                       if (r.run != nullptr && run_ == r.run)
                                         got.emplace(r.seq, copy_reply(r));
                                     });
  if (got.empty()) return;
  std::lock_guard lock(mutex_);
  for (auto it = got.begin(); it != got.end();) {
    it = abandoned_.erase(it->first) > 0 ? got.erase(it) : std::next(it);
  }
  arrived_.merge(got);
  arrivals_.fetch_add(1, std::memory_order_release);
  arrived_cv_.notify_all();
}

reply_data client::call_for(const std::string& who, dds_entity_t writer, const std::string& worker,
                            stride_remote_request& r,
                            const std::function<void(const reply_data::log_line&)>& forward) {
  // the algorithm adds the simulated time of a failed step
  const std::string where = who + ": " + to_string(static_cast<op>(r.op)) + ": ";
  reply_data reply;
  try {
    reply = call(writer, worker, r);
  } catch (const worker_lost& e) {
    throw worker_lost(where + e.what());
  } catch (const std::exception& e) {
    throw cosim::component_error(where + e.what());
  }
  for (const auto& l : reply.log) forward(l);
  if (reply.network >= limits_.stall) {
    // a bad network, not a lost worker: the run goes on, but it is told (docs/failover.md)
    ++stalls_;
    char late[32];
    std::snprintf(late, sizeof late, "%.2f", std::chrono::duration<double>(reply.network).count());
    forward({cosim::log_level::warning, "", "network",
             "the network held up the reply of worker '" + worker + "' to '" +
                 to_string(static_cast<op>(r.op)) + "' for " + late +
                 " s (a stall shorter than the lease; the run goes on unchanged)"});
  }
  if (reply.result == status::error) throw cosim::component_error(where + reply.message);
  return reply;
}

std::uint64_t client::send(dds_entity_t writer, const std::string& worker,
                           stride_remote_request& r) {
  r.run = const_cast<char*>(run_.c_str());
  r.seq = ++next_seq_;
  dds::check(dds_write(writer, &r), "request to worker '" + worker + "'");
  return r.seq;
}

std::optional<reply_data> client::wait_reply(
    std::uint64_t seq, std::uint64_t seen, const std::string& worker,
    std::optional<std::chrono::steady_clock::time_point> until) {
  // a short step's reply comes back within tens of microseconds: watching for it saves the
  // wake-up of a sleeping thread, which costs as much again on a virtual machine
  const auto spin_until = std::chrono::steady_clock::now() + limits_.spin;
  while (arrivals_.load(std::memory_order_acquire) == seen &&
         std::chrono::steady_clock::now() < spin_until) {
    // the reply is delivered by a DDS thread of this process: let it have the core
    std::this_thread::yield();
  }
  std::unique_lock lock(mutex_);
  for (;;) {
    if (const auto it = arrived_.find(seq); it != arrived_.end()) {
      reply_data out = std::move(it->second);
      arrived_.erase(it);
      return out;
    }
    const auto wake = until ? std::min(*until, std::chrono::steady_clock::now() + limits_.poll)
                            : std::chrono::steady_clock::now() + limits_.poll;
    if (arrived_cv_.wait_until(lock, wake) == std::cv_status::timeout &&
        arrived_.find(seq) == arrived_.end()) {
      lock.unlock();
      // a reply the listener has not passed on (should DDS not call it again for samples that
      // arrive while it runs) is taken here, at the latest one poll later
      take_replies();
      const bool still_there = alive(worker);
      lock.lock();
      if (arrived_.find(seq) != arrived_.end()) continue;
      if (!still_there) {
        abandoned_.insert(seq);  // should the worker come back and answer, it is dropped
        throw worker_lost("worker '" + worker + "' is gone (its liveliness on DDS domain " +
                          std::to_string(settings_.domain) + " lapsed)");
      }
      if (until && std::chrono::steady_clock::now() >= *until) {
        abandoned_.insert(seq);  // should it come after all, it is dropped
        return std::nullopt;
      }
    }
  }
}

reply_data client::call(dds_entity_t writer, const std::string& worker, stride_remote_request& r) {
  const std::uint64_t seen = arrivals_.load(std::memory_order_acquire);
  const auto sent = std::chrono::steady_clock::now();
  const std::uint64_t seq = send(writer, worker, r);
  // the reply takes tens of microseconds at least: time for what the run left to do (a row of
  // its results to format), which then costs it nothing
  cosim::run_deferred_work();
  reply_data reply = *wait_reply(seq, seen, worker, std::nullopt);
  reply.network = std::chrono::steady_clock::now() - sent - reply.busy;
  return reply;
}

}  // namespace stride::remote
