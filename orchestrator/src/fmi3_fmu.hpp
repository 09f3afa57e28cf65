// Import of FMI 3.0 Co-Simulation FMUs (docs/fmi3-rules.md), the leaf beside the 2.0 one in
// fmu.cpp: `fmu::load` reads the archive's fmiVersion and hands a 3.0 archive to `load_fmi3`;
// `fmu::instantiate` then makes its instances with `instantiate_fmi3`.
#ifndef STRIDE_COSIM_SRC_FMI3_FMU_HPP
#define STRIDE_COSIM_SRC_FMI3_FMU_HPP

#include <filesystem>
#include <memory>
#include <mutex>
#include <span>
#include <string>
#include <vector>

#include "fmi3_model_description.hpp"
#include "me_instance.hpp"
#include "stride/cosim/fmu.hpp"
#include "stride/fmi3/fmi3_api.h"

namespace stride::cosim::fmi3 {

// The entry points Stride calls with either interface.
#define STRIDE_FMI3_COMMON_FUNCTIONS(X) \
  X(fmi3GetVersion)                     \
  X(fmi3FreeInstance)                   \
  X(fmi3EnterInitializationMode)        \
  X(fmi3ExitInitializationMode)         \
  X(fmi3Terminate)                      \
  X(fmi3GetFloat32)                     \
  X(fmi3GetFloat64)                     \
  X(fmi3GetInt8)                        \
  X(fmi3GetUInt8)                       \
  X(fmi3GetInt16)                       \
  X(fmi3GetUInt16)                      \
  X(fmi3GetInt32)                       \
  X(fmi3GetUInt32)                      \
  X(fmi3GetInt64)                       \
  X(fmi3GetUInt64)                      \
  X(fmi3GetBoolean)                     \
  X(fmi3GetString)                      \
  X(fmi3GetBinary)                      \
  X(fmi3SetFloat32)                     \
  X(fmi3SetFloat64)                     \
  X(fmi3SetInt8)                        \
  X(fmi3SetUInt8)                       \
  X(fmi3SetInt16)                       \
  X(fmi3SetUInt16)                      \
  X(fmi3SetInt32)                       \
  X(fmi3SetUInt32)                      \
  X(fmi3SetInt64)                       \
  X(fmi3SetUInt64)                      \
  X(fmi3SetBoolean)                     \
  X(fmi3SetString)                      \
  X(fmi3SetBinary)                      \
  X(fmi3GetFMUState)                    \
  X(fmi3SetFMUState)                    \
  X(fmi3FreeFMUState)                   \
  X(fmi3SerializedFMUStateSize)         \
  X(fmi3SerializeFMUState)              \
  X(fmi3DeserializeFMUState)

// Co-Simulation without events or clocks.
#define STRIDE_FMI3_CS_FUNCTIONS(X) \
  X(fmi3InstantiateCoSimulation)    \
  X(fmi3DoStep)

// Model Exchange (docs/model-exchange.md).
#define STRIDE_FMI3_ME_FUNCTIONS(X)    \
  X(fmi3InstantiateModelExchange)      \
  X(fmi3EnterEventMode)                \
  X(fmi3UpdateDiscreteStates)          \
  X(fmi3EnterContinuousTimeMode)       \
  X(fmi3CompletedIntegratorStep)       \
  X(fmi3SetTime)                       \
  X(fmi3SetContinuousStates)           \
  X(fmi3GetContinuousStates)           \
  X(fmi3GetContinuousStateDerivatives) \
  X(fmi3GetEventIndicators)            \
  X(fmi3GetNominalsOfContinuousStates) \
  X(fmi3GetNumberOfContinuousStates)   \
  X(fmi3GetNumberOfEventIndicators)

struct functions {
#define STRIDE_DECLARE_POINTER(name) name##TYPE* name = nullptr;
  STRIDE_FMI3_COMMON_FUNCTIONS(STRIDE_DECLARE_POINTER)
  STRIDE_FMI3_CS_FUNCTIONS(STRIDE_DECLARE_POINTER)
  STRIDE_FMI3_ME_FUNCTIONS(STRIDE_DECLARE_POINTER)
#undef STRIDE_DECLARE_POINTER
};

/// A loaded FMI 3.0 binary with its parsed model description.
struct binary {
  std::filesystem::path file;       ///< the .fmu, for messages
  std::filesystem::path resources;  ///< extracted resources/ folder; empty if none
  fmi3::description description;
  functions fn;
  void* library = nullptr;
  std::mutex* library_mutex = nullptr;  ///< serializes dlopen/dlclose with the 2.0 loader

  binary() = default;
  binary(const binary&) = delete;
  binary& operator=(const binary&) = delete;
  ~binary();
};

/// Parses `xml` (the archive's modelDescription.xml), refuses what Stride does not offer
/// (neither <CoSimulation> nor <ModelExchange>, two binaries, clocks), opens
/// binaries/x86_64-linux/<modelIdentifier>.so from `dir` with RTLD_LOCAL and resolves the
/// functions of the interfaces the FMU declares.
/// \throws fmu_import_error naming `file` and the feature or defect.
std::shared_ptr<binary> load(const std::filesystem::path& file, const std::filesystem::path& dir,
                             const std::string& xml, std::mutex& library_mutex);

/// One instance of `bin` as a component (fmi3InstantiateCoSimulation with visible=false,
/// eventModeUsed=false, earlyReturnAllowed=false, no intermediate update). `owner` keeps the
/// extraction and the binary alive.
/// \throws component_error naming the instance if the FMU refuses.
std::unique_ptr<component> instantiate(std::shared_ptr<const void> owner, const binary& bin,
                                       const std::string& name, const instance_options& options);

/// One Model Exchange instance of `bin` (fmi3InstantiateModelExchange with visible=false) for
/// the runner of me_component.hpp.
/// \throws component_error naming the instance if the FMU refuses.
std::unique_ptr<cosim::detail::me_instance> instantiate_model_exchange(
    std::shared_ptr<const void> owner, const binary& bin, const std::string& name,
    const instance_options& options);

/// Throws for a failing status, naming the function (each component's own check).
using call_checker = void (*)(void* context, const char* function, fmi3Status status);

/// The instance's FMU state, serialized (the FMU state itself is freed on every path).
std::vector<std::byte> save_state(const functions& fn, fmi3Instance instance, call_checker check,
                                  void* context);
void restore_state(const functions& fn, fmi3Instance instance, std::span<const std::byte> bytes,
                   call_checker check, void* context);

/// "fmi3OK", "fmi3Error", ...
std::string status_name(fmi3Status s);

/// Hands one message of the FMU's logMessage callback to `sink`; never throws (it runs inside C
/// code).
void forward_log(const log_sink& sink, const std::string& component, fmi3Status status,
                 fmi3String category, fmi3String message) noexcept;

}  // namespace stride::cosim::fmi3

#endif  // STRIDE_COSIM_SRC_FMI3_FMU_HPP
