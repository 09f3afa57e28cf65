#include "stride/cosim/fmu.hpp"

#include <dlfcn.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <mutex>
#include <vector>

#include "fmi2_calls.hpp"
#include "fmi2_log.hpp"
#include "fmi3_fmu.hpp"
#include "me_component.hpp"
#include "required_symbol.hpp"
#include "stride/common/files.hpp"
#include "stride/cosim/error.hpp"
#include "stride/fmi2/fmi2_api.h"
#include "stride/fmi2/vocabulary.hpp"

namespace stride::cosim {

namespace fs = std::filesystem;

std::string file_uri(const fs::path& absolute_path) {
  static constexpr char hex[] = "0123456789ABCDEF";
  std::string out = "file://";
  for (const unsigned char c : absolute_path.generic_string()) {
    const bool plain = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                       c == '/' || c == '-' || c == '_' || c == '.' || c == '~';
    if (plain) {
      out += static_cast<char>(c);
    } else {
      out += '%';
      out += hex[c >> 4];
      out += hex[c & 15];
    }
  }
  return out;
}

namespace {

// The 34 resolved entry points.
struct fmi2_functions {
#define STRIDE_DECLARE_POINTER(name) name##TYPE* name = nullptr;
  STRIDE_FMI2_CS_FUNCTIONS(STRIDE_DECLARE_POINTER)
#undef STRIDE_DECLARE_POINTER
};

std::string status_name(fmi2Status s) {
  return std::string(fmi2::to_string(static_cast<fmi2::status>(s)));
}

}  // namespace

class fmu::impl {
 public:
  fs::path file;
  temp_dir dir;
  stride::cosim::model_description md;
  void* library = nullptr;
  fmi2_functions fn;
  std::atomic<int> instances{0};  // runs on several threads may share one import
  // set for an FMI 3.0 archive, which has its own loader and component (fmi3_fmu.cpp)
  std::shared_ptr<fmi3::binary> fmi3;

  explicit impl(temp_dir d) : dir(std::move(d)) {}
  ~impl();
};

namespace {

// Loading and unloading FMU binaries one at a time in the process: a binary's static
// constructors and destructors (e.g. a physics library's process-wide set-up and tear-down,
// reference counted without atomics) then never run concurrently with another's.
std::mutex& library_mutex() {
  static std::mutex m;
  return m;
}

// One instance of an FMU.
class fmu_component final : public component {
 public:
  fmu_component(std::shared_ptr<fmu> owner, fmu::impl& fmu_impl, std::string name,
                const instance_options& options)
      : owner_(std::move(owner)),
        fmu_(fmu_impl),
        fn_(fmu_impl.fn),
        name_(std::move(name)),
        log_(options.log ? options.log : stderr_log_sink()),
        callbacks_{&fmu_component::logger, std::calloc, std::free, nullptr, this} {
    const std::string uri = owner_->resource_uri();
    instance_ =
        fn_.fmi2Instantiate(name_.c_str(), fmi2CoSimulation, fmu_.md.guid.c_str(), uri.c_str(),
                            &callbacks_, fmi2False, options.logging_on ? fmi2True : fmi2False);
    if (instance_ == nullptr) {
      throw component_error("component '" + name_ + "': fmi2Instantiate of " + fmu_.file.string() +
                            " failed (GUID " + fmu_.md.guid +
                            "; see the FMU's log messages above)");
    }
  }

  ~fmu_component() override {
    if (instance_ == nullptr || fatal_) return;
    if (may_terminate()) fn_.fmi2Terminate(instance_);
    fn_.fmi2FreeInstance(instance_);
  }

  const std::string& name() const noexcept override { return name_; }
  const stride::cosim::model_description& model_description() const noexcept override {
    return fmu_.md;
  }

  void setup(time_point start, std::optional<time_point> stop) override {
    check("fmi2SetupExperiment",
          fn_.fmi2SetupExperiment(instance_, fmi2False, 0.0, to_seconds(start),
                                  stop ? fmi2True : fmi2False, stop ? to_seconds(*stop) : 0.0));
  }
  void enter_initialization() override {
    check("fmi2EnterInitializationMode", fn_.fmi2EnterInitializationMode(instance_));
  }
  void exit_initialization() override {
    check("fmi2ExitInitializationMode", fn_.fmi2ExitInitializationMode(instance_));
    stepping_ = true;
  }

  // FMI 2.0 allows fmi2Terminate only after initialization (step mode) and not after an error;
  // an instance still in initialization mode is only freed
  void terminate() override {
    if (!may_terminate()) return;
    terminated_ = true;
    check("fmi2Terminate", fn_.fmi2Terminate(instance_));
  }

  void set_values(const variable_refs& refs, const value_block& values) override {
    detail::fmi2_set_values(fn_, instance_, refs, values, scratch_, checker());
  }

  void get_values(const variable_refs& refs, value_block& values) override {
    detail::fmi2_get_values(fn_, instance_, refs, values, scratch_, checker());
    refuse_non_finite(refs.reals, values.reals);
  }

  void expose(const variable_refs& inputs, const variable_refs& outputs) override {
    inputs_ = inputs;
    outputs_ = outputs;
  }

  step_result step(time_point t, duration dt, const value_block& inputs,
                   value_block& outputs) override {
    set_values(inputs_, inputs);
    const fmi2Status s = fn_.fmi2DoStep(instance_, to_seconds(t), to_seconds(dt), fmi2True);
    if (s == fmi2Discard) {
      fmi2Boolean terminated = fmi2False;
      const fmi2Status q = fn_.fmi2GetBooleanStatus(instance_, fmi2Terminated, &terminated);
      if ((q == fmi2OK || q == fmi2Warning) && terminated == fmi2True) {
        return step_result::terminate;
      }
      failed_ = true;
      throw component_error("component '" + name_ +
                            "': fmi2DoStep returned fmi2Discard without requesting termination "
                            "(fixed-step masters cannot retry a step)");
    }
    if (s != fmi2OK && s != fmi2Warning) check("fmi2DoStep", s);
    get_values(outputs_, outputs);
    return step_result::complete;
  }

  std::vector<std::byte> save_state() override {
    require_state_support();
    return detail::fmi2_save_state(fn_, instance_, checker());
  }

  void restore_state(std::span<const std::byte> bytes) override {
    require_state_support();
    detail::fmi2_restore_state(fn_, instance_, bytes, checker());
  }

 private:
  void require_state_support() const {
    const auto& cs = *fmu_.md.co_simulation;
    if (!cs.can_get_and_set_fmu_state || !cs.can_serialize_fmu_state) {
      throw component_error("component '" + name_ + "': " + fmu_.file.string() +
                            " cannot save its state (canGetAndSetFMUstate and "
                            "canSerializeFMUstate are not both true)");
    }
  }

  // An FMU that computes an infinity or NaN ends the run here, naming the variable, instead of
  // passing the value on to other components and into the results.
  void refuse_non_finite(const std::vector<value_reference>& refs,
                         const std::vector<double>& values) const {
    for (std::size_t i = 0; i < refs.size(); ++i) {
      if (std::isfinite(values[i])) continue;
      std::string variable = "value reference " + std::to_string(refs[i]);
      for (const auto& v : fmu_.md.variables) {
        if (v.type == variable_type::real && v.reference == refs[i]) variable = v.name;
      }
      const char* text = std::isnan(values[i]) ? "NaN" : values[i] > 0 ? "inf" : "-inf";
      throw component_error("component '" + name_ + "': fmi2GetReal gave " + name_ + "." +
                            variable + " = " + text +
                            ", not a finite number (non-finite values are not passed on)");
    }
  }

  void check(const char* function, fmi2Status s) {
    if (s == fmi2OK || s == fmi2Warning) return;
    if (s == fmi2Fatal) fatal_ = true;
    if (s == fmi2Error || s == fmi2Discard || s == fmi2Pending) failed_ = true;
    throw component_error("component '" + name_ + "': " + function + " returned " + status_name(s));
  }
  // check() as the shared calls of fmi2_calls.hpp take it
  struct status_check {
    fmu_component* self;
    void operator()(const char* function, fmi2Status s) const { self->check(function, s); }
  };
  status_check checker() { return {this}; }

  static void logger(fmi2ComponentEnvironment env, fmi2String /*instance*/, fmi2Status status,
                     fmi2String category, fmi2String message, ...) {
    auto* self = static_cast<fmu_component*>(env);
    if (self == nullptr) return;
    std::va_list args;
    va_start(args, message);
    detail::forward_fmi2_log(self->log_, self->name_, status, category, message, args);
    va_end(args);
  }

  std::shared_ptr<fmu> owner_;
  fmu::impl& fmu_;
  const fmi2_functions& fn_;
  std::string name_;
  log_sink log_;
  fmi2CallbackFunctions callbacks_;
  fmi2Component instance_ = nullptr;
  bool may_terminate() const { return stepping_ && !terminated_ && !failed_ && !fatal_; }

  bool stepping_ = false;  // initialization mode left: step mode
  bool terminated_ = false;
  bool failed_ = false;
  bool fatal_ = false;
  variable_refs inputs_;   // set by every step
  variable_refs outputs_;  // read after every step
  detail::fmi2_scratch scratch_;
};

}  // namespace

fmu::fmu(std::unique_ptr<impl> pimpl) : pimpl_(std::move(pimpl)) {}
fmu::~fmu() = default;

const fs::path& fmu::file() const noexcept {
  return pimpl_->file;
}
const fs::path& fmu::extracted_dir() const noexcept {
  return pimpl_->dir.path();
}
const model_description& fmu::model_description() const noexcept {
  return pimpl_->md;
}
std::string fmu::resource_uri() const {
  return file_uri(pimpl_->dir.path() / "resources") + "/";
}

fmu::impl::~impl() {
  if (library == nullptr) return;
  const std::lock_guard lock(library_mutex());
  ::dlclose(library);
}

std::shared_ptr<fmu> fmu::load(const fs::path& file, const fmu_import_options& options) {
  const std::string where = file.string();
  if (!fs::is_regular_file(file)) throw fmu_import_error(where + ": FMU file not found");

  // the temp dir is removed by RAII on every exit path below
  auto p = std::make_unique<impl>(temp_dir("stride-fmu-", options.extract_root));
  p->file = fs::absolute(file);
  extract_archive(file, p->dir.path(), options.limits);

  const fs::path md_file = p->dir.path() / "modelDescription.xml";
  if (!fs::is_regular_file(md_file)) {
    throw fmu_import_error(where + ": no modelDescription.xml at the archive root");
  }
  if (const std::string xml = common::read_file(md_file);
      fmi3::declared_fmi_version(xml).starts_with("3")) {
    p->fmi3 = fmi3::load(file, p->dir.path(), xml, library_mutex());
    p->md = p->fmi3->description.scalar;
    return std::shared_ptr<fmu>(new fmu(std::move(p)));
  }
  try {
    p->md = parse_model_description(md_file);
  } catch (const fmu_import_error& e) {
    // name the FMU rather than the temporary path
    std::string message = e.what();
    const std::string tmp = md_file.string();
    if (message.rfind(tmp, 0) == 0)
      message = where + "!modelDescription.xml" + message.substr(tmp.size());
    throw fmu_import_error(message);
  }
  if (!p->md.co_simulation && !p->md.model_exchange) {
    throw fmu_import_error(where + ": neither <CoSimulation> nor <ModelExchange> is declared");
  }
  // a Model Exchange-only FMU: its runner resolves the functions (me_component.cpp)
  const bool cs = p->md.co_simulation.has_value();
  const std::string& id =
      cs ? p->md.co_simulation->model_identifier : p->md.model_exchange->model_identifier;
  // it names the binary: a path here would load a library from outside the archive
  const bool identifier = !id.empty() && !std::isdigit(static_cast<unsigned char>(id[0])) &&
                          std::all_of(id.begin(), id.end(), [](char c) {
                            return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
                          });
  if (!identifier) {
    throw fmu_import_error(where + ": modelIdentifier \"" + id +
                           "\" is not a C identifier (FMI 2.0 requires one: it names the binary "
                           "and prefixes its functions)");
  }
  const fs::path binary = p->dir.path() / "binaries" / "linux64" / (id + ".so");
  if (!fs::is_regular_file(binary)) {
    throw fmu_import_error(where + ": missing binary binaries/linux64/" + id +
                           ".so (the FMU has no binary for this platform)");
  }
  {
    const std::lock_guard lock(library_mutex());
    p->library = ::dlopen(binary.c_str(), RTLD_NOW | RTLD_LOCAL);
  }
  if (p->library == nullptr) {
    const char* why = ::dlerror();
    throw fmu_import_error(where + ": cannot load binaries/linux64/" + id +
                           ".so: " + (why ? why : "unknown error"));
  }
  const std::string binary_name = where + ": binaries/linux64/" + id + ".so";
#define STRIDE_RESOLVE(name)                  \
  p->fn.name = reinterpret_cast<name##TYPE*>( \
      detail::required_symbol(::dlsym(p->library, #name), #name, binary_name));
  if (cs) {
    STRIDE_FMI2_CS_FUNCTIONS(STRIDE_RESOLVE)
  } else {
    STRIDE_RESOLVE(fmi2GetVersion)
  }
#undef STRIDE_RESOLVE
  const std::string version = p->fn.fmi2GetVersion() ? p->fn.fmi2GetVersion() : "";
  if (version != "2.0") {
    throw fmu_import_error(where + ": fmi2GetVersion() returns \"" + version + "\", not \"2.0\"");
  }
  return std::shared_ptr<fmu>(new fmu(std::move(p)));
}

void* fmu::symbol(const char* name) const noexcept {
  return ::dlsym(pimpl_->library, name);
}

std::unique_ptr<component> fmu::instantiate(const std::string& instance_name,
                                            const instance_options& options) {
  if (options.model_exchange || !pimpl_->md.co_simulation) {
    if (!pimpl_->md.model_exchange) {
      throw component_error("component '" + instance_name + "': " + pimpl_->file.string() +
                            " has no <ModelExchange> interface (kind=\"model-exchange\")");
    }
    auto instance =
        pimpl_->fmi3 ? fmi3::instantiate_model_exchange(shared_from_this(), *pimpl_->fmi3,
                                                        instance_name, options)
                     : instantiate_fmi2_model_exchange(shared_from_this(), instance_name, options);
    return run_model_exchange(std::move(instance), instance_name, options);
  }
  const auto& cs = *pimpl_->md.co_simulation;
  if (cs.can_be_instantiated_only_once_per_process && pimpl_->instances > 0) {
    throw component_error("component '" + instance_name + "': " + pimpl_->file.string() +
                          " can be instantiated only once per process");
  }
  std::unique_ptr<component> c =
      pimpl_->fmi3
          ? fmi3::instantiate(shared_from_this(), *pimpl_->fmi3, instance_name, options)
          : std::make_unique<fmu_component>(shared_from_this(), *pimpl_, instance_name, options);
  ++pimpl_->instances;
  return c;
}

}  // namespace stride::cosim
