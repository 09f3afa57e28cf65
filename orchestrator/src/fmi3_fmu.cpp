#include "fmi3_fmu.hpp"

#include <dlfcn.h>

#include <algorithm>
#include <cctype>

#include "required_symbol.hpp"
#include "stride/cosim/error.hpp"

namespace stride::cosim::fmi3 {

namespace fs = std::filesystem;

binary::~binary() {
  if (library == nullptr) return;
  const std::lock_guard lock(*library_mutex);
  ::dlclose(library);
}

namespace {

// It names the binary: a path here would load a library from outside the archive.
bool is_identifier(const std::string& id) {
  return !id.empty() && !std::isdigit(static_cast<unsigned char>(id[0])) &&
         std::all_of(id.begin(), id.end(), [](char c) {
           return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
         });
}

}  // namespace

std::shared_ptr<binary> load(const fs::path& file, const fs::path& dir, const std::string& xml,
                             std::mutex& library_mutex) {
  const std::string where = file.string();
  auto b = std::make_shared<binary>();
  b->file = fs::absolute(file);
  b->library_mutex = &library_mutex;
  b->description = parse_description(xml, where + "!modelDescription.xml");
  const auto& md = b->description.scalar;
  if (!md.co_simulation && !md.model_exchange) {
    throw fmu_import_error(where +
                           ": neither <CoSimulation> nor <ModelExchange> is declared (FMI 3.0 "
                           "Scheduled Execution is not supported)");
  }
  if (md.co_simulation && md.model_exchange &&
      md.co_simulation->model_identifier != md.model_exchange->model_identifier) {
    throw fmu_import_error(where +
                           ": different Co-Simulation and Model Exchange binaries; only one "
                           "binary per FMU is supported");
  }
  const std::string& id =
      md.co_simulation ? md.co_simulation->model_identifier : md.model_exchange->model_identifier;
  if (!is_identifier(id)) {
    throw fmu_import_error(where + ": modelIdentifier \"" + id +
                           "\" is not a C identifier (it names the binary)");
  }
  if (fs::is_directory(dir / "resources")) b->resources = dir / "resources";
  const std::string relative = "binaries/x86_64-linux/" + id + ".so";
  const fs::path so = dir / "binaries" / "x86_64-linux" / (id + ".so");
  if (!fs::is_regular_file(so)) {
    throw fmu_import_error(where + ": missing binary " + relative +
                           " (the FMU has no binary for this platform)");
  }
  {
    const std::lock_guard lock(library_mutex);
    b->library = ::dlopen(so.c_str(), RTLD_NOW | RTLD_LOCAL);
  }
  if (b->library == nullptr) {
    const char* why = ::dlerror();
    throw fmu_import_error(where + ": cannot load " + relative + ": " +
                           (why ? why : "unknown error"));
  }
  const std::string binary_name = where + ": " + relative;
#define STRIDE_RESOLVE(name)                  \
  b->fn.name = reinterpret_cast<name##TYPE*>( \
      cosim::detail::required_symbol(::dlsym(b->library, #name), #name, binary_name));
  STRIDE_FMI3_COMMON_FUNCTIONS(STRIDE_RESOLVE)
  if (md.co_simulation) {
    STRIDE_FMI3_CS_FUNCTIONS(STRIDE_RESOLVE)
  }
  if (md.model_exchange) {
    STRIDE_FMI3_ME_FUNCTIONS(STRIDE_RESOLVE)
  }
#undef STRIDE_RESOLVE
  const char* version = b->fn.fmi3GetVersion();
  if (version == nullptr || std::string(version) != "3.0") {
    throw fmu_import_error(where + ": fmi3GetVersion() returns \"" + (version ? version : "") +
                           "\", not \"3.0\"");
  }
  return b;
}

std::vector<std::byte> save_state(const functions& fn, fmi3Instance instance, call_checker check,
                                  void* context) {
  fmi3FMUState state = nullptr;
  check(context, "fmi3GetFMUState", fn.fmi3GetFMUState(instance, &state));
  std::vector<std::byte> bytes;
  try {
    size_t size = 0;
    check(context, "fmi3SerializedFMUStateSize",
          fn.fmi3SerializedFMUStateSize(instance, state, &size));
    bytes.resize(size);
    check(
        context, "fmi3SerializeFMUState",
        fn.fmi3SerializeFMUState(instance, state, reinterpret_cast<fmi3Byte*>(bytes.data()), size));
  } catch (...) {
    fn.fmi3FreeFMUState(instance, &state);
    throw;
  }
  check(context, "fmi3FreeFMUState", fn.fmi3FreeFMUState(instance, &state));
  return bytes;
}

void restore_state(const functions& fn, fmi3Instance instance, std::span<const std::byte> bytes,
                   call_checker check, void* context) {
  fmi3FMUState state = nullptr;
  check(context, "fmi3DeserializeFMUState",
        fn.fmi3DeserializeFMUState(instance, reinterpret_cast<const fmi3Byte*>(bytes.data()),
                                   bytes.size(), &state));
  const fmi3Status set = fn.fmi3SetFMUState(instance, state);
  fn.fmi3FreeFMUState(instance, &state);
  check(context, "fmi3SetFMUState", set);
}

std::string status_name(fmi3Status s) {
  switch (s) {
    case fmi3OK:
      return "fmi3OK";
    case fmi3Warning:
      return "fmi3Warning";
    case fmi3Discard:
      return "fmi3Discard";
    case fmi3Error:
      return "fmi3Error";
    case fmi3Fatal:
      return "fmi3Fatal";
  }
  return "status " + std::to_string(static_cast<int>(s));
}

void forward_log(const log_sink& sink, const std::string& component, fmi3Status status,
                 fmi3String category, fmi3String message) noexcept {
  if (message == nullptr) return;
  log_level level = log_level::info;
  if (status == fmi3Warning) level = log_level::warning;
  if (status == fmi3Error || status == fmi3Fatal || status == fmi3Discard) {
    level = log_level::error;
  }
  try {
    sink(level, component, category ? category : "", message);
  } catch (...) {
    // a throwing sink must not unwind through C code
  }
}

}  // namespace stride::cosim::fmi3
