#include "security.hpp"

#include <cstdio>
#include <stdexcept>

#include "stride/remote/keystore.hpp"

namespace stride::cli {
namespace {

namespace keystore = remote::keystore;

void print(const std::vector<std::string>& lines) {
  for (const std::string& line : lines) std::printf("%s\n", line.c_str());
}

int init(const security_arguments& a) {
  keystore::init_options o;
  try {
    o.domains = keystore::parse_domains(a.domains);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string("--domains: ") + e.what() + " (e.g. 0,3-5)");
  }
  o.level = a.protection == "sign" ? keystore::protection::sign : keystore::protection::encrypt;
  o.valid_days = a.ca_valid_days;
  print(keystore::init(a.dir, o));
  return 0;
}

int add(const security_arguments& a) {
  keystore::identity_options o;
  o.valid_days = a.identity_valid_days;
  print(keystore::add(a.dir, a.name, o));
  return 0;
}

}  // namespace

CLI::App* add_security_command(CLI::App& app, security_arguments& args) {
  auto* c = app.add_subcommand(
      "security", "Make and inspect DDS Security keystores: who may join Stride's DDS domains");
  c->require_subcommand(1);

  args.init = c->add_subcommand(
      "init",
      "Make a keystore in DIR (new or empty): a CA and the signed governance of its domains");
  args.init->add_option("DIR", args.dir, "Folder of the keystore")->required();
  args.init->add_option("--domains", args.domains, "DDS domains it governs, e.g. 0,3-5")
      ->capture_default_str();
  args.init
      ->add_option("--protection", args.protection,
                   "encrypt, or sign only: discovery, messages and topic data")
      ->capture_default_str()
      ->check(CLI::IsMember({"encrypt", "sign"}));
  args.init->add_option("--valid-days", args.ca_valid_days, "Days the CA is valid")
      ->capture_default_str()
      ->check(CLI::Range(1, 36500));

  args.add = c->add_subcommand(
      "add", "Add identity NAME to the keystore DIR: DIR/NAME is what one host needs");
  args.add->add_option("DIR", args.dir, "Folder of the keystore")->required();
  args.add->add_option("NAME", args.name, "Name of the identity (A-Z a-z 0-9 _ . -)")->required();
  args.add->add_option("--valid-days", args.identity_valid_days, "Days the identity is valid")
      ->capture_default_str()
      ->check(CLI::Range(1, 36500));

  args.show = c->add_subcommand(
      "show", "Describe a keystore or one identity: subjects, validity, domains, checks");
  args.show->add_option("DIR", args.dir, "A keystore, or an identity folder DIR/NAME")->required();
  return c;
}

int security(const security_arguments& args) {
  if (*args.init) return init(args);
  if (*args.add) return add(args);
  std::fputs(remote::keystore::show(args.dir).c_str(), stdout);
  return 0;
}

}  // namespace stride::cli
