// Archive rules of docs/fmi-rules.md §2.1, read with libzip without extracting anything, and
// the ties between the archive and its modelDescription.xml.
#include <sys/stat.h>
#include <zip.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <fstream>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "model_description_check.hpp"
#include "model_description_check3.hpp"
#include "reporter.hpp"
#include "stride/fmi_check/fmu_check.hpp"
#include "xs_values.hpp"

namespace stride::fmi_check {

namespace {

using detail::quote;

constexpr std::uint64_t k_max_model_description_size = 64u * 1024u * 1024u;
constexpr std::uint64_t k_max_binary_size = 1024u * 1024u * 1024u;

struct zip_closer {
  void operator()(zip_t* z) const { zip_discard(z); }
};
struct zip_file_closer {
  void operator()(zip_file_t* f) const { zip_fclose(f); }
};

std::uint16_t le16(const unsigned char* p) {
  return static_cast<std::uint16_t>(p[0] | (p[1] << 8));
}
std::uint32_t le32(const unsigned char* p) {
  return static_cast<std::uint32_t>(p[0]) | (static_cast<std::uint32_t>(p[1]) << 8) |
         (static_cast<std::uint32_t>(p[2]) << 16) | (static_cast<std::uint32_t>(p[3]) << 24);
}

/// What libzip does not tell: ZIP64, split/spanned archives and "version needed to extract",
/// read from the end-of-central-directory record and the central directory headers.
void check_raw_format(const std::filesystem::path& fmu, detail::reporter& out) {
  std::ifstream in(fmu, std::ios::binary);
  if (!in) return;  // libzip already opened it; nothing more to learn here
  in.seekg(0, std::ios::end);
  const auto size = static_cast<std::uint64_t>(in.tellg());
  constexpr std::uint64_t k_eocd_size = 22;
  if (size < k_eocd_size) return;
  const std::uint64_t tail_size = std::min<std::uint64_t>(size, k_eocd_size + 0xFFFF);
  std::vector<unsigned char> tail(tail_size);
  in.seekg(static_cast<std::streamoff>(size - tail_size));
  in.read(reinterpret_cast<char*>(tail.data()), static_cast<std::streamsize>(tail_size));
  if (!in) return;
  std::size_t eocd = tail_size - k_eocd_size + 1;
  while (eocd-- > 0) {
    if (le32(&tail[eocd]) == 0x06054b50u) break;
  }
  if (eocd == static_cast<std::size_t>(-1)) return;
  const unsigned char* e = &tail[eocd];
  const std::uint16_t disk = le16(e + 4);
  const std::uint16_t cd_disk = le16(e + 6);
  const std::uint16_t entries_on_disk = le16(e + 8);
  const std::uint16_t entries = le16(e + 10);
  const std::uint32_t cd_size = le32(e + 12);
  const std::uint32_t cd_offset = le32(e + 16);
  if (disk != 0 || cd_disk != 0 || entries_on_disk != entries) {
    out.error("archive.format", "the archive is split or spanned over several disks");
    return;
  }
  if (cd_offset == 0xFFFFFFFFu || cd_size == 0xFFFFFFFFu || entries == 0xFFFFu) {
    out.error("archive.format",
              "the archive uses ZIP64 (version 4.5 needed to extract; FMI "
              "allows at most 2.0)");
    return;
  }
  if (static_cast<std::uint64_t>(cd_offset) + cd_size > size) return;
  std::vector<unsigned char> cd(cd_size);
  in.seekg(cd_offset);
  in.read(reinterpret_cast<char*>(cd.data()), static_cast<std::streamsize>(cd_size));
  if (!in) return;
  std::size_t pos = 0;
  for (std::uint16_t i = 0; i < entries && pos + 46 <= cd.size(); ++i) {
    const unsigned char* h = &cd[pos];
    if (le32(h) != 0x02014b50u) return;
    const std::uint16_t needed = le16(h + 6);
    const std::size_t name_length = le16(h + 28);
    const std::size_t extra_length = le16(h + 30);
    const std::size_t comment_length = le16(h + 32);
    if (pos + 46 + name_length > cd.size()) return;
    const std::string name(reinterpret_cast<const char*>(h + 46), name_length);
    // the low byte is the spec version times ten; the high byte names the host system
    const unsigned version = needed & 0xFFu;
    if (version > 20) {
      out.error("archive.format",
                "entry " + quote(name) + " needs ZIP version " + std::to_string(version / 10) +
                    "." + std::to_string(version % 10) + " to extract; FMI allows at most 2.0");
    }
    pos += 46 + name_length + extra_length + comment_length;
  }
}

/// Decompresses an entry completely, so libzip verifies its CRC. ZIP_CHECKCONS is not used on
/// open: it rejects archives written by libarchive (`cmake -E tar --format=zip`), whose local
/// headers carry sizes next to a data descriptor, which every unzip tool accepts.
void check_entry_data(zip_t* archive, zip_uint64_t index, const std::string& entry,
                      detail::reporter& out) {
  std::unique_ptr<zip_file_t, zip_file_closer> file(zip_fopen_index(archive, index, 0));
  if (!file) {
    out.error("archive.open", entry + " cannot be opened: " + zip_strerror(archive));
    return;
  }
  std::array<char, 65536> buffer{};
  zip_int64_t n = 0;
  while ((n = zip_fread(file.get(), buffer.data(), buffer.size())) > 0) {
  }
  if (n < 0) {
    out.error("archive.open", entry + " cannot be decompressed: " + zip_file_strerror(file.get()));
  }
}

/// The whole content of an entry of at most `max_size` bytes; nullopt with `problem` set if it
/// cannot be read.
std::optional<std::string> read_entry(zip_t* archive, zip_uint64_t index, std::uint64_t max_size,
                                      std::string& problem) {
  zip_stat_t st;
  zip_stat_init(&st);
  if (zip_stat_index(archive, index, 0, &st) != 0 || (st.valid & ZIP_STAT_SIZE) == 0 ||
      st.size > max_size) {
    problem =
        "cannot determine its size, or it is larger than " + std::to_string(max_size) + " bytes";
    return std::nullopt;
  }
  std::unique_ptr<zip_file_t, zip_file_closer> file(zip_fopen_index(archive, index, 0));
  if (!file) {
    problem = zip_strerror(archive);
    return std::nullopt;
  }
  std::string content(static_cast<std::size_t>(st.size), '\0');
  const zip_int64_t read = zip_fread(file.get(), content.data(), st.size);
  if (read < 0 || static_cast<zip_uint64_t>(read) != st.size) {
    problem = zip_file_strerror(file.get());
    return std::nullopt;
  }
  return content;
}

bool has_dot_dot_component(const std::string& name) {
  std::size_t start = 0;
  while (start <= name.size()) {
    std::size_t end = name.find_first_of("/\\", start);
    if (end == std::string::npos) end = name.size();
    if (name.compare(start, end - start, "..") == 0 && end - start == 2) return true;
    start = end + 1;
  }
  return false;
}

bool is_absolute_name(const std::string& name) {
  if (name.empty()) return false;
  if (name.front() == '/' || name.front() == '\\') return true;
  // a Windows drive letter, as some zip tools store it
  return name.size() >= 2 && name[1] == ':' &&
         ((name[0] >= 'A' && name[0] <= 'Z') || (name[0] >= 'a' && name[0] <= 'z'));
}

}  // namespace

std::vector<finding> check_fmu(const std::filesystem::path& fmu) {
  detail::reporter out;
  int error_code = 0;
  std::unique_ptr<zip_t, zip_closer> archive(zip_open(fmu.c_str(), ZIP_RDONLY, &error_code));
  if (!archive) {
    zip_error_t error;
    zip_error_init_with_code(&error, error_code);
    out.error("archive.open",
              "cannot open " + fmu.string() + " as a ZIP archive: " + zip_error_strerror(&error));
    zip_error_fini(&error);
    return out.take();
  }
  if (fmu.extension() != ".fmu") {
    out.warning("archive.extension",
                "the file name " + quote(fmu.filename().string()) + " does not end in .fmu");
  }
  check_raw_format(fmu, out);

  archive_listing listing;
  std::set<std::string> names;
  const zip_int64_t count = zip_get_num_entries(archive.get(), 0);
  std::optional<zip_uint64_t> model_description_index;
  std::vector<std::string> nested_model_descriptions;
  for (zip_int64_t i = 0; i < count; ++i) {
    const auto index = static_cast<zip_uint64_t>(i);
    const char* raw_name = zip_get_name(archive.get(), index, ZIP_FL_ENC_RAW);
    if (raw_name == nullptr) {
      out.error("archive.open", "cannot read the name of entry " + std::to_string(i) + ": " +
                                    zip_strerror(archive.get()));
      continue;
    }
    const std::string name(raw_name);
    listing.push_back(name);
    const std::string entry = "entry " + quote(name);

    zip_stat_t st;
    zip_stat_init(&st);
    if (zip_stat_index(archive.get(), index, ZIP_FL_ENC_RAW, &st) == 0) {
      if ((st.valid & ZIP_STAT_COMP_METHOD) != 0 && st.comp_method != ZIP_CM_STORE &&
          st.comp_method != ZIP_CM_DEFLATE) {
        out.error("archive.compression", entry + " uses compression method " +
                                             std::to_string(st.comp_method) +
                                             "; only store (0) and deflate (8) are allowed");
      }
      if ((st.valid & ZIP_STAT_ENCRYPTION_METHOD) != 0 && st.encryption_method != ZIP_EM_NONE) {
        out.error("archive.encryption", entry + " is encrypted");
      }
    }
    if (!name.ends_with("/") && (st.valid & ZIP_STAT_ENCRYPTION_METHOD) != 0 &&
        st.encryption_method == ZIP_EM_NONE) {
      check_entry_data(archive.get(), index, entry, out);
    }
    zip_uint8_t opsys = 0;
    zip_uint32_t attributes = 0;
    if (zip_file_get_external_attributes(archive.get(), index, 0, &opsys, &attributes) == 0 &&
        opsys == ZIP_OPSYS_UNIX && S_ISLNK((attributes >> 16) & S_IFMT)) {
      out.error("archive.link", entry + " is a symbolic link");
    }
    if (name.find('\\') != std::string::npos) {
      out.error("archive.backslash", entry + " contains a backslash; ZIP paths use '/'");
    }
    if (is_absolute_name(name)) {
      out.error("archive.path", entry + " is an absolute path");
    } else if (has_dot_dot_component(name)) {
      out.error("archive.path", entry + " has a '..' component");
    }
    for (unsigned char c : name) {
      if (c >= 0x80) {
        out.warning("archive.name_ascii", entry + " is not ASCII; importers may mangle it");
        break;
      }
    }
    if (!names.insert(name).second) {
      out.error("archive.duplicate_entry", entry + " occurs more than once");
    }
    if (name == "modelDescription.xml") {
      model_description_index = index;
    } else if (name.ends_with("/modelDescription.xml") ||
               name.ends_with("\\modelDescription.xml")) {
      nested_model_descriptions.push_back(name);
    }
  }

  if (!model_description_index) {
    std::string message = "there is no modelDescription.xml at the archive root";
    if (!nested_model_descriptions.empty()) {
      message += " (found " + quote(nested_model_descriptions.front()) +
                 ": zip the content of the folder, not the folder)";
    }
    out.error("archive.model_description", std::move(message));
    return out.take();
  }

  std::string problem;
  const auto xml =
      read_entry(archive.get(), *model_description_index, k_max_model_description_size, problem);
  if (!xml) {
    out.error("archive.model_description", "cannot read modelDescription.xml: " + problem);
    return out.take();
  }
  int major_version = 0;
  std::string model_identifier;
  out.append(detail::check_description(*xml, &listing, &major_version, &model_identifier));
  if (major_version == 3 && !model_identifier.empty()) {
    // the FMI 3.0 rules look into the binary too: its exported functions
    const std::string binary = "binaries/x86_64-linux/" + model_identifier + ".so";
    const zip_int64_t index = zip_name_locate(archive.get(), binary.c_str(), ZIP_FL_ENC_RAW);
    if (index >= 0) {
      const auto bytes =
          read_entry(archive.get(), static_cast<zip_uint64_t>(index), k_max_binary_size, problem);
      if (bytes) {
        detail::check_exports3(out, binary, *bytes);
      } else {
        out.error("fmi3.exports.elf", "cannot read " + quote(binary) + ": " + problem);
      }
    }
  }
  return out.take();
}

namespace detail {

void check_binary_layout(reporter& out, const archive_listing& archive,
                         std::span<const binary_name> binaries, const binary_layout& layout) {
  const std::string prefix(layout.rule_prefix);
  std::set<std::string, std::less<>> reported;
  for (const std::string& entry : archive) {
    if (!entry.starts_with("binaries/")) continue;
    const std::string_view rest = std::string_view(entry).substr(9);
    const auto slash = rest.find('/');
    if (slash == std::string_view::npos) continue;
    const std::string_view dir = rest.substr(0, slash);
    const auto it = layout.foreign_dirs.find(dir);
    if (it != layout.foreign_dirs.end() && reported.emplace(dir).second) {
      out.error(prefix + "archive.platform_dir",
                "binaries/" + std::string(dir) + "/ is " + std::string(layout.foreign_kind) + "; " +
                    std::string(layout.version) + " importers only look in binaries/" +
                    std::string(it->second) + "/");
    }
  }
  // interface elements sharing a modelIdentifier share one binary
  std::map<std::string_view, std::string> named_by;
  for (const binary_name& b : binaries) {
    if (b.model_identifier.empty()) continue;
    std::string& elements = named_by[b.model_identifier];
    elements += (elements.empty() ? "" : " and ") + std::string(b.element) + "@modelIdentifier";
  }
  for (const auto& [model_identifier, elements] : named_by) {
    const std::string binary = "binaries/" + std::string(layout.platform_dir) + "/" +
                               std::string(model_identifier) + ".so";
    if (std::find(archive.begin(), archive.end(), binary) != archive.end()) continue;
    std::string hint;
    for (const std::string& entry : archive) {
      if (entry.starts_with("binaries/") && entry.ends_with(".so")) {
        hint += (hint.empty() ? " (found: " : ", ") + entry;
      }
    }
    if (!hint.empty()) hint += ")";
    out.error(prefix + "archive.binary",
              "the archive has no " + binary + " (named after " + elements + ")" + hint);
  }
}

void check_archive_ties(reporter& out, const archive_listing& archive,
                        std::string_view model_identifier, std::string_view me_model_identifier) {
  // FMI 3 platform tuples for platforms that have an FMI 2 name are not searched by FMI 2 tools
  static const std::map<std::string_view, std::string_view> k_fmi3_tuples = {
      {"x86_64-linux", "linux64"},
      {"x86-linux", "linux32"},
      {"x86_64-windows", "win64"},
      {"x86-windows", "win32"},
      {"x86_64-darwin", "darwin64"}};
  const std::array<binary_name, 2> binaries{
      {{model_identifier, "CoSimulation"}, {me_model_identifier, "ModelExchange"}}};
  check_binary_layout(out, archive, binaries,
                      {"linux64", k_fmi3_tuples, "an FMI 3 platform tuple", "FMI 2", ""});
}

}  // namespace detail

}  // namespace stride::fmi_check
