// Reading a results CSV back: numbers, Booleans, text columns, quoting, and errors naming the
// file and line.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "stride/cosim/archive.hpp"
#include "stride/suite/results.hpp"

namespace stride::suite {
namespace {

namespace fs = std::filesystem;
using ::testing::ElementsAre;
using ::testing::HasSubstr;
using ::testing::StartsWith;

class suite_results : public ::testing::Test {
 protected:
  cosim::temp_dir scratch{"stride-suite-results-"};
  fs::path write(const std::string& name, const std::string& text) {
    const fs::path file = scratch.path() / name;
    std::ofstream(file, std::ios::binary) << text;
    return file;
  }
  // the message of the runtime_error reading `file` throws, or ""
  static std::string read_error(const fs::path& file) {
    try {
      read_recorded_signals(file);
    } catch (const std::runtime_error& e) {
      return e.what();
    }
    return "";
  }
};

TEST_F(suite_results, reads_numbers_booleans_and_text) {
  const fs::path file = write("r.csv",
                              "time,a.y,a.on,a.label,\"b.vec[1]\"\r\n"
                              "0,1.5,0,\"hello, world\",-2\r\n"
                              "\r\n"
                              "0.25,-3e-3,1,\"say \"\"hi\"\"\",nan\r\n");
  const recorded_signals r = read_recorded_signals(file);
  EXPECT_EQ(r.file, file);
  EXPECT_THAT(r.time, ElementsAre(0.0, 0.25));
  EXPECT_THAT(r.names, ElementsAre("a.y", "a.on", "a.label", "b.vec[1]"));
  EXPECT_THAT(r.is_text, ElementsAre(false, false, true, false));
  EXPECT_THAT(r.values[0], ElementsAre(1.5, -3e-3));
  EXPECT_THAT(r.values[1], ElementsAre(0.0, 1.0));
  EXPECT_TRUE(r.values[2].empty());  // text keeps no numbers
  ASSERT_EQ(r.values[3].size(), 2u);
  EXPECT_EQ(r.values[3][0], -2.0);
  EXPECT_TRUE(std::isnan(r.values[3][1]));  // a recorded NaN is a number, not text
  EXPECT_EQ(r.column("a.label"), 2u);
  EXPECT_EQ(r.column("b.vec[1]"), 3u);
  EXPECT_EQ(r.column("a"), std::nullopt);
}

TEST_F(suite_results, a_single_text_cell_makes_the_column_text) {
  const recorded_signals r = read_recorded_signals(write("r.csv", "time,x\n0,1\n1,two\n2,3\n"));
  EXPECT_THAT(r.is_text, ElementsAre(true));
  EXPECT_TRUE(r.values[0].empty());
  EXPECT_EQ(r.time.size(), 3u);
}

TEST_F(suite_results, header_only_has_no_rows) {
  const recorded_signals r = read_recorded_signals(write("r.csv", "time,x\n"));
  EXPECT_TRUE(r.time.empty());
  EXPECT_THAT(r.names, ElementsAre("x"));
  EXPECT_TRUE(r.values[0].empty());
}

TEST_F(suite_results, missing_file_is_named) {
  const fs::path file = scratch.path() / "not_recorded.csv";
  EXPECT_THAT(read_error(file), StartsWith(file.string() + ": cannot read"));
}

TEST_F(suite_results, empty_file_is_named) {
  const fs::path file = write("empty.csv", "");
  EXPECT_THAT(read_error(file), StartsWith(file.string() + ": empty"));
}

TEST_F(suite_results, time_must_be_the_first_column) {
  const fs::path file = write("r.csv", "a.y,time\n1,0\n");
  EXPECT_THAT(read_error(file), StartsWith(file.string() + ":1: the first column must be 'time'"));
}

TEST_F(suite_results, row_of_wrong_length_names_file_and_line) {
  // the blank line still counts: the short row is line 4
  const fs::path file = write("r.csv", "time,a,b\n0,1,2\n\n0.1,1\n");
  EXPECT_THAT(read_error(file), StartsWith(file.string() + ":4: 2 fields, the header has 3"));
  const fs::path longer = write("r2.csv", "time,a\n0,1\n0.1,1,2\n");
  EXPECT_THAT(read_error(longer), StartsWith(longer.string() + ":3: 3 fields, the header has 2"));
}

TEST_F(suite_results, time_that_is_not_a_number_names_file_and_line) {
  const fs::path file = write("r.csv", "time,a\n0,1\nsoon,2\n");
  EXPECT_THAT(read_error(file), StartsWith(file.string() + ":3: time 'soon' is not a number"));
}

}  // namespace
}  // namespace stride::suite
