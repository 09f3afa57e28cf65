#include "table_journal.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <utility>

namespace stride::remote {

namespace fs = std::filesystem;

namespace {

constexpr char k_magic[8] = {'S', 'T', 'R', 'T', 'J', 'N', 'L', '1'};

class byte_out {
 public:
  template <class T>
  void put(const T& v) {
    const auto* p = reinterpret_cast<const unsigned char*>(&v);
    bytes.insert(bytes.end(), p, p + sizeof(T));
  }
  std::vector<unsigned char> bytes;
};

class byte_in {
 public:
  byte_in(const std::vector<unsigned char>& b, std::size_t pos) : b_(b), pos_(pos) {}
  template <class T>
  bool get(T& v) {
    if (b_.size() - pos_ < sizeof(T)) return false;
    std::memcpy(&v, b_.data() + pos_, sizeof(T));
    pos_ += sizeof(T);
    return true;
  }
  std::size_t pos() const { return pos_; }
  std::size_t left() const { return b_.size() - pos_; }

 private:
  const std::vector<unsigned char>& b_;
  std::size_t pos_;
};

// a record: its length, then the round and its updates
std::vector<unsigned char> encode(const journal_round& r) {
  byte_out body;
  body.put(r.round);
  body.put(static_cast<std::uint32_t>(r.updates.size()));
  for (const auto& u : r.updates) {
    body.put(static_cast<std::int32_t>(u.agent));
    body.put(static_cast<std::uint8_t>(u.last));
    body.put(static_cast<std::uint64_t>(u.entries.size()));
    for (std::size_t i = 0; i < u.entries.size(); ++i) {
      body.put(u.entries[i]);
      body.put(u.increments[i]);
    }
  }
  byte_out out;
  out.put(static_cast<std::uint64_t>(body.bytes.size()));
  out.bytes.insert(out.bytes.end(), body.bytes.begin(), body.bytes.end());
  return out.bytes;
}

struct parsed {
  journal_contents contents;
  std::uint64_t valid_size = 0;
};

parsed parse(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw std::runtime_error(file.string() + ": cannot read the shared table's journal");
  const std::vector<unsigned char> b((std::istreambuf_iterator<char>(in)),
                                     std::istreambuf_iterator<char>());
  parsed p;
  if (b.empty()) return p;  // created, nothing merged yet
  const auto damaged = [&](const std::string& why) {
    return std::runtime_error(file.string() + ": damaged journal (" + why + ")");
  };
  if (b.size() < sizeof k_magic || std::memcmp(b.data(), k_magic, sizeof k_magic) != 0) {
    throw std::runtime_error(file.string() + ": not a shared table journal");
  }
  byte_in r(b, sizeof k_magic);
  std::int32_t agents = 0;
  std::uint64_t size = 0;
  if (!r.get(agents) || !r.get(size) || agents < 1 || size > r.left() / sizeof(double)) {
    return p;  // the header itself was cut short: nothing merged
  }
  p.contents.has_header = true;
  p.contents.agents = agents;
  p.contents.initial.resize(size);
  for (auto& v : p.contents.initial) r.get(v);
  p.valid_size = r.pos();
  for (;;) {
    std::uint64_t length = 0;
    if (!r.get(length) || length > r.left()) break;  // the end, or a record cut short
    const std::size_t end = r.pos() + length;
    journal_round round;
    std::uint32_t count = 0;
    if (!r.get(round.round) || !r.get(count)) throw damaged("short record");
    for (std::uint32_t i = 0; i < count; ++i) {
      table_update u;
      std::int32_t agent = 0;
      std::uint8_t last = 0;
      std::uint64_t n = 0;
      if (!r.get(agent) || !r.get(last) || !r.get(n) || n > r.left() / 12) {
        throw damaged("update of round " + std::to_string(round.round));
      }
      u.agent = agent;
      u.round = round.round;
      u.last = last != 0;
      u.entries.resize(n);
      u.increments.resize(n);
      for (std::uint64_t k = 0; k < n; ++k) {
        r.get(u.entries[k]);
        r.get(u.increments[k]);
      }
      round.updates.push_back(std::move(u));
    }
    if (r.pos() != end) throw damaged("record of round " + std::to_string(round.round));
    const std::int64_t expected = static_cast<std::int64_t>(p.contents.rounds.size()) + 1;
    if (round.round != expected) {
      throw damaged("round " + std::to_string(round.round) + " where " + std::to_string(expected) +
                    " belongs");
    }
    p.contents.rounds.push_back(std::move(round));
    p.valid_size = end;
  }
  return p;
}

}  // namespace

journal_contents read_journal(const fs::path& file) {
  return parse(file).contents;
}

std::uint64_t journal_valid_size(const fs::path& file) {
  return parse(file).valid_size;
}

journal_writer::journal_writer(const fs::path& file, std::uint64_t keep_bytes) : file_(file) {
  fd_ = ::open(file.c_str(), O_WRONLY | O_CREAT | O_CLOEXEC, 0644);
  if (fd_ < 0 || ::ftruncate(fd_, static_cast<off_t>(keep_bytes)) != 0 ||
      ::lseek(fd_, 0, SEEK_END) < 0) {
    const std::string why = std::strerror(errno);
    if (fd_ >= 0) ::close(fd_);
    fd_ = -1;
    throw std::runtime_error("cannot write the shared table's journal " + file.string() + ": " +
                             why);
  }
}

journal_writer::~journal_writer() {
  if (fd_ >= 0) ::close(fd_);
}

journal_writer::journal_writer(journal_writer&& o) noexcept
    : file_(std::move(o.file_)), fd_(std::exchange(o.fd_, -1)) {}

journal_writer& journal_writer::operator=(journal_writer&& o) noexcept {
  if (this != &o) {
    if (fd_ >= 0) ::close(fd_);
    file_ = std::move(o.file_);
    fd_ = std::exchange(o.fd_, -1);
  }
  return *this;
}

void journal_writer::header(int agents, const std::vector<double>& initial) {
  byte_out out;
  for (const char c : k_magic) out.put(c);
  out.put(static_cast<std::int32_t>(agents));
  out.put(static_cast<std::uint64_t>(initial.size()));
  for (const double v : initial) out.put(v);
  write(out.bytes);
}

void journal_writer::round(const journal_round& r) {
  write(encode(r));
}

void journal_writer::write(const std::vector<unsigned char>& bytes) {
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd_, bytes.data() + done, bytes.size() - done);
    if (n < 0) {
      if (errno == EINTR) continue;
      throw std::runtime_error("cannot write the shared table's journal " + file_.string() + ": " +
                               std::strerror(errno));
    }
    done += static_cast<std::size_t>(n);
  }
}

}  // namespace stride::remote
