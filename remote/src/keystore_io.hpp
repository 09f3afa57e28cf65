// Files of a keystore (keystore.cpp, keystore_show.cpp): reading, creating with a mode from the
// start, and errors that name the file.
#ifndef STRIDE_REMOTE_KEYSTORE_IO_HPP
#define STRIDE_REMOTE_KEYSTORE_IO_HPP

#include <sys/types.h>

#include <chrono>
#include <filesystem>
#include <stdexcept>
#include <string>

namespace stride::remote::keystore::io {

/// Runs `f`, naming `file` in what it throws ("FILE: what").
template <typename F>
auto about(const std::filesystem::path& file, F&& f) -> decltype(f()) {
  try {
    return f();
  } catch (const std::exception& e) {
    throw std::runtime_error(file.string() + ": " + e.what());
  }
}

/// Creates `file` with `mode` from the start (O_CREAT | O_EXCL | O_NOFOLLOW): never an existing
/// file, never through a symbolic link, never chmod-ed after writing.
void write_new(const std::filesystem::path& file, const std::string& text, mode_t mode);
void make_directory(const std::filesystem::path& dir, mode_t mode);

/// "YYYY-MM-DD HH:MM:SS UTC"
std::string date(std::chrono::system_clock::time_point t);

}  // namespace stride::remote::keystore::io

#endif  // STRIDE_REMOTE_KEYSTORE_IO_HPP
