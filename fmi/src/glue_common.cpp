#include "glue_common.hpp"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>
#include <memory>
#include <mutex>
#include <stdexcept>

#include "stride/common/bytes.hpp"
#include "stride/common/text.hpp"
#include "stride/sdk/model_description.hpp"

namespace stride::sdk::glue {
namespace {

// Format 2: the header and the component's image encoded field by field (portable). Format 1
// copied the header struct and the data from memory; its images are refused by name.
constexpr std::string_view k_state_magic = "STRDSTA2";
constexpr std::string_view k_state_magic_v1 = "STRDSTA1";

struct state_header {
  std::string guid;
  time_ns time = 0;
  std::uint32_t lifecycle = 0;
  bool terminate_requested = false;
};

using header_reader = common::byte_reader<std::runtime_error>;

// Reads the header; the reader is left at the component's image.
state_header read_header(header_reader& r) {
  const auto magic = r.get_raw(k_state_magic.size());
  if (std::memcmp(magic.data(), k_state_magic_v1.data(), magic.size()) == 0) {
    throw std::runtime_error(
        "an FMU state of an earlier Stride (format 1, in its host's memory layout), which this "
        "version does not read");
  }
  if (std::memcmp(magic.data(), k_state_magic.data(), magic.size()) != 0) {
    throw std::runtime_error("not a Stride FMU state");
  }
  state_header h;
  h.guid = r.get_string();
  h.time = r.get<std::int64_t>();
  h.lifecycle = r.get<std::uint32_t>();
  h.terminate_requested = r.get<std::uint8_t>() != 0;
  return h;
}

template <class T>
void write_value(char* at, const variable&, T x) {
  std::memcpy(at, &x, sizeof x);
}

// A String longer than the variable's capacity is refused, never truncated.
void write_value(char* at, const variable& v, std::string_view s) {
  if (s.size() > v.string_capacity) {
    throw std::length_error("string of " + std::to_string(s.size()) +
                            " characters exceeds the capacity of " +
                            std::to_string(v.string_capacity));
  }
  std::memcpy(at, s.data(), s.size());
  at[s.size()] = '\0';
}

}  // namespace

// A generated FMU reads its interface from its resources; a compiled one has one definition.
const loaded_fmu& definition_for(const std::string& resource_dir) {
  static std::mutex mutex;
  static std::map<std::string, std::unique_ptr<const loaded_fmu>> loaded;
  std::lock_guard lock(mutex);
  auto& entry = loaded[resource_dir];
  if (!entry) {
    std::shared_ptr<const fmu_definition> fmu = detail::fmu_for(resource_dir);
    std::string guid = compute_guid(*fmu);
    entry = std::make_unique<const loaded_fmu>(loaded_fmu{std::move(fmu), std::move(guid)});
  }
  return *entry;
}

std::vector<std::string> known_log_categories(const fmu_definition& fmu) {
  std::vector<std::string> names = {"logStatusWarning", "logStatusError", "logStatusFatal",
                                    "logEvents", "logCalls"};
  for (const auto& category : fmu.info.log_categories) names.push_back(category.first);
  return names;
}

bool settable(const variable& v, std::uint32_t state) {
  if (v.variability_kind == variability::constant) return false;
  if (state & (instantiated | initialization_mode)) {
    return v.causality_kind == causality::input || v.initial == initial_kind::exact ||
           v.initial == initial_kind::approx;
  }
  if (state & step_complete) {
    return v.causality_kind == causality::input ||
           (v.causality_kind == causality::parameter && v.variability_kind == variability::tunable);
  }
  return false;
}

std::string describe(const variable& v) {
  return "'" + v.name + "' (" + std::string(to_string(v.causality_kind)) + ", " +
         std::string(to_string(v.variability_kind)) + ")";
}

std::string range_problem(const variable& v, double x) {
  if (!std::isfinite(x)) return "value is not a finite number";
  if (x < v.min || x > v.max) {
    char buffer[160];
    std::snprintf(buffer, sizeof buffer, "value %.17g is outside [%.17g, %.17g]", x, v.min, v.max);
    return buffer;
  }
  if (v.check) {
    try {
      v.check(x);
    } catch (const std::exception& e) {
      return e.what();
    }
  }
  return {};
}

void component_failed(instance& inst, const char* function_name, const std::exception& e) {
  inst.state = error;
  inst.log.error(std::string(function_name) + ": " + e.what());
}

bool refresh_values(instance& inst, const char* function_name) {
  if (!inst.values_dirty) return true;
  try {
    inst.component->calculate_values();
    inst.values_dirty = false;
    return true;
  } catch (const std::exception& e) {
    component_failed(inst, function_name, e);
    return false;
  }
}

template <class T>
std::string store_value(instance& inst, const variable& v, T x, std::string_view state_label) {
  if (!settable(v, inst.state)) {
    return "variable " + describe(v) + " cannot be set in state " + std::string(state_label);
  }
  if constexpr (std::is_same_v<T, double> || std::is_same_v<T, int>) {
    std::string problem = range_problem(v, x);
    if (!problem.empty()) return "'" + v.name + "': " + problem;
  }
  try {
    write_value(inst.data + v.offset, v, x);
    inst.component->on_set(v);
  } catch (const std::exception& e) {
    return "'" + v.name + "': " + e.what();
  }
  inst.values_dirty = true;
  return {};
}

template std::string store_value<double>(instance&, const variable&, double, std::string_view);
template std::string store_value<int>(instance&, const variable&, int, std::string_view);
template std::string store_value<bool>(instance&, const variable&, bool, std::string_view);
template std::string store_value<std::string_view>(instance&, const variable&, std::string_view,
                                                   std::string_view);

std::vector<std::byte> serialize(instance& inst) {
  common::byte_writer w;
  w.put_raw(std::as_bytes(std::span(k_state_magic)));
  w.put_string(inst.loaded.guid);
  w.put(static_cast<std::int64_t>(inst.time));
  w.put(static_cast<std::uint32_t>(inst.state));
  w.put(static_cast<std::uint8_t>(inst.terminate_requested ? 1 : 0));
  w.put_raw(inst.component->save_state());
  return w.take();
}

std::string state_problem(const instance& inst, const std::byte* bytes, std::size_t size) {
  if (bytes == nullptr) return "no FMU state";
  header_reader r(std::span(bytes, size), "too short to be an FMU state");
  try {
    const state_header header = read_header(r);
    if (header.guid != inst.loaded.guid) {
      return "state belongs to another FMU (GUID " + header.guid + ")";
    }
  } catch (const std::exception& e) {
    return e.what();
  }
  return {};
}

void restore(instance& inst, const std::vector<std::byte>& image) {
  header_reader r(image, "too short to be an FMU state");
  const state_header header = read_header(r);
  inst.component->restore_state(r.get_rest());
  inst.time = header.time;
  inst.state = header.lifecycle;
  inst.terminate_requested = header.terminate_requested;
  inst.values_dirty = true;
}

saved_state* find_state(instance& inst, void* handle) {
  auto* state = static_cast<saved_state*>(handle);
  return inst.saved_states.count(state) ? state : nullptr;
}

std::string take_state(instance& inst, void** handle) {
  if (handle == nullptr) return "null FMU state pointer";
  saved_state* target = nullptr;
  if (*handle != nullptr) {
    target = find_state(inst, *handle);
    if (target == nullptr) return "unknown FMU state to overwrite";
  }
  try {
    std::vector<std::byte> bytes = serialize(inst);
    if (target == nullptr) {
      target = new saved_state;
      inst.saved_states.insert(target);
    }
    target->bytes = std::move(bytes);
  } catch (const std::exception& e) {
    return e.what();
  }
  *handle = target;
  return {};
}

std::string load_state(instance& inst, const void* bytes, std::size_t size, void** handle) {
  if (handle == nullptr) return "null FMU state pointer";
  const auto* begin = static_cast<const std::byte*>(bytes);
  std::string problem = state_problem(inst, begin, size);
  if (!problem.empty()) return problem;
  auto* s = new saved_state;
  s->bytes.assign(begin, begin + size);
  inst.saved_states.insert(s);
  *handle = s;
  return {};
}

instance::instance(const loaded_fmu& definition, std::string name, std::string resource_dir,
                   log_sink sink)
    : loaded(definition), fmu(*definition.fmu), log(std::move(sink)) {
  context.instance_name = std::move(name);
  context.resource_dir = std::move(resource_dir);
  context.log = &log;
}

void instance::create_component() {
  component = fmu.create(context);
  data = static_cast<char*>(component->data());
  values_dirty = true;
}

std::string past_stop_message(const instance& inst, time_ns end) {
  return "the step ends at " + stride::text::format_double(to_seconds(end)) +
         " s, past the stopTime " + stride::text::format_double(to_seconds(*inst.stop_time)) +
         " s declared at initialization";
}

}  // namespace stride::sdk::glue

// libstdc++ is linked statically into every FMU; its emergency exception pool would be lost on
// each dlclose. Releasing it when the library unloads keeps importers leak-free under valgrind.
namespace __gnu_cxx {
void __freeres() noexcept;
}
__attribute__((destructor)) static void release_static_libstdcxx() {
  __gnu_cxx::__freeres();
}
