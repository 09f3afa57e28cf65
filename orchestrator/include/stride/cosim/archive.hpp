// Safe extraction of FMU archives into private temporary directories, and reading one entry.
#ifndef STRIDE_COSIM_ARCHIVE_HPP
#define STRIDE_COSIM_ARCHIVE_HPP

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

namespace stride::cosim {

/// A directory created with mkdtemp and removed, with everything inside, on destruction.
class temp_dir {
 public:
  /// Creates `<parent>/<prefix>XXXXXX` (parent defaults to the system temp directory).
  /// \throws std::system_error if it cannot be created.
  explicit temp_dir(const std::string& prefix = "stride-",
                    const std::filesystem::path& parent = {});
  ~temp_dir();
  temp_dir(const temp_dir&) = delete;
  temp_dir& operator=(const temp_dir&) = delete;
  temp_dir(temp_dir&& other) noexcept;
  temp_dir& operator=(temp_dir&& other) noexcept;

  const std::filesystem::path& path() const noexcept { return path_; }

 private:
  std::filesystem::path path_;
};

/// Limits that protect against zip bombs.
struct extract_limits {
  std::uint64_t max_entry_size = std::uint64_t{2} << 30;  ///< 2 GiB per entry
  std::uint64_t max_total_size = std::uint64_t{8} << 30;  ///< 8 GiB per archive
  std::uint64_t max_entries = 100000;
};

/// Extracts every entry of the zip archive `archive` into the existing directory `destination`.
/// Rejects (before writing anything) entries whose name is absolute, contains "..", a backslash
/// or a NUL, symbolic links, and entries over the limits; the size limit is enforced again
/// while inflating. Existing files are never overwritten and never followed; a refused archive
/// leaves nothing it created behind.
/// \throws fmu_import_error naming the archive and the entry.
void extract_archive(const std::filesystem::path& archive, const std::filesystem::path& destination,
                     const extract_limits& limits = {});

/// The content of the entry `name` of the zip archive `archive`, nullopt when it has none; only
/// that entry is inflated (reading modelDescription.xml without unpacking the binaries).
/// \throws fmu_import_error for an archive that is not a zip, and for an entry over `max_size`
/// or that inflates to another size than it declares.
std::optional<std::string> read_archive_entry(const std::filesystem::path& archive,
                                              const std::string& name,
                                              std::uint64_t max_size = std::uint64_t{64} << 20);

}  // namespace stride::cosim

#endif  // STRIDE_COSIM_ARCHIVE_HPP
