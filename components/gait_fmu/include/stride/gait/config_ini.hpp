// ROBOTIS-style config.ini support: a line-preserving INI document and the [Walking Config]
// reader/writer (docs/walking-generator.md §2.1).
//
// Format: sections "[name]" and keys are matched case-insensitively; "key = value" or
// "key: value"; ';' or '#' start a comment on a whole line and also after a value (outside double
// quotes); whitespace is trimmed. As in the framework (minIni) only the first section of a name and
// the first occurrence of a key count. Unlike the framework, bad input is an error (config_error).
#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "stride/gait/walking_params.hpp"

namespace stride::gait {

/// Malformed or invalid configuration; the message names file, line and key.
class config_error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Name of the framework's section.
inline constexpr std::string_view walking_config_section = "Walking Config";
/// A value equal to this is treated as absent by the framework.
inline constexpr double ini_absent_sentinel = -1024;

/// One physical line of an INI document.
struct ini_line {
  enum class kind { blank, comment, section, entry, invalid };
  kind type = kind::blank;
  std::string text;             ///< the line as written, without its terminator
  std::string eol;              ///< "\n", "\r\n" or "" (last line without terminator)
  std::string name;             ///< section name (section) or key (entry), trimmed
  std::string value;            ///< entry value: trailing comment removed, trimmed, quotes removed
  std::size_t value_begin = 0;  ///< span of the value as written in `text` (for in-place rewrite)
  std::size_t value_end = 0;
};

/// An INI file kept line by line: comments, order, unknown keys and other sections survive a
/// get/set/write round trip; a changed value is rewritten in place (its trailing comment kept).
class ini_document {
 public:
  ini_document() = default;

  /// Parses text; `source` names it in error messages (usually the file name).
  static ini_document parse(std::string_view text, std::string source = "<string>");
  /// Reads a file; throws config_error if it cannot be read.
  static ini_document load(const std::filesystem::path& file);

  /// Writes the document back (byte-identical if nothing was changed); throws config_error.
  void save(const std::filesystem::path& file) const;
  /// The document text.
  std::string str() const;

  const std::string& source() const { return source_; }
  const std::vector<ini_line>& lines() const { return lines_; }

  /// Index (0-based line number) of the first section header with this name, if any.
  std::optional<std::size_t> find_section(std::string_view section) const;
  /// Index of the first entry `key` inside the first section `section`, if any.
  std::optional<std::size_t> find_entry(std::string_view section, std::string_view key) const;

  bool has_section(std::string_view section) const { return find_section(section).has_value(); }
  /// Value of the first `key` in the first section `section`.
  std::optional<std::string> get(std::string_view section, std::string_view key) const;

  /// Sets a value: rewritten in place if the key exists, else appended after the section's last
  /// entry; the section is appended at the end if missing. Values containing ';', '#' or
  /// surrounding blanks are quoted; a line break is rejected (std::invalid_argument).
  void set(std::string_view section, std::string_view key, std::string_view value);

 private:
  std::vector<ini_line> lines_;
  std::string source_ = "<string>";
  std::string eol_ = "\n";  // terminator used for inserted lines (the file's first one)
};

/// Reads the [Walking Config] section of `doc` on top of `base`.
///  - a missing section, a line in it that is not "key = value", a non-numeric value, a
///    fractional p/i/d gain or a value outside its valid range throw config_error naming
///    file:line and key;
///  - a value of exactly -1024 is treated as absent (framework sentinel);
///  - legacy (pre-2011) keys such as a_offset or z_move_amplitude, unknown keys, repeated keys and
///  a
///    repeated section are ignored (the framework ignores them too) with a warning naming
///    file:line.
/// `warnings` may be null.
walking_params read_walking_config(const ini_document& doc, walking_params base,
                                   std::vector<std::string>* warnings);

/// Loads `file` and reads it as above; a file that cannot be read is a config_error.
walking_params read_walking_config(const std::filesystem::path& file, walking_params base,
                                   std::vector<std::string>* warnings);

/// The text the writer uses for a parameter: gains as integers, reals as "%f" (six decimals, the
/// walk_tuner style, e.g. "-10.000000") when that reads back exactly, else the shortest exact form.
std::string format_param_value(const param_info& info, const walking_params& params);

/// Writes every parameter into the [Walking Config] section of `doc` (created if missing). Entries
/// whose current text already reads back to the same value are left untouched.
void update_walking_config(ini_document& doc, const walking_params& params);

/// The content of a new config.ini for `params` (header comment + section).
std::string make_walking_config_text(const walking_params& params);

/// Writes `params` to `file`: an existing file is updated in place by update_walking_config()
/// (other sections, comments and unknown keys kept); a new file gets make_walking_config_text().
void write_walking_config(const std::filesystem::path& file, const walking_params& params);

}  // namespace stride::gait
