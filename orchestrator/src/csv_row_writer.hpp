// The rows of a CSV results file, formatted and written on a thread of their own or on the run's.
// Turning a row's values into text is most of its cost (the DARwIn-OP walk records 190 numbers
// every 8 ms step, about 12 µs of formatting): on a thread of its own it overlaps the next steps
// and the run's thread only copies the values.
#ifndef STRIDE_COSIM_CSV_ROW_WRITER_HPP
#define STRIDE_COSIM_CSV_ROW_WRITER_HPP

#include <condition_variable>
#include <cstdint>
#include <cstdio>
#include <deque>
#include <filesystem>
#include <mutex>
#include <span>
#include <string>
#include <string_view>
#include <thread>
#include <vector>

#include "stride/cosim/model_description.hpp"
#include "stride/cosim/time.hpp"

namespace stride::cosim::detail {

/// One value of a row as the run's thread copies it (a string column's value travels apart).
union csv_cell {
  double real;
  std::int64_t integer;
  bool boolean;
};

class csv_row_writer {
 public:
  /// Writes `first` (the header, or nothing when continuing a file), then the rows, to `out`,
  /// which it owns from now on; `columns` are the types of the values after the time, `file`
  /// names the file in errors. Without `own_thread`, rows are formatted and written by the
  /// caller, every few rows.
  csv_row_writer(std::FILE* out, std::filesystem::path file, std::vector<variable_type> columns,
                 std::string first, bool own_thread = true);
  /// Writes what is queued and closes the file, errors ignored: an unwinding run keeps what it
  /// can; the error that ends it is already on its way.
  ~csv_row_writer();
  csv_row_writer(const csv_row_writer&) = delete;
  csv_row_writer& operator=(const csv_row_writer&) = delete;

  /// The cells of a new row at `t`, one per column, to be filled before end_row() (a string
  /// column's cell is unused: its value goes to add_string()).
  std::span<csv_cell> begin_row(time_point t);
  /// The value of the row's next string column.
  void add_string(std::string_view value);
  /// Queues the row. Waits while the writer is far behind. \throws error naming the file when
  /// an earlier write failed.
  void end_row();
  /// Returns once every row added is written and flushed to the file. \throws error as end_row().
  void flush();
  /// flush(), then closes the file; no rows after it. \throws error as end_row(), or when closing
  /// fails.
  void close();

 private:
  struct batch {
    std::vector<time_point> times;
    std::vector<csv_cell> cells;
    std::vector<std::string> strings;
  };

  void hand_over();
  void run();
  void write_now(batch& rows);  // and empties `rows`
  void write_now(std::deque<batch>& queued);
  void flush_file();
  void format(const batch& rows);
  void write_text();
  void throw_if_failed() const;

  const std::filesystem::path file_;
  const std::vector<variable_type> columns_;
  const bool own_thread_;
  std::FILE* out_;
  std::string text_;  // formatted, not yet written (the thread that writes)
  batch filling_;     // run's thread

  mutable std::mutex mutex_;
  std::condition_variable work_;   // writer: rows queued, flush asked, or stop
  std::condition_variable space_;  // run's thread: a batch written, or flushed
  std::deque<batch> queued_;
  std::vector<batch> spare_;
  std::uint64_t flush_asked_ = 0;
  std::uint64_t flushed_ = 0;
  bool stop_ = false;
  std::string error_;  // the first write error; the writer writes nothing after it

  std::thread thread_;
};

}  // namespace stride::cosim::detail

#endif  // STRIDE_COSIM_CSV_ROW_WRITER_HPP
