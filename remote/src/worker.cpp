#include "stride/remote/worker.hpp"

#include <unistd.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <fstream>
#include <map>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <thread>

#include "dds.hpp"
#include "hosted.hpp"
#include "me_wire.hpp"
#include "protocol.hpp"
#include "stride/common/files.hpp"
#include "stride/cosim/archive.hpp"
#include "stride/cosim/run.hpp"
#include "stride/remote/refused_peers.hpp"

namespace stride::remote {

namespace fs = std::filesystem;

namespace {

constexpr auto k_liveliness_lease = std::chrono::milliseconds(1000);
constexpr auto k_poll = std::chrono::milliseconds(100);
constexpr auto k_watch = std::chrono::microseconds(500);

std::string host_name() {
  char host[256] = {};
  ::gethostname(host, sizeof host - 1);
  return host;
}

std::string worker_name(const worker_options& o) {
  return o.name.empty() ? host_name() + "-" + std::to_string(::getpid()) : o.name;
}

std::vector<worker_description> read_announcements(dds_entity_t reader) {
  std::vector<worker_description> out;
  dds::read_all<stride_remote_worker_info>(reader, [&](const stride_remote_worker_info& w,
                                                       const dds_sample_info_t& i) {
    if (!i.valid_data || i.instance_state != DDS_IST_ALIVE) return;
    out.push_back({w.name ? w.name : "", w.host ? w.host : "", w.pid, w.version ? w.version : ""});
  });
  return out;
}

using instance = hosted_instance;

// what the worker keeps for one run: its instances and step groups, and whose requests they are
struct run_state {
  dds_instance_handle_t orchestrator = 0;  // the request writer of the run's orchestrator
  std::uint64_t requests = 0;              // served so far: reported when the run ends
  // the run's own reply writer, in the run's partition: a run that stops acknowledging (its
  // orchestrator gone) never holds up the replies of another
  dds::entity reply_publisher;
  dds::entity replies;
  std::map<std::string, instance> instances;
  std::map<std::string, hosted_group> groups;  // by group name; refer to instances: go first
};

class host {
 public:
  explicit host(const worker_options& o)
      : options_(o),
        name_(worker_name(o)),
        participant_(dds::make_participant(o.dds)),
        topics_(participant_.get()),
        cache_("stride-worker-") {
    check_name_is_free();
    request_subscriber_ = dds::make_subscriber(participant_.get(), worker_partition(name_));
    dds_qos_t* qos = dds::reliable_qos();
    // DDS's receive thread only signals: a reply written on it could block on a full history
    // that only the same thread can drain (by taking the acknowledgements in)
    dds_listener_t* listener = dds_create_listener(this);
    dds_lset_data_available_arg(
        listener, [](dds_entity_t, void* self) { static_cast<host*>(self)->signal_requests(); },
        this, true);
    requests_ = dds::entity(dds::check(
        dds_create_reader(request_subscriber_.get(), topics_.request.get(), qos, listener),
        "request reader"));
    dds_delete_listener(listener);
    dds_delete_qos(qos);
    qos = dds::announcement_qos(k_liveliness_lease);
    announcer_ = dds::entity(
        dds::check(dds_create_writer(participant_.get(), topics_.worker_info.get(), qos, nullptr),
                   "announcement writer"));
    dds_delete_qos(qos);
    const std::string h = host_name();
    const std::string version(cosim::version());
    stride_remote_worker_info info{const_cast<char*>(name_.c_str()), const_cast<char*>(h.c_str()),
                                   static_cast<std::int64_t>(::getpid()),
                                   const_cast<char*>(version.c_str())};
    dds::check(dds_write(announcer_.get(), &info), "announcement");
  }

  const std::string& name() const { return name_; }

  ~host() { requests_.reset(); }  // no listener call after this

  // Serves requests on a thread of its own until `stop`; this thread tidies up.
  void serve(const std::atomic<bool>& stop) {
    std::thread server([&] { serve_requests(stop); });
    while (!stop.load()) {
      std::this_thread::sleep_for(k_poll);
      std::lock_guard lock(mutex_);
      drop_vanished_runs();
      ended_.clear();
    }
    signal_requests();
    server.join();
  }

 private:
  void signal_requests() {
    {
      std::lock_guard lock(signal_mutex_);  // a server about to sleep sees it or is woken
      signals_.fetch_add(1, std::memory_order_release);
    }
    signal_cv_.notify_one();
  }

  // The next request usually follows within tens of microseconds of a reply: the server watches
  // for it for a while before it sleeps, since a wake-up costs about as much as the round trip.
  // It also takes requests every poll, should a signal go missing.
  void serve_requests(const std::atomic<bool>& stop) {
    std::uint64_t served = 0;
    while (!stop.load()) {
      const auto watch_until = std::chrono::steady_clock::now() + k_watch;
      while (signals_.load(std::memory_order_acquire) == served &&
             std::chrono::steady_clock::now() < watch_until) {
        std::this_thread::yield();
      }
      {
        std::unique_lock lock(signal_mutex_);
        signal_cv_.wait_for(lock, k_poll, [&] { return signals_.load() != served || stop.load(); });
        served = signals_.load();
      }
      take_requests();
    }
  }

  void take_requests() {
    std::lock_guard lock(mutex_);
    dds::take_all<stride_remote_request>(
        requests_.get(),
        [&](const stride_remote_request& r, const dds_sample_info_t& i) { handle(r, i); });
  }

  void check_name_is_free() {
    dds_qos_t* qos = dds::announcement_qos(std::chrono::milliseconds(0));
    dds::entity reader(
        dds::check(dds_create_reader(participant_.get(), topics_.worker_info.get(), qos, nullptr),
                   "announcement reader"));
    dds_delete_qos(qos);
    // announcements of workers already there arrive within discovery (milliseconds here)
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    for (const auto& w : read_announcements(reader.get())) {
      if (w.name == name_) {
        throw std::runtime_error("a worker named '" + name_ + "' is already on DDS domain " +
                                 std::to_string(options_.dds.domain) + " (host " + w.host +
                                 ", pid " + std::to_string(w.pid) + ")");
      }
    }
  }

  void log(const std::string& line) {
    if (options_.log == nullptr) return;
    std::fprintf(options_.log, "worker %s: %s\n", name_.c_str(), line.c_str());
    std::fflush(options_.log);
  }

  run_state& run_for(const std::string& id, dds_instance_handle_t orchestrator) {
    const auto [it, fresh] = runs_.try_emplace(id);
    if (fresh) {
      run_state& rs = it->second;
      rs.orchestrator = orchestrator;
      rs.reply_publisher = dds::make_publisher(participant_.get(), run_partition(id));
      dds_qos_t* qos = dds::reliable_qos();
      rs.replies = dds::entity(
          dds::check(dds_create_writer(rs.reply_publisher.get(), topics_.reply.get(), qos, nullptr),
                     "reply writer for run " + id));
      dds_delete_qos(qos);
      log("run " + id + " begins");
    }
    return it->second;
  }

  void end_run(const std::string& id, const char* why) {
    const auto it = runs_.find(id);
    if (it == runs_.end()) return;
    log("run " + id + " ends (" + why + "; " + std::to_string(it->second.requests) + " requests)");
    // DDS entities may not be deleted from a listener: the main thread deletes the run's writer
    ended_.push_back(std::move(it->second));
    runs_.erase(it);
  }

  // a run whose orchestrator went away without saying so: its instances go
  void drop_vanished_runs() {
    dds_instance_handle_t handles[256];
    const dds_return_t n = dds_get_matched_publications(requests_.get(), handles, 256);
    for (auto it = runs_.begin(); it != runs_.end();) {
      bool present = false;
      for (dds_return_t i = 0; i < n && i < 256; ++i)
        present |= handles[i] == it->second.orchestrator;
      if (present) {
        ++it;
      } else {
        log("run " + it->first + " ends (its orchestrator is gone; " +
            std::to_string(it->second.requests) + " requests)");
        it = runs_.erase(it);
      }
    }
  }

  instance& find(run_state& rs, const char* component) {
    const auto it = rs.instances.find(component);
    if (it == rs.instances.end()) {
      throw std::runtime_error(std::string("no instance '") + component + "' on this worker");
    }
    return it->second;
  }

  // loads a shipped archive (or says it needs it)
  status load(const stride_remote_request& r) {
    const std::string hash = r.text != nullptr ? r.text : "";
    if (options_.allowed_fmus && options_.allowed_fmus->count(hash) == 0) {
      log("run " + std::string(r.run != nullptr ? r.run : "") + ": refused FMU " + hash +
          " for component '" + (r.component != nullptr ? r.component : "") +
          "': not on the allow-list");
      throw std::runtime_error("the FMU archive with SHA-256 " + hash +
                               " is not on the allow-list of worker '" + name_ +
                               "' (stride worker --allow-fmu)");
    }
    if (fmus_.count(hash) > 0) return status::ok;
    if (r.blob._length == 0) return status::need_archive;
    const std::vector<std::byte> archive = get_blob(r.blob);
    if (content_hash(archive) != hash) {
      throw std::runtime_error("the archive does not have the content hash it was sent with");
    }
    const fs::path file = cache_.path() / (hash + ".fmu");
    common::write_file_atomically(
        file, std::string_view(reinterpret_cast<const char*>(archive.data()), archive.size()));
    fmus_[hash] = cosim::fmu::load(file, options_.import);
    log("loaded " + fmus_[hash]->model_description().model_name + " (" + hash.substr(0, 12) + ")");
    return status::ok;
  }

  void handle(const stride_remote_request& r, const dds_sample_info_t& info) {
    const std::string run_id = r.run != nullptr ? r.run : "";
    const auto o = static_cast<op>(r.op);
    if (o == op::end_run) {
      end_run(run_id, "its orchestrator said so");
      return;
    }
    const auto began = std::chrono::steady_clock::now();
    run_state& rs = run_for(run_id, info.publication_handle);
    ++rs.requests;
    stride_remote_reply reply{};
    reply.ended = -1;
    reply.run = r.run;
    reply.seq = r.seq;
    reply.message = const_cast<char*>("");
    std::string message;
    wire_storage storage;
    std::vector<std::byte> blob;
    logged_.clear();
    try {
      reply.status = static_cast<std::int32_t>(serve_one(rs, r, reply, storage, blob));
    } catch (const std::exception& e) {
      message = e.what();
      reply = stride_remote_reply{};
      reply.run = r.run;
      reply.seq = r.seq;
      reply.status = static_cast<std::int32_t>(status::error);
      reply.ended = -1;
      reply.message = message.data();
    }
    std::vector<stride_remote_log_line> lines;
    for (const auto& l : logged_) {
      lines.push_back({static_cast<std::int32_t>(l.level), const_cast<char*>(l.source.c_str()),
                       const_cast<char*>(l.category.c_str()),
                       const_cast<char*>(l.message.c_str())});
    }
    reply.log._length = reply.log._maximum = static_cast<std::uint32_t>(lines.size());
    reply.log._buffer = lines.data();
    reply.log._release = false;
    reply.busy_ns = std::chrono::duration_cast<std::chrono::nanoseconds>(
                        std::chrono::steady_clock::now() - began)
                        .count();
    if (const dds_return_t rc = dds_write(rs.replies.get(), &reply); rc < 0) {
      log("run " + run_id + ": the reply to request " + std::to_string(r.seq) +
          " could not be sent (DDS error " + std::to_string(rc) + ")");
    }
  }

  status serve_one(run_state& rs, const stride_remote_request& r, stride_remote_reply& reply,
                   wire_storage& storage, std::vector<std::byte>& blob) {
    const auto o = static_cast<op>(r.op);
    switch (o) {
      case op::hello:  // the orchestrator's handshake: the run and its reply path now exist
        return status::ok;
      case op::load:
        return load(r);
      case op::instantiate: {
        const auto f = fmus_.find(r.text);
        if (f == fmus_.end()) throw std::runtime_error("no FMU with that content hash is loaded");
        if (rs.instances.count(r.component) > 0) {
          throw std::runtime_error(std::string("instance '") + r.component + "' exists already");
        }
        cosim::instance_options io;
        io.logging_on = r.logging;
        cosim::value_block settings;
        copy_values(r.data, settings);
        io.model_exchange = model_exchange_from_wire(settings);
        // what the component logs goes back with the reply of the request being served
        io.log = [this](cosim::log_level level, std::string_view source, std::string_view category,
                        std::string_view message) {
          logged_.push_back(
              {level, std::string(source), std::string(category), std::string(message)});
        };
        rs.instances[r.component].component = f->second->instantiate(r.component, io);
        return status::ok;
      }
      case op::setup: {
        instance& i = find(rs, r.component);
        std::optional<cosim::time_point> stop;
        if (r.dt_ns >= 0) stop = cosim::time_point(cosim::duration(r.dt_ns));
        i.component->setup(cosim::time_point(cosim::duration(r.t_ns)), stop);
        return status::ok;
      }
      case op::set_values: {
        instance& i = find(rs, r.component);
        const cosim::variable_refs refs = get_refs(r.more);
        cosim::value_block v;
        get_values(r.data, refs, v);
        i.component->set_values(refs, v);
        return status::ok;
      }
      case op::get_values: {
        instance& i = find(rs, r.component);
        const cosim::variable_refs refs = get_refs(r.data);
        i.component->get_values(refs, i.out);
        put_values(i.out, reply.data, storage);
        return status::ok;
      }
      case op::expose: {
        instance& i = find(rs, r.component);
        i.inputs = get_refs(r.data);
        i.outputs = get_refs(r.more);
        i.component->expose(i.inputs, i.outputs);
        i.out.resize_for(i.outputs);
        return status::ok;
      }
      case op::enter_initialization:
        find(rs, r.component).component->enter_initialization();
        return status::ok;
      case op::exit_initialization:
        find(rs, r.component).component->exit_initialization();
        return status::ok;
      case op::step: {
        instance& i = find(rs, r.component);
        get_values(r.data, i.inputs, i.in);
        const auto result = i.component->step(cosim::time_point(cosim::duration(r.t_ns)),
                                              cosim::duration(r.dt_ns), i.in, i.out);
        if (result == cosim::step_result::terminate) return status::terminate;
        put_values(i.out, reply.data, storage);
        return status::ok;
      }
      case op::save_state:
        blob = find(rs, r.component).component->save_state();
        put_blob(blob, reply.blob);
        return status::ok;
      case op::restore_state:
        find(rs, r.component).component->restore_state(get_blob(r.blob));
        return status::ok;
      case op::terminate:
        find(rs, r.component).component->terminate();
        return status::ok;
      case op::free_instance:
        std::erase_if(rs.groups, [&](const auto& g) { return g.second.has_member(r.component); });
        rs.instances.erase(r.component);
        return status::ok;
      case op::group_setup: {
        // a new setup (after a restore) replaces the group
        rs.groups.erase(r.component);
        rs.groups.try_emplace(r.component, r, [&](const std::string& name) -> instance& {
          return find(rs, name.c_str());
        });
        return status::ok;
      }
      case op::group_step: {
        const auto g = rs.groups.find(r.component);
        if (g == rs.groups.end()) {
          throw std::runtime_error(std::string("no step group '") + r.component + "'");
        }
        g->second.step(r, reply);
        return reply.ended >= 0 ? status::terminate : status::ok;
      }
      case op::end_run:
        break;
    }
    throw std::runtime_error("unknown operation " + std::to_string(r.op));
  }

  worker_options options_;
  std::string name_;
  dds::entity participant_;
  topics topics_;
  cosim::temp_dir cache_;  // shipped archives, by content hash
  dds::entity request_subscriber_;
  dds::entity requests_;
  dds::entity announcer_;
  std::mutex mutex_;  // runs_ and fmus_: the server serves, the main thread tidies
  std::mutex signal_mutex_;
  std::condition_variable signal_cv_;
  std::atomic<std::uint64_t> signals_{0};  // data-available signals from DDS so far
  std::map<std::string, std::shared_ptr<cosim::fmu>> fmus_;  // content hash → imported FMU
  std::map<std::string, run_state> runs_;
  std::vector<run_state> ended_;  // runs ended by a request, deleted by the main thread
  struct log_entry {
    cosim::log_level level;
    std::string source;
    std::string category;
    std::string message;
  };
  std::vector<log_entry> logged_;  // by the components, while serving the current request
};

}  // namespace

void serve(const worker_options& options, const std::atomic<bool>& stop) {
  const std::string name = worker_name(options);
  refused_peer_log refused([&](const std::string& line) {
    if (options.log == nullptr) return;
    std::fprintf(options.log, "worker %s: %s\n", name.c_str(), line.c_str());
    std::fflush(options.log);
  });
  host h(options);
  if (options.log != nullptr) {
    std::fprintf(options.log, "worker %s ready on DDS domain %d (pid %ld)\n", h.name().c_str(),
                 options.dds.domain, static_cast<long>(::getpid()));
    std::fflush(options.log);
  }
  h.serve(stop);
}

std::vector<worker_description> visible_workers(const dds_settings& dds,
                                                std::chrono::milliseconds discovery) {
  dds::entity participant = dds::make_participant(dds);
  topics t(participant.get());
  dds_qos_t* qos = dds::announcement_qos(std::chrono::milliseconds(0));
  dds::entity reader(dds::check(
      dds_create_reader(participant.get(), t.worker_info.get(), qos, nullptr), "reader"));
  dds_delete_qos(qos);
  std::this_thread::sleep_for(discovery);
  return read_announcements(reader.get());
}

}  // namespace stride::remote
