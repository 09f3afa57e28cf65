// Small helpers for figures drawn with gnuplot: numbers and strings as gnuplot reads them, and
// running a script. Used by `stride plot` (run_plots.hpp) and by applications' own figures.
#ifndef STRIDE_COSIM_GNUPLOT_HPP
#define STRIDE_COSIM_GNUPLOT_HPP

#include <filesystem>
#include <string>

namespace stride::cosim::gnuplot {

/// The terminal every figure uses: PNG (pngcairo), 960x680, no enhanced text.
inline constexpr const char* k_png_terminal =
    "set terminal pngcairo size 960,680 noenhanced font ',11'\n";

/// Shortest text that reads back as `v`; "NaN" (which gnuplot leaves blank) for NaN.
std::string num(double v);
/// A gnuplot single-quoted string.
std::string quote(const std::string& s);
/// \throws std::runtime_error naming the file when it cannot be written.
void write_text(const std::filesystem::path& file, const std::string& text);
/// Runs gnuplot on `script`. \throws std::runtime_error when gnuplot is missing (naming the
/// Debian package) or fails (with its messages).
void run(const std::filesystem::path& script);

}  // namespace stride::cosim::gnuplot

#endif  // STRIDE_COSIM_GNUPLOT_HPP
