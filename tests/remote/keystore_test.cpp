// DDS Security keystores (stride/remote/keystore.hpp): the files and their modes, certificates
// issued by the keystore's CA and no other, validity, signed permissions that verify (and stop
// verifying when tampered with), the documents' structure as Cyclone DDS parses it, refusals.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <tinyxml2.h>

#include <cstdlib>
#include <fstream>
#include <regex>
#include <sstream>

#include "keystore_x509.hpp"
#include "stride/remote/keystore.hpp"

namespace stride::remote::keystore {
namespace {

namespace fs = std::filesystem;
using std::chrono::days;
using std::chrono::system_clock;
using ::testing::ElementsAre;
using ::testing::HasSubstr;
using ::testing::Not;

std::string read(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

unsigned mode(const fs::path& p) {
  struct stat st {};
  EXPECT_EQ(::stat(p.c_str(), &st), 0) << p;
  return st.st_mode & 07777;
}

// the message of what `f` throws ("" when it does not)
template <typename F>
std::string error_of(F&& f) {
  try {
    f();
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

// the element names under `e`, in order
std::vector<std::string> children(const tinyxml2::XMLElement* e) {
  std::vector<std::string> names;
  for (auto* c = e->FirstChildElement(); c != nullptr; c = c->NextSiblingElement()) {
    names.push_back(c->Name());
  }
  return names;
}

class keystore_test : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string pattern = (fs::temp_directory_path() / "stride-keystore-test-XXXXXX").string();
    ASSERT_NE(::mkdtemp(pattern.data()), nullptr);
    scratch = pattern;
  }
  void TearDown() override { fs::remove_all(scratch); }

  // a keystore with `domains` and identity "alice"
  fs::path keystore(const std::string& name, std::vector<int> domains = {0, 3, 4, 5}) {
    init_options o;
    o.domains = std::move(domains);
    init(scratch / name, o);
    add(scratch / name, "alice", {});
    return scratch / name;
  }

  fs::path scratch;
};

TEST_F(keystore_test, init_makes_every_file_with_private_modes) {
  const fs::path dir = scratch / "ks";
  const auto lines = init(dir, {});
  ASSERT_EQ(lines.size(), 4u);
  for (const char* file :
       {"ca.cert.pem", "private/ca.key.pem", "governance.xml", "governance.p7s"}) {
    EXPECT_TRUE(fs::is_regular_file(dir / file)) << file;
  }
  EXPECT_THAT(lines[0], HasSubstr((dir / "ca.cert.pem").string()));
  EXPECT_THAT(lines[0], HasSubstr("CN=Stride keystore CA "));
  EXPECT_EQ(mode(dir / "private"), 0700u);
  EXPECT_EQ(mode(dir / "private" / "ca.key.pem"), 0600u);
  const auto ca = read_certificate(dir / "ca.cert.pem");
  EXPECT_EQ(ca.subject, ca.issuer);  // self-signed
  EXPECT_TRUE(issued_by(dir / "ca.cert.pem", dir / "ca.cert.pem"));
  EXPECT_EQ(ca.not_after - ca.not_before, days(3650));
}

TEST_F(keystore_test, init_refuses_a_non_empty_folder_and_leaves_it_alone) {
  const fs::path dir = scratch / "ks";
  fs::create_directory(dir);
  std::ofstream(dir / "notes.txt") << "mine";
  const std::string error = error_of([&] { init(dir, {}); });
  EXPECT_THAT(error, HasSubstr(dir.string()));
  EXPECT_THAT(error, HasSubstr("not empty"));
  EXPECT_EQ(read(dir / "notes.txt"), "mine");
  EXPECT_FALSE(fs::exists(dir / "ca.cert.pem"));
  // a second init over a keystore is refused the same way
  const fs::path made = scratch / "made";
  init(made, {});
  const std::string ca = read(made / "ca.cert.pem");
  EXPECT_THAT(error_of([&] { init(made, {}); }), HasSubstr("not empty"));
  EXPECT_EQ(read(made / "ca.cert.pem"), ca);
}

TEST_F(keystore_test, init_accepts_an_empty_folder_and_refuses_bad_options) {
  fs::create_directory(scratch / "empty");
  EXPECT_EQ(init(scratch / "empty", {}).size(), 4u);
  init_options o;
  o.domains = {231};
  EXPECT_THAT(error_of([&] { init(scratch / "a", o); }), HasSubstr("231"));
  o.domains = {};
  EXPECT_THAT(error_of([&] { init(scratch / "b", o); }), HasSubstr("domain"));
  o.domains = {0};
  o.valid_days = 0;
  EXPECT_THAT(error_of([&] { init(scratch / "c", o); }), HasSubstr("valid days"));
  EXPECT_FALSE(fs::exists(scratch / "a"));
  EXPECT_FALSE(fs::exists(scratch / "c"));
}

TEST_F(keystore_test, add_makes_a_self_contained_identity_issued_by_the_ca) {
  const fs::path dir = keystore("ks");
  const fs::path id = dir / "alice";
  for (const char* file : {"identity_ca.cert.pem", "permissions_ca.cert.pem", "governance.p7s",
                           "cert.pem", "key.pem", "permissions.xml", "permissions.p7s"}) {
    EXPECT_TRUE(fs::is_regular_file(id / file)) << file;
  }
  EXPECT_EQ(mode(id / "key.pem"), 0600u);
  EXPECT_EQ(read(id / "identity_ca.cert.pem"), read(dir / "ca.cert.pem"));
  EXPECT_EQ(read(id / "permissions_ca.cert.pem"), read(dir / "ca.cert.pem"));
  EXPECT_EQ(read(id / "governance.p7s"), read(dir / "governance.p7s"));
  EXPECT_TRUE(issued_by(id / "cert.pem", dir / "ca.cert.pem"));
  EXPECT_TRUE(issued_by(id / "cert.pem", id / "identity_ca.cert.pem"));

  const fs::path other = keystore("other");
  EXPECT_FALSE(issued_by(id / "cert.pem", other / "ca.cert.pem"));
  EXPECT_FALSE(issued_by(other / "alice" / "cert.pem", dir / "ca.cert.pem"));

  // CN=NAME and the keystore's O, in the RFC 2253 text Cyclone compares
  const auto cert = read_certificate(id / "cert.pem");
  const auto ca = read_certificate(dir / "ca.cert.pem");
  EXPECT_TRUE(std::regex_match(cert.subject, std::regex("CN=alice,O=Stride keystore [0-9a-f]{8}")))
      << cert.subject;
  EXPECT_THAT(ca.subject, HasSubstr(cert.subject.substr(cert.subject.find(",O="))));
  EXPECT_EQ(cert.issuer, ca.subject);
}

TEST_F(keystore_test, validity_honours_valid_days_and_not_before) {
  const fs::path dir = keystore("ks");
  identity_options o;
  o.valid_days = 30;
  o.not_before = system_clock::now() - days(40);
  add(dir, "old", o);
  const auto old = read_certificate(dir / "old" / "cert.pem");
  EXPECT_EQ(old.not_before, std::chrono::floor<std::chrono::seconds>(*o.not_before));
  EXPECT_EQ(old.not_after - old.not_before, days(30));
  EXPECT_LT(old.not_after, system_clock::now());  // expired
  EXPECT_THAT(show(dir / "old"), HasSubstr("(expired)"));

  const auto before = std::chrono::floor<std::chrono::seconds>(system_clock::now());
  add(dir, "now", {});
  const auto now = read_certificate(dir / "now" / "cert.pem");
  EXPECT_GE(now.not_before, before);
  EXPECT_LE(now.not_before, system_clock::now());
  EXPECT_EQ(now.not_after - now.not_before, days(365));
}

TEST_F(keystore_test, an_identity_never_outlives_its_ca) {
  init_options o;
  o.valid_days = 10;
  init(scratch / "ks", o);
  const auto lines = add(scratch / "ks", "alice", {});
  EXPECT_THAT(lines[0], HasSubstr("cut to the CA's expiry"));
  EXPECT_EQ(read_certificate(scratch / "ks" / "alice" / "cert.pem").not_after,
            read_certificate(scratch / "ks" / "ca.cert.pem").not_after);
}

TEST_F(keystore_test, permissions_verify_against_the_ca_and_allow_the_init_domains) {
  const fs::path dir = keystore("ks");
  const fs::path id = dir / "alice";
  EXPECT_THAT(permitted_domains(id / "permissions.p7s", id / "permissions_ca.cert.pem"),
              ElementsAre(0, 3, 4, 5));
  EXPECT_THAT(permitted_domains(id / "permissions.xml"), ElementsAre(0, 3, 4, 5));
  const fs::path other = keystore("other", {7});
  const std::string error =
      error_of([&] { permitted_domains(id / "permissions.p7s", other / "ca.cert.pem"); });
  EXPECT_THAT(error, HasSubstr((id / "permissions.p7s").string()));
  EXPECT_THAT(permitted_domains(other / "alice" / "permissions.p7s", other / "ca.cert.pem"),
              ElementsAre(7));
}

TEST_F(keystore_test, tampered_permissions_fail_verification_naming_the_file) {
  const fs::path id = keystore("ks") / "alice";
  std::string signed_text = read(id / "permissions.p7s");
  const auto at = signed_text.find("<id>0</id>");
  ASSERT_NE(at, std::string::npos);
  signed_text[at + 4] = '1';  // one byte of the XML: domain 0 becomes domain 1
  fs::remove(id / "permissions.p7s");
  std::ofstream(id / "permissions.p7s", std::ios::binary) << signed_text;
  const std::string error =
      error_of([&] { permitted_domains(id / "permissions.p7s", id / "permissions_ca.cert.pem"); });
  EXPECT_THAT(error, HasSubstr((id / "permissions.p7s").string()));
  EXPECT_THAT(error, HasSubstr("does not verify"));
  EXPECT_THAT(error_of([&] { show(id); }), HasSubstr("permissions.p7s"));
  // unverified, the changed text is what it says
  EXPECT_THAT(permitted_domains(id / "permissions.p7s"), ElementsAre(1, 3, 4, 5));
}

TEST_F(keystore_test, permissions_grant_the_certificate_subject_and_validity_exactly) {
  const fs::path id = keystore("ks") / "alice";
  tinyxml2::XMLDocument doc;
  ASSERT_EQ(doc.LoadFile((id / "permissions.xml").c_str()), tinyxml2::XML_SUCCESS);
  const auto* grant =
      doc.RootElement()->FirstChildElement("permissions")->FirstChildElement("grant");
  ASSERT_NE(grant, nullptr);
  const auto cert = read_certificate(id / "cert.pem");
  EXPECT_STREQ(grant->FirstChildElement("subject_name")->GetText(), cert.subject.c_str());
  EXPECT_STREQ(grant->Attribute("name"), "alice");
  EXPECT_THAT(children(grant), ElementsAre("subject_name", "validity", "allow_rule", "default"));
  EXPECT_STREQ(grant->FirstChildElement("default")->GetText(), "DENY");
  const std::string not_before =
      grant->FirstChildElement("validity")->FirstChildElement("not_before")->GetText();
  EXPECT_TRUE(std::regex_match(not_before, std::regex(R"(\d{4}-\d\d-\d\dT\d\d:\d\d:\d\d)")));
  const auto* rule = grant->FirstChildElement("allow_rule");
  EXPECT_THAT(children(rule), ElementsAre("domains", "publish", "subscribe"));
  for (const char* kind : {"publish", "subscribe"}) {
    const auto* criteria = rule->FirstChildElement(kind);
    std::vector<std::string> topics;
    for (auto* t = criteria->FirstChildElement("topics")->FirstChildElement("topic"); t;
         t = t->NextSiblingElement("topic")) {
      topics.push_back(t->GetText());
    }
    EXPECT_EQ(topics, stride_topics()) << kind;
    // a rule without partitions covers only the default partition
    EXPECT_STREQ(
        criteria->FirstChildElement("partitions")->FirstChildElement("partition")->GetText(), "*");
  }
}

TEST_F(keystore_test, governance_follows_the_schema_order_and_the_protection) {
  for (const auto level : {protection::encrypt, protection::sign}) {
    init_options o;
    o.level = level;
    const fs::path dir = scratch / (level == protection::encrypt ? "e" : "s");
    init(dir, o);
    tinyxml2::XMLDocument doc;
    ASSERT_EQ(doc.LoadFile((dir / "governance.xml").c_str()), tinyxml2::XML_SUCCESS);
    const auto* root = doc.RootElement();
    // Cyclone's parser refuses any other attribute
    std::vector<std::string> attributes;
    for (auto* a = root->FirstAttribute(); a; a = a->Next()) attributes.push_back(a->Name());
    EXPECT_THAT(attributes, ElementsAre("xmlns:xsi", "xsi:noNamespaceSchemaLocation"));
    const auto* rule =
        root->FirstChildElement("domain_access_rules")->FirstChildElement("domain_rule");
    EXPECT_THAT(
        children(rule),
        ElementsAre("domains", "allow_unauthenticated_participants", "enable_join_access_control",
                    "discovery_protection_kind", "liveliness_protection_kind",
                    "rtps_protection_kind", "topic_access_rules"));
    const auto* topic =
        rule->FirstChildElement("topic_access_rules")->FirstChildElement("topic_rule");
    EXPECT_THAT(children(topic),
                ElementsAre("topic_expression", "enable_discovery_protection",
                            "enable_liveliness_protection", "enable_read_access_control",
                            "enable_write_access_control", "metadata_protection_kind",
                            "data_protection_kind"));
    const char* kind = level == protection::encrypt ? "ENCRYPT" : "SIGN";
    for (const char* e :
         {"discovery_protection_kind", "liveliness_protection_kind", "rtps_protection_kind"}) {
      EXPECT_STREQ(rule->FirstChildElement(e)->GetText(), kind) << e;
    }
    // each message is protected once, as a whole: not its submessages and payloads again
    for (const char* e : {"metadata_protection_kind", "data_protection_kind"}) {
      EXPECT_STREQ(topic->FirstChildElement(e)->GetText(), "NONE") << e;
    }
    EXPECT_STREQ(rule->FirstChildElement("allow_unauthenticated_participants")->GetText(), "false");
    EXPECT_THAT(show(dir), HasSubstr(level == protection::encrypt ? "encrypt" : "sign"));
  }
}

TEST_F(keystore_test, bad_names_and_existing_identities_are_refused) {
  const fs::path dir = keystore("ks");
  const std::vector<std::string> bad_names{
      "", "a/b", "..", ".", "a b", "caf\xc3\xa9", std::string(65, 'a'), "a,O=x"};
  for (const std::string& name : bad_names) {
    EXPECT_THAT(error_of([&] { add(dir, name, {}); }), HasSubstr("not allowed")) << name;
  }
  EXPECT_TRUE(valid_identity_name("worker-1.host_a"));
  const std::string cert = read(dir / "alice" / "cert.pem");
  const std::string error = error_of([&] { add(dir, "alice", {}); });
  EXPECT_THAT(error, HasSubstr((dir / "alice").string()));
  EXPECT_THAT(error, HasSubstr("already exists"));
  EXPECT_EQ(read(dir / "alice" / "cert.pem"), cert);
  // "private" is the CA's folder
  EXPECT_THAT(error_of([&] { add(dir, "private", {}); }), HasSubstr("already exists"));
  // not a keystore
  fs::create_directory(scratch / "plain");
  EXPECT_THAT(error_of([&] { add(scratch / "plain", "bob", {}); }), HasSubstr("ca.cert.pem"));
  EXPECT_FALSE(fs::exists(scratch / "plain" / "bob"));
}

TEST_F(keystore_test, show_describes_keystores_and_identities) {
  const fs::path dir = keystore("ks");
  add(dir, "bob", {});
  const std::string ks = show(dir);
  const auto ca = read_certificate(dir / "ca.cert.pem");
  EXPECT_THAT(ks, HasSubstr(ca.subject));
  EXPECT_THAT(ks, HasSubstr("0,3-5"));
  EXPECT_THAT(ks, HasSubstr("encrypt"));
  EXPECT_THAT(ks, HasSubstr("alice: CN=alice"));
  EXPECT_THAT(ks, HasSubstr("bob: CN=bob"));
  EXPECT_THAT(ks, HasSubstr("mode 0600"));

  const fs::path id = dir / "alice";
  const std::string alice = show(id);
  EXPECT_THAT(alice, HasSubstr(read_certificate(id / "cert.pem").subject));
  EXPECT_THAT(alice, HasSubstr(ca.subject));  // the issuer
  EXPECT_THAT(alice, HasSubstr("0,3-5"));
  EXPECT_THAT(alice, HasSubstr("(valid)"));
  EXPECT_THAT(alice, HasSubstr("key.pem, mode 0600"));
  EXPECT_THAT(alice, Not(HasSubstr("chmod")));
  fs::permissions(id / "key.pem", fs::perms::owner_read | fs::perms::owner_write |
                                      fs::perms::group_read | fs::perms::others_read);
  EXPECT_THAT(show(id), HasSubstr("mode 0644 (should be 0600: run chmod 600"));

  fs::remove(id / "permissions_ca.cert.pem");
  EXPECT_THAT(error_of([&] { show(id); }), HasSubstr((id / "permissions_ca.cert.pem").string()));
  EXPECT_THAT(error_of([&] { show(scratch); }), HasSubstr("neither a keystore"));
}

// A keystore whose governance also protects submessages and payloads inside each message (as
// keystores once did) still works; `show` says it is slower than a new one.
TEST_F(keystore_test, show_tells_a_governance_that_protects_inside_each_message) {
  const fs::path dir = keystore("ks");
  EXPECT_THAT(show(dir), Not(HasSubstr("protected again")));
  std::string xml = read(dir / "governance.xml");
  for (const std::string layer : {"metadata_protection_kind", "data_protection_kind"}) {
    const std::string none = "<" + layer + ">NONE<";
    ASSERT_NE(xml.find(none), std::string::npos) << layer;
    xml.replace(xml.find(none), none.size(), "<" + layer + ">ENCRYPT<");
  }
  const auto ca = x509::certificate_from_pem(read(dir / "ca.cert.pem"));
  const auto ca_key = x509::key_from_pem(read(dir / "private" / "ca.key.pem"));
  std::ofstream(dir / "governance.p7s", std::ios::binary)
      << x509::smime_sign(xml, ca.get(), ca_key.get());
  const std::string text = show(dir);
  EXPECT_THAT(text, HasSubstr("encrypt, each message's submessages and payloads protected again"));
  EXPECT_THAT(text, HasSubstr("0,3-5"));
}

TEST(keystore_domains, parse_and_format_domain_lists) {
  EXPECT_THAT(parse_domains("0,3-5"), ElementsAre(0, 3, 4, 5));
  EXPECT_THAT(parse_domains("5,0,5"), ElementsAre(0, 5));
  EXPECT_THAT(parse_domains("230"), ElementsAre(230));
  for (const char* bad : {"", "231", "5-3", "a", "1,", "-1", "1-", " 1", "0x1"}) {
    EXPECT_THROW(parse_domains(bad), std::invalid_argument) << bad;
  }
  EXPECT_EQ(format_domains({5, 0, 3, 4}), "0,3-5");
  EXPECT_EQ(format_domains({1, 3}), "1,3");
  EXPECT_THAT(stride_topics(), ElementsAre("stride_remote_request", "stride_remote_reply",
                                           "stride_remote_worker_info", "stride_table_update",
                                           "stride_table_state"));
}

}  // namespace
}  // namespace stride::remote::keystore
