#include "installed_files.hpp"

#include <filesystem>
#include <string>

#include "stride/cosim/system_builder.hpp"

namespace stride::cli {

namespace fs = std::filesystem;

CLI::Validator existing_or_installed_model() {
  return CLI::Validator(
      [](std::string& file) -> std::string {
        std::error_code error;
        // a folder may be a system (an SSP's); the system reader says when it is not
        if (fs::is_regular_file(file, error) || fs::is_directory(file, error)) return {};
        if (fs::exists(file, error)) return "Not a regular file: " + file;
        const fs::path data = cosim::installed_data_dir();
        if (fs::path(file).is_relative() && !data.empty()) {
          const fs::path shipped = data / "models" / file;
          if (fs::is_regular_file(shipped, error)) {
            file = shipped.string();
            return {};
          }
          return "File does not exist: " + file + " (nor in " + (data / "models").string() + ")";
        }
        return "File does not exist: " + file;
      },
      "FILE", "FILE");
}

}  // namespace stride::cli
