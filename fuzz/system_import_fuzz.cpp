// The SSP and OSP importers (libstride) on arbitrary bytes: the input read as an .ssd, as an
// OspSystemStructure.xml and as the .ssv parameter set (with its .ssm mapping) of a fixed SSD,
// beside an FMU "m.fmu" that declares a few variables (no binary: the importers read model
// descriptions only), so that components, connections and parameters are reached.
#include <zip.h>

#include <exception>
#include <filesystem>
#include <fstream>
#include <string>

#include "fuzz_input.hpp"
#include "stride/cosim/system_import.hpp"

namespace {

constexpr std::string_view k_model_description = R"(<?xml version="1.0" encoding="UTF-8"?>
<fmiModelDescription fmiVersion="2.0" modelName="m" guid="{m}">
  <CoSimulation modelIdentifier="m"/>
  <ModelVariables>
    <ScalarVariable name="gain" valueReference="0" causality="parameter" variability="fixed"><Real start="1"/></ScalarVariable>
    <ScalarVariable name="u" valueReference="1" causality="input"><Real start="0" unit="m"/></ScalarVariable>
    <ScalarVariable name="y" valueReference="2" causality="output"><Real unit="m"/></ScalarVariable>
    <ScalarVariable name="n" valueReference="3" causality="input" variability="discrete"><Integer start="0"/></ScalarVariable>
    <ScalarVariable name="c" valueReference="4" causality="output" variability="discrete"><Integer/></ScalarVariable>
    <ScalarVariable name="on" valueReference="5" causality="input" variability="discrete"><Boolean start="false"/></ScalarVariable>
  </ModelVariables>
  <ModelStructure/>
</fmiModelDescription>
)";

// binds "p.ssv" through the mapping "p.ssm" to the component m
constexpr std::string_view k_binding_ssd = R"(<?xml version="1.0" encoding="UTF-8"?>
<ssd:SystemStructureDescription version="1.0" name="bind"
    xmlns:ssd="http://ssp-standard.org/SSP1/SystemStructureDescription">
  <ssd:System name="top">
    <ssd:Elements>
      <ssd:Component name="m" source="m.fmu">
        <ssd:ParameterBindings>
          <ssd:ParameterBinding source="p.ssv"/>
          <ssd:ParameterBinding source="p.ssv"><ssd:ParameterMapping source="p.ssm"/></ssd:ParameterBinding>
        </ssd:ParameterBindings>
      </ssd:Component>
    </ssd:Elements>
  </ssd:System>
</ssd:SystemStructureDescription>
)";

void write_text(const std::filesystem::path& file, std::string_view text) {
  std::ofstream(file, std::ios::binary) << text;
}

constexpr std::string_view k_empty_mapping = R"(<ssm:ParameterMapping version="1.0"
    xmlns:ssm="http://ssp-standard.org/SSP1/SystemStructureParameterMapping"/>)";
constexpr std::string_view k_plain_set = R"(<ssv:ParameterSet version="1.0" name="p"
    xmlns:ssv="http://ssp-standard.org/SSP1/SystemStructureParameterValues">
  <ssv:Parameters><ssv:Parameter name="g"><ssv:Real value="2"/></ssv:Parameter></ssv:Parameters>
</ssv:ParameterSet>)";

void write_fmu(const std::filesystem::path& file) {
  int error = 0;
  zip_t* za = zip_open(file.c_str(), ZIP_CREATE | ZIP_TRUNCATE, &error);
  if (za == nullptr) return;
  zip_source_t* src =
      zip_source_buffer(za, k_model_description.data(), k_model_description.size(), 0);
  if (zip_file_add(za, "modelDescription.xml", src, ZIP_FL_ENC_UTF_8) < 0) zip_source_free(src);
  zip_close(za);
}

void load(const std::filesystem::path& file) {
  try {
    (void)stride::cosim::load_system_file(file, [](stride::cosim::log_level, std::string_view,
                                                   std::string_view, std::string_view) {});
  } catch (const std::exception&) {
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  namespace fs = std::filesystem;
  const stride::fuzz::input_file input(data, size, "fuzz.ssd");
  // the harness's own file operations never throw: only the importers are under test
  std::error_code ignored;
  const auto copy = [&](const fs::path& from, const fs::path& to) {
    fs::copy_file(from, to, fs::copy_options::overwrite_existing, ignored);
  };
  write_fmu(input.dir() / "m.fmu");
  load(input.path());
  const auto osp = input.dir() / "OspSystemStructure.xml";
  copy(input.path(), osp);
  load(osp);
  // the input as a parameter set, then as a parameter mapping
  const auto dir = input.dir() / "bind";
  fs::create_directories(dir, ignored);
  write_fmu(dir / "m.fmu");
  write_text(dir / "SystemStructure.ssd", k_binding_ssd);
  copy(input.path(), dir / "p.ssv");
  write_text(dir / "p.ssm", k_empty_mapping);
  load(dir);
  write_text(dir / "p.ssv", k_plain_set);
  copy(input.path(), dir / "p.ssm");
  load(dir);
  return 0;
}
