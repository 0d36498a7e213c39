// SPDX-License-Identifier: Apache-2.0
// formal-summary: the figures of `make formal` (tests/formal.mk) in summary.json and
// summary.md, and its verdict.
//
//   formal-summary --sby-dir DIR --work DIR --out DIR TASK...
//
// For each TASK it reads the task's description, SBY-DIR/TASK.sby (mode and depth from
// [options], the module from `prep -top`, its parameters from `chparam -set`), and what
// SymbiYosys wrote in WORK/TASK: `status` (PASS, FAIL, ERROR, ...), the JUnit report
// TASK.xml (one testcase per assert and cover statement, with its location and whether
// it failed) and logfile.txt (the elapsed clock time). A task passes when SymbiYosys
// says PASS, it has at least one assertion (prove, bmc) or cover statement (cover), and
// in cover mode every cover statement is reached. Writes OUT/summary.json and
// OUT/summary.md, prints the table, and exits 0 when every task passes, 1 otherwise
// (each failing task named on stderr), 2 on bad arguments or a missing description.
#include "report_json.hpp"
#include "report_util.hpp"

#include "sgm/params.hpp"

#include <cstdlib>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace {

using sgm::Error;
using sgm::eval::JsonWriter;

struct Task {
  std::string name, module, parameters, mode, status;
  int depth = 0;
  long seconds = 0;
  int assertions = 0, assertionsFailed = 0, covers = 0, coversReached = 0;
  std::vector<std::string> failedAt;  // locations of failed assertions and unreached covers
  std::string verdict;                // "pass" or "fail"
  std::string reason;                 // why a task failed
};

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t\r") - b + 1);
}

std::vector<std::string> words(const std::string& s) {
  std::istringstream in(s);
  std::vector<std::string> out;
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}

// [options] mode / depth, [script] prep -top / chparam -set NAME VALUE ... of a .sby file.
void readSby(const std::string& path, Task& t) {
  if (!sgm::eval::isFile(path)) throw Error(path + ": no such task description");
  std::string section;
  for (const std::string& raw : sgm::eval::readLines(path)) {
    const std::string line = trim(raw);
    if (line.empty() || line[0] == '#') continue;
    if (line.front() == '[') {
      section = line;
      continue;
    }
    const auto w = words(line);
    if (section == "[options]" && w.size() == 2 && w[0] == "mode") t.mode = w[1];
    if (section == "[options]" && w.size() == 2 && w[0] == "depth") t.depth = std::atoi(w[1].c_str());
    if (section != "[script]") continue;
    for (size_t i = 0; i + 1 < w.size(); ++i)
      if (w[0] == "prep" && w[i] == "-top") t.module = w[i + 1];
    if (w.size() >= 4 && w[0] == "chparam")
      for (size_t i = 1; i + 2 < w.size(); i += 3)
        if (w[i] == "-set") t.parameters += (t.parameters.empty() ? "" : " ") + w[i + 1] + "=" + w[i + 2];
  }
  if (t.mode.empty() || t.module.empty()) throw Error(path + ": no 'mode' option or no 'prep -top' line");
}

std::string attribute(const std::string& tag, const std::string& name) {
  const std::string key = " " + name + "=\"";
  const auto at = tag.find(key);
  if (at == std::string::npos) return "";
  const auto end = tag.find('"', at + key.size());
  return tag.substr(at + key.size(), end == std::string::npos ? std::string::npos : end - at - key.size());
}

// The JUnit report: one <testcase ... type="ASSERT|COVER" location="..."> per property,
// holding <failure .../> when it failed (cover: unreached) and <skipped /> when not checked.
void readJunit(const std::string& path, Task& t) {
  if (!sgm::eval::isFile(path)) return;
  const std::string xml = sgm::eval::readTextFile(path);
  for (size_t at = xml.find("<testcase "); at != std::string::npos; at = xml.find("<testcase ", at + 1)) {
    const auto tagEnd = xml.find('>', at);
    if (tagEnd == std::string::npos) break;
    const std::string tag = xml.substr(at, tagEnd - at);
    const bool selfClosed = tag.back() == '/';
    const auto close = selfClosed ? tagEnd : xml.find("</testcase>", tagEnd);
    const std::string body = xml.substr(tagEnd, close == std::string::npos ? std::string::npos : close - tagEnd);
    const bool failed = body.find("<failure") != std::string::npos;
    const bool skipped = body.find("<skipped") != std::string::npos;
    const std::string type = attribute(tag, "type");
    if (type == "ASSERT") {
      ++t.assertions;
      if (failed) {
        ++t.assertionsFailed;
        t.failedAt.push_back("assert " + attribute(tag, "location"));
      }
    } else if (type == "COVER") {
      ++t.covers;
      if (t.mode == "cover" && !failed && !skipped) ++t.coversReached;
      if (t.mode == "cover" && (failed || skipped)) t.failedAt.push_back("cover " + attribute(tag, "location"));
    }
  }
}

// "... summary: Elapsed clock time [H:MM:SS (secs)]: 0:00:02 (2)"
long elapsedSeconds(const std::string& logfile) {
  long seconds = 0;
  for (const std::string& line : sgm::eval::readLines(logfile)) {
    const auto at = line.find("Elapsed clock time");
    const auto open = line.rfind('(');
    if (at != std::string::npos && open != std::string::npos && open > at) seconds = std::atol(line.c_str() + open + 1);
  }
  return seconds;
}

Task readTask(const std::string& sbyDir, const std::string& work, const std::string& name) {
  Task t;
  t.name = name;
  readSby(sbyDir + "/" + name + ".sby", t);
  const std::string dir = work + "/" + name;
  const auto status = words(sgm::eval::readFirstLine(dir + "/status"));
  t.status = status.empty() ? "NOT RUN" : status[0];
  readJunit(dir + "/" + name + ".xml", t);
  t.seconds = elapsedSeconds(dir + "/logfile.txt");
  if (t.status != "PASS")
    t.reason = "SymbiYosys status " + t.status + " (" + dir + "/logfile.txt)";
  else if (t.mode != "cover" && t.assertions == 0)
    t.reason = "no assertion in the model";
  else if (t.mode == "cover" && t.covers == 0)
    t.reason = "no cover statement in the model";
  else if (t.mode == "cover" && t.coversReached != t.covers)
    t.reason = std::to_string(t.covers - t.coversReached) + " cover statement(s) unreached";
  t.verdict = t.reason.empty() ? "pass" : "fail";
  return t;
}

std::string json(const std::vector<Task>& tasks) {
  int passed = 0;
  for (const Task& t : tasks) passed += t.verdict == "pass";
  JsonWriter j;
  j.beginObject();
  j.key("tasks").integer(long(tasks.size()));
  j.key("passed").integer(passed);
  j.key("failed").integer(long(tasks.size()) - passed);
  j.key("rows").beginArray();
  for (const Task& t : tasks) {
    j.beginObject();
    j.key("task").string(t.name);
    j.key("module").string(t.module);
    j.key("parameters").string(t.parameters);
    j.key("mode").string(t.mode);
    j.key("depth").integer(t.depth);
    j.key("assertions").integer(t.assertions);
    j.key("assertions_failed").integer(t.assertionsFailed);
    j.key("covers").integer(t.covers);
    if (t.mode == "cover")
      j.key("covers_reached").integer(t.coversReached);
    else
      j.key("covers_reached").null();
    j.key("status").string(t.status);
    j.key("result").string(t.verdict);
    j.key("reason").string(t.reason);
    j.key("seconds").integer(t.seconds);
    j.key("failed_at").beginArray();
    for (const std::string& f : t.failedAt) j.string(f);
    j.endArray();
    j.endObject();
  }
  j.endArray();
  j.endObject();
  return j.str();
}

std::string markdown(const std::vector<Task>& tasks) {
  std::ostringstream md;
  int passed = 0;
  long seconds = 0;
  for (const Task& t : tasks) passed += t.verdict == "pass", seconds += t.seconds;
  md << "# make formal\n\n"
     << tasks.size() << " tasks, " << passed << " passed, " << tasks.size() - passed << " failed; " << seconds
     << " s of SymbiYosys in all (smtbmc z3). Properties: docs/formal.md.\n\n"
     << "| task | module | parameters | mode | depth | assertions | covers reached / total | result | s |\n"
     << "| --- | --- | --- | --- | --- | --- | --- | --- | --- |\n";
  for (const Task& t : tasks) {
    md << "| " << t.name << " | " << t.module << " | " << (t.parameters.empty() ? "defaults" : t.parameters) << " | "
       << t.mode << " | " << t.depth << " | " << t.assertions << " | ";
    if (t.mode == "cover")
      md << t.coversReached << " / " << t.covers;
    else
      md << "-";
    md << " | " << (t.verdict == "pass" ? "pass" : "FAIL: " + t.reason) << " | " << t.seconds << " |\n";
  }
  bool any = false;
  for (const Task& t : tasks)
    for (const std::string& f : t.failedAt) {
      if (!any) md << "\nFailed assertions and unreached covers:\n\n";
      any = true;
      md << "- " << t.name << ": " << f << "\n";
    }
  return md.str();
}

[[noreturn]] void usage(const std::string& problem) {
  std::cerr << "formal-summary: error: " << problem
            << " (usage: formal-summary --sby-dir DIR --work DIR --out DIR TASK...)\n";
  std::exit(2);
}

}  // namespace

int main(int argc, char** argv) {
  std::string sbyDir, work, out;
  std::vector<std::string> names;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--sby-dir" || a == "--work" || a == "--out") {
      if (i + 1 >= argc) usage(a + " needs a directory");
      (a == "--sby-dir" ? sbyDir : a == "--work" ? work : out) = argv[++i];
    } else if (!a.empty() && a[0] == '-') {
      usage("unknown option " + a);
    } else {
      names.push_back(a);
    }
  }
  if (sbyDir.empty() || work.empty() || out.empty()) usage("--sby-dir, --work and --out are required");
  if (names.empty()) usage("no task");
  try {
    std::vector<Task> tasks;
    for (const std::string& n : names) tasks.push_back(readTask(sbyDir, work, n));
    sgm::eval::writeTextFile(out + "/summary.json", json(tasks));
    const std::string md = markdown(tasks);
    sgm::eval::writeTextFile(out + "/summary.md", md);
    std::cout << md;
    int failed = 0;
    for (const Task& t : tasks)
      if (t.verdict != "pass") {
        std::cerr << "formal: " << t.name << " failed: " << t.reason << "\n";
        ++failed;
      }
    return failed ? 1 : 0;
  } catch (const std::exception& e) {
    std::cerr << "formal-summary: error: " << e.what() << "\n";
    return 2;
  }
}
