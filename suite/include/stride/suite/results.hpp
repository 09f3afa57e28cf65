// What a case recorded: the results CSV of its run, read back column by column.
#ifndef STRIDE_SUITE_RESULTS_HPP
#define STRIDE_SUITE_RESULTS_HPP

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace stride::suite {

/// A results CSV as `stride run` writes it: `time`, then one column per signal. Numbers (and
/// Booleans as 0/1) become doubles; a column holding text is kept as text only.
struct recorded_signals {
  std::filesystem::path file;
  std::vector<double> time;
  std::vector<std::string> names;
  std::vector<std::vector<double>> values;  ///< per column; empty for a text column
  std::vector<bool> is_text;

  /// Index of a column, or nullopt.
  std::optional<std::size_t> column(const std::string& name) const;
};

/// Reads a results (or reference) CSV. \throws std::runtime_error naming the file and line for a
/// missing file, no `time` column first, a row of the wrong length or a time that is not a
/// number.
recorded_signals read_recorded_signals(const std::filesystem::path& file);

}  // namespace stride::suite

#endif  // STRIDE_SUITE_RESULTS_HPP
