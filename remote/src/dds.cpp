#include "dds.hpp"

#include <cstdlib>
#include <map>
#include <mutex>
#include <stdexcept>
#include <thread>

#include "dds_security.hpp"

namespace stride::remote::dds {

namespace fs = std::filesystem;

dds_return_t check(dds_return_t rc, const std::string& what) {
  if (rc < 0) throw std::runtime_error(what + ": " + dds_strretcode(rc));
  return rc;
}

namespace {

// the configuration text and identity each domain of this process was set up with
struct domain_setup {
  std::string config;
  fs::path identity;
};
std::mutex g_domains_mutex;
std::map<int, domain_setup> g_domains;

std::string config_text(const dds_settings& s) {
  if (!s.config_file.empty()) {
    if (!fs::is_regular_file(s.config_file)) {
      throw std::runtime_error("DDS configuration " + s.config_file.string() + " not found");
    }
    return "file://" + fs::absolute(s.config_file).string();
  }
  if (const char* uri = std::getenv("CYCLONEDDS_URI"); uri != nullptr && *uri != '\0') return {};
  return loopback_config();
}

}  // namespace

namespace {

// sets the domain up with the settings' configuration, once per process
void set_up_domain(const dds_settings& settings, const fs::path& identity) {
  const std::string config = config_text(settings);
  std::lock_guard lock(g_domains_mutex);
  const auto it = g_domains.find(settings.domain);
  if (it != g_domains.end()) {
    if (it->second.config != config) {
      throw std::runtime_error("DDS domain " + std::to_string(settings.domain) +
                               " is already set up with another configuration in this process");
    }
    if (it->second.identity != identity) {
      throw std::runtime_error("DDS domain " + std::to_string(settings.domain) +
                               " is already joined with another security identity in this "
                               "process");
    }
    return;
  }
  if (!config.empty()) {
    // the domain entity lives as long as the process: participants come and go on it
    const dds_entity_t domain =
        dds_create_domain(static_cast<dds_domainid_t>(settings.domain), config.c_str());
    // Already set up: by the process hosting this code (an FMU that links this layer and runs
    // inside a stride process or worker); its configuration applies.
    if (domain != DDS_RETCODE_PRECONDITION_NOT_MET) {
      check(domain, "cannot set up DDS domain " + std::to_string(settings.domain));
    }
  }
  g_domains[settings.domain] = {config, identity};
}

dds_entity_t create_participant(int domain, const fs::path& identity) {
  if (identity.empty()) {
    return check(dds_create_participant(static_cast<dds_domainid_t>(domain), nullptr, nullptr),
                 "cannot join DDS domain " + std::to_string(domain));
  }
  dds_qos_t* qos = dds_create_qos();
  add_security(qos, identity);
  const dds_entity_t p = dds_create_participant(static_cast<dds_domainid_t>(domain), qos, nullptr);
  dds_delete_qos(qos);
  // Cyclone's log (stderr) has said which file or check failed
  return check(p, "cannot join DDS domain " + std::to_string(domain) +
                      " with the security identity " + identity.string() +
                      " (see the DDS messages above and `stride security show " +
                      identity.string() + "`)");
}

}  // namespace

entity make_participant(const dds_settings& settings) {
  if (settings.domain < 0 || settings.domain > 230) {
    // the port numbers Cyclone derives from the domain run out above 232
    throw std::runtime_error("DDS domain " + std::to_string(settings.domain) +
                             " is out of range (0..230)");
  }
  const fs::path identity = effective_identity(settings);
  if (!identity.empty()) {
    // before this process touches the domain: with a bad identity it joins nothing at all
    check_security_files(identity);
    check_identity(identity, settings.domain);
  }
  set_up_domain(settings, identity);
  // One participant per process and domain, found through DDS so that FMUs linking their own copy
  // of this layer share it too: a pair of processes then makes one DDS Security handshake, and
  // Cyclone 0.10's security plugins leak memory on every message when a process has several
  // secure participants (RELIABILITY.md).
  static std::mutex creating;
  std::lock_guard lock(creating);
  dds_entity_t existing[1] = {};
  if (dds_lookup_participant(static_cast<dds_domainid_t>(settings.domain), existing, 1) > 0) {
    return entity::borrowed(existing[0]);
  }
  return entity::borrowed(create_participant(settings.domain, identity));
}

}  // namespace stride::remote::dds

void stride::remote::close_dds() {
  {
    std::lock_guard lock(dds::g_domains_mutex);
    if (dds::g_domains.empty()) return;  // DDS never started here
    dds::g_domains.clear();
  }
  dds_delete(DDS_CYCLONEDDS_HANDLE);
}

namespace stride::remote::dds {

dds_qos_t* reliable_qos() {
  dds_qos_t* qos = dds_create_qos();
  dds_qset_reliability(qos, DDS_RELIABILITY_RELIABLE, DDS_SECS(10));
  dds_qset_history(qos, DDS_HISTORY_KEEP_ALL, 0);
  return qos;
}

dds_qos_t* announcement_qos(std::chrono::milliseconds lease) {
  dds_qos_t* qos = dds_create_qos();
  dds_qset_reliability(qos, DDS_RELIABILITY_RELIABLE, DDS_SECS(1));
  dds_qset_durability(qos, DDS_DURABILITY_TRANSIENT_LOCAL);
  dds_qset_history(qos, DDS_HISTORY_KEEP_LAST, 1);
  if (lease.count() > 0)
    dds_qset_liveliness(qos, DDS_LIVELINESS_AUTOMATIC, DDS_MSECS(lease.count()));
  return qos;
}

namespace {

// a publisher or subscriber (made by `create`) whose QoS names one partition
template <class Create>
entity partitioned(dds_entity_t participant, const std::string& partition, Create create,
                   const char* what) {
  dds_qos_t* qos = dds_create_qos();
  dds_qset_partition1(qos, partition.c_str());
  const dds_entity_t e = create(participant, qos, nullptr);
  dds_delete_qos(qos);
  return entity(check(e, std::string(what) + " for partition " + partition));
}

}  // namespace

entity make_publisher(dds_entity_t participant, const std::string& partition) {
  return partitioned(participant, partition, dds_create_publisher, "publisher");
}

entity make_subscriber(dds_entity_t participant, const std::string& partition) {
  return partitioned(participant, partition, dds_create_subscriber, "subscriber");
}

bool wait_for_reader(dds_entity_t writer, std::chrono::milliseconds timeout) {
  const auto until = std::chrono::steady_clock::now() + timeout;
  for (;;) {
    dds_publication_matched_status_t st{};
    check(dds_get_publication_matched_status(writer, &st), "publication status");
    if (st.current_count > 0) return true;
    if (std::chrono::steady_clock::now() >= until) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
}

}  // namespace stride::remote::dds
