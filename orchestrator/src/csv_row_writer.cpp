#include "csv_row_writer.hpp"

#include <charconv>
#include <cstring>
#include <utility>

#include "stride/cosim/error.hpp"

namespace stride::cosim::detail {

namespace {

// rows per hand-over to the writer (one wake-up each), and hand-overs the writer may lag behind
constexpr std::size_t k_batch_rows = 16;
constexpr std::size_t k_max_queued = 8;
constexpr std::size_t k_write_size = std::size_t{1} << 16;

void append_double(std::string& out, double d) {
  char buf[32];
  auto [end, ec] = std::to_chars(buf, buf + sizeof buf, d);
  if (ec == std::errc()) out.append(buf, end);
}

}  // namespace

csv_row_writer::csv_row_writer(std::FILE* out, std::filesystem::path file,
                               std::vector<variable_type> columns, std::string first,
                               bool own_thread)
    : file_(std::move(file)),
      columns_(std::move(columns)),
      own_thread_(own_thread),
      out_(out),
      text_(std::move(first)) {
  if (!own_thread_) return;
  try {
    thread_ = std::thread([this] { run(); });
  } catch (...) {
    std::fclose(out_);
    throw;
  }
}

csv_row_writer::~csv_row_writer() {
  {
    std::lock_guard lock(mutex_);
    if (!filling_.times.empty()) queued_.push_back(std::move(filling_));
    stop_ = true;
  }
  work_.notify_one();
  if (thread_.joinable()) {
    thread_.join();
  } else if (out_ != nullptr) {
    write_now(queued_);
    write_text();
  }
  if (out_ != nullptr) std::fclose(out_);
}

std::span<csv_cell> csv_row_writer::begin_row(time_point t) {
  filling_.times.push_back(t);
  const std::size_t at = filling_.cells.size();
  filling_.cells.resize(at + columns_.size());
  return {filling_.cells.data() + at, columns_.size()};
}

void csv_row_writer::add_string(std::string_view value) {
  filling_.strings.emplace_back(value);
}

void csv_row_writer::end_row() {
  if (filling_.times.size() >= k_batch_rows) hand_over();
}

void csv_row_writer::hand_over() {
  if (!own_thread_) {
    throw_if_failed();
    write_now(filling_);
    throw_if_failed();
    return;
  }
  std::unique_lock lock(mutex_);
  space_.wait(lock, [&] { return queued_.size() < k_max_queued || !error_.empty(); });
  throw_if_failed();
  queued_.push_back(std::move(filling_));
  if (spare_.empty()) {
    filling_ = batch{};
  } else {
    filling_ = std::move(spare_.back());
    spare_.pop_back();
  }
  lock.unlock();
  work_.notify_one();
}

void csv_row_writer::flush() {
  if (!filling_.times.empty()) hand_over();
  if (!own_thread_) {
    flush_file();
    throw_if_failed();
    return;
  }
  std::unique_lock lock(mutex_);
  const std::uint64_t ticket = ++flush_asked_;
  work_.notify_one();
  space_.wait(lock, [&] { return flushed_ >= ticket || !error_.empty(); });
  throw_if_failed();
}

void csv_row_writer::close() {
  if (out_ == nullptr) return;
  flush();
  {
    std::lock_guard lock(mutex_);
    stop_ = true;
  }
  work_.notify_one();
  if (thread_.joinable()) thread_.join();
  std::FILE* out = std::exchange(out_, nullptr);
  if (std::fclose(out) != 0) {
    throw error("cannot write " + file_.string() + ": " + std::strerror(errno));
  }
}

void csv_row_writer::throw_if_failed() const {
  if (!error_.empty()) throw error(error_);
}

void csv_row_writer::run() {
  std::unique_lock lock(mutex_);
  for (;;) {
    work_.wait(lock, [&] { return !queued_.empty() || flush_asked_ != flushed_ || stop_; });
    if (!queued_.empty()) {
      batch rows = std::move(queued_.front());
      queued_.pop_front();
      lock.unlock();
      write_now(rows);
      lock.lock();
      spare_.push_back(std::move(rows));
      space_.notify_one();
      continue;
    }
    const std::uint64_t asked = flush_asked_;
    const bool stopping = stop_;
    lock.unlock();
    flush_file();
    lock.lock();
    flushed_ = asked;
    space_.notify_all();
    if (stopping && queued_.empty()) return;
  }
}

void csv_row_writer::write_now(batch& rows) {
  format(rows);
  if (text_.size() >= k_write_size) write_text();
  rows.times.clear();
  rows.cells.clear();
  rows.strings.clear();
}

void csv_row_writer::write_now(std::deque<batch>& queued) {
  for (auto& rows : queued) write_now(rows);
  queued.clear();
}

void csv_row_writer::flush_file() {
  write_text();
  if (error_.empty() && std::fflush(out_) != 0) {
    std::lock_guard lock(mutex_);
    error_ = "cannot write " + file_.string() + ": " + std::strerror(errno);
  }
}

void csv_row_writer::format(const batch& rows) {
  const std::size_t width = columns_.size();
  std::size_t next_string = 0;
  for (std::size_t r = 0; r < rows.times.size(); ++r) {
    text_ += format_seconds(rows.times[r]);
    const csv_cell* cells = rows.cells.data() + r * width;
    for (std::size_t c = 0; c < width; ++c) {
      text_ += ',';
      switch (columns_[c]) {
        case variable_type::real:
          append_double(text_, cells[c].real);
          break;
        case variable_type::integer:
        case variable_type::enumeration:
          text_ += std::to_string(cells[c].integer);
          break;
        case variable_type::boolean:
          text_ += cells[c].boolean ? '1' : '0';
          break;
        case variable_type::string:
          // always quoted so an empty string stays a field
          text_ += '"';
          for (char ch : rows.strings[next_string++]) {
            if (ch == '"') text_ += '"';
            text_ += ch;
          }
          text_ += '"';
          break;
      }
    }
    text_ += '\n';
  }
}

// A full disk must end the run with an error, not leave a silently truncated file: the first
// failure is kept for the run's thread, and nothing is written after it. (Only this thread sets
// error_; the run's thread reads it under the mutex.)
void csv_row_writer::write_text() {
  if (error_.empty() && !text_.empty() &&
      std::fwrite(text_.data(), 1, text_.size(), out_) != text_.size()) {
    std::lock_guard lock(mutex_);
    error_ = "cannot write " + file_.string() + ": " + std::strerror(errno);
  }
  text_.clear();
}

}  // namespace stride::cosim::detail
