#include "keystore_io.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "stride/common/text.hpp"

namespace stride::remote::keystore::io {

namespace fs = std::filesystem;
using sys_clock = std::chrono::system_clock;

namespace {

std::string system_error_text() {
  return std::strerror(errno);
}

}  // namespace

void write_new(const fs::path& file, const std::string& text, mode_t mode) {
  const int fd = ::open(file.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC | O_NOFOLLOW, mode);
  if (fd < 0)
    throw std::runtime_error(file.string() + ": cannot create (" + system_error_text() + ")");
  std::size_t done = 0;
  while (done < text.size()) {
    const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const std::string why = system_error_text();
      ::close(fd);
      throw std::runtime_error(file.string() + ": cannot write (" + why + ")");
    }
    done += static_cast<std::size_t>(n);
  }
  if (::close(fd) != 0) {
    throw std::runtime_error(file.string() + ": cannot write (" + system_error_text() + ")");
  }
}

void make_directory(const fs::path& dir, mode_t mode) {
  if (::mkdir(dir.c_str(), mode) != 0) {
    throw std::runtime_error(dir.string() + ": cannot create (" + system_error_text() + ")");
  }
}

std::string date(sys_clock::time_point t) {
  return text::utc_text(t, "%Y-%m-%d %H:%M:%S UTC");
}

}  // namespace stride::remote::keystore::io
