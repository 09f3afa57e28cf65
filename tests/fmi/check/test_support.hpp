// Helpers of the FMU check tests: temp folders, ZIP archives written with libzip at test time,
// running a command.
#ifndef STRIDE_TESTS_FMI_CHECK_TEST_SUPPORT_HPP
#define STRIDE_TESTS_FMI_CHECK_TEST_SUPPORT_HPP

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace stride::fmi_check::test {

/// A fresh directory under the system temp folder, removed with everything in it.
class temp_dir {
 public:
  temp_dir();
  ~temp_dir();
  temp_dir(const temp_dir&) = delete;
  temp_dir& operator=(const temp_dir&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

/// One entry of a test archive.
struct zip_entry {
  std::string name;
  std::string content;
  int compression = 8;                             // ZIP_CM_DEFLATE; 0 stores, 12 is bzip2
  bool symlink = false;                            // Unix symlink whose target is `content`
  bool encrypt = false;                            // WinZip AES-128 with a fixed password
  std::optional<std::filesystem::path> from_file;  // content read from this file instead
};

/// Writes `entries` to a new ZIP file at `path` with libzip; throws on failure.
void write_zip(const std::filesystem::path& path, const std::vector<zip_entry>& entries);

/// The whole content of a file; throws when it cannot be read.
std::string read_text(const std::filesystem::path& path);

struct command_result {
  int exit_code = -1;
  std::string output;  // stdout and stderr, interleaved
};

/// Runs `command` through /bin/sh and collects its output.
command_result run_command(const std::string& command);

/// Single-quotes a string for /bin/sh.
std::string shell_quote(const std::string& s);

}  // namespace stride::fmi_check::test

#endif  // STRIDE_TESTS_FMI_CHECK_TEST_SUPPORT_HPP
