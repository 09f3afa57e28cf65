// The SSP and OSP importers (libstride) on arbitrary bytes: the input read as an .ssd and as an
// OspSystemStructure.xml, beside an FMU "m.fmu" that declares a few variables (no binary: the
// importers read model descriptions only), so that components, connections and parameters are
// reached.
#include <zip.h>

#include <exception>
#include <filesystem>
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
  const stride::fuzz::input_file input(data, size, "fuzz.ssd");
  write_fmu(input.dir() / "m.fmu");
  load(input.path());
  const auto osp = input.dir() / "OspSystemStructure.xml";
  std::filesystem::copy_file(input.path(), osp);
  load(osp);
  return 0;
}
