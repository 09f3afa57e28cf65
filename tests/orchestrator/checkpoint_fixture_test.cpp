// A checkpoint written elsewhere (docs/checkpoint-format.md): the run folder in data/checkpoint-v2
// was interrupted by SIGINT on another machine, in another folder, and is checked in. Resumed
// here, in a folder of its own, it ends where a run that was never stopped ends. A checkpoint of
// an unknown version, or with state images of the other byte order, is refused naming why; one
// of version 1 is still read. The fixture holds state images of the stride_test FMU: when its
// variables or data change (a new GUID or layout), make it again: run stride_test_counting.xml
// with --stop-time 10000 --record-interval 0.5, SIGINT it, keep the header and first rows of
// results.csv, set stop="1000" in system.xml, and set k_checkpoint_time to "interrupted_at".
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
const fs::path k_fixture = k_data / "checkpoint-v2";
constexpr double k_checkpoint_time = 958.73;  // the fixture's "interrupted_at"

// byte offsets in the fixture's checkpoint: the magic's length (8) and text (21), then these
constexpr std::size_t k_version_at = 29, k_order_at = 33, k_time_at = 34;

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
  const fs::path dir = copy_of_fixture("run");
  const auto resumed = resume(dir);
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  const std::string expected = rows_after(read_file(full / "results.csv"), k_checkpoint_time);
  ASSERT_FALSE(expected.empty());
  EXPECT_EQ(rows_after(read_file(dir / "results.csv"), k_checkpoint_time), expected);
  EXPECT_THAT(read_file(dir / "manifest.json"), HasSubstr("\"status\": \"ok\""));

  // version 1: the version in the magic, no byte-order field
  const fs::path v1 = copy_of_fixture("v1");
  const std::string v2 = read_file(k_fixture / "checkpoint.stride");
  std::string magic = "stride run checkpoint 1";
  std::string length(8, '\0');
  length[0] = static_cast<char>(magic.size());
  std::ofstream(v1 / "checkpoint.stride", std::ios::binary | std::ios::trunc)
      << length + magic + v2.substr(k_time_at);
  const auto old = resume(v1);
  ASSERT_EQ(old.exit_code, 0) << old.err;
  EXPECT_EQ(rows_after(read_file(v1 / "results.csv"), k_checkpoint_time), expected);
}

TEST_F(checkpoint_fixture, an_unknown_version_or_the_other_byte_order_is_refused_naming_it) {
  const fs::path future = copy_of_fixture("future");
  patch(future / "checkpoint.stride", k_version_at, std::string("\x07\0\0\0", 4));
  const auto r = resume(future);
  EXPECT_NE(r.exit_code, 0);
  EXPECT_THAT(r.err, HasSubstr("checkpoint.stride: checkpoint version 7 is unknown: this stride "
                               "reads versions 1 to 2"));

  const fs::path big = copy_of_fixture("big");
  patch(big / "checkpoint.stride", k_order_at, std::string("\x01", 1));
  const auto b = resume(big);
  EXPECT_NE(b.exit_code, 0);
  EXPECT_THAT(b.err, HasSubstr("written on a big-endian host; the components' state images in it "
                               "are in that byte order, this host is little-endian"));

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
