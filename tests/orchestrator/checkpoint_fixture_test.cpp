// A checkpoint written elsewhere (docs/checkpoint-format.md): the run folder in data/checkpoint-v3
// was interrupted by SIGINT on another machine, in another folder, and is checked in. Resumed
// here, in a folder of its own, it ends where a run that was never stopped ends; marked as
// written on a big-endian host it resumes the same, since the images of Stride's components are
// portable. An earlier or unknown version, a non-portable image from a host of the other byte
// order and a damaged file are refused naming why. The fixture holds state images of the
// stride_test FMU: when its variables or data change (a new GUID or field list), make it again:
// run stride_test_counting.xml with --stop-time 10000 --record-interval 0.5, SIGINT it before
// t = 1000 s, keep the header and first rows of results.csv, set stop="1000" in system.xml and
// stop_time in manifest.json, name files without their folders in manifest.json, and set
// k_checkpoint_time to its "interrupted_at".
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "process.hpp"
#include "stride/cosim/archive.hpp"

namespace stride::cosim {
namespace {

namespace fs = std::filesystem;
using test::quoted;
using test::read_file;
using ::testing::HasSubstr;

const std::string k_cli = STRIDE_CLI;
const fs::path k_data = STRIDE_TEST_DATA_DIR;
const fs::path k_fixture = k_data / "checkpoint-v3";
constexpr double k_checkpoint_time = 858.84;  // the fixture's "interrupted_at"

// byte offsets in the fixture's checkpoint: the magic's length (8) and text (21), then these
constexpr std::size_t k_version_at = 29, k_order_at = 33, k_time_at = 34;
const std::string k_big_endian("\x01", 1);

class checkpoint_fixture : public ::testing::Test {
 protected:
  temp_dir scratch{"stride-checkpoint-"};

  // the fixture, copied to a folder of this test's own
  fs::path copy_of_fixture(const std::string& name) {
    const fs::path dir = scratch.path() / "somewhere else" / name;
    fs::create_directories(dir);
    for (const auto& e : fs::directory_iterator(k_fixture)) {
      fs::copy_file(e.path(), dir / e.path().filename());
    }
    return dir;
  }
  test::process_result resume(const fs::path& dir) {
    return test::run_command("'" + k_cli + "' run --resume " + quoted(dir) + " --quiet",
                             scratch.path());
  }
  static void patch(const fs::path& file, std::size_t at, const std::string& bytes) {
    std::string text = read_file(file);
    text.replace(at, bytes.size(), bytes);
    std::ofstream(file, std::ios::binary | std::ios::trunc) << text;
  }
};

// the rows of a results CSV after simulated time `after`
std::string rows_after(const std::string& csv, double after) {
  std::string out;
  std::size_t at = csv.find('\n') + 1;
  while (at < csv.size()) {
    const std::size_t end = csv.find('\n', at);
    const std::string line = csv.substr(at, end - at + 1);
    if (std::stod(line) > after) out += line;
    at = end + 1;
  }
  return out;
}

TEST_F(checkpoint_fixture, a_checkpoint_from_another_machine_resumes_to_the_uninterrupted_end) {
  const fs::path full = scratch.path() / "full";
  const auto r = test::run_command(
      "'" + k_cli + "' run " + quoted(k_data / "stride_test_counting.xml") +
          " --stop-time 1000 --record-interval 0.5 --quiet --output " + quoted(full),
      scratch.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string expected = rows_after(read_file(full / "results.csv"), k_checkpoint_time);
  ASSERT_FALSE(expected.empty());

  const fs::path dir = copy_of_fixture("run");
  const auto resumed = resume(dir);
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  EXPECT_EQ(rows_after(read_file(dir / "results.csv"), k_checkpoint_time), expected);
  EXPECT_THAT(read_file(dir / "manifest.json"), HasSubstr("\"status\": \"ok\""));

  // what a big-endian host writes: the same bytes but for the byte-order field
  const fs::path big = copy_of_fixture("big");
  patch(big / "checkpoint.stride", k_order_at, k_big_endian);
  const auto from_big = resume(big);
  ASSERT_EQ(from_big.exit_code, 0) << from_big.err;
  EXPECT_EQ(rows_after(read_file(big / "results.csv"), k_checkpoint_time), expected);
}

TEST_F(checkpoint_fixture, another_version_a_foreign_image_or_damage_is_refused_naming_it) {
  const auto refused = [&](const std::string& name, std::size_t at, const std::string& bytes) {
    const fs::path dir = copy_of_fixture(name);
    patch(dir / "checkpoint.stride", at, bytes);
    const auto r = resume(dir);
    EXPECT_NE(r.exit_code, 0) << name;
    return r.err;
  };
  EXPECT_THAT(refused("future", k_version_at, std::string("\x07\0\0\0", 4)),
              HasSubstr("checkpoint.stride: checkpoint version 7 is unknown: this stride reads "
                        "version 3"));
  EXPECT_THAT(refused("earlier", k_version_at, std::string("\x02\0\0\0", 4)),
              HasSubstr("checkpoint.stride: checkpoint version 2 was written by an earlier "
                        "stride, whose components saved their state in their host's memory "
                        "layout"));

  // version 1: the version in the magic, no byte-order field
  const std::string bytes = read_file(k_fixture / "checkpoint.stride");
  const fs::path v1 = copy_of_fixture("v1");
  const std::string magic = "stride run checkpoint 1";
  std::string length(8, '\0');
  length[0] = static_cast<char>(magic.size());
  std::ofstream(v1 / "checkpoint.stride", std::ios::binary | std::ios::trunc)
      << length + magic + bytes.substr(k_time_at);
  const auto old = resume(v1);
  EXPECT_NE(old.exit_code, 0);
  EXPECT_THAT(old.err, HasSubstr("checkpoint version 1 was written by an earlier stride"));

  // an image that is not a Stride component's, from a host of the other byte order
  const std::size_t image_at = bytes.find("STRDSTA2");
  ASSERT_NE(image_at, std::string::npos);
  const fs::path foreign = copy_of_fixture("foreign");
  patch(foreign / "checkpoint.stride", image_at, "OTHERFMU");
  patch(foreign / "checkpoint.stride", k_order_at, k_big_endian);
  const auto f = resume(foreign);
  EXPECT_NE(f.exit_code, 0);
  EXPECT_THAT(f.err, HasSubstr("written on a big-endian host, and the state of component 'a' is "
                               "in its FMU's own format, in that host's byte order"));

  const fs::path cut = copy_of_fixture("cut");
  fs::resize_file(cut / "checkpoint.stride", 100);
  const auto c = resume(cut);
  EXPECT_NE(c.exit_code, 0);
  EXPECT_THAT(c.err, HasSubstr("checkpoint.stride: damaged or truncated"));
  // nothing was lost: the rows the folder had are still there
  EXPECT_EQ(read_file(cut / "results.csv"), read_file(k_fixture / "results.csv"));
}

}  // namespace
}  // namespace stride::cosim
