// Whether a DDS configuration lets other hosts reach this process: a worker that can be reached
// from the network runs only with DDS Security, or when its user says --insecure.
#ifndef STRIDE_REMOTE_REACH_HPP
#define STRIDE_REMOTE_REACH_HPP

#include <string>

#include "stride/remote/settings.hpp"

namespace stride::remote {

/// Why the DDS configuration of `settings` (its file, else CYCLONEDDS_URI, else the shipped
/// loopback one) can reach beyond this machine, or "" when it stays on the loopback interface.
/// A configuration that names no interface, names a non-loopback interface or peer, or cannot be
/// read is taken to reach beyond it (Cyclone would pick a network interface of its own).
std::string reach_beyond_loopback(const dds_settings& settings);

}  // namespace stride::remote

#endif  // STRIDE_REMOTE_REACH_HPP
