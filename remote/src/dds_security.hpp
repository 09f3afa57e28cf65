// DDS Security for the participants of this process: Cyclone's builtin authentication, access
// control and cryptography plugins, configured through the participant's QoS properties from an
// identity folder (stride/remote/identity.hpp).
#ifndef STRIDE_REMOTE_DDS_SECURITY_HPP
#define STRIDE_REMOTE_DDS_SECURITY_HPP

#include <dds/dds.h>

#include <filesystem>

#include "stride/remote/settings.hpp"

namespace stride::remote::dds {

/// Adds the security properties of the identity in `dir` to `qos`. \throws std::runtime_error
/// naming the file when one is missing or unreadable, or when the private key is readable by
/// others.
void add_security(dds_qos_t* qos, const std::filesystem::path& dir);

/// Runs the identity check the process has set (set_identity_check), if any.
void check_identity(const std::filesystem::path& identity, int domain);

/// Where the plugin library `name` (e.g. "dds_security_auth") is: Debian keeps Cyclone's plugins
/// in a folder beside libddsc that the loader does not search.
std::string plugin_path(const char* name);

}  // namespace stride::remote::dds

#endif  // STRIDE_REMOTE_DDS_SECURITY_HPP
