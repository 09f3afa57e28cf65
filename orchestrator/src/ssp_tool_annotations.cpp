// Step size, master algorithm and integrator as two other SSP tools write them into their own
// annotations (docs/ssp.md, "Other tools' annotations"): libcosim (type
// com.opensimulationplatform, in the ssd:DefaultExperiment) and OMSimulator (type
// org.openmodelica, on its ssd:Systems). Both tools' fixed-step masters step every component from
// the same communication point with the inputs of the last one, which is Stride's Jacobi
// algorithm. Stride's own annotation wins over them.
#include "ssp_model.hpp"
#include "stride/cosim/error.hpp"

namespace stride::cosim::detail::ssp {

namespace {

using tinyxml2::XMLElement;

// Whether `e` is the tool's element `local`: by its namespace, or, as the tools themselves read
// their files without namespaces, by the tool's usual prefix when that is not declared.
bool is_tool_element(const xml_file& file, const XMLElement& e, std::string_view ns,
                     std::string_view prefix, std::string_view local) {
  if (xml_file::local(e) != local) return false;
  const std::string_view declared = file.ns(e);
  if (!declared.empty()) return declared == ns;
  const std::string_view name = e.Name();
  return name.size() == prefix.size() + 1 + local.size() && name.starts_with(prefix) &&
         name[prefix.size()] == ':';
}

const XMLElement* tool_child(const xml_file& file, const XMLElement& parent, std::string_view ns,
                             std::string_view prefix, std::string_view local) {
  for (const XMLElement* c = parent.FirstChildElement(); c != nullptr;
       c = c->NextSiblingElement()) {
    if (is_tool_element(file, *c, ns, prefix, local)) return c;
  }
  return nullptr;
}

duration positive_step(const xml_file& file, const XMLElement& e, const char* attribute) {
  const duration step = file.seconds(e, file.required(e, attribute), attribute);
  if (step <= duration::zero()) file.fail(e, std::string(attribute) + " must be positive");
  return step;
}

std::optional<double> positive_number(const xml_file& file, const XMLElement& e,
                                      const char* attribute) {
  const std::optional<double> v = file.real(e, attribute);
  if (v && *v <= 0) file.fail(e, std::string(attribute) + " must be positive");
  return v;
}

tool_stepping stepping(const xml_file& file, const XMLElement& annotation, const XMLElement& at,
                       duration step, std::string_view tool) {
  return {step, algorithm_kind::jacobi,
          std::string(tool) + " (" + file.attribute(annotation, "type").value_or("") + ") at " +
              file.at(at).str(),
          file.at(at)};
}

// OMSimulator's CVODE settings; its minimumStepSize and initialStepSize have no counterpart in
// Stride's integrator, which chooses those itself
model_exchange_options variable_step_solver(const xml_file& file, const XMLElement& e) {
  if (const auto d = file.attribute(e, "description"); d && *d != "cvode") {
    file.fail(e, "OMSimulator's variable-step solver \"" + *d +
                     "\" is not supported: Stride integrates with cvode");
  }
  model_exchange_options o;
  o.rtol = positive_number(file, e, "relativeTolerance");
  o.atol = positive_number(file, e, "absoluteTolerance");
  if (e.Attribute("maximumStepSize") != nullptr) {
    o.max_step = to_seconds(positive_step(file, e, "maximumStepSize"));
  }
  return o;
}

}  // namespace

std::optional<tool_stepping> read_osp_stepping(const xml_file& file, const XMLElement& annotation) {
  const XMLElement* algorithm =
      tool_child(file, annotation, k_osp_annotations_ns, "osp", "Algorithm");
  if (algorithm == nullptr) return std::nullopt;
  const XMLElement* fixed = algorithm->FirstChildElement();
  if (fixed == nullptr) file.fail(*algorithm, "names no algorithm");
  if (!is_tool_element(file, *fixed, k_osp_annotations_ns, "osp", "FixedStepAlgorithm")) {
    file.fail(*fixed,
              "libcosim's algorithm '" + std::string(xml_file::local(*fixed)) +
                  "' is not supported: Stride reads osp:FixedStepAlgorithm (its Jacobi master)");
  }
  // libcosim's own files spell it baseStepSize; early ones stepSize. numWorkerThreads sets
  // libcosim's parallelism, which does not change its results.
  file.allow_attributes(*fixed, {"baseStepSize", "stepSize", "numWorkerThreads"});
  const char* attribute = fixed->Attribute("baseStepSize") != nullptr ? "baseStepSize" : "stepSize";
  return stepping(file, annotation, *fixed, positive_step(file, *fixed, attribute),
                  "libcosim's annotation");
}

oms_simulation read_oms_simulation(const xml_file& file, const XMLElement& annotation) {
  // newer files wrap the content in oms:Annotations, older ones do not
  const XMLElement* content = tool_child(file, annotation, k_oms_ns, "oms", "Annotations");
  if (content == nullptr) content = &annotation;
  const XMLElement* info = tool_child(file, *content, k_oms_ns, "oms", "SimulationInformation");
  oms_simulation out;
  if (info == nullptr) return out;
  for (const XMLElement* c = info->FirstChildElement(); c != nullptr; c = c->NextSiblingElement()) {
    if (is_tool_element(file, *c, k_oms_ns, "oms", "FixedStepMaster")) {
      out.master = stepping(file, annotation, *c, positive_step(file, *c, "stepSize"),
                            "OMSimulator's annotation");
    } else if (is_tool_element(file, *c, k_oms_ns, "oms", "VariableStepSolver")) {
      out.solver = variable_step_solver(file, *c);
    } else if (is_tool_element(file, *c, k_oms_ns, "oms", "FixedStepSolver")) {
      model_exchange_options o;
      o.solver = model_exchange_options::solver_kind::euler;
      o.max_step = to_seconds(positive_step(file, *c, "stepSize"));
      out.solver = o;
    }
  }
  return out;
}

// Stride's annotation alone decides step and algorithm when it is there (an archive Stride
// exported carries the other tools' too); else the other tools' annotations, which must agree.
void take_stepping(const ssd_content& content, system_structure& s) {
  s.base_step = content.step;
  s.algorithm = content.algorithm.value_or(algorithm_kind::gauss_seidel);
  if (content.stride_annotation) {
    s.notes.stepping_from =
        "Stride's annotation (org.stride-sim.system) at " + content.stride_annotation->str();
    return;
  }
  if (content.tool_steppings.empty()) return;
  const tool_stepping& first = content.tool_steppings.front();
  s.notes.stepping_from = first.source;
  for (const auto& other : content.tool_steppings) {
    if (other.step != first.step) {
      throw validation_error(other.where.str() + ": the step " + format_seconds(other.step) +
                             " s of " + other.source + " differs from the step " +
                             format_seconds(first.step) + " s of " + first.source +
                             "; give one step (or Stride's system annotation, or --step)");
    }
    if (&other != &first) s.notes.stepping_from += " and " + other.source;
  }
  s.base_step = first.step;
  s.algorithm = first.algorithm;
}

}  // namespace stride::cosim::detail::ssp
