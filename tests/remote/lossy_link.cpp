// lossy_link: a bad network link in user space, for kernels without the netem qdisc. It joins
// two TUN devices that already exist in two network namespaces and carries each IP packet from
// one to the other after a delay with jitter, dropping, duplicating and reordering some as netem
// does, drawn from a seeded generator. On SIGTERM or SIGINT it prints what it did, so that a
// test can check the impairments happened.
// usage: lossy_link NETNS_A DEV_A NETNS_B DEV_B [--delay MS] [--jitter MS] [--loss P]
//                   [--duplicate P] [--reorder P] [--seed N]
//   NETNS_*  a namespace file (/run/netns/NAME); DEV_* a TUN device in it (ip tuntap add)
//   --reorder P  that fraction of the packets goes out at once, overtaking delayed ones
#include <fcntl.h>
#include <linux/if.h>
#include <linux/if_tun.h>
#include <poll.h>
#include <sched.h>
#include <sys/ioctl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <queue>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using clock_type = std::chrono::steady_clock;

volatile std::sig_atomic_t g_stop = 0;

struct settings {
  double delay_ms = 2, jitter_ms = 1, loss = 0, duplicate = 0, reorder = 0;
  unsigned long seed = 1;
};

struct packet {
  clock_type::time_point due;
  std::uint64_t sequence = 0;  // arrival order in its direction
  int direction = 0;           // 0: a to b, 1: b to a
  std::vector<char> bytes;
  bool operator>(const packet& o) const {
    return due != o.due ? due > o.due : sequence > o.sequence;
  }
};

struct counts {
  std::uint64_t received = 0, dropped = 0, duplicated = 0, reordered = 0, sent = 0;
};

[[noreturn]] void fail(const std::string& what) {
  std::fprintf(stderr, "lossy_link: %s: %s\n", what.c_str(), std::strerror(errno));
  std::exit(1);
}

// The TUN device `name` of the namespace `netns`, opened from inside it.
int attach(const char* netns, const char* name) {
  const int ns = open(netns, O_RDONLY | O_CLOEXEC);
  if (ns < 0) fail(std::string("cannot open ") + netns);
  if (setns(ns, CLONE_NEWNET) != 0) fail(std::string("cannot enter ") + netns);
  close(ns);
  const int fd = open("/dev/net/tun", O_RDWR | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) fail("cannot open /dev/net/tun");
  ifreq request{};
  request.ifr_flags = IFF_TUN | IFF_NO_PI;
  std::strncpy(request.ifr_name, name, IFNAMSIZ - 1);
  if (ioctl(fd, TUNSETIFF, &request) != 0) fail(std::string("cannot attach to ") + name);
  return fd;
}

settings parse(int argc, char** argv) {
  settings s;
  for (int i = 5; i + 1 < argc; i += 2) {
    const std::string key = argv[i];
    const double value = std::stod(argv[i + 1]);
    if (key == "--delay")
      s.delay_ms = value;
    else if (key == "--jitter")
      s.jitter_ms = value;
    else if (key == "--loss")
      s.loss = value;
    else if (key == "--duplicate")
      s.duplicate = value;
    else if (key == "--reorder")
      s.reorder = value;
    else if (key == "--seed")
      s.seed = static_cast<unsigned long>(value);
    else
      throw std::invalid_argument("unknown option " + key);
  }
  return s;
}

class impaired_link {
 public:
  impaired_link(int fd_a, int fd_b, settings s) : fds_{fd_a, fd_b}, s_(s), random_(s.seed) {}

  void run() {
    std::vector<char> buffer(65536);
    while (g_stop == 0) {
      pollfd polled[2] = {{fds_[0], POLLIN, 0}, {fds_[1], POLLIN, 0}};
      const timespec wait = until_next();
      const int n = ppoll(polled, 2, queue_.empty() ? nullptr : &wait, nullptr);
      if (n < 0 && errno != EINTR) fail("poll");
      for (int d = 0; d < 2 && n > 0; ++d) {
        if ((polled[d].revents & POLLIN) == 0) continue;
        for (;;) {
          const ssize_t got = read(fds_[d], buffer.data(), buffer.size());
          if (got <= 0) break;
          arrive(d, std::vector<char>(buffer.begin(), buffer.begin() + got));
        }
      }
      deliver_due();
    }
  }
  const counts& done() const { return counts_; }

 private:
  double uniform() { return std::uniform_real_distribution<double>(0.0, 1.0)(random_); }

  void arrive(int direction, std::vector<char> bytes) {
    ++counts_.received;
    if (uniform() < s_.loss) {
      ++counts_.dropped;
      return;
    }
    const int copies = uniform() < s_.duplicate ? 2 : 1;
    counts_.duplicated += static_cast<std::uint64_t>(copies - 1);
    for (int c = 0; c < copies; ++c) {
      double ms = 0;
      if (uniform() >= s_.reorder) {
        ms = std::max(0.0, s_.delay_ms + s_.jitter_ms * (2 * uniform() - 1));
      }
      const auto due = clock_type::now() + std::chrono::duration_cast<clock_type::duration>(
                                               std::chrono::duration<double, std::milli>(ms));
      queue_.push(packet{due, next_[direction]++, direction, bytes});
    }
  }

  void deliver_due() {
    const auto now = clock_type::now();
    while (!queue_.empty() && queue_.top().due <= now) {
      const packet& p = queue_.top();
      // a packet behind one that arrived after it has been overtaken
      if (sent_any_[p.direction] && p.sequence < last_sent_[p.direction]) ++counts_.reordered;
      last_sent_[p.direction] = std::max(last_sent_[p.direction], p.sequence);
      sent_any_[p.direction] = true;
      if (write(fds_[1 - p.direction], p.bytes.data(), p.bytes.size()) > 0) ++counts_.sent;
      queue_.pop();
    }
  }

  timespec until_next() const {
    if (queue_.empty()) return {0, 0};
    const auto left = queue_.top().due - clock_type::now();
    const auto ns = std::max<std::int64_t>(
        0, std::chrono::duration_cast<std::chrono::nanoseconds>(left).count());
    return {static_cast<time_t>(ns / 1'000'000'000), static_cast<long>(ns % 1'000'000'000)};
  }

  int fds_[2];
  settings s_;
  std::mt19937_64 random_;
  std::priority_queue<packet, std::vector<packet>, std::greater<>> queue_;
  std::uint64_t next_[2] = {0, 0};
  std::uint64_t last_sent_[2] = {0, 0};
  bool sent_any_[2] = {false, false};
  counts counts_;
};

void on_signal(int) {
  g_stop = 1;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 5 || (argc - 5) % 2 != 0) {
    std::fprintf(stderr,
                 "usage: lossy_link NETNS_A DEV_A NETNS_B DEV_B [--delay MS] [--jitter MS] "
                 "[--loss P] [--duplicate P] [--reorder P] [--seed N]\n");
    return 2;
  }
  settings s;
  try {
    s = parse(argc, argv);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "lossy_link: %s\n", e.what());
    return 2;
  }
  const int a = attach(argv[1], argv[2]);
  const int b = attach(argv[3], argv[4]);
  std::signal(SIGTERM, on_signal);
  std::signal(SIGINT, on_signal);
  impaired_link l(a, b, s);
  std::printf("lossy_link: ready\n");
  std::fflush(stdout);
  l.run();
  const counts& c = l.done();
  std::printf(
      "lossy_link: %llu packets, %llu dropped, %llu duplicated, %llu reordered, %llu sent\n",
      static_cast<unsigned long long>(c.received), static_cast<unsigned long long>(c.dropped),
      static_cast<unsigned long long>(c.duplicated), static_cast<unsigned long long>(c.reordered),
      static_cast<unsigned long long>(c.sent));
  return 0;
}
