// In-process stand-ins for component instances on workers, for the tests of the failover layer:
// a cluster of named workers that can be "killed", and an instance whose calls throw worker_lost
// once its worker is dead.
#ifndef STRIDE_TESTS_REMOTE_FAKE_CLUSTER_HPP
#define STRIDE_TESTS_REMOTE_FAKE_CLUSTER_HPP

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstring>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "client.hpp"
#include "stride/cosim/component.hpp"
#include "stride/cosim/log.hpp"

namespace stride::remote::test {

constexpr cosim::duration k_dt = std::chrono::milliseconds(10);

// the workers of a test: which are dead, what was made and saved on them
struct fake_cluster {
  std::set<std::string> dead;
  std::set<std::string> refusing;  // answer, but cannot take the component
  int instances = 0;
  int images = 0;
  std::string dies_at_image;  // a worker that is lost when it is asked for a state image
  void check(const std::string& worker) const {
    if (dead.contains(worker)) throw worker_lost("worker '" + worker + "' is gone");
  }
};

// y(t+dt) = y + (u + gain) * dt, a parameter and a state that depend on every earlier call
class accumulator final : public cosim::component {
 public:
  accumulator(fake_cluster& cluster, std::string worker, std::string name = "acc")
      : cluster_(cluster), worker_(std::move(worker)), name_(std::move(name)) {
    ++cluster_.instances;
  }
  const std::string& name() const noexcept override { return name_; }
  const cosim::model_description& model_description() const noexcept override { return md_; }
  void setup(cosim::time_point, std::optional<cosim::time_point>) override { alive(); }
  void enter_initialization() override {
    alive();
    in_init_ = true;
  }
  void exit_initialization() override {
    alive();
    if (!in_init_) throw cosim::component_error("exit_initialization before enter");
    in_init_ = false;
  }
  void terminate() override { alive(); }
  void set_values(const cosim::variable_refs&, const cosim::value_block& v) override {
    alive();
    gain_ = v.reals.at(0);
  }
  void get_values(const cosim::variable_refs&, cosim::value_block& v) override {
    alive();
    v.reals = {y_};
  }
  void expose(const cosim::variable_refs&, const cosim::variable_refs&) override { alive(); }
  cosim::step_result step(cosim::time_point, cosim::duration dt, const cosim::value_block& in,
                          cosim::value_block& out) override {
    alive();
    y_ += (in.reals.at(0) + gain_) * std::chrono::duration<double>(dt).count();
    out.reals = {y_};
    return cosim::step_result::complete;
  }
  std::vector<std::byte> save_state() override {
    if (worker_ == cluster_.dies_at_image) cluster_.dead.insert(worker_);
    alive();
    ++cluster_.images;
    std::vector<std::byte> b(2 * sizeof(double));
    std::memcpy(b.data(), &y_, sizeof y_);
    std::memcpy(b.data() + sizeof y_, &gain_, sizeof gain_);
    return b;
  }
  void restore_state(std::span<const std::byte> s) override {
    alive();
    std::memcpy(&y_, s.data(), sizeof y_);
    std::memcpy(&gain_, s.data() + sizeof y_, sizeof gain_);
  }

 private:
  void alive() const { cluster_.check(worker_); }
  fake_cluster& cluster_;
  std::string worker_;
  std::string name_;
  cosim::model_description md_;
  double y_ = 0, gain_ = 0;
  bool in_init_ = false;
};

struct log_capture {
  std::vector<std::string> lines;
  cosim::log_sink sink() {
    return [this](cosim::log_level, std::string_view source, std::string_view category,
                  std::string_view message) {
      lines.push_back(std::string(source) + " [" + std::string(category) + "] " +
                      std::string(message));
    };
  }
  std::string all() const {
    std::string s;
    for (const auto& l : lines) s += l + "\n";
    return s;
  }
};

// Runs `run`, which must end with the loss of `worker` when no standby is left: an error that
// says so, and not a worker_lost (which would look like a loss that can still be taken over).
template <class F>
void expect_loss_with_no_standby_left(F&& run, const std::string& worker) {
  try {
    run();
    FAIL() << "the last loss had no standby";
  } catch (const worker_lost&) {
    FAIL() << "the error must not look like a loss that can still be taken over";
  } catch (const cosim::component_error& e) {
    EXPECT_THAT(e.what(), ::testing::AllOf(::testing::HasSubstr("worker '" + worker + "' is gone"),
                                           ::testing::HasSubstr("no standby worker is left")));
  }
}

}  // namespace stride::remote::test

#endif  // STRIDE_TESTS_REMOTE_FAKE_CLUSTER_HPP
