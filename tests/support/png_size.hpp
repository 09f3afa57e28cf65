// The pixel size of a PNG file, read from its signature and IHDR chunk: a figure test can check
// that gnuplot wrote a real image of the size its script asked for, not just some bytes.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <optional>
#include <utility>

namespace stride::test {

/// (width, height), or nothing when the file is missing or not a PNG.
inline std::optional<std::pair<std::uint32_t, std::uint32_t>> png_size(
    const std::filesystem::path& file) {
  std::array<unsigned char, 24> head{};
  std::ifstream in(file, std::ios::binary);
  if (!in.read(reinterpret_cast<char*>(head.data()), head.size())) return std::nullopt;
  constexpr std::array<unsigned char, 8> k_signature = {0x89, 'P',  'N',  'G',
                                                        '\r', '\n', 0x1a, '\n'};
  constexpr std::array<unsigned char, 4> k_ihdr = {'I', 'H', 'D', 'R'};
  for (std::size_t i = 0; i < 8; ++i) {
    if (head[i] != k_signature[i]) return std::nullopt;
  }
  for (std::size_t i = 0; i < 4; ++i) {
    if (head[12 + i] != k_ihdr[i]) return std::nullopt;
  }
  const auto be32 = [&head](std::size_t at) {
    std::uint32_t v = 0;
    for (std::size_t i = 0; i < 4; ++i) v = (v << 8) | head[at + i];
    return v;
  };
  return std::make_pair(be32(16), be32(20));
}

}  // namespace stride::test
