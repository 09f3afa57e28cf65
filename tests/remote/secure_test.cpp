// Workers only trusted peers reach, end to end: real `stride worker` and `stride run` processes
// with identities from `stride security` keystores, Cyclone's DDS Security plugins on the
// loopback interface, the FMU allow-list, and the refusal to serve the network unprotected. Each
// test has its own DDS domain (100..119).
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <string>
#include <thread>

#include "../orchestrator/process.hpp"
#include "protocol.hpp"
#include "stride/cosim/archive.hpp"
#include "stride/remote/keystore.hpp"
#include "worker_process.hpp"

namespace stride::remote::test {
namespace {

namespace fs = std::filesystem;
using cosim::test::quoted;
using cosim::test::run_command;
using ::testing::AllOf;
using ::testing::HasSubstr;
using ::testing::Not;

const std::string k_cli = STRIDE_CLI;
const fs::path k_source = STRIDE_SOURCE_DIR;
const fs::path k_fmus = STRIDE_FMU_DIR;
const fs::path k_demo = k_source / "models" / "experiments" / "demo.xml";

std::string read(const fs::path& file) {
  return cosim::test::read_file(file);
}

bool holds_an_fmu(const fs::path& dir) {
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    if (e.path().extension() == ".fmu") return true;
  }
  return false;
}

class secure_remote : public ::testing::Test {
 protected:
  void SetUp() override { ::unsetenv(k_security_env); }

  cosim::temp_dir scratch{"stride-secure-"};

  // a keystore for `domains` with the identities `names`
  fs::path keystore(const std::string& name, const std::vector<std::string>& names,
                    const std::string& domains) {
    const fs::path dir = scratch.path() / name;
    const auto made = run_command(
        "'" + k_cli + "' security init " + quoted(dir) + " --domains " + domains, scratch.path());
    EXPECT_EQ(made.exit_code, 0) << made.err;
    for (const auto& n : names) {
      const auto added =
          run_command("'" + k_cli + "' security add " + quoted(dir) + " " + n, scratch.path());
      EXPECT_EQ(added.exit_code, 0) << added.err;
    }
    return dir;
  }
  worker_process start_worker(const std::string& name, int domain,
                              const std::vector<std::string>& extra,
                              const std::vector<std::string>& environment = {}) {
    return worker_process(k_cli, name, domain, scratch.path() / (name + ".log"), extra,
                          environment);
  }
  // the stride_test pair with b on worker w1, 100 steps
  fs::path pair_on_w1() {
    std::string xml = read(k_source / "tests/orchestrator/data/stride_test_pair.xml");
    const std::string from = "<component name=\"b\" fmu=\"stride_test\"";
    const auto at = xml.find(from);
    EXPECT_NE(at, std::string::npos);
    xml.replace(at, from.size(), from + " worker=\"w1\"");
    const fs::path f = scratch.path() / "pair-on-w1.xml";
    std::ofstream(f, std::ios::binary) << xml;
    return f;
  }
  cosim::test::process_result run(const fs::path& system, const std::string& out,
                                  const std::string& args) {
    return run_command("'" + k_cli + "' run " + quoted(system) + " --quiet --output " +
                           quoted(scratch.path() / out) + " " + args,
                       scratch.path());
  }
  std::string results(const std::string& out) { return read(scratch.path() / out / "results.csv"); }
};

#ifdef STRIDE_REMOTE_HAVE_WALK
TEST_F(secure_remote, the_walk_with_the_robot_on_a_secure_worker_equals_the_walk_in_process) {
  const fs::path ks = keystore("ks", {"w1", "orchestrator"}, "100");
  auto w = start_worker("w1", 100, {"--security", (ks / "w1").string()});
  ASSERT_TRUE(w.ready()) << w.output();
  ASSERT_EQ(run(k_source / "models/walk.xml", "local", "--stop-time 10").exit_code, 0);
  const auto remote = run(k_source / "models/distributed/walk-robot-on-worker.xml", "remote",
                          "--stop-time 10 --domain 100 --security " + quoted(ks / "orchestrator"));
  ASSERT_EQ(remote.exit_code, 0) << remote.err << w.output();
  EXPECT_EQ(results("remote"), results("local"));
  EXPECT_THAT(w.output(), HasSubstr("loaded robot"));
  // the identity may also come from the environment; without one the worker is invisible
  const auto listed = run_command(
      "STRIDE_SECURITY=" + quoted(ks / "orchestrator") + " '" + k_cli + "' workers --domain 100",
      scratch.path());
  EXPECT_THAT(listed.out, HasSubstr("w1"));
  const auto unlisted = run_command("'" + k_cli + "' workers --domain 100", scratch.path());
  EXPECT_THAT(unlisted.out, HasSubstr("no worker on DDS domain 100"));
}
#endif

TEST_F(secure_remote, runs_without_a_proper_identity_fail_and_the_worker_serves_the_next) {
  const fs::path ks = keystore("ks", {"w1", "orchestrator"}, "101");
  const fs::path other = keystore("other", {"orchestrator"}, "101");
  const fs::path elsewhere = keystore("elsewhere", {"orchestrator"}, "7");
  keystore::identity_options old;
  old.valid_days = 1;
  old.not_before = std::chrono::system_clock::now() - std::chrono::hours(24 * 10);
  keystore::add(ks, "expired", old);
  keystore::identity_options early;
  early.not_before = std::chrono::system_clock::now() + std::chrono::hours(48);
  keystore::add(ks, "early", early);
  auto w = start_worker("w1", 101, {"--security", (ks / "w1").string()});
  ASSERT_TRUE(w.ready()) << w.output();
  const fs::path system = pair_on_w1();

  const auto none = run(system, "none", "--domain 101 --worker-timeout 3");
  EXPECT_NE(none.exit_code, 0);
  EXPECT_THAT(none.err, AllOf(HasSubstr("worker 'w1' did not appear on DDS domain 101"),
                              HasSubstr("out of reach of a run without it")));
  const auto foreign =
      run(system, "foreign",
          "--domain 101 --worker-timeout 3 --security " + quoted(other / "orchestrator"));
  EXPECT_NE(foreign.exit_code, 0);
  EXPECT_THAT(foreign.err,
              AllOf(HasSubstr("worker 'w1' did not appear on DDS domain 101"),
                    HasSubstr("unless its own comes from the same keystore"),
                    HasSubstr((other / "orchestrator" / "identity_ca.cert.pem").string()),
                    HasSubstr("`stride security add " + other.string() + " w1`")));
  // Both sides say once whom they refused: the side that answers the handshake (DDS picks it by
  // the participants' ids) refuses the other's certificate, the side that asked gets no answer.
  ASSERT_TRUE(w.wait_for("refused peer ")) << w.output();
  const std::string log = w.output();
  EXPECT_EQ(log.find("refused peer "), log.rfind("refused peer ")) << log;
  EXPECT_THAT(foreign.err, HasSubstr("stride: refused peer "));
  EXPECT_EQ(foreign.err.find("refused peer "), foreign.err.rfind("refused peer ")) << foreign.err;
  const std::string refusal = "unable to get local issuer certificate";
  const std::string silence = "it did not answer the DDS Security handshake";
  if (log.find(refusal) != std::string::npos) {
    EXPECT_THAT(log, HasSubstr("CN=orchestrator: " + refusal));
    EXPECT_THAT(foreign.err, HasSubstr(silence));
  } else {
    EXPECT_THAT(log, HasSubstr(silence));
    EXPECT_THAT(foreign.err, HasSubstr("CN=w1: " + refusal));
  }
  const auto expired = run(system, "expired", "--domain 101 --security " + quoted(ks / "expired"));
  EXPECT_NE(expired.exit_code, 0);
  EXPECT_THAT(expired.err,
              AllOf(HasSubstr((ks / "expired" / "cert.pem").string()), HasSubstr("expired")));
  const auto not_yet = run(system, "early", "--domain 101 --security " + quoted(ks / "early"));
  EXPECT_NE(not_yet.exit_code, 0);
  EXPECT_THAT(not_yet.err, AllOf(HasSubstr((ks / "early" / "cert.pem").string()),
                                 HasSubstr("is not valid before")));
  const auto domain =
      run(system, "domain", "--domain 101 --security " + quoted(elsewhere / "orchestrator"));
  EXPECT_NE(domain.exit_code, 0);
  EXPECT_THAT(domain.err, AllOf(HasSubstr("permissions.p7s"), HasSubstr("domain 101")));
  // a worker with such an identity does not start (it would serve nobody)
  const auto expired_worker = run_command(
      "'" + k_cli + "' worker --name w9 --domain 101 --security " + quoted(ks / "expired"),
      scratch.path());
  EXPECT_EQ(expired_worker.exit_code, 1);
  EXPECT_THAT(expired_worker.err,
              AllOf(HasSubstr((ks / "expired" / "cert.pem").string()), HasSubstr("expired")));
  // each one line that says what to do
  EXPECT_THAT(expired.err, HasSubstr("make a new identity with `stride security add"));
  EXPECT_THAT(not_yet.err, HasSubstr("check this host's clock"));
  EXPECT_THAT(domain.err, HasSubstr("`stride security init DIR --domains 101`"));
  for (const auto* e : {&expired, &not_yet, &domain, &expired_worker}) {
    EXPECT_EQ(std::count(e->err.begin(), e->err.end(), '\n'), 1) << e->err;
  }
  EXPECT_THAT(w.output(), Not(HasSubstr("begins")));  // none of them reached the worker

  const auto proper =
      run(system, "proper", "--domain 101 --security " + quoted(ks / "orchestrator"));
  ASSERT_EQ(proper.exit_code, 0) << proper.err << w.output();
  EXPECT_THAT(w.output(), HasSubstr("loaded stride_test"));
  EXPECT_THAT(proper.err, Not(HasSubstr("refused peer")));
  EXPECT_EQ(w.output().find("refused peer "), w.output().rfind("refused peer ")) << w.output();
}

// `stride test --security` hands the identity to the processes of its cases. Case runs use DDS
// domain 0, so the worker has a name no other test uses.
TEST_F(secure_remote, a_suite_case_reaches_a_secure_worker_through_test_security) {
  const fs::path ks = keystore("ks", {"worker", "tester"}, "0");
  const std::string name = "secure-suite-" + std::to_string(::getpid());
  auto w = worker_process(k_cli, name, 0, scratch.path() / "w.log",
                          {"--security", (ks / "worker").string()});
  ASSERT_TRUE(w.ready()) << w.output();
  std::string xml = read(pair_on_w1());
  xml.replace(xml.find("worker=\"w1\""), 11, "worker=\"" + name + "\"");
  std::ofstream(scratch.path() / "pair.xml", std::ios::binary) << xml;
  std::ofstream(scratch.path() / "suite.xml")
      << "<suite name=\"secure\" version=\"1\"><case name=\"pair\" system=\"pair.xml\">"
         "<bounds signal=\"b.y\" min=\"-1e9\" max=\"1e9\"/></case></suite>";
  const std::string test = "'" + k_cli + "' test " + quoted(scratch.path() / "suite.xml");
  const auto secure = run_command(test + " --output " + quoted(scratch.path() / "secure") +
                                      " --security " + quoted(ks / "tester"),
                                  scratch.path());
  EXPECT_EQ(secure.exit_code, 0) << secure.out << secure.err << w.output();
  const auto plain =
      run_command(test + " --output " + quoted(scratch.path() / "plain"), scratch.path());
  EXPECT_NE(plain.exit_code, 0) << plain.out;  // without an identity the worker is out of reach
}

TEST_F(secure_remote, an_identity_with_a_key_others_can_read_or_a_missing_file_is_named) {
  const fs::path ks = keystore("ks", {"orchestrator"}, "102");
  const fs::path key = ks / "orchestrator" / "key.pem";
  const auto list_workers = [&] {
    return run_command(
        "'" + k_cli + "' workers --domain 102 --wait 0 --security " + quoted(ks / "orchestrator"),
        scratch.path());
  };
  ::chmod(key.c_str(), 0644);
  const auto open_key = list_workers();
  EXPECT_EQ(open_key.exit_code, 1);
  EXPECT_THAT(open_key.err, AllOf(HasSubstr(key.string()), HasSubstr("chmod 600")));
  ::chmod(key.c_str(), 0600);
  fs::remove(ks / "orchestrator" / "governance.p7s");
  const auto missing = list_workers();
  EXPECT_EQ(missing.exit_code, 1);
  EXPECT_THAT(missing.err, AllOf(HasSubstr("governance.p7s"), HasSubstr("missing")));
  // a file nobody can read as one (a folder in its place: even root cannot read that)
  fs::create_directory(ks / "orchestrator" / "governance.p7s");
  const auto unreadable = list_workers();
  EXPECT_EQ(unreadable.exit_code, 1);
  EXPECT_THAT(unreadable.err, AllOf(HasSubstr("governance.p7s"), HasSubstr("not a readable")));
  for (const auto* e : {&open_key, &missing, &unreadable}) {
    EXPECT_EQ(std::count(e->err.begin(), e->err.end(), '\n'), 1) << e->err;  // one line
  }
}

TEST_F(secure_remote, listed_fmus_run_and_unlisted_ones_are_refused_before_touching_the_disk) {
  const fs::path allowed = scratch.path() / "allowed";
  fs::create_directories(allowed);
  fs::copy_file(k_fmus / "stride_test.fmu", allowed / "stride_test.fmu");
  const fs::path tmp_ok = scratch.path() / "tmp-ok", tmp_refused = scratch.path() / "tmp-refused";
  fs::create_directories(tmp_ok);
  fs::create_directories(tmp_refused);
  const fs::path system = pair_on_w1();
  {
    auto w =
        start_worker("w1", 103, {"--allow-fmu", allowed.string()}, {"TMPDIR=" + tmp_ok.string()});
    ASSERT_TRUE(w.ready()) << w.output();
    const auto ok = run(system, "ok", "--domain 103");
    EXPECT_EQ(ok.exit_code, 0) << ok.err;
    EXPECT_TRUE(holds_an_fmu(tmp_ok));  // the control: a listed archive is written there
  }
  const fs::path list = scratch.path() / "list.txt";
  std::ofstream(list) << std::string(64, '0') << "  some-other.fmu\n";
  auto w =
      start_worker("w1", 104, {"--allow-fmu", list.string()}, {"TMPDIR=" + tmp_refused.string()});
  ASSERT_TRUE(w.ready()) << w.output();
  const auto refused = run(system, "refused", "--domain 104");
  EXPECT_NE(refused.exit_code, 0);
  const std::string bytes = read(k_fmus / "stride_test.fmu");
  const std::string hash = content_hash(std::as_bytes(std::span(bytes.data(), bytes.size())));
  EXPECT_THAT(refused.err,
              AllOf(HasSubstr("'b'"), HasSubstr(hash), HasSubstr("allow-list of worker 'w1'")));
  EXPECT_THAT(w.output(), HasSubstr("refused FMU " + hash + " for component 'b'"));
  EXPECT_FALSE(holds_an_fmu(tmp_refused));
}

TEST_F(secure_remote, a_worker_that_the_network_reaches_needs_security_or_insecure) {
  const std::string config = (k_source / "docs/dds/multi-host.xml").string();
  const std::vector<std::string> env = {"MY_IFACE=eth0", "PEER_ADDR=10.213.9.9"};
  auto refused = start_worker("w1", 105, {"--dds-config", config}, env);
  EXPECT_EQ(refused.wait_exit(), 1);
  EXPECT_THAT(refused.output(), AllOf(HasSubstr("network interface 'eth0'"),
                                      HasSubstr("--security"), HasSubstr("--insecure")));
  // on loopback, --insecure still says what it exposes, once
  auto insecure = start_worker("w2", 105, {"--insecure"});
  ASSERT_TRUE(insecure.ready()) << insecure.output();
  EXPECT_THAT(insecure.output(), HasSubstr("warning: --insecure"));
}

// Publishes, with plain Cyclone calls and no identity, a well-formed request asking worker w1 on
// `domain` to load the stride_test FMU, again and again for about two seconds.
void send_rogue_load_request(int domain) {
  const dds_entity_t d = dds_create_domain(static_cast<dds_domainid_t>(domain), loopback_config());
  ASSERT_GT(d, 0);
  const dds_entity_t participant =
      dds_create_participant(static_cast<dds_domainid_t>(domain), nullptr, nullptr);
  ASSERT_GT(participant, 0);
  dds_qos_t* qos = dds_create_qos();
  dds_qset_reliability(qos, DDS_RELIABILITY_RELIABLE, DDS_SECS(10));
  dds_qset_history(qos, DDS_HISTORY_KEEP_ALL, 0);
  const dds_entity_t topic = dds_create_topic(participant, &stride_remote_request_desc,
                                              "stride_remote_request", qos, nullptr);
  dds_qos_t* partition = dds_create_qos();
  dds_qset_partition1(partition, "stride.worker.w1");
  const dds_entity_t publisher = dds_create_publisher(participant, partition, nullptr);
  const dds_entity_t writer = dds_create_writer(publisher, topic, qos, nullptr);
  dds_delete_qos(partition);
  dds_delete_qos(qos);
  ASSERT_GT(writer, 0);
  std::string archive = read(k_fmus / "stride_test.fmu");
  std::string hash = content_hash(std::as_bytes(std::span(archive.data(), archive.size())));
  stride_remote_request r{};
  r.run = const_cast<char*>("rogue-run");
  r.component = const_cast<char*>("intruder");
  r.text = hash.data();
  r.op = static_cast<std::int32_t>(op::load);
  r.blob._buffer = reinterpret_cast<std::uint8_t*>(archive.data());
  r.blob._length = r.blob._maximum = static_cast<std::uint32_t>(archive.size());
  for (int i = 0; i < 20; ++i) {
    r.seq = static_cast<std::uint64_t>(i + 1);
    dds_write(writer, &r);
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  dds_delete(participant);
  dds_delete(d);
}

TEST_F(secure_remote, a_rogue_participant_without_identity_is_never_heard_by_a_secure_worker) {
  const fs::path ks = keystore("ks", {"w1"}, "106");
  const fs::path tmp_secure = scratch.path() / "tmp-secure", tmp_open = scratch.path() / "tmp-open";
  fs::create_directories(tmp_secure);
  fs::create_directories(tmp_open);
  auto secure = start_worker("w1", 106, {"--security", (ks / "w1").string()},
                             {"TMPDIR=" + tmp_secure.string()});
  auto open = worker_process(k_cli, "w1", 107, scratch.path() / "open.log", {},
                             {"TMPDIR=" + tmp_open.string()});
  ASSERT_TRUE(secure.ready() && open.ready()) << secure.output() << open.output();
  send_rogue_load_request(106);
  send_rogue_load_request(107);
  // the control: the same request loads the FMU on a worker without security
  EXPECT_TRUE(open.wait_for("loaded stride_test")) << open.output();
  EXPECT_THAT(open.output(), HasSubstr("run rogue-run begins"));
  EXPECT_TRUE(holds_an_fmu(tmp_open));
  EXPECT_THAT(secure.output(), AllOf(Not(HasSubstr("rogue-run")), Not(HasSubstr("loaded"))));
  EXPECT_FALSE(holds_an_fmu(tmp_secure));
}

#ifdef STRIDE_REMOTE_HAVE_AGENTS
TEST_F(secure_remote, agents_on_secure_workers_learn_what_agents_without_security_learn) {
  const fs::path ks = keystore("ks", {"w1", "w2", "orchestrator"}, "108");
  auto w1 = start_worker("w1", 108, {"--security", (ks / "w1").string()});
  auto w2 = start_worker("w2", 108, {"--security", (ks / "w2").string()});
  ASSERT_TRUE(w1.ready() && w2.ready()) << w1.output() << w2.output();
  std::string xml = read(k_demo);
  const auto at = xml.find("/>", xml.find("<simulation ")) + 2;   // <agents> follows <simulation>
  xml.insert(at, "\n  <agents count=\"1\" workers=\"w1 w2\"/>");  // --agents 2 below
  const fs::path system = scratch.path() / "agents.xml";
  std::ofstream(system, std::ios::binary) << xml;
  const std::string learner =
      " --no-plots --set learner.steps_per_episode=4"
      " --set learner.footsteps_per_step=2 --set learner.total_steps=12";
  const auto plain = run(k_demo, "plain", "--agents 2" + learner);
  ASSERT_EQ(plain.exit_code, 0) << plain.err;
  const auto secure =
      run(system, "secure",
          "--agents 2 --domain 108 --security " + quoted(ks / "orchestrator") + learner);
  ASSERT_EQ(secure.exit_code, 0) << secure.err << w1.output() << w2.output();
  for (const char* f :
       {"agent1/v_table.csv", "agent2/v_table.csv", "agent2/steps.csv", "shared_table.csv"}) {
    EXPECT_EQ(read(scratch.path() / "secure" / f), read(scratch.path() / "plain" / f)) << f;
  }
  EXPECT_THAT(w1.output(), HasSubstr("loaded learner"));
  EXPECT_THAT(w2.output(), HasSubstr("loaded learner"));
}
#endif

}  // namespace
}  // namespace stride::remote::test
