// Builds zip archives at test time with libzip (no binary test data is committed), including
// malicious ones: "../" entries, absolute paths, symbolic links.
#ifndef STRIDE_TESTS_ORCHESTRATOR_ZIP_WRITER_HPP
#define STRIDE_TESTS_ORCHESTRATOR_ZIP_WRITER_HPP

#include <sys/stat.h>
#include <zip.h>

#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace stride::cosim::test {

struct zip_entry {
  std::string name;
  std::string content;
  bool symlink = false;    ///< content is the link target
  std::uint32_t mode = 0;  ///< when not 0: the Unix mode written into the external attributes
};

inline void write_zip(const std::filesystem::path& file, const std::vector<zip_entry>& entries) {
  int err = 0;
  zip_t* za = zip_open(file.c_str(), ZIP_CREATE | ZIP_TRUNCATE, &err);
  if (za == nullptr) throw std::runtime_error("cannot create " + file.string());
  // libzip keeps the source buffers until zip_close, so keep the texts alive
  std::vector<std::string> keep;
  keep.reserve(entries.size());
  for (const auto& e : entries) {
    keep.push_back(e.content);
    zip_source_t* src = zip_source_buffer(za, keep.back().data(), keep.back().size(), 0);
    const zip_int64_t index = zip_file_add(za, e.name.c_str(), src, ZIP_FL_ENC_UTF_8);
    if (index < 0) {
      zip_source_free(src);
      zip_discard(za);
      throw std::runtime_error("cannot add " + e.name);
    }
    const std::uint32_t mode = e.symlink ? (S_IFLNK | 0777) : e.mode;
    if (mode != 0) {
      zip_file_set_external_attributes(za, static_cast<zip_uint64_t>(index), 0, ZIP_OPSYS_UNIX,
                                       static_cast<zip_uint32_t>(mode) << 16);
    }
  }
  if (zip_close(za) != 0) {
    zip_discard(za);
    throw std::runtime_error("cannot write " + file.string());
  }
}

/// Reads every entry of an archive (name, content), to rewrite FMUs in tests.
inline std::vector<zip_entry> read_zip(const std::filesystem::path& file) {
  int err = 0;
  zip_t* za = zip_open(file.c_str(), ZIP_RDONLY, &err);
  if (za == nullptr) throw std::runtime_error("cannot open " + file.string());
  std::vector<zip_entry> out;
  const zip_int64_t n = zip_get_num_entries(za, 0);
  for (zip_int64_t i = 0; i < n; ++i) {
    zip_stat_t st;
    zip_stat_index(za, static_cast<zip_uint64_t>(i), 0, &st);
    if (std::string(st.name).ends_with("/")) continue;  // folders are implied by file names
    zip_file_t* f = zip_fopen_index(za, static_cast<zip_uint64_t>(i), 0);
    std::string content(st.size, '\0');
    if (st.size > 0) zip_fread(f, content.data(), st.size);
    zip_fclose(f);
    out.push_back({st.name, std::move(content), false});
  }
  zip_discard(za);
  return out;
}

}  // namespace stride::cosim::test

#endif  // STRIDE_TESTS_ORCHESTRATOR_ZIP_WRITER_HPP
