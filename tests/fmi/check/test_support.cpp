#include "test_support.hpp"

#include <sys/stat.h>
#include <sys/wait.h>
#include <zip.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace stride::fmi_check::test {

temp_dir::temp_dir() {
  std::string pattern = (std::filesystem::temp_directory_path() / "stride_fmi_check_XXXXXX");
  if (mkdtemp(pattern.data()) == nullptr) throw std::runtime_error("mkdtemp failed: " + pattern);
  path_ = pattern;
}

temp_dir::~temp_dir() {
  std::error_code ignored;
  std::filesystem::remove_all(path_, ignored);
}

void write_zip(const std::filesystem::path& path, const std::vector<zip_entry>& entries) {
  int error_code = 0;
  zip_t* archive = zip_open(path.c_str(), ZIP_CREATE | ZIP_TRUNCATE, &error_code);
  if (archive == nullptr) throw std::runtime_error("zip_open failed for " + path.string());
  auto fail = [&](const std::string& what) {
    const std::string message = what + ": " + zip_strerror(archive);
    zip_discard(archive);
    throw std::runtime_error(message);
  };
  for (const zip_entry& e : entries) {
    // libzip copies the buffer on zip_close only; keep it alive in a heap copy it frees
    std::string data = e.from_file ? read_text(*e.from_file) : e.content;
    void* copy = std::malloc(data.size() + 1);
    if (copy == nullptr) fail("out of memory");
    std::copy(data.begin(), data.end(), static_cast<char*>(copy));
    zip_source_t* source = zip_source_buffer(archive, copy, data.size(), 1);
    if (source == nullptr) {
      std::free(copy);
      fail("zip_source_buffer " + e.name);
    }
    const zip_int64_t index = zip_file_add(archive, e.name.c_str(), source, ZIP_FL_ENC_RAW);
    if (index < 0) {
      zip_source_free(source);
      fail("zip_file_add " + e.name);
    }
    const auto i = static_cast<zip_uint64_t>(index);
    if (zip_set_file_compression(archive, i, e.compression, 0) != 0) {
      fail("zip_set_file_compression " + e.name);
    }
    if (e.symlink &&
        zip_file_set_external_attributes(archive, i, 0, ZIP_OPSYS_UNIX,
                                         static_cast<zip_uint32_t>(S_IFLNK | 0777) << 16) != 0) {
      fail("zip_file_set_external_attributes " + e.name);
    }
    if (e.encrypt && zip_file_set_encryption(archive, i, ZIP_EM_AES_128, "secret") != 0) {
      fail("zip_file_set_encryption " + e.name);
    }
  }
  if (zip_close(archive) != 0) fail("zip_close " + path.string());
}

std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + path.string());
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

command_result run_command(const std::string& command) {
  command_result result;
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  if (pipe == nullptr) throw std::runtime_error("popen failed: " + command);
  std::array<char, 4096> buffer{};
  std::size_t n = 0;
  while ((n = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0) {
    result.output.append(buffer.data(), n);
  }
  const int status = pclose(pipe);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  return result;
}

std::string shell_quote(const std::string& s) {
  std::string out = "'";
  for (char c : s) {
    if (c == '\'') {
      out += "'\\''";
    } else {
      out += c;
    }
  }
  return out + "'";
}

}  // namespace stride::fmi_check::test
