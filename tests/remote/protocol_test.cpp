// The wire conversions of the remote protocol: values of every type survive the trip, sizes are
// checked, archives are named by their SHA-256.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <stdexcept>

#include "me_wire.hpp"
#include "protocol.hpp"

namespace stride::remote {
namespace {

using ::testing::HasSubstr;

cosim::variable_refs refs_of_every_type() {
  cosim::variable_refs r;
  r.reals = {1, 7};
  r.integers = {3};
  r.booleans = {4, 5, 6};
  r.strings = {9, 2};
  return r;
}

TEST(remote_protocol, values_of_every_type_survive_the_wire) {
  const cosim::variable_refs refs = refs_of_every_type();
  cosim::value_block v;
  v.reals = {-0.0, 1e-300};
  v.integers = {-2147483647 - 1};
  v.booleans = {true, false, true};
  v.strings = {"", "text with, commas"};
  stride_remote_values wire{};
  wire_storage storage;
  put_values(v, wire, storage);
  cosim::value_block back;
  get_values(wire, refs, back);
  EXPECT_EQ(back.reals, v.reals);
  EXPECT_TRUE(std::signbit(back.reals[0]));  // bit for bit, not only equal
  EXPECT_EQ(back.integers, v.integers);
  EXPECT_EQ(back.booleans, v.booleans);
  EXPECT_EQ(back.strings, v.strings);
}

TEST(remote_protocol, references_survive_the_wire_and_carry_no_values) {
  const cosim::variable_refs refs = refs_of_every_type();
  stride_remote_values wire{};
  put_refs(refs, wire);
  const cosim::variable_refs back = get_refs(wire);
  EXPECT_EQ(back.reals, refs.reals);
  EXPECT_EQ(back.integers, refs.integers);
  EXPECT_EQ(back.booleans, refs.booleans);
  EXPECT_EQ(back.strings, refs.strings);

  double one = 1;
  wire.reals._buffer = &one;
  wire.reals._length = 1;
  EXPECT_THROW(get_refs(wire), std::runtime_error);
}

TEST(remote_protocol, values_of_the_wrong_count_are_refused) {
  const cosim::variable_refs refs = refs_of_every_type();
  cosim::value_block v;
  v.resize_for(refs);
  v.booleans.pop_back();
  EXPECT_FALSE(fits(v, refs));
  stride_remote_values wire{};
  wire_storage storage;
  put_values(v, wire, storage);
  cosim::value_block back;
  try {
    get_values(wire, refs, back);
    FAIL() << "accepted 2 booleans for 3 references";
  } catch (const std::runtime_error& e) {
    EXPECT_THAT(e.what(), HasSubstr("2 booleans where 3 were expected"));
  }
  v.booleans.push_back(false);
  EXPECT_TRUE(fits(v, refs));
}

TEST(remote_protocol, archives_are_named_by_their_sha256) {
  const std::string abc = "abc";
  const auto* p = reinterpret_cast<const std::byte*>(abc.data());
  // FIPS 180-2, appendix B.1
  EXPECT_EQ(content_hash({p, abc.size()}),
            "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  EXPECT_EQ(content_hash({}), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
}

TEST(remote_protocol, blobs_survive_the_wire) {
  std::vector<std::byte> bytes = {std::byte{0}, std::byte{255}, std::byte{7}};
  dds_sequence_octet wire{};
  put_blob(bytes, wire);
  EXPECT_EQ(get_blob(wire), bytes);
}

TEST(remote_protocol, partitions_keep_workers_and_runs_apart) {
  EXPECT_EQ(worker_partition("w1"), "stride.worker.w1");
  EXPECT_EQ(run_partition("r"), "stride.run.r");
  EXPECT_NE(worker_partition("a"), run_partition("a"));
  EXPECT_EQ(to_string(op::step), "step");
}

}  // namespace
// Model Exchange settings of an instantiate request: what is set, and only that, comes back
TEST(remote_protocol, model_exchange_settings_survive_the_wire) {
  EXPECT_FALSE(model_exchange_from_wire(model_exchange_to_wire(std::nullopt)).has_value());
  cosim::model_exchange_options o;
  o.solver = cosim::model_exchange_options::solver_kind::euler;
  o.method = cosim::model_exchange_options::method_kind::adams;
  o.rtol = 1e-7;
  o.max_step = 0.25;
  const auto back = model_exchange_from_wire(model_exchange_to_wire(o));
  ASSERT_TRUE(back.has_value());
  EXPECT_EQ(back->solver, o.solver);
  EXPECT_EQ(back->method, o.method);
  EXPECT_EQ(back->rtol, o.rtol);
  EXPECT_FALSE(back->atol.has_value());
  EXPECT_EQ(back->max_step, o.max_step);
}

TEST(remote_protocol, malformed_model_exchange_settings_are_refused) {
  auto v = model_exchange_to_wire(cosim::model_exchange_options{});
  auto bad_solver = v;
  bad_solver.strings[1] = "rk45";
  EXPECT_THROW(model_exchange_from_wire(bad_solver), std::runtime_error);
  auto short_block = v;
  short_block.reals.pop_back();
  EXPECT_THROW(model_exchange_from_wire(short_block), std::runtime_error);
  auto negative = v;
  negative.booleans[0] = true;
  negative.reals[0] = -1;
  EXPECT_THROW(model_exchange_from_wire(negative), std::runtime_error);
}

}  // namespace stride::remote
