#include "stride/cosim/archive.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#include <zip.h>

#include <array>
#include <cerrno>
#include <cstdlib>
#include <memory>
#include <string>
#include <system_error>
#include <vector>

#include "stride/cosim/error.hpp"

namespace stride::cosim {

namespace fs = std::filesystem;

temp_dir::temp_dir(const std::string& prefix, const fs::path& parent) {
  const fs::path base = parent.empty() ? fs::temp_directory_path() : parent;
  std::string pattern = (base / (prefix + "XXXXXX")).string();
  std::vector<char> buffer(pattern.begin(), pattern.end());
  buffer.push_back('\0');
  if (::mkdtemp(buffer.data()) == nullptr) {
    throw std::system_error(errno, std::generic_category(),
                            "cannot create a temporary directory in " + base.string());
  }
  path_ = fs::path(buffer.data());
}

temp_dir::~temp_dir() {
  if (!path_.empty()) {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
}

temp_dir::temp_dir(temp_dir&& other) noexcept : path_(std::move(other.path_)) {
  other.path_.clear();
}

temp_dir& temp_dir::operator=(temp_dir&& other) noexcept {
  if (this != &other) {
    if (!path_.empty()) {
      std::error_code ec;
      fs::remove_all(path_, ec);
    }
    path_ = std::move(other.path_);
    other.path_.clear();
  }
  return *this;
}

namespace {

struct zip_closer {
  void operator()(zip_t* z) const noexcept { zip_discard(z); }
};
struct zip_file_closer {
  void operator()(zip_file_t* f) const noexcept { zip_fclose(f); }
};
struct fd_closer {
  int fd;
  ~fd_closer() {
    if (fd >= 0) ::close(fd);
  }
};

// Why an entry name is unsafe, or nullptr if it is fine.
const char* unsafe_name_reason(const std::string& name) {
  if (name.empty()) return "has an empty name";
  if (name.find('\0') != std::string::npos) return "has a NUL in its name";
  if (name.find('\\') != std::string::npos) return "has a backslash in its name";
  if (name.front() == '/') return "is an absolute path";
  if (name.size() >= 2 && name[1] == ':') return "is an absolute (drive) path";
  // every path element must be a plain name
  std::size_t begin = 0;
  while (begin <= name.size()) {
    std::size_t end = name.find('/', begin);
    if (end == std::string::npos) end = name.size();
    const std::string_view part(name.data() + begin, end - begin);
    if (part == "..") return "escapes the archive with '..'";
    if (part == ".") return "has a '.' path element";
    if (part.empty() && end != name.size()) return "has an empty path element";
    begin = end + 1;
  }
  return nullptr;
}

std::unique_ptr<zip_t, zip_closer> open_zip(const fs::path& archive) {
  if (!fs::is_regular_file(archive)) throw fmu_import_error(archive.string() + ": file not found");
  int error_code = 0;
  std::unique_ptr<zip_t, zip_closer> za(zip_open(archive.c_str(), ZIP_RDONLY, &error_code));
  if (!za) {
    zip_error_t ze;
    zip_error_init_with_code(&ze, error_code);
    std::string message = std::string("not a zip archive: ") + zip_error_strerror(&ze);
    zip_error_fini(&ze);
    throw fmu_import_error(archive.string() + ": " + message);
  }
  return za;
}

}  // namespace

std::optional<std::string> read_archive_entry(const fs::path& archive, const std::string& name,
                                              std::uint64_t max_size) {
  const auto za = open_zip(archive);
  const auto fail = [&](const std::string& message) {
    throw fmu_import_error(archive.string() + ": entry \"" + name + "\" " + message);
  };
  const zip_int64_t index = zip_name_locate(za.get(), name.c_str(), ZIP_FL_ENC_RAW);
  if (index < 0) return std::nullopt;
  zip_stat_t st;
  zip_stat_init(&st);
  if (zip_stat_index(za.get(), static_cast<zip_uint64_t>(index), ZIP_FL_ENC_RAW, &st) != 0 ||
      (st.valid & ZIP_STAT_SIZE) == 0) {
    fail("cannot be read");
  }
  if (st.size > max_size) {
    fail("is too large (" + std::to_string(st.size) + " bytes, limit " + std::to_string(max_size) +
         ")");
  }
  std::unique_ptr<zip_file_t, zip_file_closer> zf(
      zip_fopen_index(za.get(), static_cast<zip_uint64_t>(index), 0));
  if (!zf) fail(std::string("cannot be opened: ") + zip_strerror(za.get()));
  std::string text(static_cast<std::size_t>(st.size), '\0');
  zip_uint64_t got = 0;
  for (;;) {
    // one byte more than declared is read to see whether the size lies
    char spill = 0;
    char* to = got < st.size ? text.data() + got : &spill;
    const zip_uint64_t want = got < st.size ? st.size - got : 1;
    const zip_int64_t n = zip_fread(zf.get(), to, want);
    if (n < 0) fail(std::string("cannot be inflated: ") + zip_file_strerror(zf.get()));
    if (n == 0) break;
    got += static_cast<zip_uint64_t>(n);
    if (got > st.size) fail("inflates beyond its declared size");
  }
  if (got != st.size) fail("is shorter than its declared size");
  return text;
}

void extract_archive(const fs::path& archive, const fs::path& destination,
                     const extract_limits& limits) {
  const std::string where = archive.string();
  auto fail = [&](const std::string& message) -> void {
    throw fmu_import_error(where + ": " + message);
  };
  const auto za = open_zip(archive);
  const zip_int64_t count = zip_get_num_entries(za.get(), 0);
  if (count < 0 || static_cast<std::uint64_t>(count) > limits.max_entries) {
    fail("too many entries (" + std::to_string(count) + ")");
  }

  // pass 1: check every entry before anything is written
  struct entry {
    zip_uint64_t index;
    std::string name;
    bool directory;
    zip_uint64_t size;
  };
  std::vector<entry> entries;
  std::uint64_t total = 0;
  for (zip_int64_t i = 0; i < count; ++i) {
    const auto index = static_cast<zip_uint64_t>(i);
    zip_stat_t st;
    zip_stat_init(&st);
    if (zip_stat_index(za.get(), index, ZIP_FL_ENC_RAW, &st) != 0 ||
        (st.valid & ZIP_STAT_NAME) == 0) {
      fail("cannot read entry #" + std::to_string(i));
    }
    std::string name = st.name;
    if (const char* why = unsafe_name_reason(name)) fail("entry \"" + name + "\" " + why);
    zip_uint8_t opsys = 0;
    zip_uint32_t attributes = 0;
    if (zip_file_get_external_attributes(za.get(), index, 0, &opsys, &attributes) == 0 &&
        opsys == ZIP_OPSYS_UNIX) {
      const auto mode = static_cast<mode_t>(attributes >> 16);
      if (S_ISLNK(mode)) fail("entry \"" + name + "\" is a symbolic link");
      // permission bits without a file type (as some zip writers leave them) mean a plain entry
      if ((mode & S_IFMT) != 0 && !S_ISREG(mode) && !S_ISDIR(mode)) {
        fail("entry \"" + name + "\" is not a regular file or directory");
      }
    }
    const bool directory = name.back() == '/';
    const zip_uint64_t size = (st.valid & ZIP_STAT_SIZE) ? st.size : 0;
    if (size > limits.max_entry_size) {
      fail("entry \"" + name + "\" is too large (" + std::to_string(size) + " bytes, limit " +
           std::to_string(limits.max_entry_size) + ")");
    }
    total += size;
    if (total > limits.max_total_size) fail("archive content exceeds the size limit");
    entries.push_back({index, std::move(name), directory, size});
  }

  // pass 2: write; the destination is ours, so no symlinks exist inside it. What this pass
  // creates is removed again if it fails: a refused archive leaves no half-extracted files.
  const fs::path root = fs::weakly_canonical(destination);
  std::vector<fs::path> created;
  const auto make_directories = [&created](const fs::path& dir) {
    std::vector<fs::path> missing;
    for (fs::path p = dir; !p.empty() && !fs::exists(p); p = p.parent_path()) missing.push_back(p);
    for (auto it = missing.rbegin(); it != missing.rend(); ++it) {
      fs::create_directory(*it);
      created.push_back(*it);
    }
  };
  std::array<char, 1 << 16> buffer{};
  std::uint64_t written_total = 0;
  try {
    for (const auto& e : entries) {
      const fs::path target = (root / e.name).lexically_normal();
      // defence in depth: the normalised path must still be inside the destination
      const auto rel = target.lexically_relative(root);
      if (rel.empty() || *rel.begin() == "..") fail("entry \"" + e.name + "\" escapes the archive");
      if (e.directory) {
        make_directories(target);
        continue;
      }
      make_directories(target.parent_path());
      std::unique_ptr<zip_file_t, zip_file_closer> zf(zip_fopen_index(za.get(), e.index, 0));
      if (!zf) fail("cannot open entry \"" + e.name + "\": " + zip_strerror(za.get()));
      const int fd =
          ::open(target.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0644);
      if (fd < 0) {
        fail("cannot create \"" + e.name + "\": " + std::generic_category().message(errno));
      }
      created.push_back(target);
      fd_closer closer{fd};
      std::uint64_t written = 0;
      for (;;) {
        const zip_int64_t n = zip_fread(zf.get(), buffer.data(), buffer.size());
        if (n < 0) fail("cannot inflate entry \"" + e.name + "\": " + zip_file_strerror(zf.get()));
        if (n == 0) break;
        written += static_cast<std::uint64_t>(n);
        written_total += static_cast<std::uint64_t>(n);
        // the declared size may lie; enforce the limits on what is actually inflated
        if (written > limits.max_entry_size || written > e.size ||
            written_total > limits.max_total_size) {
          fail("entry \"" + e.name + "\" inflates beyond its declared size or the size limit");
        }
        const char* p = buffer.data();
        auto left = static_cast<std::size_t>(n);
        while (left > 0) {
          const ssize_t w = ::write(fd, p, left);
          if (w < 0) {
            if (errno == EINTR) continue;
            fail("cannot write \"" + e.name + "\": " + std::generic_category().message(errno));
          }
          p += w;
          left -= static_cast<std::size_t>(w);
        }
      }
    }
  } catch (...) {
    std::error_code ignored;
    for (auto it = created.rbegin(); it != created.rend(); ++it) fs::remove(*it, ignored);
    throw;
  }
}

}  // namespace stride::cosim
