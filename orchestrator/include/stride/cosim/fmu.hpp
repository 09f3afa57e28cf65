// Import of FMI 2.0 and FMI 3.0 Co-Simulation FMUs: unzip, parse, dlopen, instantiate.
#ifndef STRIDE_COSIM_FMU_HPP
#define STRIDE_COSIM_FMU_HPP

#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "stride/cosim/archive.hpp"
#include "stride/cosim/component.hpp"
#include "stride/cosim/log.hpp"
#include "stride/cosim/model_description.hpp"
#include "stride/cosim/model_exchange.hpp"

namespace stride::cosim {

/// How an FMU is imported.
struct fmu_import_options {
  /// parent of the private extraction directory; empty = the system temp directory
  std::filesystem::path extract_root;
  extract_limits limits;
};

/// How an instance is created.
struct instance_options {
  log_sink log;             ///< FMU log messages; empty = stderr_log_sink()
  bool logging_on = false;  ///< the loggingOn argument of fmi2Instantiate (debug logging)
  /// Set: run the FMU's Model Exchange interface with this integrator. An FMU without
  /// <CoSimulation> always runs as Model Exchange (with defaults when this is empty).
  std::optional<model_exchange_options> model_exchange = std::nullopt;
};

/// An imported FMU: its extracted files, its model description and its loaded binary. The
/// extraction directory is removed when the last reference (including instances) goes away.
class fmu : public std::enable_shared_from_this<fmu> {
 public:
  /// Unzips `file` into a private temporary directory, parses modelDescription.xml, checks
  /// fmiVersion 2.0 and CoSimulation, opens binaries/linux64/<modelIdentifier>.so with
  /// RTLD_LOCAL and resolves all 34 FMI 2.0 CS functions. An archive declaring fmiVersion 3.x
  /// is read as FMI 3.0 instead (binaries/x86_64-linux/, docs/fmu-interop.md).
  /// \throws fmu_import_error naming the FMU file and what is wrong.
  static std::shared_ptr<fmu> load(const std::filesystem::path& file,
                                   const fmu_import_options& options = {});

  ~fmu();
  fmu(const fmu&) = delete;
  fmu& operator=(const fmu&) = delete;

  const std::filesystem::path& file() const noexcept;
  const std::filesystem::path& extracted_dir() const noexcept;
  const stride::cosim::model_description& model_description() const noexcept;
  /// file:// URI of the resources folder, with a trailing slash.
  std::string resource_uri() const;

  /// Calls fmi2Instantiate (CoSimulation, the GUID of the model description).
  /// \throws component_error naming the instance if the FMU refuses (e.g. wrong GUID).
  std::unique_ptr<component> instantiate(const std::string& instance_name,
                                         const instance_options& options = {});

  /// The address of `name` in the loaded binary, or nullptr (the Model Exchange runner
  /// resolves its functions with it).
  void* symbol(const char* name) const noexcept;

  class impl;

 private:
  explicit fmu(std::unique_ptr<impl> pimpl);
  std::unique_ptr<impl> pimpl_;
};

/// Percent-encoded file:// URI of an absolute path.
std::string file_uri(const std::filesystem::path& absolute_path);

}  // namespace stride::cosim

#endif  // STRIDE_COSIM_FMU_HPP
