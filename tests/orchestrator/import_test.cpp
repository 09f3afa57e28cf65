// FMU import without a real FMU: archive safety (archives made at test time), the
// modelDescription.xml reader, and import errors that need no binary.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>

#include "stride/cosim/archive.hpp"
#include "stride/cosim/error.hpp"
#include "stride/cosim/fmu.hpp"
#include "stride/cosim/model_description.hpp"
#include "zip_writer.hpp"

namespace stride::cosim {
namespace {

namespace fs = std::filesystem;
using test::write_zip;
using test::zip_entry;
using ::testing::HasSubstr;

const char* const k_model_description = R"(<?xml version="1.0" encoding="UTF-8"?>
<fmiModelDescription fmiVersion="2.0" modelName="demo" guid="{1234}" generationTool="hand"
                     variableNamingConvention="structured">
  <CoSimulation modelIdentifier="demo" canHandleVariableCommunicationStepSize="true"
                canGetAndSetFMUstate="false"/>
  <UnitDefinitions><Unit name="rad"/></UnitDefinitions>
  <TypeDefinitions>
    <SimpleType name="Angle"><Real quantity="Angle" unit="rad"/></SimpleType>
  </TypeDefinitions>
  <DefaultExperiment startTime="0" stopTime="10" stepSize="0.008"/>
  <ModelVariables>
    <ScalarVariable name="gain" valueReference="0" causality="parameter" variability="tunable">
      <Real start="2" min="0" max="10"/>
    </ScalarVariable>
    <ScalarVariable name="u" valueReference="1" causality="input">
      <Real start="0" declaredType="Angle"/>
    </ScalarVariable>
    <ScalarVariable name="y" valueReference="2" causality="output" description="gain * u">
      <Real unit="m"/>
    </ScalarVariable>
    <ScalarVariable name="n" valueReference="3" causality="output" variability="discrete">
      <Integer/>
    </ScalarVariable>
    <ScalarVariable name="label" valueReference="4" causality="parameter" variability="fixed">
      <String start="stride"/>
    </ScalarVariable>
    <ScalarVariable name="on" valueReference="5" causality="input" variability="discrete">
      <Boolean start="true"/>
    </ScalarVariable>
  </ModelVariables>
  <ModelStructure>
    <Outputs>
      <Unknown index="3" dependencies="2"/>
      <Unknown index="4"/>
    </Outputs>
  </ModelStructure>
</fmiModelDescription>
)";

class cosim_import : public ::testing::Test {
 protected:
  temp_dir root{"stride-import-test-"};
  fs::path extract_root = root.path() / "extract";
  fs::path outside = root.path() / "outside";

  void SetUp() override {
    fs::create_directories(extract_root);
    fs::create_directories(outside / "inner");
  }

  fmu_import_options options() const {
    fmu_import_options o;
    o.extract_root = extract_root;
    return o;
  }

  std::string load_error(const fs::path& file, const fmu_import_options& o) const {
    try {
      fmu::load(file, o);
    } catch (const fmu_import_error& e) {
      return e.what();
    }
    return "no error";
  }

  bool extract_root_is_empty() const { return fs::is_empty(extract_root); }
};

TEST_F(cosim_import, rejects_parent_directory_entries_and_writes_nothing_outside) {
  // an archive placed deep inside `outside`, so "../" would land in `outside`
  const fs::path fmu_file = outside / "inner" / "evil.fmu";
  write_zip(fmu_file, {{"modelDescription.xml", k_model_description},
                       {"resources/../../escaped.txt", "x"},
                       {"../escaped.txt", "x"}});
  const std::string message = load_error(fmu_file, options());
  EXPECT_THAT(message, HasSubstr("escapes the archive with '..'"));
  EXPECT_THAT(message, HasSubstr(fmu_file.string()));
  EXPECT_FALSE(fs::exists(root.path() / "escaped.txt"));
  EXPECT_FALSE(fs::exists(outside / "escaped.txt"));
  EXPECT_FALSE(fs::exists(extract_root / "escaped.txt"));
  EXPECT_TRUE(extract_root_is_empty());  // the temporary folder was removed
}

TEST_F(cosim_import, rejects_absolute_paths) {
  const fs::path target = outside / "absolute.txt";
  const fs::path fmu_file = root.path() / "abs.fmu";
  write_zip(fmu_file, {{"modelDescription.xml", k_model_description}, {target.string(), "x"}});
  EXPECT_THAT(load_error(fmu_file, options()), HasSubstr("is an absolute path"));
  EXPECT_FALSE(fs::exists(target));
  EXPECT_TRUE(extract_root_is_empty());
}

TEST_F(cosim_import, rejects_symbolic_links) {
  const fs::path fmu_file = root.path() / "link.fmu";
  write_zip(fmu_file, {{"modelDescription.xml", k_model_description},
                       {"resources/link", outside.string(), true},
                       {"resources/link/planted.txt", "x"}});
  EXPECT_THAT(load_error(fmu_file, options()),
              HasSubstr("entry \"resources/link\" is a symbolic link"));
  EXPECT_FALSE(fs::exists(outside / "planted.txt"));
  EXPECT_TRUE(extract_root_is_empty());
}

TEST_F(cosim_import, rejects_oversized_entries) {
  const fs::path fmu_file = root.path() / "big.fmu";
  write_zip(fmu_file, {{"modelDescription.xml", k_model_description},
                       {"resources/big.bin", std::string(100000, 'z')}});
  auto o = options();
  o.limits.max_entry_size = 50000;
  EXPECT_THAT(load_error(fmu_file, o), HasSubstr("\"resources/big.bin\" is too large"));
  o.limits.max_entry_size = 1000000;
  o.limits.max_total_size = 50000;
  EXPECT_THAT(load_error(fmu_file, o), HasSubstr("exceeds the size limit"));
  EXPECT_TRUE(extract_root_is_empty());
}

// An archive whose headers declare an entry smaller than its content (a zip bomb lies this way):
// extraction stops at the declared size, whatever the limits allow, and leaves nothing behind.
TEST_F(cosim_import, an_entry_longer_than_its_declared_size_is_refused) {
  const fs::path file = root.path() / "liar.zip";
  write_zip(file, {{"a.txt", std::string(20000, 'a')}});
  std::string bytes;
  {
    std::ifstream in(file, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), {});
  }
  // the uncompressed size: offset 22 of the local header, 24 of the central directory header
  const auto patch = [&](const std::string& signature, std::size_t offset) {
    const auto at = bytes.find(signature);
    ASSERT_NE(at, std::string::npos);
    const std::uint32_t declared = 100;
    for (int i = 0; i < 4; ++i) bytes[at + offset + i] = static_cast<char>(declared >> (8 * i));
  };
  patch(std::string("PK\x03\x04", 4), 22);
  patch(std::string("PK\x01\x02", 4), 24);
  std::ofstream(file, std::ios::binary | std::ios::trunc) << bytes;
  const fs::path dest = root.path() / "dest";
  fs::create_directories(dest);
  try {
    extract_archive(file, dest);
    ADD_FAILURE() << "no error";
  } catch (const fmu_import_error& e) {
    EXPECT_THAT(e.what(), HasSubstr("entry \"a.txt\" inflates beyond its declared size"));
  }
  EXPECT_TRUE(fs::is_empty(dest));
}

TEST_F(cosim_import, one_entry_is_read_alone_within_the_same_limits) {
  const fs::path file = root.path() / "one.zip";
  write_zip(file, {{"modelDescription.xml", "<fmiModelDescription/>"},
                   {"binaries/linux64/big.so", std::string(300000, 'x')}});
  EXPECT_EQ(read_archive_entry(file, "modelDescription.xml"), "<fmiModelDescription/>");
  EXPECT_EQ(read_archive_entry(file, "missing.xml"), std::nullopt);
  EXPECT_EQ(read_archive_entry(file, "binaries/linux64/big.so")->size(), 300000u);
  try {
    read_archive_entry(file, "binaries/linux64/big.so", 1000);
    ADD_FAILURE() << "no error";
  } catch (const fmu_import_error& e) {
    EXPECT_THAT(e.what(), HasSubstr("entry \"binaries/linux64/big.so\" is too large (300000 "
                                    "bytes, limit 1000)"));
  }
  // a size in the headers that the data does not keep
  std::string bytes;
  {
    std::ifstream in(file, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), {});
  }
  const auto patch = [&](const std::string& signature, std::size_t offset) {
    const auto at = bytes.find(signature);  // the first entry's headers
    ASSERT_NE(at, std::string::npos);
    for (int i = 0; i < 4; ++i) bytes[at + offset + i] = static_cast<char>(i == 0 ? 5 : 0);
  };
  patch(std::string("PK\x03\x04", 4), 22);
  patch(std::string("PK\x01\x02", 4), 24);
  std::ofstream(file, std::ios::binary | std::ios::trunc) << bytes;
  try {
    read_archive_entry(file, "modelDescription.xml");
    ADD_FAILURE() << "no error";
  } catch (const fmu_import_error& e) {
    EXPECT_THAT(e.what(), HasSubstr("entry \"modelDescription.xml\" inflates beyond its declared "
                                    "size"));
  }
  std::ofstream(root.path() / "junk.zip") << "not a zip";
  EXPECT_THROW(read_archive_entry(root.path() / "junk.zip", "modelDescription.xml"),
               fmu_import_error);
}

TEST_F(cosim_import, the_description_of_an_archive_is_read_without_unpacking_it) {
  const fs::path fmu_file = root.path() / "described.fmu";
  write_zip(fmu_file, {{"modelDescription.xml", k_model_description},
                       {"binaries/linux64/demo.so", "not an ELF file"}});
  const model_description md = read_archive_description(fmu_file);
  ASSERT_EQ(md.variables.size(), 6u);
  EXPECT_EQ(md.variables[2].name, "y");
  const fs::path broken = root.path() / "broken.fmu";
  write_zip(broken, {{"modelDescription.xml", "<fmiModelDescription"}});
  try {
    read_archive_description(broken);
    ADD_FAILURE() << "no error";
  } catch (const fmu_import_error& e) {
    EXPECT_THAT(e.what(), HasSubstr((broken / "modelDescription.xml").string()));
  }
  const fs::path empty = root.path() / "empty.fmu";
  write_zip(empty, {{"resources/x", "x"}});
  try {
    read_archive_description(empty);
    ADD_FAILURE() << "no error";
  } catch (const fmu_import_error& e) {
    EXPECT_EQ(std::string(e.what()),
              empty.string() + ": no modelDescription.xml at the archive root");
  }
  EXPECT_TRUE(extract_root_is_empty());
}

TEST_F(cosim_import, rejects_backslashes_and_non_zip_files) {
  const fs::path fmu_file = root.path() / "win.fmu";
  write_zip(fmu_file, {{"binaries\\linux64\\demo.so", "x"}});
  EXPECT_THAT(load_error(fmu_file, options()), HasSubstr("backslash"));
  const fs::path junk = root.path() / "junk.fmu";
  std::ofstream(junk) << "not a zip";
  EXPECT_THAT(load_error(junk, options()), HasSubstr("not a zip archive"));
  EXPECT_THAT(load_error(root.path() / "missing.fmu", options()), HasSubstr("FMU file not found"));
  EXPECT_TRUE(extract_root_is_empty());
}

TEST_F(cosim_import, extracts_a_safe_archive) {
  const fs::path fmu_file = root.path() / "ok.zip";
  write_zip(fmu_file, {{"a/b/c.txt", "hello"}, {"top.txt", ""}});
  const fs::path dest = root.path() / "dest";
  fs::create_directories(dest);
  extract_archive(fmu_file, dest);
  std::ifstream in(dest / "a/b/c.txt");
  std::string text;
  in >> text;
  EXPECT_EQ(text, "hello");
  EXPECT_TRUE(fs::is_regular_file(dest / "top.txt"));
}

// Python's zipfile.writestr and other tools write permission bits without a file type
TEST_F(cosim_import, entries_with_permissions_but_no_file_type_are_files) {
  const fs::path fmu_file = root.path() / "typeless.zip";
  write_zip(fmu_file, {{"a/b.txt", "hello", false, 0600}, {"c.txt", "", false, 0644}});
  const fs::path dest = root.path() / "dest";
  fs::create_directories(dest);
  extract_archive(fmu_file, dest);
  std::ifstream in(dest / "a/b.txt");
  std::string text;
  in >> text;
  EXPECT_EQ(text, "hello");
  EXPECT_TRUE(fs::is_regular_file(dest / "c.txt"));
  // a type that is neither file, folder nor link is still refused
  write_zip(fmu_file, {{"fifo", "", false, S_IFIFO | 0600}});
  fs::remove_all(dest);
  fs::create_directories(dest);
  try {
    extract_archive(fmu_file, dest);
    ADD_FAILURE() << "a FIFO entry was extracted";
  } catch (const std::exception& e) {
    EXPECT_THAT(e.what(), HasSubstr("entry \"fifo\" is not a regular file or directory"));
  }
}

// the identifier names the binary: a path would make the importer load code from elsewhere
TEST_F(cosim_import, a_model_identifier_that_is_not_an_identifier_is_refused) {
  for (const std::string id : {"../../../tmp/evil", "/tmp/evil", "a b", "9lives"}) {
    std::string md = k_model_description;
    md.replace(md.find("modelIdentifier=\"demo\""), 22, "modelIdentifier=\"" + id + "\"");
    const fs::path fmu_file = root.path() / "id.fmu";
    write_zip(fmu_file, {{"modelDescription.xml", md}});
    EXPECT_EQ(load_error(fmu_file, options()),
              fmu_file.string() + ": modelIdentifier \"" + id +
                  "\" is not a C identifier (FMI 2.0 requires one: it names the binary and "
                  "prefixes its functions)")
        << id;
    EXPECT_TRUE(extract_root_is_empty());
  }
}

TEST_F(cosim_import, missing_binary_is_named) {
  const fs::path fmu_file = root.path() / "nobin.fmu";
  write_zip(fmu_file,
            {{"modelDescription.xml", k_model_description}, {"binaries/win64/demo.dll", "MZ"}});
  EXPECT_EQ(load_error(fmu_file, options()),
            fmu_file.string() +
                ": missing binary binaries/linux64/demo.so (the FMU has no binary for this "
                "platform)");
  EXPECT_TRUE(extract_root_is_empty());
}

TEST_F(cosim_import, unloadable_binary_is_named) {
  const fs::path fmu_file = root.path() / "badbin.fmu";
  write_zip(fmu_file, {{"modelDescription.xml", k_model_description},
                       {"binaries/linux64/demo.so", "not an ELF file"}});
  EXPECT_THAT(load_error(fmu_file, options()), HasSubstr("cannot load binaries/linux64/demo.so"));
  EXPECT_TRUE(extract_root_is_empty());
}

TEST_F(cosim_import, model_description_problems_are_named) {
  auto with = [&](const std::string& name, std::string md) {
    const fs::path f = root.path() / (name + ".fmu");
    write_zip(f, {{"modelDescription.xml", std::move(md)}});
    return load_error(f, options());
  };
  std::string md = k_model_description;
  auto replaced = [&](const std::string& from, const std::string& to) {
    std::string copy = md;
    copy.replace(copy.find(from), from.size(), to);
    return copy;
  };
  EXPECT_THAT(with("v1", replaced("fmiVersion=\"2.0\"", "fmiVersion=\"1.0\"")),
              HasSubstr("v1.fmu!modelDescription.xml:2: fmiVersion is \"1.0\""));
  EXPECT_THAT(with("noguid", replaced("guid=\"{1234}\"", "")), HasSubstr("missing or empty guid"));
  // a Model Exchange-only FMU is imported (docs/model-exchange.md): it fails later, here at
  // its missing binary; one with neither interface is refused
  EXPECT_THAT(with("me", replaced("<CoSimulation", "<ModelExchange")),
              HasSubstr("missing binary binaries/linux64/demo.so"));
  EXPECT_THAT(with("neither", replaced("<CoSimulation", "<Other")),
              HasSubstr("neither <CoSimulation> nor <ModelExchange> is declared"));
  EXPECT_THAT(with("badindex", replaced("index=\"3\"", "index=\"9\"")),
              HasSubstr("ModelStructure index \"9\" is not a variable position 1..6"));
  EXPECT_THAT(with("dup", replaced("name=\"n\"", "name=\"u\"")),
              HasSubstr("duplicate variable name \"u\""));
  EXPECT_THAT(with("broken", replaced("</ModelVariables>", "")), HasSubstr("malformed XML"));
  EXPECT_THAT(with("nanstop", replaced("stopTime=\"10\"", "stopTime=\"NaN\"")),
              HasSubstr("nanstop.fmu!modelDescription.xml:10: attribute stopTime=\"NaN\" is not "
                        "a finite number"));
  EXPECT_THAT(with("hexstep", replaced("stepSize=\"0.008\"", "stepSize=\"0x1p-7\"")),
              HasSubstr("attribute stepSize=\"0x1p-7\" is not a finite number"));
  const fs::path empty = root.path() / "empty.fmu";
  write_zip(empty, {{"resources/x", "x"}});
  EXPECT_THAT(load_error(empty, options()),
              HasSubstr("no modelDescription.xml at the archive root"));
  EXPECT_TRUE(extract_root_is_empty());
}

// ModelExchange, numberOfEventIndicators, derivative attributes and ModelStructure/Derivatives
TEST(cosim_model_description, reads_the_model_exchange_declarations) {
  const std::string head =
      "<fmiModelDescription fmiVersion=\"2.0\" guid=\"{me}\" numberOfEventIndicators=\"2\">\n"
      "<ModelExchange modelIdentifier=\"m\" completedIntegratorStepNotNeeded=\"true\" "
      "canGetAndSetFMUstate=\"true\"/>\n<ModelVariables>\n"
      "<ScalarVariable name=\"v\" valueReference=\"0\"><Real/></ScalarVariable>\n"
      "<ScalarVariable name=\"x\" valueReference=\"1\"><Real/></ScalarVariable>\n";
  const auto md = parse_model_description_text(
      head +
          "<ScalarVariable name=\"der(x)\" valueReference=\"2\"><Real derivative=\"2\"/>"
          "</ScalarVariable>\n</ModelVariables>\n"
          "<ModelStructure><Derivatives><Unknown index=\"3\"/></Derivatives></ModelStructure>\n"
          "</fmiModelDescription>",
      "me");
  EXPECT_FALSE(md.co_simulation);
  ASSERT_TRUE(md.model_exchange);
  EXPECT_EQ(md.model_exchange->model_identifier, "m");
  EXPECT_TRUE(md.model_exchange->completed_integrator_step_not_needed);
  EXPECT_TRUE(md.model_exchange->can_get_and_set_fmu_state);
  EXPECT_FALSE(md.model_exchange->can_serialize_fmu_state);
  EXPECT_EQ(md.number_of_event_indicators, 2u);
  EXPECT_EQ(md.derivatives, std::vector<std::size_t>{2});
  EXPECT_EQ(md.variables[2].derivative_of, std::optional<std::size_t>(1));
  EXPECT_FALSE(md.variables[1].derivative_of);

  const auto error_of = [&](const std::string& rest) {
    try {
      parse_model_description_text(head + rest, "me.xml");
    } catch (const fmu_import_error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const std::string end = "</ModelVariables>\n<ModelStructure><Derivatives><Unknown index=\"";
  EXPECT_EQ(error_of(end + "2\"/></Derivatives></ModelStructure></fmiModelDescription>"),
            "me.xml:7: Derivatives lists \"x\", which is not a Real with a derivative attribute");
  EXPECT_EQ(error_of("<ScalarVariable name=\"d\" valueReference=\"2\"><Real derivative=\"9\"/>"
                     "</ScalarVariable>\n" +
                     end + "3\"/></Derivatives></ModelStructure></fmiModelDescription>"),
            "me.xml:6: variable \"d\": derivative=\"9\" is not a variable position 1..3");
  EXPECT_EQ(error_of("<ScalarVariable name=\"d\" valueReference=\"2\"><Real derivative=\"0\"/>"
                     "</ScalarVariable>\n</ModelVariables></fmiModelDescription>"),
            "me.xml:6: variable \"d\": derivative=\"0\" is not a variable position");
}

TEST(cosim_model_description, reads_variables_structure_and_capabilities) {
  const auto md = parse_model_description_text(k_model_description, "demo");
  EXPECT_EQ(md.model_name, "demo");
  EXPECT_EQ(md.guid, "{1234}");
  EXPECT_EQ(md.generation_tool, "hand");
  ASSERT_TRUE(md.co_simulation);
  EXPECT_EQ(md.co_simulation->model_identifier, "demo");
  EXPECT_TRUE(md.co_simulation->can_handle_variable_communication_step_size);
  EXPECT_FALSE(md.co_simulation->can_get_and_set_fmu_state);
  EXPECT_EQ(*md.default_experiment.step_size, 0.008);
  EXPECT_FALSE(md.default_experiment.tolerance);
  ASSERT_EQ(md.variables.size(), 6u);
  const auto& gain = md.variables[0];
  EXPECT_EQ(gain.causality, causality::parameter);
  EXPECT_EQ(gain.variability, variability::tunable);
  EXPECT_EQ(*gain.start, "2");
  EXPECT_EQ(*gain.min, "0");
  EXPECT_EQ(*gain.max, "10");
  EXPECT_EQ(md.variables[1].unit, "rad");  // from its declared type
  EXPECT_EQ(md.variables[1].declared_type, "Angle");
  EXPECT_EQ(md.variables[2].unit, "m");
  EXPECT_EQ(md.variables[2].variability, variability::continuous);
  EXPECT_EQ(md.variables[2].description, "gain * u");
  EXPECT_EQ(md.variables[3].type, variable_type::integer);
  EXPECT_EQ(*md.variables[4].start, "stride");
  EXPECT_EQ(md.variables[5].type, variable_type::boolean);
  EXPECT_EQ(md.variables[0].line, 12);
  // y depends on u only; n lists no dependencies attribute: depends on everything
  EXPECT_TRUE(md.has_feedthrough(2, 1));
  EXPECT_FALSE(md.has_feedthrough(2, 5));
  EXPECT_TRUE(md.has_feedthrough(3, 5));
}

TEST(cosim_fmu, resource_uri_is_percent_encoded) {
  EXPECT_EQ(file_uri("/tmp/a b/résumé"), "file:///tmp/a%20b/r%C3%A9sum%C3%A9");
}

}  // namespace
}  // namespace stride::cosim
