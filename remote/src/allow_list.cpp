#include "stride/remote/allow_list.hpp"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "protocol.hpp"
#include "stride/common/files.hpp"

namespace stride::remote {

namespace fs = std::filesystem;

namespace {

bool is_digest(const std::string& s) {
  return s.size() == 64 &&
         std::all_of(s.begin(), s.end(), [](unsigned char c) { return std::isxdigit(c) != 0; });
}

void add_digests_of_file(const fs::path& file, fmu_allow_list& list) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error("--allow-fmu: cannot read " + file.string());
  int number = 0;
  for (std::string line; std::getline(in, line);) {
    ++number;
    std::istringstream words(line);
    std::string digest;
    if (!(words >> digest) || digest.starts_with('#')) continue;
    if (!is_digest(digest)) {
      throw std::runtime_error("--allow-fmu: " + file.string() + ":" + std::to_string(number) +
                               ": '" + digest + "' is not a SHA-256 digest (64 hex digits)");
    }
    std::transform(digest.begin(), digest.end(), digest.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    list.insert(digest);
  }
}

void add_digests_of_folder(const fs::path& dir, fmu_allow_list& list) {
  std::size_t found = 0;
  for (const auto& entry : fs::directory_iterator(dir)) {
    if (!entry.is_regular_file() || entry.path().extension() != ".fmu") continue;
    const std::string bytes = common::read_file(entry.path());
    list.insert(content_hash(std::as_bytes(std::span(bytes.data(), bytes.size()))));
    ++found;
  }
  if (found == 0) throw std::runtime_error("--allow-fmu: no .fmu file in " + dir.string());
}

}  // namespace

void add_allowed_fmus(const fs::path& source, fmu_allow_list& list) {
  if (fs::is_directory(source)) {
    add_digests_of_folder(source, list);
  } else {
    add_digests_of_file(source, list);
  }
}

}  // namespace stride::remote
