// Cyclone DDS's own authentication plugin, with a window on its handshakes (handshake_watch.h).
// Cyclone loads this library as the participant's authentication plugin; it loads the real one,
// keeps the real plugin's object and functions, and replaces only those that begin, decide and
// end a handshake with ones that call the real function and then tell the listener what came of
// it. The rest of the object is the real plugin's, untouched. A peer's handshake is otherwise
// invisible to the side that asked: a peer that refuses it never answers.
#include <dds/security/dds_security_api_authentication.h>
#include <dlfcn.h>

#include <cstdint>
#include <cstdio>
#include <map>
#include <mutex>
#include <string>

#include "handshake_watch.h"

namespace {

struct peer {
  std::string subject;     // of its certificate, when its identity token says it
  std::string ca_subject;  // of its CA, likewise
  std::string guid;        // of its participant, as Cyclone's traces write it
};

struct watch {
  std::mutex mutex;
  std::string real_plugin;
  stride_handshake_listener listener = nullptr;
  void* context = nullptr;
  void* library = nullptr;
  int (*real_finalize)(void*) = nullptr;
  dds_security_authentication real{};               // the real plugin's functions
  std::map<std::int64_t, peer> peers;               // remote identity handle → its certificate
  std::map<std::int64_t, std::int64_t> handshakes;  // handshake handle → remote identity handle
};

// never destroyed: Cyclone may still return handles while the process exits
watch& the_watch() {
  static watch* const w = new watch;
  return *w;
}

std::string property(const DDS_Security_IdentityToken* token, const char* name) {
  if (token == nullptr) return {};
  const DDS_Security_PropertySeq& p = token->properties;
  for (DDS_Security_unsigned_long i = 0; i < p._length; ++i) {
    if (p._buffer[i].name != nullptr && p._buffer[i].value != nullptr &&
        std::string(p._buffer[i].name) == name) {
      return p._buffer[i].value;
    }
  }
  return {};
}

std::string participant(const DDS_Security_GUID_t* guid) {
  if (guid == nullptr) return {};
  const unsigned char* b = guid->prefix;
  char text[64];
  std::snprintf(text, sizeof text,
                "%02x%02x%02x%02x:%02x%02x%02x%02x:%02x%02x%02x%02x:%02x%02x%02x%02x", b[0], b[1],
                b[2], b[3], b[4], b[5], b[6], b[7], b[8], b[9], b[10], b[11],
                guid->entityId.entityKey[0], guid->entityId.entityKey[1],
                guid->entityId.entityKey[2], guid->entityId.entityKind);
  return text;
}

// The listener is called with the lock held, so that stride_watch_handshakes(…, nullptr, …)
// returns only when no call to the listener it replaces is under way.
void tell(stride_handshake_event event, std::int64_t remote, const char* detail) {
  watch& w = the_watch();
  std::lock_guard lock(w.mutex);
  if (w.listener == nullptr) return;
  peer who;
  if (const auto it = w.peers.find(remote); it != w.peers.end()) who = it->second;
  // Cyclone 0.10's identity tokens carry no subject: the participant is then all there is to say
  if (who.subject.empty() && !who.guid.empty()) who.subject = "participant " + who.guid;
  w.listener(w.context, event, remote, who.subject.c_str(), who.ca_subject.c_str(),
             detail != nullptr ? detail : "");
}

std::int64_t remote_of(DDS_Security_HandshakeHandle handshake) {
  watch& w = the_watch();
  std::lock_guard lock(w.mutex);
  const auto it = w.handshakes.find(handshake);
  return it == w.handshakes.end() ? 0 : it->second;
}

void remember(DDS_Security_HandshakeHandle handshake, DDS_Security_IdentityHandle remote) {
  if (handshake == 0) return;
  watch& w = the_watch();
  std::lock_guard lock(w.mutex);
  w.handshakes[handshake] = remote;
}

// what a step of the handshake came to, for the listener
void settle(DDS_Security_ValidationResult_t result, std::int64_t remote,
            const DDS_Security_SecurityException* ex) {
  if (result == DDS_SECURITY_VALIDATION_OK || result == DDS_SECURITY_VALIDATION_OK_FINAL_MESSAGE) {
    tell(STRIDE_HANDSHAKE_AUTHENTICATED, remote, nullptr);
  } else if (result == DDS_SECURITY_VALIDATION_FAILED) {
    tell(STRIDE_HANDSHAKE_FAILED, remote, ex != nullptr ? ex->message : nullptr);
  }
}

DDS_Security_ValidationResult_t validate_remote_identity(
    dds_security_authentication* self, DDS_Security_IdentityHandle* remote_handle,
    DDS_Security_AuthRequestMessageToken* local_request,
    const DDS_Security_AuthRequestMessageToken* remote_request,
    const DDS_Security_IdentityHandle local_handle, const DDS_Security_IdentityToken* remote_token,
    const DDS_Security_GUID_t* remote_guid, DDS_Security_SecurityException* ex) {
  const auto result =
      the_watch().real.validate_remote_identity(self, remote_handle, local_request, remote_request,
                                                local_handle, remote_token, remote_guid, ex);
  if (remote_handle != nullptr && *remote_handle != 0) {
    watch& w = the_watch();
    std::lock_guard lock(w.mutex);
    w.peers[*remote_handle] = {property(remote_token, "dds.cert.sn"),
                               property(remote_token, "dds.ca.sn"), participant(remote_guid)};
  }
  return result;
}

DDS_Security_ValidationResult_t begin_handshake_request(dds_security_authentication* self,
                                                        DDS_Security_HandshakeHandle* handshake,
                                                        DDS_Security_HandshakeMessageToken* message,
                                                        const DDS_Security_IdentityHandle initiator,
                                                        const DDS_Security_IdentityHandle replier,
                                                        const DDS_Security_OctetSeq* local_data,
                                                        DDS_Security_SecurityException* ex) {
  const auto result = the_watch().real.begin_handshake_request(self, handshake, message, initiator,
                                                               replier, local_data, ex);
  if (result == DDS_SECURITY_VALIDATION_PENDING_HANDSHAKE_MESSAGE && handshake != nullptr) {
    remember(*handshake, replier);
    tell(STRIDE_HANDSHAKE_REQUESTED, replier, nullptr);
  } else {
    settle(result, replier, ex);
  }
  return result;
}

DDS_Security_ValidationResult_t begin_handshake_reply(
    dds_security_authentication* self, DDS_Security_HandshakeHandle* handshake,
    DDS_Security_HandshakeMessageToken* out, const DDS_Security_HandshakeMessageToken* in,
    const DDS_Security_IdentityHandle initiator, const DDS_Security_IdentityHandle replier,
    const DDS_Security_OctetSeq* local_data, DDS_Security_SecurityException* ex) {
  const auto result = the_watch().real.begin_handshake_reply(self, handshake, out, in, initiator,
                                                             replier, local_data, ex);
  if (handshake != nullptr) remember(*handshake, initiator);
  settle(result, initiator, ex);
  return result;
}

DDS_Security_ValidationResult_t process_handshake(dds_security_authentication* self,
                                                  DDS_Security_HandshakeMessageToken* out,
                                                  const DDS_Security_HandshakeMessageToken* in,
                                                  const DDS_Security_HandshakeHandle handshake,
                                                  DDS_Security_SecurityException* ex) {
  const auto result = the_watch().real.process_handshake(self, out, in, handshake, ex);
  settle(result, remote_of(handshake), ex);
  return result;
}

DDS_Security_boolean return_handshake_handle(dds_security_authentication* self,
                                             const DDS_Security_HandshakeHandle handshake,
                                             DDS_Security_SecurityException* ex) {
  const std::int64_t remote = remote_of(handshake);
  const auto result = the_watch().real.return_handshake_handle(self, handshake, ex);
  if (remote != 0) {
    tell(STRIDE_HANDSHAKE_ENDED, remote, nullptr);
    watch& w = the_watch();
    std::lock_guard lock(w.mutex);
    w.handshakes.erase(handshake);
  }
  return result;
}

DDS_Security_boolean return_identity_handle(dds_security_authentication* self,
                                            const DDS_Security_IdentityHandle identity,
                                            DDS_Security_SecurityException* ex) {
  watch& w = the_watch();
  {
    std::lock_guard lock(w.mutex);
    w.peers.erase(identity);
  }
  return w.real.return_identity_handle(self, identity, ex);
}

}  // namespace

extern "C" {

__attribute__((visibility("default"))) void stride_watch_handshakes(
    const char* real_plugin, stride_handshake_listener listener, void* context) {
  watch& w = the_watch();
  std::lock_guard lock(w.mutex);
  w.real_plugin = real_plugin != nullptr ? real_plugin : "";
  w.listener = listener;
  w.context = context;
}

__attribute__((visibility("default"))) int stride_init_authentication(const char* argument,
                                                                      void** context,
                                                                      void* domain) {
  watch& w = the_watch();
  using init_fn = int (*)(const char*, void**, void*);
  init_fn real_init = nullptr;
  {
    std::lock_guard lock(w.mutex);
    if (w.library == nullptr) {
      w.library = ::dlopen(w.real_plugin.c_str(), RTLD_NOW | RTLD_LOCAL);
      if (w.library == nullptr) {
        std::fprintf(stderr, "stride: cannot load DDS Security plugin %s: %s\n",
                     w.real_plugin.c_str(), ::dlerror());
        return -1;
      }
    }
    real_init = reinterpret_cast<init_fn>(::dlsym(w.library, "init_authentication"));
    w.real_finalize =
        reinterpret_cast<int (*)(void*)>(::dlsym(w.library, "finalize_authentication"));
  }
  if (real_init == nullptr || w.real_finalize == nullptr) return -1;
  const int status = real_init(argument, context, domain);
  if (status != 0 || context == nullptr || *context == nullptr) return status;
  // Every participant's object comes from the same library, so one copy of its functions serves
  // them all; each object keeps its own state.
  auto* plugin = static_cast<dds_security_authentication*>(*context);
  {
    std::lock_guard lock(w.mutex);
    if (w.real.validate_remote_identity == nullptr) w.real = *plugin;
  }
  plugin->validate_remote_identity = &validate_remote_identity;
  plugin->begin_handshake_request = &begin_handshake_request;
  plugin->begin_handshake_reply = &begin_handshake_reply;
  plugin->process_handshake = &process_handshake;
  plugin->return_handshake_handle = &return_handshake_handle;
  plugin->return_identity_handle = &return_identity_handle;
  return status;
}

__attribute__((visibility("default"))) int stride_finalize_authentication(void* context) {
  watch& w = the_watch();
  return w.real_finalize != nullptr ? w.real_finalize(context) : -1;
}

}  // extern "C"
