#include <unistd.h>

#include <atomic>
#include <charconv>
#include <chrono>
#include <stdexcept>

#include "stride/remote/shared_table.hpp"

namespace stride::remote {

std::string table_endpoint::str() const {
  std::string s = "dds;domain=" + std::to_string(domain) + ";table=" + table +
                  ";agents=" + std::to_string(agents) +
                  ";mode=" + (synchronous ? "synchronous" : "asynchronous");
  if (!config_file.empty()) s += ";config=" + config_file.string();
  return s;
}

namespace {

int parse_int(std::string_view key, std::string_view value, int lo, int hi) {
  int v = 0;
  const auto [end, ec] = std::from_chars(value.data(), value.data() + value.size(), v);
  if (ec != std::errc() || end != value.data() + value.size() || v < lo || v > hi) {
    throw std::invalid_argument("shared table: " + std::string(key) + " '" + std::string(value) +
                                "' is not a whole number in " + std::to_string(lo) + ".." +
                                std::to_string(hi));
  }
  return v;
}

}  // namespace

table_endpoint table_endpoint::parse(std::string_view text) {
  if (!text.starts_with("dds;")) {
    throw std::invalid_argument("shared table '" + std::string(text) +
                                "' does not start with 'dds;'");
  }
  table_endpoint e;
  bool have_table = false;
  std::string_view rest = text.substr(4);
  while (!rest.empty()) {
    const auto semi = rest.find(';');
    const std::string_view item = rest.substr(0, semi);
    rest = semi == std::string_view::npos ? std::string_view() : rest.substr(semi + 1);
    const auto eq = item.find('=');
    if (eq == std::string_view::npos) {
      throw std::invalid_argument("shared table: '" + std::string(item) + "' is not key=value");
    }
    const std::string_view key = item.substr(0, eq), value = item.substr(eq + 1);
    if (key == "domain") {
      e.domain = parse_int(key, value, 0, 230);
    } else if (key == "table") {
      if (value.empty()) throw std::invalid_argument("shared table: empty table name");
      e.table = std::string(value);
      have_table = true;
    } else if (key == "agents") {
      e.agents = parse_int(key, value, 1, 100000);
    } else if (key == "mode") {
      if (value != "synchronous" && value != "asynchronous") {
        throw std::invalid_argument("shared table: mode '" + std::string(value) +
                                    "' is neither synchronous nor asynchronous");
      }
      e.synchronous = value == "synchronous";
    } else if (key == "config") {
      e.config_file = std::string(value);
    } else {
      throw std::invalid_argument("shared table: unknown key '" + std::string(key) +
                                  "' (known: domain, table, agents, mode, config)");
    }
  }
  if (!have_table)
    throw std::invalid_argument("shared table '" + std::string(text) + "' has no table=");
  return e;
}

std::string unique_table_name(std::string_view prefix) {
  static std::atomic<unsigned> counter{0};
  char host[64] = {};
  gethostname(host, sizeof host - 1);
  const auto now = std::chrono::system_clock::now().time_since_epoch();
  return std::string(prefix) + "." + host + "." + std::to_string(getpid()) + "." +
         std::to_string(std::chrono::duration_cast<std::chrono::microseconds>(now).count()) + "." +
         std::to_string(counter++);
}

}  // namespace stride::remote
