// SPDX-License-Identifier: Apache-2.0
// coverage-summary: line and toggle coverage of rtl/ from Verilator coverage
// data files (make coverage). A coverage point is one (file, line, column,
// kind, signal) of the source, merged over every instance and every data file:
// it is covered when any of them counted it at least once. Line coverage
// counts the v_line and v_branch points (statements and both arms of every
// if/case), toggle coverage the v_toggle points (one per signal bit).
//
//   coverage-summary --out DIR [--waivers FILE] DATA.dat...
//
// Writes DIR/summary.json, DIR/summary.md (per file, then every uncovered
// line point with its source line), and prints the totals. A waiver file
// lists "file | source line | reason" for line points that cannot be reached
// (matched by the trimmed source text, so edits elsewhere in the file keep the
// waiver valid); waived points are listed with their reason and counted apart.
#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

namespace {

struct Point {
  std::string file, kind, signal;
  int line = 0, column = 0;
  std::string instance;  // hierarchy; not part of the ordering (points merge over instances)
  bool operator<(const Point& o) const {
    return std::tie(file, line, column, kind, signal) < std::tie(o.file, o.line, o.column, o.kind, o.signal);
  }
};

struct Totals {
  long points = 0, covered = 0, waived = 0;
  double percent() const { return points ? 100.0 * double(covered) / double(points) : 100.0; }
  double percentWithWaivers() const { return points ? 100.0 * double(covered + waived) / double(points) : 100.0; }
};

[[noreturn]] void fail(const std::string& message) {
  std::cerr << "coverage-summary: error: " << message << "\n";
  std::exit(2);
}

// One line of a SystemC::Coverage-3 file: C '<\1key\2value...>' count
bool parseLine(const std::string& text, Point& point, long& count) {
  if (text.size() < 4 || text[0] != 'C') return false;
  const size_t open = text.find('\''), close = text.rfind('\'');
  if (open == std::string::npos || close <= open) return false;
  const std::string body = text.substr(open + 1, close - open - 1);
  count = std::stol(text.substr(close + 1));
  std::map<std::string, std::string> fields;
  for (size_t i = 0; i < body.size();) {
    if (body[i] != '\1') return false;
    const size_t sep = body.find('\2', i + 1);
    if (sep == std::string::npos) return false;
    size_t end = body.find('\1', sep + 1);
    if (end == std::string::npos) end = body.size();
    fields[body.substr(i + 1, sep - i - 1)] = body.substr(sep + 1, end - sep - 1);
    i = end;
  }
  point.file = fields["f"];
  point.line = std::stoi(fields.count("l") ? fields["l"] : "0");
  point.column = std::stoi(fields.count("n") ? fields["n"] : "0");
  const std::string page = fields["page"];
  point.kind = page.substr(0, page.find('/'));
  point.signal = fields["o"];
  point.instance = fields["h"];
  return true;
}

std::vector<std::string> readSource(const std::string& file) {
  std::vector<std::string> lines;
  std::ifstream in(file);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

std::string trim(const std::string& s) {
  const size_t a = s.find_first_not_of(" \t"), b = s.find_last_not_of(" \t");
  return a == std::string::npos ? "" : s.substr(a, b - a + 1);
}

std::string jsonString(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    if (c == '\n') {
      out += "\\n";
      continue;
    }
    out += c;
  }
  return out + "\"";
}

std::string percent(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f", v);
  return buf;
}

}  // namespace

int main(int argc, char** argv) {
  std::string out, waiverFile;
  std::vector<std::string> inputs;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--out" && i + 1 < argc)
      out = argv[++i];
    else if (a == "--waivers" && i + 1 < argc)
      waiverFile = argv[++i];
    else if (a.rfind("--", 0) == 0)
      fail("unknown option '" + a + "'");
    else
      inputs.push_back(a);
  }
  if (out.empty() || inputs.empty()) fail("usage: coverage-summary --out DIR [--waivers FILE] DATA.dat...");

  std::map<Point, long> counts;
  std::map<std::pair<std::string, std::string>, long> toggleByInstance;  // (instance, signal bit) -> changes
  for (const std::string& path : inputs) {
    std::ifstream in(path);
    if (!in) fail("cannot open '" + path + "'");
    long n = 0;
    for (std::string line; std::getline(in, line);) {
      Point p;
      long c = 0;
      if (!parseLine(line, p, c)) continue;
      if (p.file.rfind("rtl/", 0) != 0) continue;  // only the core's sources
      counts[p] += c;
      if (p.kind == "v_toggle") toggleByInstance[{p.instance, p.signal}] += c;
      ++n;
    }
    if (n == 0) fail("'" + path + "' holds no coverage point of rtl/");
  }

  std::map<std::string, std::vector<std::string>> sources;
  const auto sourceLine = [&](const Point& p) {
    auto& src = sources[p.file];
    if (src.empty()) src = readSource(p.file);
    return p.line >= 1 && p.line <= int(src.size()) ? trim(src[p.line - 1]) : std::string();
  };
  std::map<std::string, std::string> waivers;  // "file | source line" -> reason
  if (!waiverFile.empty()) {
    std::ifstream in(waiverFile);
    if (!in) fail("cannot open '" + waiverFile + "'");
    for (std::string line; std::getline(in, line);) {
      line = trim(line);
      if (line.empty() || line[0] == '#') continue;
      const size_t a = line.find(" | "), b = a == std::string::npos ? a : line.find(" | ", a + 3);
      if (b == std::string::npos) fail("waiver is not 'file | source line | reason': '" + line + "'");
      const std::string file = trim(line.substr(0, a)), text = trim(line.substr(a + 3, b - a - 3));
      // A waiver names a source line that exists: one that no longer does is stale.
      auto& src = sources[file];
      if (src.empty()) src = readSource(file);
      bool found = false;
      for (const std::string& l : src) found = found || trim(l) == text;
      if (!found) fail("waiver names a line that " + file + " does not have (stale): '" + text + "'");
      waivers[file + " | " + text] = trim(line.substr(b + 3));
    }
  }

  std::map<std::string, Totals> lineByFile, toggleByFile;
  Totals line, toggle, toggleInstances;
  for (const auto& [key, c] : toggleByInstance) ++toggleInstances.points, toggleInstances.covered += c >= 2;
  std::vector<std::pair<Point, std::string>> uncovered;  // line points, with waiver reason or ""
  std::set<std::string> usedWaivers;
  for (const auto& [p, c] : counts) {
    const bool isLine = p.kind == "v_line" || p.kind == "v_branch";
    if (!isLine && p.kind != "v_toggle") continue;
    Totals& file = isLine ? lineByFile[p.file] : toggleByFile[p.file];
    Totals& all = isLine ? line : toggle;
    ++file.points, ++all.points;
    // A bit toggled both ways when it changed at least twice (changes alternate direction).
    if (c >= (isLine ? 1 : 2)) {
      ++file.covered, ++all.covered;
      continue;
    }
    if (!isLine) continue;
    const std::string where = p.file + " | " + sourceLine(p);
    const auto w = waivers.find(where);
    if (w != waivers.end()) ++file.waived, ++all.waived, usedWaivers.insert(where);
    uncovered.push_back({p, w == waivers.end() ? "" : w->second});
  }
  for (const auto& [where, reason] : waivers)
    if (!usedWaivers.count(where))
      std::cerr << "coverage-summary: note: waiver " << where << " matches no uncovered point (stale?)\n";

  std::ostringstream md;
  // Files with toggle points and no line points (only continuous assignments).
  std::string assignOnly;
  for (const auto& [file, g] : toggleByFile) {
    const auto it = lineByFile.find(file);
    if (g.points > 0 && (it == lineByFile.end() || it->second.points == 0))
      assignOnly += (assignOnly.empty() ? "" : ", ") + file;
  }
  md << "# RTL coverage\n\nLine coverage: " << line.covered << " of " << line.points << " points, **"
     << percent(line.percent()) << " %** (" << percent(line.percentWithWaivers()) << " % counting the " << line.waived
     << " waived unreachable points). Toggle coverage: " << toggle.covered << " of " << toggle.points
     << " signal bits of the source, **" << percent(toggle.percent())
     << " %**; counted per instance (every PE, path and "
        "stage separately): "
     << toggleInstances.covered << " of " << toggleInstances.points << ", **" << percent(toggleInstances.percent())
     << " %**.\n\n"
     << "A point is covered when any instance in any run reached it at least once. Line points are Verilator's "
        "v_line and v_branch points (statements, both arms of each if/case); toggle points are signal bits, covered when the bit rose and fell (changed at least twice). Modules made only of continuous assignments have toggle points but no line points"
     << (assignOnly.empty() ? std::string() : " (here: " + assignOnly + ")") << ".\n\n"
     << "| file | line points | covered | % | toggle bits | toggled | % |\n|---|---|---|---|---|---|---|\n";
  for (const auto& [file, t] : lineByFile) {
    const Totals& g = toggleByFile[file];
    md << "| " << file << " | " << t.points << " | " << t.covered << " | " << percent(t.percent()) << " | " << g.points
       << " | " << g.covered << " | " << percent(g.percent()) << " |\n";
  }
  md << "\n## Uncovered line points\n\n";
  if (uncovered.empty()) md << "None.\n";
  for (const auto& [p, reason] : uncovered) {
    const std::string text = sourceLine(p);
    md << "- `" << p.file << ":" << p.line << "` (" << p.kind.substr(2) << ") `" << text << "`"
       << (reason.empty() ? "" : " — waived: " + reason) << "\n";
  }

  std::ostringstream js;
  js << "{\n  \"line\": {\"points\": " << line.points << ", \"covered\": " << line.covered
     << ", \"waived\": " << line.waived << ", \"percent\": " << percent(line.percent())
     << ", \"percent_with_waivers\": " << percent(line.percentWithWaivers())
     << "},\n  \"toggle\": {\"points\": " << toggle.points << ", \"covered\": " << toggle.covered
     << ", \"percent\": " << percent(toggle.percent()) << ", \"instance_points\": " << toggleInstances.points
     << ", \"instance_covered\": " << toggleInstances.covered
     << ", \"instance_percent\": " << percent(toggleInstances.percent()) << "},\n  \"files\": {";
  bool first = true;
  for (const auto& [file, t] : lineByFile) {
    const Totals& g = toggleByFile[file];
    js << (first ? "\n" : ",\n") << "    " << jsonString(file) << ": {\"line_points\": " << t.points
       << ", \"line_covered\": " << t.covered << ", \"line_percent\": " << percent(t.percent())
       << ", \"toggle_points\": " << g.points << ", \"toggle_covered\": " << g.covered
       << ", \"toggle_percent\": " << percent(g.percent()) << "}";
    first = false;
  }
  js << "\n  },\n  \"uncovered_lines\": [";
  first = true;
  for (const auto& [p, reason] : uncovered) {
    js << (first ? "\n" : ",\n") << "    {\"file\": " << jsonString(p.file) << ", \"line\": " << p.line
       << ", \"kind\": " << jsonString(p.kind) << ", \"waiver\": " << (reason.empty() ? "null" : jsonString(reason))
       << "}";
    first = false;
  }
  js << "\n  ]\n}\n";

  for (const auto& [name, text] : {std::pair{"summary.md", md.str()}, {"summary.json", js.str()}}) {
    std::ofstream f(out + "/" + name);
    f << text;
    if (!f) fail("cannot write '" + out + "/" + name + "'");
  }
  std::printf(
      "coverage: line %s %% (%ld/%ld points, %s %% with %ld waived), toggle %s %% (%ld/%ld source bits; %s %% per "
      "instance, %ld/%ld)\n",
      percent(line.percent()).c_str(), line.covered, line.points, percent(line.percentWithWaivers()).c_str(),
      line.waived, percent(toggle.percent()).c_str(), toggle.covered, toggle.points,
      percent(toggleInstances.percent()).c_str(), toggleInstances.covered, toggleInstances.points);
  std::printf("coverage: wrote %s/summary.md, %s/summary.json\n", out.c_str(), out.c_str());
  return 0;
}
