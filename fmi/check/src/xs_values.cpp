#include "xs_values.hpp"

#include <charconv>
#include <cmath>
#include <limits>
#include <regex>

namespace stride::fmi_check::detail {

namespace {

bool is_ws(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\n';
}

bool all_digits(std::string_view s) {
  if (s.empty()) return false;
  for (char c : s) {
    if (c < '0' || c > '9') return false;
  }
  return true;
}

int to_int(std::string_view digits) {
  int v = 0;
  for (char c : digits) v = v * 10 + (c - '0');
  return v;
}

bool is_leap(long year) {
  return (year % 4 == 0 && year % 100 != 0) || year % 400 == 0;
}

}  // namespace

std::string_view trim(std::string_view s) {
  while (!s.empty() && is_ws(s.front())) s.remove_prefix(1);
  while (!s.empty() && is_ws(s.back())) s.remove_suffix(1);
  return s;
}

std::vector<std::string_view> split_ws(std::string_view s) {
  std::vector<std::string_view> parts;
  std::size_t i = 0;
  while (i < s.size()) {
    while (i < s.size() && is_ws(s[i])) ++i;
    std::size_t j = i;
    while (j < s.size() && !is_ws(s[j])) ++j;
    if (j > i) parts.push_back(s.substr(i, j - i));
    i = j;
  }
  return parts;
}

std::optional<bool> parse_xs_boolean(std::string_view s) {
  s = trim(s);
  if (s == "true" || s == "1") return true;
  if (s == "false" || s == "0") return false;
  return std::nullopt;
}

std::optional<std::uint32_t> parse_xs_unsigned_int(std::string_view s) {
  s = trim(s);
  if (!s.empty() && s.front() == '+') s.remove_prefix(1);
  if (!all_digits(s)) return std::nullopt;
  std::uint64_t v = 0;
  for (char c : s) {
    v = v * 10 + static_cast<std::uint64_t>(c - '0');
    if (v > std::numeric_limits<std::uint32_t>::max()) return std::nullopt;
  }
  return static_cast<std::uint32_t>(v);
}

std::optional<std::int32_t> parse_xs_int(std::string_view s) {
  s = trim(s);
  bool negative = false;
  if (!s.empty() && (s.front() == '+' || s.front() == '-')) {
    negative = s.front() == '-';
    s.remove_prefix(1);
  }
  if (!all_digits(s)) return std::nullopt;
  std::int64_t v = 0;
  for (char c : s) {
    v = v * 10 + (c - '0');
    if (v > std::int64_t{std::numeric_limits<std::int32_t>::max()} + 1) return std::nullopt;
  }
  if (negative) v = -v;
  if (v < std::numeric_limits<std::int32_t>::min() || v > std::numeric_limits<std::int32_t>::max())
    return std::nullopt;
  return static_cast<std::int32_t>(v);
}

std::optional<std::int64_t> parse_xs_long(std::string_view s) {
  s = trim(s);
  bool negative = false;
  if (!s.empty() && (s.front() == '+' || s.front() == '-')) {
    negative = s.front() == '-';
    s.remove_prefix(1);
  }
  if (!all_digits(s)) return std::nullopt;
  // accumulated as a negative number: its range reaches one further than the positive one
  constexpr std::int64_t k_min = std::numeric_limits<std::int64_t>::min();
  std::int64_t v = 0;
  for (char c : s) {
    const int digit = c - '0';
    if (v < (k_min + digit) / 10) return std::nullopt;
    v = v * 10 - digit;
  }
  if (negative) return v;
  if (v == k_min) return std::nullopt;
  return -v;
}

std::optional<std::uint64_t> parse_xs_unsigned_long(std::string_view s) {
  s = trim(s);
  if (!s.empty() && s.front() == '+') s.remove_prefix(1);
  if (!all_digits(s)) return std::nullopt;
  constexpr std::uint64_t k_max = std::numeric_limits<std::uint64_t>::max();
  std::uint64_t v = 0;
  for (char c : s) {
    const auto digit = static_cast<std::uint64_t>(c - '0');
    if (v > (k_max - digit) / 10) return std::nullopt;
    v = v * 10 + digit;
  }
  return v;
}

bool is_xs_hex_binary(std::string_view s) {
  s = trim(s);
  if (s.size() % 2 != 0) return false;
  for (char c : s) {
    const bool hex = (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f') || (c >= 'A' && c <= 'F');
    if (!hex) return false;
  }
  return true;
}

std::optional<double> parse_xs_double(std::string_view s) {
  s = trim(s);
  if (s == "INF" || s == "+INF") return std::numeric_limits<double>::infinity();
  if (s == "-INF") return -std::numeric_limits<double>::infinity();
  if (s == "NaN") return std::numeric_limits<double>::quiet_NaN();
  // from_chars also accepts "inf"/"nan" spellings that xs:double does not: require a digit.
  bool has_digit = false;
  for (char c : s) {
    if (c >= '0' && c <= '9') has_digit = true;
    if (!((c >= '0' && c <= '9') || c == '.' || c == 'e' || c == 'E' || c == '+' || c == '-'))
      return std::nullopt;
  }
  if (!has_digit) return std::nullopt;
  if (!s.empty() && s.front() == '+') {
    s.remove_prefix(1);
    if (!s.empty() && s.front() == '-') return std::nullopt;  // "+-1": from_chars would take "-1"
  }
  double v = 0.0;
  auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc{} || end != s.data() + s.size()) return std::nullopt;
  return v;
}

bool is_xs_date_time(std::string_view s) {
  static const std::regex pattern(
      R"(^(-?)(\d{4,})-(\d{2})-(\d{2})T(\d{2}):(\d{2}):(\d{2})(\.\d+)?(Z|([+-])(\d{2}):(\d{2}))?$)");
  const std::string text(s);
  std::smatch m;
  if (!std::regex_match(text, m, pattern)) return false;
  const std::string year_digits = m[2].str();
  if (year_digits.size() > 4 && year_digits.front() == '0') return false;
  if (year_digits.find_first_not_of('0') == std::string::npos) return false;  // no year 0
  // leap years repeat every 400 years, and 10000 is a multiple of 400: the last four digits
  // decide, however long the year
  const long year = std::stol(year_digits.substr(year_digits.size() - 4));
  const int month = to_int(m[3].str());
  const int day = to_int(m[4].str());
  const int hour = to_int(m[5].str());
  const int minute = to_int(m[6].str());
  const int second = to_int(m[7].str());
  if (month < 1 || month > 12) return false;
  static constexpr int k_days[] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
  int days_in_month = k_days[month - 1];
  if (month == 2 && is_leap(year)) days_in_month = 29;
  if (day < 1 || day > days_in_month) return false;
  if (minute > 59 || second > 59) return false;
  if (hour > 24) return false;
  if (hour == 24) {
    // 24:00:00 is the end of the day; nothing else with hour 24 is valid.
    if (minute != 0 || second != 0) return false;
    if (m[8].matched && m[8].str().find_first_not_of(".0") != std::string::npos) return false;
  }
  if (m[10].matched) {
    const int tz_hour = to_int(m[11].str());
    const int tz_minute = to_int(m[12].str());
    if (tz_minute > 59 || tz_hour > 14 || (tz_hour == 14 && tz_minute != 0)) return false;
  }
  return true;
}

bool is_c_identifier(std::string_view s) {
  if (s.empty()) return false;
  auto alpha = [](char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; };
  if (!alpha(s.front())) return false;
  for (char c : s) {
    if (!alpha(c) && !(c >= '0' && c <= '9')) return false;
  }
  return true;
}

std::string quote(std::string_view s) {
  std::string out = "\"";
  out += s;
  out += '"';
  return out;
}

}  // namespace stride::fmi_check::detail
