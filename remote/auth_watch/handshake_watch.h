/* The C interface between Stride and its wrapper of Cyclone DDS's authentication plugin
 * (libstride_dds_auth): Cyclone loads the wrapper as its plugin, the wrapper loads the real one and
 * tells a listener of the process how each peer's DDS Security handshake goes. Plain C: Cyclone
 * and the process each load it with dlopen. */
#ifndef STRIDE_HANDSHAKE_WATCH_H
#define STRIDE_HANDSHAKE_WATCH_H

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

enum stride_handshake_event {
  STRIDE_HANDSHAKE_REQUESTED = 1,     /* this process asked the peer; its answer is awaited */
  STRIDE_HANDSHAKE_AUTHENTICATED = 2, /* the peer and this process trust each other */
  STRIDE_HANDSHAKE_FAILED = 3,        /* this process refused the peer; detail says why */
  STRIDE_HANDSHAKE_ENDED = 4          /* the handshake is gone (the peer left, or it is done) */
};

/* peer: the plugin's handle of the remote identity; subject and ca_subject: what the peer's
 * identity token says of its certificate and CA; detail: the plugin's reason for a failure */
typedef void (*stride_handshake_listener)(void* context, enum stride_handshake_event event,
                                          int64_t peer, const char* subject, const char* ca_subject,
                                          const char* detail);

/* Sets the real plugin library and the listener before the first participant is created. */
void stride_watch_handshakes(const char* real_plugin, stride_handshake_listener listener,
                             void* context);

/* The plugin's entry points, named in the participant's dds.sec.auth.library.* properties. */
int stride_init_authentication(const char* argument, void** context, void* domain);
int stride_finalize_authentication(void* context);

#ifdef __cplusplus
}
#endif

#endif /* STRIDE_HANDSHAKE_WATCH_H */
