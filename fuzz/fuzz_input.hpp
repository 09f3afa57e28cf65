// Helpers shared by the fuzz targets: the input as text, or as a file for readers that take a
// path. A target passes when the code under test returns or throws a std::exception (a clean
// refusal with a message); crashes, sanitizer reports, hangs and leaks are what libFuzzer finds.
#pragma once

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

namespace stride::fuzz {

inline std::string_view as_text(const std::uint8_t* data, std::size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

/// The input written to a file of this process's own, removed again when the object goes.
class input_file {
 public:
  input_file(const std::uint8_t* data, std::size_t size, const std::string& name) {
    dir_ = std::filesystem::temp_directory_path() / ("stride-fuzz-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir_);
    path_ = dir_ / name;
    std::ofstream(path_, std::ios::binary)
        .write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  ~input_file() {
    std::error_code ignored;
    std::filesystem::remove_all(dir_, ignored);
  }
  input_file(const input_file&) = delete;
  input_file& operator=(const input_file&) = delete;

  const std::filesystem::path& path() const { return path_; }
  const std::filesystem::path& dir() const { return dir_; }

 private:
  std::filesystem::path dir_;
  std::filesystem::path path_;
};

}  // namespace stride::fuzz
