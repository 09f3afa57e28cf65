// What the SSP and OSP exporters share (docs/ssp.md, "Export"): the system checked for what
// neither format can say, its FMUs resolved and named, its connections expanded into pairs of
// scalar variables, its parameter values in canonical text. Both writers read this plan only.
#ifndef STRIDE_COSIM_SRC_EXPORT_PLAN_HPP
#define STRIDE_COSIM_SRC_EXPORT_PLAN_HPP

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "import_xml.hpp"
#include "stride/cosim/model_description.hpp"
#include "stride/cosim/system_structure.hpp"

namespace stride::cosim::detail {

/// \throws validation_error "FILE:LINE: cannot export to FORMAT: WHAT" (no place: no prefix).
[[noreturn]] void refuse_export(std::string_view format, const source_location& where,
                                const std::string& what);

/// An FMU file as the export names it ("gait.fmu"; unique within the export).
struct export_fmu {
  std::filesystem::path file;
  std::string name;
};

/// A parameter or start value: the variable and its value as canonical text.
struct export_value {
  const variable_description* variable = nullptr;
  std::string text;
};

struct export_component {
  const component_spec* spec = nullptr;
  std::size_t fmu = 0;  ///< into export_plan::fmus
  const model_description* description = nullptr;
  std::vector<std::size_t> connectors;  ///< connected variables (indices), ascending
  std::vector<export_value> values;     ///< one per variable, in the system's order
  /// SSP: values of non-String variables holding a placeholder ("${agent}"), as written; the
  /// run substitutes them (none of these variables is in `values`)
  std::vector<export_value> placeholders;
};

/// One scalar connection.
struct export_connection {
  std::size_t from = 0, to = 0;                    ///< component indices
  std::size_t from_variable = 0, to_variable = 0;  ///< variable indices of their FMUs
  bool delayed = false;
  double factor = 1.0;
  double offset = 0.0;
  source_location where;
};

/// The system as both exporters write it.
class export_plan {
 public:
  /// For SSP the plan holds the system with its replica groups expanded (the copies are
  /// components "gait[1]", ...); workers, agents and recording are the SSP writer's to annotate.
  /// \throws validation_error (via refuse_export) for anything the format cannot say: Model
  /// Exchange, names the importers refuse, unknown variables, connections other than output →
  /// input/parameter; for OSP also replica groups, agents, workers and recording other than the
  /// default.
  export_plan(const system_structure& system, const std::vector<std::filesystem::path>& search,
              std::string_view format);
  export_plan(const export_plan&) = delete;
  export_plan& operator=(const export_plan&) = delete;

  const system_structure& system() const noexcept { return system_; }
  const std::vector<export_fmu>& fmus() const noexcept { return fmus_; }
  const std::vector<export_component>& components() const noexcept { return components_; }
  /// sorted by target component and variable: the order the SSP importer gives them
  const std::vector<export_connection>& connections() const noexcept { return connections_; }
  std::string_view format() const noexcept { return format_; }
  /// The base step as a run takes it (base_step_of); nullopt when neither the system nor an FMU
  /// gives one.
  std::optional<duration> base_step() const;

 private:
  bool ssp() const noexcept { return format_ == "SSP"; }
  void check_osp_system() const;
  void add_component(const component_spec& c, const std::vector<std::filesystem::path>& search);
  std::string fmu_name_for(const std::filesystem::path& file) const;
  void add_values(export_component& out);
  static void set_value(std::vector<export_value>& values, const variable_description* v,
                        std::string text);
  static void erase_value(std::vector<export_value>& values, const variable_description* v);
  void add_connection(const connection_spec& c);
  std::vector<std::pair<std::size_t, std::size_t>> expand_side(const connection_spec& c,
                                                               const std::string& side) const;
  void finish_connections();

  std::string format_;
  system_structure system_;  // the system as written (SSP: replica groups expanded)
  fmu_facts facts_;          // owns the model descriptions the components point at
  std::vector<export_fmu> fmus_;
  std::vector<std::filesystem::path> canonical_;  // parallel to fmus_
  std::vector<export_component> components_;
  std::vector<export_connection> connections_;
};

/// `text` as a URI path (RFC 3986): unreserved characters and '/' as they are, others
/// percent-encoded (the SSP's and OSP's `source` attributes).
std::string uri_path(std::string_view text);

/// The XML text of `doc`, indented, with a declaration.
std::string xml_text(const tinyxml2::XMLDocument& doc);

/// Refuses an existing `target` unless `overwrite` (an existing non-empty folder for
/// `folder`), naming it.
void check_export_target(const std::filesystem::path& target, bool folder, bool overwrite);

}  // namespace stride::cosim::detail

#endif  // STRIDE_COSIM_SRC_EXPORT_PLAN_HPP
