// Small helpers for the study's gnuplot figures: numbers and strings as gnuplot reads them, and
// running a script.
#ifndef STRIDE_STUDY_SRC_GNUPLOT_HPP
#define STRIDE_STUDY_SRC_GNUPLOT_HPP

#include <filesystem>
#include <string>

namespace stride::study::gnuplot {

/// Shortest text that reads back as `v`; "NaN" (which gnuplot leaves blank) for NaN.
std::string num(double v);
/// " (ms)" / " (mm)" for the gait parameters a study axis is named after, else "".
std::string unit_of(const std::string& parameter);
/// A gnuplot single-quoted string.
std::string quote(const std::string& s);
/// \throws std::runtime_error naming the file when it cannot be written.
void write_text(const std::filesystem::path& file, const std::string& text);
/// Runs gnuplot on `script`. \throws std::runtime_error when gnuplot is missing (naming the
/// Debian package) or fails (with its messages).
void run(const std::filesystem::path& script);

}  // namespace stride::study::gnuplot

#endif  // STRIDE_STUDY_SRC_GNUPLOT_HPP
