// The FMU archives a worker accepts (`stride worker --allow-fmu`): defence in depth beside DDS
// Security, since even an authenticated peer should not make a worker run an arbitrary binary.
#ifndef STRIDE_REMOTE_ALLOW_LIST_HPP
#define STRIDE_REMOTE_ALLOW_LIST_HPP

#include <filesystem>
#include <set>
#include <string>

namespace stride::remote {

/// Lowercase hex SHA-256 digests of FMU archives.
using fmu_allow_list = std::set<std::string>;

/// Adds to `list` the digests `source` names: a file of lines `DIGEST [NAME]` (what `sha256sum`
/// prints; blank lines and lines starting with '#' are skipped), or the digests of the `.fmu`
/// files in a folder. \throws std::runtime_error naming the file (and line) that is wrong, or a
/// folder without any `.fmu` file.
void add_allowed_fmus(const std::filesystem::path& source, fmu_allow_list& list);

}  // namespace stride::remote

#endif  // STRIDE_REMOTE_ALLOW_LIST_HPP
