#include "stride/suite/runner.hpp"

#include <tinyxml2.h>

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>

#include "stride/cosim/error.hpp"
#include "stride/cosim/observers.hpp"

extern char** environ;

namespace stride::suite {

namespace fs = std::filesystem;

std::size_t suite_report::count(case_status s) const {
  return static_cast<std::size_t>(std::count_if(
      cases.begin(), cases.end(), [s](const case_report& c) { return c.status == s; }));
}

namespace {

std::string where(const assertion_spec& a) {
  const std::string s = a.where.str();
  return s.empty() ? s : s + ": ";
}

void check_assertion(const assertion_spec& a, const assertion_registry& kinds,
                     const fs::path& suite_dir) {
  const auto kind = kinds.find(a.kind);
  if (kind == kinds.end()) {
    std::string known;
    for (const auto& [name, k] : kinds) known += (known.empty() ? "" : ", ") + name;
    throw cosim::validation_error(where(a) + "unknown assertion <" + a.kind + "> (known: set, " +
                                  known + ")");
  }
  for (const auto& [name, value] : a.attributes) {
    const auto& allowed = kind->second.attributes;
    if (std::find(allowed.begin(), allowed.end(), name) == allowed.end()) {
      throw cosim::validation_error(where(a) + "unknown attribute '" + name + "' on <" + a.kind +
                                    ">");
    }
  }
  try {
    if (kind->second.check) kind->second.check(a, suite_dir);
    kind->second.signals(a, suite_dir);
  } catch (const std::invalid_argument& e) {
    throw cosim::validation_error(where(a) + "<" + a.kind + ">: " + e.what());
  }
}

// the signals a case must record: those of its assertions, each once
std::vector<std::string> needed_signals(const case_spec& c, const assertion_registry& kinds,
                                        const fs::path& suite_dir) {
  std::vector<std::string> out;
  for (const auto& a : c.assertions) {
    for (auto& s : kinds.at(a.kind).signals(a, suite_dir)) {
      if (std::find(out.begin(), out.end(), s) == out.end()) out.push_back(std::move(s));
    }
  }
  return out;
}

// the command line of one case's run
std::vector<std::string> case_command(const case_spec& c, const run_settings& settings,
                                      const fs::path& dir,
                                      const std::vector<std::string>& signals) {
  std::vector<std::string> args = {settings.stride.string(),
                                   "run",
                                   c.system.string(),
                                   "--output",
                                   dir.string(),
                                   "--quiet",
                                   "--no-plots",
                                   "--threads",
                                   "1",
                                   "--force"};  // the case folder holds its run.log already
  if (c.stop_time) args.insert(args.end(), {"--stop-time", *c.stop_time});
  if (c.record_interval) args.insert(args.end(), {"--record-interval", *c.record_interval});
  for (const auto& s : c.sets) args.insert(args.end(), {"--set", s});
  for (const auto& s : signals) args.insert(args.end(), {"--signals", s});
  return args;
}

pid_t spawn(const std::vector<std::string>& args, const fs::path& log) {
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, log.c_str(),
                                   O_WRONLY | O_CREAT | O_TRUNC, 0644);
  std::vector<char*> argv;
  for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  pid_t pid = 0;
  const int rc = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (rc != 0) throw std::runtime_error("cannot start " + args[0] + ": " + std::strerror(rc));
  return pid;
}

// the run's one-line error: the last non-empty line of its log, passing over the command line
// parser's closing hint
std::string last_line(const fs::path& log) {
  std::ifstream in(log);
  std::string line, last;
  while (std::getline(in, line)) {
    if (!line.empty() && line.rfind("Run with --help", 0) != 0) last = line;
  }
  return last;
}

void evaluate(const case_spec& c, const run_settings& settings, const fs::path& suite_dir,
              case_report& r) {
  recorded_signals signals;
  try {
    signals = read_recorded_signals(r.dir / "results.csv");
  } catch (const std::exception& e) {
    r.status = case_status::error;
    r.error = e.what();
    return;
  }
  const case_output out{r.dir, &signals, suite_dir};
  for (const auto& a : c.assertions) {
    outcome o;
    try {
      o = settings.kinds.at(a.kind).evaluate(a, out);
    } catch (const std::exception& e) {
      o = {false, e.what()};
    }
    if (!o.passed) r.failures.push_back(where(a) + a.kind + ": " + o.message);
  }
  r.status = r.failures.empty() ? case_status::passed : case_status::failed;
}

std::string status_word(case_status s) {
  return s == case_status::passed ? "PASS" : s == case_status::failed ? "FAIL" : "ERROR";
}

std::string seconds(double s) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f", s);
  return buf;
}

}  // namespace

void check_suite(const suite_spec& suite, const assertion_registry& kinds) {
  const fs::path dir = suite.file.parent_path();
  for (const auto& c : suite.cases) {
    if (!fs::exists(c.system)) {  // a file, or a folder (an SSP's)
      throw cosim::validation_error(c.where.str() + ": system file " + c.system.string() +
                                    " not found");
    }
    for (const auto& a : c.assertions) check_assertion(a, kinds, dir);
  }
}

suite_report run_suite(const suite_spec& suite, const run_settings& settings) {
  using clock = std::chrono::steady_clock;
  const fs::path suite_dir = suite.file.parent_path();
  std::vector<const case_spec*> selected;
  for (const auto& c : suite.cases) {
    if (settings.filter.empty() || cosim::glob_match(settings.filter, c.name)) {
      selected.push_back(&c);
    }
  }
  if (selected.empty()) {
    throw cosim::validation_error(suite.file.string() + ": no case matches --filter '" +
                                  settings.filter + "'");
  }
  suite_report report;
  report.cases.resize(selected.size());
  const auto suite_start = clock::now();
  std::map<pid_t, std::pair<std::size_t, clock::time_point>> running;
  std::size_t next = 0;
  const auto finish = [&](std::size_t i, int status, clock::time_point start) {
    case_report& r = report.cases[i];
    r.seconds = std::chrono::duration<double>(clock::now() - start).count();
    if (WIFEXITED(status) && WEXITSTATUS(status) == 0) {
      evaluate(*selected[i], settings, suite_dir, r);
    } else {
      r.status = case_status::error;
      const std::string why = last_line(r.dir / "run.log");
      r.error =
          (WIFSIGNALED(status) ? "the run was killed by signal " + std::to_string(WTERMSIG(status))
                               : "the run failed") +
          (why.empty() ? std::string() : ": " + why) + " (log: " + (r.dir / "run.log").string() +
          ")";
    }
    if (settings.progress) {
      std::fprintf(settings.progress, "%-5s %s (%s s)\n", status_word(r.status).c_str(),
                   r.name.c_str(), seconds(r.seconds).c_str());
      std::fflush(settings.progress);
    }
  };
  while (next < selected.size() || !running.empty()) {
    // start cases while there is room
    while (next < selected.size() &&
           running.size() < static_cast<std::size_t>(std::max(1, settings.jobs))) {
      const case_spec& c = *selected[next];
      case_report& r = report.cases[next];
      r.name = c.name;
      r.dir = settings.output_dir / c.name;
      fs::remove_all(r.dir);
      fs::create_directories(r.dir);
      const auto args =
          case_command(c, settings, r.dir, needed_signals(c, settings.kinds, suite_dir));
      running[spawn(args, r.dir / "run.log")] = {next, clock::now()};
      ++next;
    }
    int status = 0;
    const pid_t pid = ::waitpid(-1, &status, 0);
    if (pid < 0) throw std::runtime_error(std::string("waitpid: ") + std::strerror(errno));
    const auto it = running.find(pid);
    if (it == running.end()) continue;
    finish(it->second.first, status, it->second.second);
    running.erase(it);
  }
  report.seconds = std::chrono::duration<double>(clock::now() - suite_start).count();
  return report;
}

std::string format_summary(const suite_report& report) {
  std::string out;
  for (const auto& c : report.cases) {
    out += status_word(c.status) + "  " + c.name + " (" + seconds(c.seconds) + " s)\n";
    for (const auto& f : c.failures) out += "      " + f + "\n";
    if (c.status == case_status::error) out += "      " + c.error + "\n";
  }
  const std::size_t errors = report.count(case_status::error);
  out += std::to_string(report.count(case_status::passed)) + " passed, " +
         std::to_string(report.count(case_status::failed) + errors) + " failed";
  if (errors > 0) out += " (" + std::to_string(errors) + " could not run)";
  out += " in " + seconds(report.seconds) + " s\n";
  return out;
}

namespace {

// XML 1.0 has no place for most control characters; tinyxml2 escapes the rest
std::string xml_text(std::string s) {
  for (char& c : s) {
    if (static_cast<unsigned char>(c) < 0x20 && c != '\n' && c != '\t') c = ' ';
  }
  return s;
}

// the counts and time JUnit readers expect on <testsuites> and <testsuite>
void set_totals(tinyxml2::XMLElement* e, const std::string& name, const suite_report& report) {
  e->SetAttribute("name", name.c_str());
  e->SetAttribute("tests", static_cast<int64_t>(report.cases.size()));
  e->SetAttribute("failures", static_cast<int64_t>(report.count(case_status::failed)));
  e->SetAttribute("errors", static_cast<int64_t>(report.count(case_status::error)));
}

}  // namespace

void write_junit(const fs::path& file, const suite_spec& suite, const suite_report& report) {
  const std::string name = xml_text(suite.name);
  tinyxml2::XMLDocument doc;
  doc.InsertEndChild(doc.NewDeclaration());
  auto* root = doc.NewElement("testsuites");
  doc.InsertEndChild(root);
  set_totals(root, name, report);
  root->SetAttribute("time", seconds(report.seconds).c_str());
  auto* ts = root->InsertNewChildElement("testsuite");
  set_totals(ts, name, report);
  ts->SetAttribute("skipped", 0);
  ts->SetAttribute("time", seconds(report.seconds).c_str());
  for (const auto& c : report.cases) {
    auto* tc = ts->InsertNewChildElement("testcase");
    tc->SetAttribute("name", xml_text(c.name).c_str());
    tc->SetAttribute("classname", name.c_str());
    tc->SetAttribute("time", seconds(c.seconds).c_str());
    if (c.status == case_status::failed) {
      std::string all;
      for (const auto& f : c.failures) all += f + "\n";
      auto* f = tc->InsertNewChildElement("failure");
      f->SetAttribute("message",
                      xml_text(c.failures.empty() ? "failed" : c.failures.front()).c_str());
      f->SetAttribute("type", "assertion");
      f->SetText(xml_text(all).c_str());
    } else if (c.status == case_status::error) {
      auto* e = tc->InsertNewChildElement("error");
      e->SetAttribute("message", xml_text(c.error).c_str());
      e->SetAttribute("type", "run");
      e->SetText(xml_text(c.error).c_str());
    }
  }
  if (file.has_parent_path()) fs::create_directories(file.parent_path());
  tinyxml2::XMLPrinter printer;
  doc.Print(&printer);
  std::ofstream out(file, std::ios::binary);
  out.write(printer.CStr(), printer.CStrSize() - 1);  // without the terminating NUL
  out.close();
  if (!out) throw std::runtime_error("cannot write " + file.string());
}

}  // namespace stride::suite
