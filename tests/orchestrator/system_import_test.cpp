// load_system_file picks the reader by what the path is; an .ssp is unpacked with the FMU
// archive's safety checks into a folder that lives exactly as long as the structure.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>

#include "fake_fmu.hpp"
#include "stride/cosim/archive.hpp"
#include "stride/cosim/error.hpp"
#include "stride/cosim/system_import.hpp"

namespace stride::cosim {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

const fs::path k_data = STRIDE_TEST_DATA_DIR;

std::string read(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

class system_import : public ::testing::Test {
 protected:
  temp_dir scratch{"stride-import-test-"};
  fs::path pair = scratch.path() / "pair";

  void SetUp() override {
    fs::copy(k_data / "ssp" / "pair", pair, fs::copy_options::recursive);
    test::write_fake_fmu(pair / "resources" / "stride_test.fmu", test::stride_test_variables());
  }

  // the pair folder as an archive, plus `extra` entries
  fs::path archive(const std::string& name, std::vector<test::zip_entry> extra = {},
                   bool with_ssd = true) const {
    std::vector<test::zip_entry> entries = std::move(extra);
    if (with_ssd) entries.push_back({"SystemStructure.ssd", read(pair / "SystemStructure.ssd")});
    for (const char* f : {"resources/vectors.ssv", "resources/stride_test.fmu"}) {
      entries.push_back({f, read(pair / f)});
    }
    const fs::path file = scratch.path() / name;
    test::write_zip(file, entries);
    return file;
  }

  std::string error(const fs::path& file) const {
    try {
      load_system_file(file);
    } catch (const validation_error& e) {
      return e.what();
    }
    return "(no error)";
  }
};

// the limits and checks of FMU archives hold for SSP archives, and what an SSD names must be there
TEST_F(system_import, hostile_or_incomplete_archives_are_refused_naming_what_is_wrong) {
  // an entry that inflates beyond the size its headers declare (a zip bomb's trick)
  const fs::path bomb = archive("bomb.ssp", {{"resources/zeros.bin", std::string(200000, '\0')}});
  std::string bytes = read(bomb);
  const auto patch = [&](const std::string& signature, std::size_t offset) {
    const auto at = bytes.find(signature);  // the first headers: resources/zeros.bin's
    ASSERT_NE(at, std::string::npos);
    for (int i = 0; i < 4; ++i) bytes[at + offset + i] = static_cast<char>(i == 0 ? 100 : 0);
  };
  patch(std::string("PK\x03\x04", 4), 22);
  patch(std::string("PK\x01\x02", 4), 24);
  std::ofstream(bomb, std::ios::binary | std::ios::trunc) << bytes;
  EXPECT_THAT(error(bomb),
              HasSubstr("entry \"resources/zeros.bin\" inflates beyond its declared size"));

  // missing resources: the FMU, the parameter set
  std::vector<test::zip_entry> only_ssd = {
      {"SystemStructure.ssd", read(pair / "SystemStructure.ssd")}};
  const fs::path no_fmu = scratch.path() / "nofmu.ssp";
  test::write_zip(no_fmu,
                  {only_ssd[0], {"resources/vectors.ssv", read(pair / "resources/vectors.ssv")}});
  EXPECT_THAT(error(no_fmu),
              HasSubstr("nofmu.ssp/SystemStructure.ssd:10: <ssd:Component name=\"a\">: "
                        "FMU \"resources/stride_test.fmu\" not found"));
  const fs::path no_ssv = scratch.path() / "nossv.ssp";
  test::write_zip(
      no_ssv,
      {only_ssd[0], {"resources/stride_test.fmu", read(pair / "resources/stride_test.fmu")}});
  EXPECT_THAT(error(no_ssv), HasSubstr("\"resources/vectors.ssv\" not found"));

  // a cycle of nested systems cannot start: an SSD or SSP as a component is refused
  std::string ssd = read(pair / "SystemStructure.ssd");
  const std::string from = R"(name="b" source="resources/stride_test.fmu")";
  ssd.replace(ssd.find(from), from.size(),
              R"(name="b" type="application/x-ssp-definition" source="SystemStructure.ssd")");
  EXPECT_THAT(error(archive("cycle.ssp", {{"SystemStructure.ssd", ssd}}, false)),
              HasSubstr("cycle.ssp/SystemStructure.ssd:36: <ssd:Component name=\"b\">: type "
                        "\"application/x-ssp-definition\" is not supported"));
}

TEST_F(system_import, the_format_follows_from_the_path) {
  EXPECT_EQ(detect_system_format(pair), system_format::ssp_folder);
  EXPECT_EQ(detect_system_format(pair / "SystemStructure.ssd"), system_format::ssd);
  EXPECT_EQ(detect_system_format(archive("p.ssp")), system_format::ssp_archive);
  EXPECT_EQ(detect_system_format(k_data / "ssp" / "pair_osp"), system_format::osp);
  EXPECT_EQ(detect_system_format(k_data / "ssp" / "pair_osp" / "OspSystemStructure.xml"),
            system_format::osp);
  EXPECT_EQ(detect_system_format(k_data / "stride_test_pair.xml"), system_format::stride_xml);
  // any name, by its root element
  fs::copy_file(k_data / "ssp" / "pair_osp" / "OspSystemStructure.xml", scratch.path() / "x.xml");
  EXPECT_EQ(detect_system_format(scratch.path() / "x.xml"), system_format::osp);
  EXPECT_THAT(error(scratch.path() / "resources-none"), HasSubstr("cannot open the system file"));
  fs::create_directory(scratch.path() / "empty");
  EXPECT_THAT(error(scratch.path() / "empty"),
              HasSubstr("empty: a folder holding neither SystemStructure.ssd (SSP) nor "
                        "OspSystemStructure.xml (OSP)"));
}

TEST_F(system_import, stride_xml_reads_as_before) {
  const system_structure a = load_system_file(k_data / "stride_test_pair.xml");
  const system_structure b = parse_system_file(k_data / "stride_test_pair.xml");
  EXPECT_EQ(to_xml(a), to_xml(b));
}

TEST_F(system_import, an_archive_is_unpacked_for_as_long_as_the_structure_lives) {
  fs::path unpacked;
  {
    const system_structure s = load_system_file(archive("pair.ssp"));
    ASSERT_TRUE(s.extracted);
    unpacked = s.extracted->path();
    EXPECT_EQ(s.base_dir, unpacked);
    EXPECT_TRUE(fs::is_regular_file(unpacked / s.components[0].fmu));
    EXPECT_EQ(s.name, "pair");  // the archive's stem
    EXPECT_EQ(s.where.file, (scratch.path() / "pair.ssp" / "SystemStructure.ssd").string());
    const system_structure copy = s;  // copies share the folder
    (void)copy;
  }
  EXPECT_FALSE(fs::exists(unpacked));
}

TEST_F(system_import, bad_archives_are_refused_cleanly) {
  std::ofstream(scratch.path() / "text.ssp") << "not a zip";
  EXPECT_THAT(error(scratch.path() / "text.ssp"), HasSubstr("text.ssp: not a zip archive"));
  EXPECT_THAT(error(archive("evil.ssp", {{"../evil.txt", "x"}})),
              HasSubstr("entry \"../evil.txt\" escapes the archive"));
  EXPECT_THAT(error(archive("link.ssp", {{"resources/link.fmu", "/etc/passwd", true}})),
              HasSubstr("is a symbolic link"));
  EXPECT_THAT(error(archive("nossd.ssp", {}, false)),
              HasSubstr("nossd.ssp: no SystemStructure.ssd at its root (an SSP's default system)"));
  // an FMU the SSD names must lie inside the archive
  std::string ssd = read(pair / "SystemStructure.ssd");
  const std::string from = R"(name="b" source="resources/stride_test.fmu")";
  ssd.replace(ssd.find(from), from.size(), R"(name="b" source="../stride_test.fmu")");
  EXPECT_THAT(error(archive("out.ssp", {{"SystemStructure.ssd", ssd}}, false)),
              HasSubstr("out.ssp/SystemStructure.ssd:36: <ssd:Component name=\"b\">: FMU "
                        "\"../stride_test.fmu\" lies outside the archive"));
}

}  // namespace
}  // namespace stride::cosim
