// What the importers of foreign system formats (SSP, OSP) share: namespace-aware reading of an
// XML file with messages that name file, line and element, the facts of the FMUs a system
// names, and the resolution of their URIs.
#ifndef STRIDE_COSIM_SRC_IMPORT_XML_HPP
#define STRIDE_COSIM_SRC_IMPORT_XML_HPP

#include <tinyxml2.h>

#include <filesystem>
#include <functional>
#include <initializer_list>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "stride/cosim/log.hpp"
#include "stride/cosim/model_description.hpp"
#include "stride/cosim/system_structure.hpp"

namespace stride::cosim::detail {

inline constexpr std::string_view k_ssd_ns =
    "http://ssp-standard.org/SSP1/SystemStructureDescription";
inline constexpr std::string_view k_ssc_ns = "http://ssp-standard.org/SSP1/SystemStructureCommon";
inline constexpr std::string_view k_ssv_ns =
    "http://ssp-standard.org/SSP1/SystemStructureParameterValues";
inline constexpr std::string_view k_ssm_ns =
    "http://ssp-standard.org/SSP1/SystemStructureParameterMapping";
inline constexpr std::string_view k_ssb_ns =
    "http://ssp-standard.org/SSP1/SystemStructureSignalDictionary";
inline constexpr std::string_view k_osp_ns =
    "http://opensimulationplatform.com/MSMI/OSPSystemStructure";
/// the content of libcosim's and OMSimulator's SSP annotations (docs/ssp.md)
inline constexpr std::string_view k_osp_annotations_ns =
    "http://opensimulationplatform.com/SSP/OSPAnnotations";
inline constexpr std::string_view k_oms_ns =
    "https://raw.githubusercontent.com/OpenModelica/OMSimulator/master/schema/oms.xsd";
/// Stride's own annotation content (docs/ssp.md)
inline constexpr std::string_view k_stride_ns = "https://stride-sim.org/ssp/1";

/// One permitted child of an element: namespace, local name, its rank in the XSD sequence
/// (children of equal rank may alternate) and whether it may repeat.
struct child_rule {
  std::string_view ns;
  std::string_view local;
  int rank = 0;
  bool repeat = false;
};

/// A parsed XML file of a system; every message it makes names `shown` (the file as the user
/// knows it, e.g. "pair.ssp/SystemStructure.ssd"), the line and the element.
class xml_file {
 public:
  /// Reads and parses `path`. Files it refers to must lie below `root` when that is given (an
  /// extracted archive). \throws validation_error (not found, not UTF-8, malformed).
  xml_file(const std::filesystem::path& path, std::string shown, std::filesystem::path root = {});
  /// Parses `text` (already read from `path`).
  xml_file(std::string_view text, const std::filesystem::path& path, std::string shown);
  xml_file(const xml_file&) = delete;
  xml_file& operator=(const xml_file&) = delete;

  const tinyxml2::XMLElement& root() const { return *doc_.RootElement(); }
  const std::filesystem::path& path() const noexcept { return path_; }
  const std::string& shown() const noexcept { return shown_; }

  source_location at(const tinyxml2::XMLElement& e) const { return {shown_, e.GetLineNum()}; }
  /// "file:line: <ssd:Component name="a">: "
  std::string where(const tinyxml2::XMLElement& e) const;
  [[noreturn]] void fail(const tinyxml2::XMLElement& e, const std::string& message) const;

  /// The namespace URI of the element's prefix (xmlns declarations on it and its ancestors).
  std::string_view ns(const tinyxml2::XMLElement& e) const;
  static std::string_view local(const tinyxml2::XMLElement& e);
  bool is(const tinyxml2::XMLElement& e, std::string_view ns, std::string_view local) const;

  /// Refuses attributes other than `allowed` (namespace declarations and xsi:* pass).
  void allow_attributes(const tinyxml2::XMLElement& e,
                        std::initializer_list<std::string_view> allowed) const;
  std::optional<std::string> attribute(const tinyxml2::XMLElement& e, const char* name) const;
  std::string required(const tinyxml2::XMLElement& e, const char* name) const;
  /// xs:boolean ("true", "false", "1", "0").
  bool boolean(const tinyxml2::XMLElement& e, const char* name, bool fallback) const;
  /// A finite xs:double attribute.
  std::optional<double> real(const tinyxml2::XMLElement& e, const char* name) const;
  /// Exact seconds (a whole number of nanoseconds), from the attribute's text.
  duration seconds(const tinyxml2::XMLElement& e, std::string_view text,
                   std::string_view what) const;

  /// The existing file that the URI `uri` (an attribute of `e`) names, relative to this file's
  /// folder; `what` names it in messages ("FMU", "parameter set"). \throws validation_error
  /// for an unsupported URI, a file outside the archive, or one that does not exist.
  std::filesystem::path resolve(const tinyxml2::XMLElement& e, std::string_view uri,
                                std::string_view what) const;
  /// A file this one refers to, read as an xml_file named as the user knows it.
  std::unique_ptr<xml_file> open(const std::filesystem::path& file) const;

  /// Walks the children: each must match a rule, in the order of the ranks, a rule without
  /// `repeat` at most once; `visit` gets each child with the rule's local name.
  void children(
      const tinyxml2::XMLElement& e, const std::vector<child_rule>& rules,
      const std::function<void(const tinyxml2::XMLElement&, std::string_view)>& visit) const;

 private:
  void parse(std::string_view text);

  tinyxml2::XMLDocument doc_;
  std::filesystem::path path_;
  std::string shown_;
  std::filesystem::path root_;
};

/// The model descriptions of the FMUs a system names, each read once (the archive is unpacked
/// into a temporary folder and removed again).
class fmu_facts {
 public:
  /// \throws validation_error naming `where` when the FMU cannot be read.
  const model_description& of(const std::filesystem::path& fmu, const std::string& where);

 private:
  std::map<std::filesystem::path, model_description> known_;
};

/// A relative URI reference (RFC 3986 path, percent-encoded) or a file: URI as a path against
/// `base`; nullopt with `why` set for any other scheme, a query or a fragment.
std::optional<std::filesystem::path> uri_to_path(std::string_view uri,
                                                 const std::filesystem::path& base,
                                                 std::string& why);

/// The `fmu` text of a component_spec for an FMU file at `file` (relative to `base` where it
/// lies below it), never taken for a bundled FMU name.
std::string fmu_reference(const std::filesystem::path& file, const std::filesystem::path& base);

/// Why `name` cannot be a Stride component name (dots are the importers' to place), or "".
/// With `copy_index`, a name may end in one copy index "[k]" (k ≥ 1, no leading zero): the
/// name a replica group gives copy k of a member ("gait[1]"), as an SSP export writes it.
std::string component_name_problem(std::string_view name, bool copy_index = false);

/// The system's default name: the file's stem, or for the standard file names
/// (SystemStructure.ssd, OspSystemStructure.xml) the name of the folder or archive `shown`
/// names.
std::string default_system_name(const std::filesystem::path& shown);

/// A log sink that drops nothing: `log` or, when empty, stderr from warnings on.
log_sink sink_or_stderr(const log_sink& log);

/// An SSD (docs/ssp.md); `root` confines the files it names (an extracted .ssp), `shown` names
/// it in messages.
system_structure import_ssd(const std::filesystem::path& ssd, const std::string& shown,
                            const std::filesystem::path& root, const log_sink& log);
/// An OspSystemStructure document (docs/ssp.md).
system_structure import_osp(const xml_file& file);

}  // namespace stride::cosim::detail

#endif  // STRIDE_COSIM_SRC_IMPORT_XML_HPP
