#include "stride/sdk/resources.hpp"

namespace stride::sdk {

std::filesystem::path find_resource(const std::filesystem::path& file,
                                    const std::filesystem::path& resource_dir) {
  if (file.is_relative() && !std::filesystem::exists(file) && !resource_dir.empty()) {
    std::filesystem::path in_resources = resource_dir / file;
    if (std::filesystem::exists(in_resources)) return in_resources;
  }
  return file;
}

}  // namespace stride::sdk
