// DDS Security for the participants of this process: Cyclone's builtin authentication, access
// control and cryptography plugins, configured through the participant's QoS properties from an
// identity folder (stride/remote/identity.hpp).
#ifndef STRIDE_REMOTE_DDS_SECURITY_HPP
#define STRIDE_REMOTE_DDS_SECURITY_HPP

#include <dds/dds.h>

#include <filesystem>

#include "handshake_watch.h"
#include "stride/remote/settings.hpp"

namespace stride::remote::dds {

/// \throws std::runtime_error naming the file when one of the identity in `dir` is missing or
/// unreadable, or when its private key is readable by others.
void check_security_files(const std::filesystem::path& dir);

/// Adds the security properties of the identity in `dir` to `qos`.
void add_security(dds_qos_t* qos, const std::filesystem::path& dir);

/// Runs the identity check the process has set (set_identity_check), if any.
void check_identity(const std::filesystem::path& identity, int domain);

/// Where the plugin library `name` (e.g. "dds_security_auth") is: Debian keeps Cyclone's plugins
/// in a folder beside libddsc that the loader does not search.
std::string plugin_path(const char* name);

/// Makes every secure participant created from now on authenticate through libstride_dds_auth
/// (remote/auth_watch, loaded with the first of them), which tells `listener` how each DDS
/// Security handshake goes. \returns false, and changes nothing, when that library is not where
/// the program expects it (beside the program, or in ../lib/stride).
bool watch_handshakes(stride_handshake_listener listener, void* context);

/// watch_handshakes with the wrapper library at `library` (empty: none).
bool watch_handshakes_through(const std::filesystem::path& library,
                              stride_handshake_listener listener, void* context);

/// Whether handshakes reach the listener: the wrapper was loaded, with the first secure
/// participant. False when it could not be: Cyclone's plugin then authenticates alone and its
/// own log messages are all there is to say how handshakes go.
bool handshakes_watched();

/// The listener is called no more (participants made meanwhile keep the wrapper); returns when
/// no call to it is under way.
void stop_watching_handshakes();

}  // namespace stride::remote::dds

#endif  // STRIDE_REMOTE_DDS_SECURITY_HPP
