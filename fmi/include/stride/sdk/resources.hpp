// Files shipped in an FMU's resources/ folder.
#pragma once

#include <filesystem>

namespace stride::sdk {

/// Where the file a user named lives: a relative path that does not exist as given is looked up
/// in `resource_dir` (the FMU's unpacked resources/ folder, "" if none). Returns `file` unchanged
/// when it exists, is absolute or is not in `resource_dir` either, so an error names what the
/// user wrote.
std::filesystem::path find_resource(const std::filesystem::path& file,
                                    const std::filesystem::path& resource_dir);

}  // namespace stride::sdk
