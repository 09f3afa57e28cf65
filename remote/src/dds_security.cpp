#include "dds_security.hpp"

#include <dlfcn.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <stdexcept>
#include <string>

#include "stride/remote/identity.hpp"

namespace stride::remote::dds {

namespace fs = std::filesystem;

std::string plugin_path(const char* name) {
  const std::string file = std::string("lib") + name + ".so";
  Dl_info info{};
  if (dladdr(reinterpret_cast<void*>(&dds_create_participant), &info) != 0 &&
      info.dli_fname != nullptr) {
    const fs::path lib_dir = fs::path(info.dli_fname).parent_path();
    for (const fs::path& candidate : {lib_dir / "libddsc0debian" / file, lib_dir / file}) {
      if (fs::is_regular_file(candidate)) return candidate.string();
    }
  }
  return name;  // Cyclone then asks the loader for lib<name>.so
}

namespace {

// The wrapper plugin, once watch_handshakes found it, and the listener it is to get: the plugin
// is loaded with the first secure participant, so that a process without security never loads
// it (under LeakSanitizer, its mere presence made the leak check crash in a run of threads).
std::string g_auth_watch;
stride_handshake_listener g_listener = nullptr;
void* g_listener_context = nullptr;
using watch_fn = void (*)(const char*, stride_handshake_listener, void*);
std::atomic<watch_fn> g_set_listener{nullptr};  // set once loaded; read by DDS's threads (log sink)

// loads the wrapper and hands it the listener; false leaves Cyclone's plugin in charge, and a
// wrapper that cannot be loaded is not tried again
bool load_auth_watch() {
  if (g_set_listener != nullptr) return true;
  if (g_auth_watch.empty()) return false;
  // Cyclone's dlopen of the same path later finds this very copy, with the listener set
  void* handle = ::dlopen(g_auth_watch.c_str(), RTLD_NOW | RTLD_LOCAL);
  const auto watch = handle == nullptr
                         ? nullptr
                         : reinterpret_cast<watch_fn>(::dlsym(handle, "stride_watch_handshakes"));
  if (watch == nullptr) {
    g_auth_watch.clear();
    return false;
  }
  watch(plugin_path("dds_security_auth").c_str(), g_listener, g_listener_context);
  g_set_listener = watch;
  return true;
}

fs::path auth_watch_library() {
  std::error_code error;
  const fs::path program = fs::read_symlink("/proc/self/exe", error);
  if (error) return {};
  const char* file = "libstride_dds_auth.so";
  for (const fs::path& dir :
       {program.parent_path() / ".." / "lib" / "stride", program.parent_path()}) {
    if (fs::is_regular_file(dir / file, error)) return (dir / file).lexically_normal();
  }
  return {};
}

void check_readable(const fs::path& file, const fs::path& dir) {
  if (!fs::exists(file)) {
    throw std::runtime_error("security identity " + dir.string() + ": " + file.string() +
                             " is missing (make the identity with `stride security add KEYSTORE "
                             "NAME`)");
  }
  // opened, not only asked about: a folder in a file's place passes access() even for root
  std::ifstream in(file, std::ios::binary);
  if (!fs::is_regular_file(file) || !in || in.peek() == std::ifstream::traits_type::eof()) {
    throw std::runtime_error("security identity " + dir.string() + ": " + file.string() +
                             " is not a readable, non-empty file for this user (make the "
                             "identity again with `stride security add KEYSTORE NAME`)");
  }
}

void check_private(const fs::path& key) {
  struct stat st {};
  if (::stat(key.c_str(), &st) != 0) return;  // check_readable has said why
  if ((st.st_mode & 077) != 0) {
    char mode[8];
    std::snprintf(mode, sizeof mode, "%04o", static_cast<unsigned>(st.st_mode & 07777));
    throw std::runtime_error("private key " + key.string() + " is readable by others (mode " +
                             mode + "): run `chmod 600 " + key.string() + "`");
  }
}

std::string file_uri(const fs::path& p) {
  return "file:" + fs::absolute(p).lexically_normal().string();
}

}  // namespace

void check_security_files(const fs::path& dir) {
  if (!fs::is_directory(dir)) {
    throw std::runtime_error("security identity " + dir.string() +
                             " is not a folder (make one with `stride security add KEYSTORE "
                             "NAME`)");
  }
  const identity_files id{dir};
  for (const fs::path& f : id.all()) check_readable(f, dir);
  check_private(id.private_key());
}

void add_security(dds_qos_t* qos, const fs::path& dir) {
  const identity_files id{dir};
  const struct {
    const char* kind;
    const char* library;
    const char* init;
    const char* finalize;
  } plugins[] = {
      {"auth", "dds_security_auth", "init_authentication", "finalize_authentication"},
      {"crypto", "dds_security_crypto", "init_crypto", "finalize_crypto"},
      {"access", "dds_security_ac", "init_access_control", "finalize_access_control"},
  };
  for (const auto& p : plugins) {
    const std::string prefix = std::string("dds.sec.") + p.kind + ".library.";
    dds_qset_prop(qos, (prefix + "path").c_str(), plugin_path(p.library).c_str());
    dds_qset_prop(qos, (prefix + "init").c_str(), p.init);
    dds_qset_prop(qos, (prefix + "finalize").c_str(), p.finalize);
  }
  if (g_listener != nullptr && load_auth_watch()) {  // it loads Cyclone's plugin itself
    dds_qset_prop(qos, "dds.sec.auth.library.path", g_auth_watch.c_str());
    dds_qset_prop(qos, "dds.sec.auth.library.init", "stride_init_authentication");
    dds_qset_prop(qos, "dds.sec.auth.library.finalize", "stride_finalize_authentication");
  }
  dds_qset_prop(qos, "dds.sec.auth.identity_ca", file_uri(id.identity_ca()).c_str());
  dds_qset_prop(qos, "dds.sec.auth.identity_certificate", file_uri(id.certificate()).c_str());
  dds_qset_prop(qos, "dds.sec.auth.private_key", file_uri(id.private_key()).c_str());
  dds_qset_prop(qos, "dds.sec.access.permissions_ca", file_uri(id.permissions_ca()).c_str());
  dds_qset_prop(qos, "dds.sec.access.governance", file_uri(id.governance()).c_str());
  dds_qset_prop(qos, "dds.sec.access.permissions", file_uri(id.permissions()).c_str());
}

bool watch_handshakes(stride_handshake_listener listener, void* context) {
  return watch_handshakes_through(auth_watch_library(), listener, context);
}

bool watch_handshakes_through(const fs::path& library, stride_handshake_listener listener,
                              void* context) {
  if (library.empty()) return false;
  g_auth_watch = library.string();
  g_listener = listener;
  g_listener_context = context;
  return true;
}

bool handshakes_watched() {
  return g_set_listener != nullptr;
}

void stop_watching_handshakes() {
  g_listener = nullptr;
  if (const watch_fn set = g_set_listener; set != nullptr) {
    set(plugin_path("dds_security_auth").c_str(), nullptr, nullptr);
  }
}

}  // namespace stride::remote::dds

namespace stride::remote {

namespace {
std::atomic<identity_check> g_identity_check{nullptr};
}  // namespace

void set_identity_check(identity_check check) {
  g_identity_check.store(check);
}

void dds::check_identity(const std::filesystem::path& identity, int domain) {
  if (const identity_check check = g_identity_check.load()) check(identity, domain);
}

std::filesystem::path effective_identity(const dds_settings& settings) {
  std::filesystem::path p = settings.security;
  if (p.empty()) {
    const char* env = std::getenv(k_security_env);
    if (env == nullptr || *env == '\0') return {};
    p = env;
  }
  return std::filesystem::absolute(p).lexically_normal();  // one spelling per identity
}

}  // namespace stride::remote
