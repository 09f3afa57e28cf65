// The files of one DDS Security identity, as `stride security add KEYSTORE NAME` lays them out in
// KEYSTORE/NAME/ (docs/distributed.md). The folder holds everything a participant needs, so it
// can be copied to another host as it is.
#ifndef STRIDE_REMOTE_IDENTITY_HPP
#define STRIDE_REMOTE_IDENTITY_HPP

#include <array>
#include <filesystem>

namespace stride::remote {

struct identity_files {
  std::filesystem::path dir;

  std::filesystem::path identity_ca() const { return dir / "identity_ca.cert.pem"; }
  std::filesystem::path permissions_ca() const { return dir / "permissions_ca.cert.pem"; }
  std::filesystem::path governance() const { return dir / "governance.p7s"; }
  std::filesystem::path certificate() const { return dir / "cert.pem"; }
  std::filesystem::path private_key() const { return dir / "key.pem"; }
  std::filesystem::path permissions() const { return dir / "permissions.p7s"; }

  /// Every file a participant reads, in the order they are checked.
  std::array<std::filesystem::path, 6> all() const {
    return {identity_ca(), permissions_ca(), governance(),
            certificate(), private_key(),    permissions()};
  }
};

}  // namespace stride::remote

#endif  // STRIDE_REMOTE_IDENTITY_HPP
