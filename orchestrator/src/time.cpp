#include "stride/cosim/time.hpp"

#include <charconv>
#include <cmath>
#include <stdexcept>
#include <string>

namespace stride::cosim {

duration duration_from_seconds(double s) {
  const double ticks = std::round(s * 1e9);
  if (!std::isfinite(ticks) || std::fabs(ticks) > 9.2e18) {
    throw std::out_of_range("time " + std::to_string(s) + " s does not fit in 64-bit nanoseconds");
  }
  return duration(static_cast<std::int64_t>(ticks));
}

time_point time_from_seconds(double s) {
  return time_point(duration_from_seconds(s));
}

duration parse_duration(std::string_view text) {
  const std::string original(text);
  auto fail = [&](const char* why) -> duration {
    throw std::invalid_argument("'" + original + "' " + why);
  };
  // sign
  std::size_t i = 0;
  bool negative = false;
  if (i < text.size() && (text[i] == '+' || text[i] == '-')) negative = text[i++] == '-';
  // mantissa digits, remembering how many follow the point
  std::string digits;
  int fraction_digits = 0;
  bool any_digit = false;
  bool seen_point = false;
  for (; i < text.size(); ++i) {
    const char c = text[i];
    if (c >= '0' && c <= '9') {
      any_digit = true;
      if (!(digits.empty() && c == '0')) digits.push_back(c);
      if (seen_point) ++fraction_digits;
    } else if (c == '.' && !seen_point) {
      seen_point = true;
    } else {
      break;
    }
  }
  if (!any_digit) return fail("is not a number of seconds");
  // the zero check must see digits that were dropped as leading zeros after the point
  if (digits.empty()) return duration(0);
  // exponent
  long exponent = 0;
  if (i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
    ++i;
    const char* first = text.data() + i;
    const char* last = text.data() + text.size();
    if (first != last && *first == '+') ++first;
    auto [end, ec] = std::from_chars(first, last, exponent);
    if (ec != std::errc() || end == first) return fail("has a malformed exponent");
    i = static_cast<std::size_t>(end - text.data());
  }
  if (i != text.size()) return fail("is not a number of seconds");
  // value in ns = digits * 10^(exponent - fraction_digits + 9)
  const long shift = exponent - fraction_digits + 9;
  if (shift < 0) {
    const auto cut = static_cast<std::size_t>(-shift);
    if (cut >= digits.size()) return fail("is not a whole number of nanoseconds");
    if (digits.find_first_not_of('0', digits.size() - cut) != std::string::npos) {
      return fail("is not a whole number of nanoseconds");
    }
    digits.resize(digits.size() - cut);
  } else {
    if (shift > 30) throw std::out_of_range("'" + original + "' s is out of range");
    digits.append(static_cast<std::size_t>(shift), '0');
  }
  std::int64_t value = 0;
  auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  if (ec != std::errc() || end != digits.data() + digits.size()) {
    throw std::out_of_range("'" + original + "' s does not fit in 64-bit nanoseconds");
  }
  return duration(negative ? -value : value);
}

std::string format_seconds(duration d) {
  const std::int64_t ticks = d.count();
  // exact decimal from integer ticks: whole seconds, then up to 9 fraction digits
  const bool negative = ticks < 0;
  const auto magnitude =
      negative ? static_cast<std::uint64_t>(-(ticks + 1)) + 1 : static_cast<std::uint64_t>(ticks);
  std::string out = negative ? "-" : "";
  out += std::to_string(magnitude / 1000000000u);
  std::uint64_t fraction = magnitude % 1000000000u;
  if (fraction != 0) {
    std::string f = std::to_string(fraction);
    f.insert(0, 9 - f.size(), '0');
    while (!f.empty() && f.back() == '0') f.pop_back();
    out += "." + f;
  }
  return out;
}

}  // namespace stride::cosim
