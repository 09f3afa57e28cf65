#include <cstdint>
#include <cstdio>
#include <string>

#include "start_value.hpp"
#include "stride/sdk/model_description.hpp"

namespace stride::sdk {
namespace {

std::uint64_t fnv1a(const std::string& s, std::uint64_t hash) {
  for (unsigned char c : s) {
    hash ^= c;
    hash *= 0x100000001b3ULL;
  }
  return hash;
}

}  // namespace

std::string compute_guid(const fmu_definition& fmu) {
  // canonical text of the interface; the two seeds give 128 bits
  std::string text =
      fmu.info.model_name + '|' + fmu.info.model_identifier + '|' + fmu.info.version + '|';
  for (const variable& v : fmu.table.variables()) {
    text += v.name + '|' + std::to_string(v.value_reference) + '|';
    text += to_string(v.type);
    text += '|';
    text += to_string(v.causality_kind);
    text += '|';
    text += to_string(v.variability_kind);
    text += '|';
    text += to_string(v.initial);
    text += '|' + v.unit + '|';
    if (v.has_start()) text += format_start_value(v, fmu.table.defaults());
    text += '\n';
  }
  const std::uint64_t a = fnv1a(text, 0xcbf29ce484222325ULL);
  const std::uint64_t b = fnv1a(text, 0x84222325cbf29ce4ULL);
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "{%08x-%04x-%04x-%04x-%012llx}",
                static_cast<unsigned>(a >> 32), static_cast<unsigned>((a >> 16) & 0xffff),
                static_cast<unsigned>(a & 0xffff), static_cast<unsigned>(b >> 48),
                static_cast<unsigned long long>(b & 0xffffffffffffULL));
  return buffer;
}

}  // namespace stride::sdk
