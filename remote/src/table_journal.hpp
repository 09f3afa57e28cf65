// The journal of a synchronous shared table: the initial table, then every merged round with each
// agent's update, appended as the rounds are merged. A run interrupted at any moment (SIGKILL
// included) is continued from it (docs/swarm.md, "Resume").
#ifndef STRIDE_REMOTE_TABLE_JOURNAL_HPP
#define STRIDE_REMOTE_TABLE_JOURNAL_HPP

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <vector>

namespace stride::remote {

/// One agent's update of one round.
struct table_update {
  int agent = 0;
  std::int64_t round = 0;
  std::vector<std::uint32_t> entries;
  std::vector<double> increments;
  std::vector<double> initial;  ///< round 1 (and resume announcements) only
  bool last = false;
  bool resumed = false;
};

/// A merged round: its updates in agent order.
struct journal_round {
  std::int64_t round = 0;
  std::vector<table_update> updates;
};

struct journal_contents {
  bool has_header = false;  ///< false: nothing was merged before the interruption
  int agents = 0;
  std::vector<double> initial;
  std::vector<journal_round> rounds;  ///< 1, 2, ... in order
};

/// Reads a journal; a record cut short by the interruption at its end is left out.
/// \throws std::runtime_error naming the file when it is not a journal or is damaged before its
/// last record.
journal_contents read_journal(const std::filesystem::path& file);

/// Appends to a journal; every record goes out in one write, so a killed process leaves whole
/// records (and at most one cut short, which read_journal leaves out).
class journal_writer {
 public:
  journal_writer() = default;
  /// Opens `file`: truncated to `keep_bytes` (continuing a journal) or created afresh (0).
  journal_writer(const std::filesystem::path& file, std::uint64_t keep_bytes);
  ~journal_writer();
  journal_writer(const journal_writer&) = delete;
  journal_writer& operator=(const journal_writer&) = delete;
  journal_writer(journal_writer&& o) noexcept;
  journal_writer& operator=(journal_writer&& o) noexcept;

  bool active() const { return fd_ >= 0; }
  void header(int agents, const std::vector<double>& initial);
  void round(const journal_round& r);

 private:
  void write(const std::vector<unsigned char>& bytes);
  std::filesystem::path file_;
  int fd_ = -1;
};

/// The byte size of a journal's whole records (where appending continues).
std::uint64_t journal_valid_size(const std::filesystem::path& file);

}  // namespace stride::remote

#endif  // STRIDE_REMOTE_TABLE_JOURNAL_HPP
