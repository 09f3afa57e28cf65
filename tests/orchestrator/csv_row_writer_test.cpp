// The results file's writer, on a thread of its own or on the caller's: rows come out in order
// and complete, whatever the batching; flush() means written; a write error reaches the run's
// thread; an unwinding run keeps its rows.
#include "csv_row_writer.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <charconv>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "execution_fixtures.hpp"
#include "stride/cosim/archive.hpp"
#include "stride/cosim/error.hpp"

namespace stride::cosim::detail {
namespace {

using ::testing::HasSubstr;

std::string read_text(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

const std::vector<variable_type> k_columns = {variable_type::real, variable_type::integer,
                                              variable_type::boolean, variable_type::string};

// row `i`, as the writer gets it and as the file must show it
void add_row(csv_row_writer& w, int i) {
  const auto cells = w.begin_row(time_point(i * 250 * test::k_ms));
  cells[0].real = i / 3.0;
  cells[1].integer = -i;
  cells[2].boolean = i % 2 == 1;
  w.add_string(i % 5 == 0 ? "" : "say \"" + std::to_string(i) + "\"");
  w.end_row();
}

// (the number format itself is the recorder's test: observers_test.cpp)
std::string expected_row(int i) {
  char real[32];
  *std::to_chars(real, real + sizeof real, i / 3.0).ptr = '\0';
  return format_seconds(time_point(i * 250 * test::k_ms)) + "," + real + "," + std::to_string(-i) +
         "," + (i % 2 == 1 ? "1" : "0") + "," +
         (i % 5 == 0 ? "\"\"" : "\"say \"\"" + std::to_string(i) + "\"\"\"") + "\n";
}

std::FILE* open_for_writing(const std::filesystem::path& file) {
  std::FILE* out = std::fopen(file.c_str(), "wb");
  if (out == nullptr) throw std::runtime_error("cannot open " + file.string());
  return out;
}

// on a thread of its own (true) and on the caller's (false)
class csv_row_writer_test : public ::testing::TestWithParam<bool> {};

TEST_P(csv_row_writer_test, writes_every_row_in_order_through_many_batches) {
  temp_dir dir("stride-test-");
  const auto file = dir.path() / "r.csv";
  csv_row_writer w(open_for_writing(file), file, k_columns, "time,x,n,b,s\n", GetParam());
  std::string expected = "time,x,n,b,s\n";
  for (int i = 0; i < 5000; ++i) {  // enough to fill the writer's queue many times over
    add_row(w, i);
    expected += expected_row(i);
  }
  w.close();
  EXPECT_EQ(read_text(file), expected);
}

TEST_P(csv_row_writer_test, after_flush_the_rows_so_far_are_in_the_file) {
  temp_dir dir("stride-test-");
  const auto file = dir.path() / "r.csv";
  csv_row_writer w(open_for_writing(file), file, k_columns, "", GetParam());
  std::string expected;
  for (int i = 0; i < 3; ++i) {  // fewer rows than one batch
    add_row(w, i);
    expected += expected_row(i);
  }
  w.flush();
  EXPECT_EQ(read_text(file), expected);
  for (int i = 3; i < 40; ++i) {
    add_row(w, i);
    expected += expected_row(i);
  }
  w.flush();
  EXPECT_EQ(read_text(file), expected);
  w.close();
  EXPECT_EQ(read_text(file), expected);
}

TEST_P(csv_row_writer_test, a_run_that_unwinds_keeps_its_rows) {
  temp_dir dir("stride-test-");
  const auto file = dir.path() / "r.csv";
  std::string expected = "h\n";
  {
    csv_row_writer w(open_for_writing(file), file, k_columns, "h\n", GetParam());
    for (int i = 0; i < 21; ++i) {
      add_row(w, i);
      expected += expected_row(i);
    }
  }  // no close(): destroyed as by an exception
  EXPECT_EQ(read_text(file), expected);
}

TEST_P(csv_row_writer_test, a_full_disk_is_an_error_naming_the_file) {
  std::FILE* full = std::fopen("/dev/full", "wb");
  if (full == nullptr) GTEST_SKIP() << "no /dev/full on this machine";
  csv_row_writer w(full, "results.csv", k_columns, "time,x,n,b,s\n", GetParam());
  std::string message;
  try {
    for (int i = 0; i < 100000; ++i) add_row(w, i);  // a failed write stops the run
    w.close();
  } catch (const error& e) {
    message = e.what();
  }
  EXPECT_THAT(message, HasSubstr("cannot write results.csv: No space left on device"));
  // and it stays failed: nothing later is taken for written
  EXPECT_THROW(w.flush(), error);
}

INSTANTIATE_TEST_SUITE_P(threads, csv_row_writer_test, ::testing::Bool(),
                         [](const auto& info) { return info.param ? "own" : "callers"; });

}  // namespace
}  // namespace stride::cosim::detail
