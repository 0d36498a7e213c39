// SPDX-License-Identifier: Apache-2.0
// pnr_summary: collects the `make pnr` runs under build/pnr into summary.json
// and summary.md (synth/README.md, section "Place and route").
//
//   pnr-summary ROOT --cycles-per-pixel X --cpp-source TEXT [--check CONFIG/RUN]...
//
// ROOT holds one directory per configuration, d<D>-w<MAX_WIDTH>, with one
// directory per nextpnr-ecp5 run (device, speed and seed, e.g. lfe5u-85f-8-s1) written by synth/pnr.mk:
// meta.txt (key=value: device, package, speed, d, max_width, target_mhz,
// pnr_seconds, ...), report.json (nextpnr's --report) and the "done" stamp
// (nextpnr exited 0, i.e. the design was placed and routed). Every figure
// comes from report.json: utilisation (TRELLIS_COMB, TRELLIS_FF, DP16KD,
// MULT18X18D), fmax (achieved) and the critical path. Runs of a reference build
// (`make pnr-ref`, meta ref=<name>, one run per seed) are also gathered per build in
// "refs": the median fmax of the seeds (the figure of record), each seed's, and the
// median run's resources and critical path. --check CONFIG/RUN fails
// (exit 1, the reason on stderr) unless that run is done and reports an fmax.
#include "json_read.hpp"
#include "report_json.hpp"
#include "report_util.hpp"
#include "video_formats.hpp"

#include "sgm/params.hpp"

#include <algorithm>
#include <cstdlib>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace {

using sgm::Error;
using sgm::eval::fixed;
using sgm::eval::isFile;
using sgm::eval::Json;
using sgm::eval::JsonWriter;
using sgm::eval::kVideoFormats;
using sgm::eval::listDir;
using sgm::eval::neededMhz;
using sgm::eval::VideoFormat;

// The RTL module of a source location "rtl/sgm_path_pe.sv:43.24-43.35" (one
// module per file, named after it); empty for Yosys' own techmap files.
std::string sourceModule(const std::string& src) {
  if (src.compare(0, 4, "rtl/") != 0) return "";
  const auto dot = src.find('.', 4);
  return src.substr(4, dot == std::string::npos ? std::string::npos : dot - 4);
}

// The instance path of a public net name "u_paths.g_path[0].g_pe[11].u_pe.step[5]"
// (the components before the wire's own name); empty for internal ($) names.
std::string netInstance(const std::string& net) {
  if (net.find('$') != std::string::npos) return "";
  const auto cut = net.rfind('.');
  return cut == std::string::npos ? std::string("(top)") : net.substr(0, cut);
}

void addUnique(std::vector<std::string>& list, const std::string& item) {
  if (!item.empty() && std::find(list.begin(), list.end(), item) == list.end()) list.push_back(item);
}

// ------------------------------------------------------------------ one run
struct Run {
  std::string name;  // CONFIG/RUN
  std::map<std::string, std::string> meta;
  long lut4 = 0, lut4Avail = 0, ff = 0, ffAvail = 0, ebr = 0, ebrAvail = 0, dsp = 0, dspAvail = 0;
  long lutram = 0;
  double fmax = 0;
  std::string clock;
  std::string pathStart, pathEnd;
  std::vector<std::string> pathModules;    // RTL modules (source files), in path order
  std::vector<std::string> pathInstances;  // instance paths (public net names), in path order
  int pathLogicCells = 0;
  double pathLogicNs = 0, pathRoutingNs = 0;
};

long used(const Json& util, const char* type, long* available) {
  const Json* t = util.get(type);
  if (!t) return 0;
  if (available)
    if (const Json* a = t->get("available")) *available = static_cast<long>(a->number);
  const Json* u = t->get("used");
  return u ? static_cast<long>(u->number) : 0;
}

Run readRun(const std::string& dir, const std::string& name) {
  Run r;
  r.name = name;
  r.meta = sgm::eval::readMeta(dir + "/meta.txt", /*required=*/true);
  const Json report = sgm::eval::readJsonFile(dir + "/report.json");
  if (const Json* util = report.get("utilization")) {
    r.lut4 = used(*util, "TRELLIS_COMB", &r.lut4Avail);
    r.ff = used(*util, "TRELLIS_FF", &r.ffAvail);
    r.ebr = used(*util, "DP16KD", &r.ebrAvail);
    r.dsp = used(*util, "MULT18X18D", &r.dspAvail) + used(*util, "ALU54B", nullptr);
    r.lutram = used(*util, "TRELLIS_RAMW", nullptr);
  }
  // The slowest clock domain is the design's fmax (the core has one clock).
  if (const Json* fm = report.get("fmax")) {
    for (const auto& m : fm->members) {
      const Json* a = m.second.get("achieved");
      if (a && (r.clock.empty() || a->number < r.fmax)) {
        r.fmax = a->number;
        r.clock = m.first;
      }
    }
  }
  // The critical path of that clock to itself (nextpnr lists one per clock pair).
  if (const Json* cps = report.get("critical_paths")) {
    for (const Json& cp : cps->items) {
      const Json* from = cp.get("from");
      const Json* to = cp.get("to");
      const Json* path = cp.get("path");
      if (!path || path->items.empty() || (from && to && from->text != to->text)) continue;
      const auto cellOf = [](const Json& seg, const char* end) {
        const Json* e = seg.get(end);
        const Json* c = e ? e->get("cell") : nullptr;
        return c ? c->text : std::string();
      };
      r.pathStart = cellOf(path->items.front(), "from");
      r.pathEnd = cellOf(path->items.back(), "to");
      r.pathModules.clear();
      r.pathInstances.clear();
      r.pathLogicCells = 0;
      r.pathLogicNs = r.pathRoutingNs = 0;
      for (const Json& seg : path->items) {
        const Json* type = seg.get("type");
        const Json* delay = seg.get("delay");
        const double ns = delay ? delay->number : 0;
        if (type && type->text == "routing")
          r.pathRoutingNs += ns;
        else
          r.pathLogicNs += ns;
        if (type && type->text == "logic") ++r.pathLogicCells;
        if (const Json* sources = seg.get("sources"))
          for (const Json& src : sources->items) addUnique(r.pathModules, sourceModule(src.text));
        if (const Json* net = seg.get("net")) addUnique(r.pathInstances, netInstance(net->text));
      }
      break;
    }
  }
  return r;
}

std::string meta(const Run& r, const char* key) {
  const auto it = r.meta.find(key);
  return it == r.meta.end() ? std::string("?") : it->second;
}
double metaNumber(const Run& r, const char* key) {
  const auto it = r.meta.find(key);
  return it == r.meta.end() ? 0 : std::atof(it->second.c_str());
}

std::string joined(const std::vector<std::string>& v, const char* sep) {
  std::string out;
  for (const auto& s : v) out += (out.empty() ? "" : sep) + s;
  return out;
}

// The critical path of a run in one line: start -> end (cells, logic + routing; modules).
std::string pathText(const Run& r) {
  return r.pathStart + " -> " + r.pathEnd + " (" + std::to_string(r.pathLogicCells) + " logic cells, " +
         fixed(r.pathLogicNs, 2) + " ns logic + " + fixed(r.pathRoutingNs, 2) + " ns routing; through " +
         joined(r.pathModules, " > ") + ")";
}

// A meta.txt value, empty when the run's meta.txt predates the key.
std::string metaText(const Run& r, const char* key) {
  const std::string v = meta(r, key);
  return v == "?" ? std::string() : v;
}

// The fields that name a run: run, device, package, speed, d.
void writeRunHeader(JsonWriter& j, const Run& r) {
  j.key("run").string(r.name);
  j.key("device").string(meta(r, "device"));
  j.key("package").string(meta(r, "package"));
  j.key("speed").integer(std::atol(meta(r, "speed").c_str()));
  j.key("d").integer(std::atol(meta(r, "d").c_str()));
}

// "critical_path": {start, end, modules, instances, logic_cells, logic_ns, routing_ns}.
void writeCriticalPath(JsonWriter& j, const Run& r) {
  j.key("critical_path").beginObject();
  j.key("start").string(r.pathStart);
  j.key("end").string(r.pathEnd);
  j.key("modules").beginArray();
  for (const auto& m : r.pathModules) j.string(m);
  j.endArray();
  j.key("instances").beginArray();
  for (const auto& m : r.pathInstances) j.string(m);
  j.endArray();
  j.key("logic_cells").integer(r.pathLogicCells);
  j.key("logic_ns").real(r.pathLogicNs);
  j.key("routing_ns").real(r.pathRoutingNs);
  j.endObject();
}

// "formats": per video format, the clock it needs at cpp cycles per pixel, whether fmaxMhz
// meets it and whether its width fits maxWidth.
void writeFormats(JsonWriter& j, double fmaxMhz, long maxWidth, double cpp) {
  j.key("formats").beginArray();
  for (const VideoFormat& f : kVideoFormats) {
    j.beginObject();
    j.key("format").string(f.name);
    j.key("needed_mhz").real(neededMhz(f, cpp));
    j.key("clock_met").boolean(fmaxMhz >= neededMhz(f, cpp));
    j.key("width_fits").boolean(f.width <= maxWidth);
    j.endObject();
  }
  j.endArray();
}

// ------------------------------------------------------------------ reference builds
// The runs of one reference build (meta ref=<name>), one per seed, sorted by fmax.
struct Ref {
  std::string name;
  std::vector<const Run*> runs;
  // The median of the seeds' fmax (the mean of the two middle ones for an even count) and
  // the run the build's resources and critical path are taken from (the lower middle).
  double medianFmax() const {
    const size_t n = runs.size();
    return n % 2 ? runs[n / 2]->fmax : (runs[n / 2 - 1]->fmax + runs[n / 2]->fmax) / 2;
  }
  const Run& medianRun() const { return *runs[(runs.size() - 1) / 2]; }
};

std::vector<Ref> gatherRefs(const std::vector<Run>& runs) {
  std::map<std::string, Ref> byName;
  for (const Run& r : runs) {
    const std::string name = metaText(r, "ref");
    if (name.empty()) continue;
    Ref& ref = byName[name];
    ref.name = name;
    ref.runs.push_back(&r);
  }
  std::vector<Ref> refs;
  for (auto& [name, ref] : byName) {
    std::sort(ref.runs.begin(), ref.runs.end(), [](const Run* a, const Run* b) { return a->fmax < b->fmax; });
    refs.push_back(ref);
  }
  return refs;
}

// The seeds of a reference build in seed order: "seed 1: 121.3, seed 2: 118.0".
std::string seedsText(const Ref& ref) {
  std::vector<const Run*> bySeed = ref.runs;
  std::sort(bySeed.begin(), bySeed.end(),
            [](const Run* a, const Run* b) { return metaNumber(*a, "seed") < metaNumber(*b, "seed"); });
  std::string out;
  for (const Run* r : bySeed) out += (out.empty() ? "" : ", ") + meta(*r, "seed") + ": " + fixed(r->fmax, 1);
  return out;
}

// Runs of the loop harness (`make pnr-loop`, meta kind=loop) and of the whole core.
bool isLoopRun(const Run& r) { return meta(r, "kind") == "loop"; }

void writeSummary(const std::string& root, const std::vector<Run>& allRuns, double cpp, const std::string& cppSource) {
  std::vector<Run> runs, loops;
  for (const Run& r : allRuns) (isLoopRun(r) ? loops : runs).push_back(r);
  JsonWriter j;
  j.beginObject();
  j.key("cycles_per_pixel").real(cpp);
  j.key("cycles_per_pixel_source").string(cppSource);
  j.key("runs").beginArray();
  for (const Run& r : runs) {
    j.beginObject();
    writeRunHeader(j, r);
    j.key("max_width").integer(std::atol(meta(r, "max_width").c_str()));
    j.key("lanes").integer(meta(r, "lanes") == "?" ? 1 : std::atol(meta(r, "lanes").c_str()));  // runs before lanes: 1
    j.key("lut4").integer(r.lut4);
    j.key("lut4_available").integer(r.lut4Avail);
    j.key("lutram_slices").integer(r.lutram);
    j.key("ff").integer(r.ff);
    j.key("ff_available").integer(r.ffAvail);
    j.key("ebr").integer(r.ebr);
    j.key("ebr_available").integer(r.ebrAvail);
    j.key("dsp").integer(r.dsp);
    j.key("fmax_mhz").real(r.fmax);
    j.key("target_mhz").real(metaNumber(r, "target_mhz"));
    writeCriticalPath(j, r);
    j.key("pnr_seconds").integer(std::atol(meta(r, "pnr_seconds").c_str()));
    j.key("synth_seconds").integer(std::atol(meta(r, "synth_seconds").c_str()));
    j.key("seed").integer(std::atol(meta(r, "seed").c_str()));
    j.key("nextpnr").string(meta(r, "nextpnr"));
    j.key("nextpnr_flags").string(metaText(r, "nextpnr_flags"));
    j.key("synth_flags").string(metaText(r, "synth_flags"));
    j.key("yosys").string(meta(r, "yosys"));
    j.key("rtl_commit").string(meta(r, "rtl_commit"));
    j.key("date").string(meta(r, "date"));
    writeFormats(j, r.fmax, std::atol(meta(r, "max_width").c_str()), cpp);
    j.endObject();
  }
  j.endArray();
  j.key("loop_runs").beginArray();
  for (const Run& r : loops) {
    j.beginObject();
    writeRunHeader(j, r);
    j.key("lanes").integer(std::atol(meta(r, "lanes").c_str()));
    j.key("lut4").integer(r.lut4);
    j.key("ff").integer(r.ff);
    j.key("fmax_mhz").real(r.fmax);
    j.key("target_mhz").real(metaNumber(r, "target_mhz"));
    writeCriticalPath(j, r);
    j.key("pnr_seconds").integer(std::atol(meta(r, "pnr_seconds").c_str()));
    j.key("synth_flags").string(metaText(r, "synth_flags"));
    j.key("nextpnr_flags").string(metaText(r, "nextpnr_flags"));
    j.key("date").string(meta(r, "date"));
    j.endObject();
  }
  j.endArray();
  const std::vector<Ref> refs = gatherRefs(runs);
  j.key("refs").beginArray();
  for (const Ref& ref : refs) {
    const Run& m = ref.medianRun();
    j.beginObject();
    j.key("ref").string(ref.name);
    j.key("median_run").string(m.name);
    writeRunHeader(j, m);
    j.key("max_width").integer(std::atol(meta(m, "max_width").c_str()));
    j.key("lanes").integer(std::atol(meta(m, "lanes").c_str()));
    j.key("right_block").integer(std::atol(meta(m, "right_block").c_str()));
    j.key("edge_reset").integer(std::atol(meta(m, "edge_reset").c_str()));
    j.key("uniqueness").integer(std::atol(meta(m, "uniqueness").c_str()));
    j.key("ad_term").integer(std::atol(meta(m, "ad_term").c_str()));
    j.key("lut4").integer(m.lut4);
    j.key("lut4_available").integer(m.lut4Avail);
    j.key("ff").integer(m.ff);
    j.key("ff_available").integer(m.ffAvail);
    j.key("ebr").integer(m.ebr);
    j.key("ebr_available").integer(m.ebrAvail);
    j.key("dsp").integer(m.dsp);
    j.key("target_mhz").real(metaNumber(m, "target_mhz"));
    j.key("fmax_median_mhz").real(ref.medianFmax());
    j.key("seeds").beginArray();
    for (const Run* r : ref.runs) {
      j.beginObject();
      j.key("seed").integer(std::atol(meta(*r, "seed").c_str()));
      j.key("run").string(r->name);
      j.key("fmax_mhz").real(r->fmax);
      j.endObject();
    }
    j.endArray();
    writeCriticalPath(j, m);
    j.key("rtl_commit").string(meta(m, "rtl_commit"));
    j.key("nextpnr").string(meta(m, "nextpnr"));
    j.key("yosys").string(meta(m, "yosys"));
    j.key("date").string(meta(m, "date"));
    writeFormats(j, ref.medianFmax(), std::atol(meta(m, "max_width").c_str()), cpp);
    j.endObject();
  }
  j.endArray();
  j.endObject();
  sgm::eval::writeTextFile(root + "/summary.json", j.str());

  std::ostringstream md;
  md << "# Place and route of sgm_top on ECP5 (nextpnr-ecp5)\n\n"
     << "Figures from nextpnr's own report (`--report`) of each run under " << root
     << "; LUT4 = TRELLIS_COMB cells (LUT4s, carry halves and LUT-RAM LUTs), EBR = DP16KD.\n\n"
     << "| run | device | speed | D | MAX_WIDTH | LUT4 | FF | EBR | DSP | fmax (MHz) | target (MHz) | "
        "critical path | P&R (s) |\n|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  // A run's options beside its name: "(synth_ecp5 -nowidelut; nextpnr --no-tmdriv)".
  auto flagsOf = [&](const Run& r) {
    std::string s;
    for (const auto& [key, tool] : {std::pair<const char*, const char*>{"synth_flags", "synth_ecp5"},
                                    std::pair<const char*, const char*>{"nextpnr_flags", "nextpnr"}}) {
      const std::string f = metaText(r, key);
      if (f.empty()) continue;
      s += (s.empty() ? " (`" : "; `") + std::string(tool) + " " + f + "`";
    }
    return s.empty() ? s : s + ")";
  };
  for (const Run& r : runs)
    md << "| " << r.name << flagsOf(r) << " | " << meta(r, "device") << "-" << meta(r, "package") << " | "
       << meta(r, "speed") << " | " << meta(r, "d") << " | " << meta(r, "max_width") << " | " << r.lut4 << " / "
       << r.lut4Avail << " | " << r.ff << " / " << r.ffAvail << " | " << r.ebr << " / " << r.ebrAvail << " | " << r.dsp
       << " | **" << fixed(r.fmax, 1) << "** | " << meta(r, "target_mhz") << " | " << pathText(r) << " | "
       << meta(r, "pnr_seconds") << " |\n";
  if (!refs.empty()) {
    md << "\n## Reference builds (`make pnr-ref`)\n\n"
       << "scripts/refs.mk names each build. fmax is the median of its seeds' (each seed's in the next column); "
          "the resources and the critical path are the median run's.\n\n"
       << "| build | run | D | MAX_WIDTH | lanes | LUT4 | FF | EBR | DSP | fmax, median (MHz) | seeds (MHz) | "
          "target (MHz) | critical path | formats met |\n|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    for (const Ref& ref : refs) {
      const Run& m = ref.medianRun();
      std::string met;
      for (const VideoFormat& f : kVideoFormats)
        if (ref.medianFmax() >= neededMhz(f, cpp) && f.width <= std::atol(meta(m, "max_width").c_str()))
          met += (met.empty() ? "" : ", ") + std::string(f.name);
      md << "| " << ref.name << " | " << m.name << " | " << meta(m, "d") << " | " << meta(m, "max_width") << " | "
         << meta(m, "lanes") << " | " << m.lut4 << " / " << m.lut4Avail << " | " << m.ff << " / " << m.ffAvail << " | "
         << m.ebr << " / " << m.ebrAvail << " | " << m.dsp << " | **" << fixed(ref.medianFmax(), 1) << "** | "
         << seedsText(ref) << " | " << meta(m, "target_mhz") << " | " << pathText(m) << " | "
         << (met.empty() ? std::string("none") : met) << " |\n";
    }
  }
  if (!loops.empty()) {
    md << "\n## The 0 degree loop alone (`make pnr-loop`)\n\n"
       << "synth/sgm_path_loop.sv: the recursion of the 0 degree path (D sub-PEs and the minimum tree) with "
          "LANES registers in the loop, the clock a schedule of LANES interleaved row lanes could reach "
          "(docs/lanes.md); LANES = 1 is the core's loop as it is.\n\n"
       << "| run | device | speed | D | LANES | LUT4 | FF | fmax (MHz) | target (MHz) | critical path | P&R (s) |\n"
       << "|---|---|---|---|---|---|---|---|---|---|---|\n";
    for (const Run& r : loops)
      md << "| " << r.name << flagsOf(r) << " | " << meta(r, "device") << "-" << meta(r, "package") << " | "
         << meta(r, "speed") << " | " << meta(r, "d") << " | " << meta(r, "lanes") << " | " << r.lut4 << " | " << r.ff
         << " | **" << fixed(r.fmax, 1) << "** | " << meta(r, "target_mhz") << " | " << pathText(r) << " | "
         << meta(r, "pnr_seconds") << " |\n";
  }
  md << "\n## Clock per video format\n\n"
     << "Needed clock = active pixels per second x " << fixed(cpp, 3) << " cycles per pixel (" << cppSource
     << "). The paper's clocks (Table II) are for its 9 cycles per pixel. A format is met when the routed fmax "
        "reaches the needed clock; frames wider than MAX_WIDTH need a larger build (marked *width*).\n\n"
     << "| format | paper, Table II (MHz) | needed here (MHz) |";
  for (const Run& r : runs) md << " " << r.name << " (" << fixed(r.fmax, 1) << " MHz) |";
  md << "\n|---|---|---|";
  for (size_t i = 0; i < runs.size(); ++i) md << "---|";
  md << "\n";
  for (const VideoFormat& f : kVideoFormats) {
    md << "| " << f.name << " | " << (f.paperMhz > 0 ? fixed(f.paperMhz, 1) : std::string("-")) << " | "
       << fixed(neededMhz(f, cpp), 1) << " |";
    for (const Run& r : runs) {
      md << " " << (r.fmax >= neededMhz(f, cpp) ? "met" : "not met");
      if (f.width > std::atol(meta(r, "max_width").c_str())) md << " (*width*)";
      md << " |";
    }
    md << "\n";
  }
  sgm::eval::writeTextFile(root + "/summary.md", md.str());
}

}  // namespace

int main(int argc, char** argv) {
  try {
    if (argc < 2) throw Error("usage: pnr-summary ROOT --cycles-per-pixel X --cpp-source TEXT [--check CONFIG/RUN]...");
    const std::string root = argv[1];
    double cpp = 0;
    std::string cppSource;
    std::vector<std::string> checks;
    for (int i = 2; i < argc; ++i) {
      const std::string a = argv[i];
      if (i + 1 >= argc) throw Error("pnr-summary: " + a + " needs a value");
      if (a == "--cycles-per-pixel")
        cpp = std::atof(argv[++i]);
      else if (a == "--cpp-source")
        cppSource = argv[++i];
      else if (a == "--check")
        checks.push_back(argv[++i]);
      else
        throw Error("pnr-summary: unknown option " + a);
    }
    if (!(cpp >= 1.0)) throw Error("pnr-summary: --cycles-per-pixel must be a number >= 1");
    std::vector<Run> runs;
    for (const auto& cfg : listDir(root))
      for (const auto& run : listDir(root + "/" + cfg)) {
        const std::string dir = root + "/" + cfg + "/" + run;
        if (isFile(dir + "/done") && isFile(dir + "/report.json")) runs.push_back(readRun(dir, cfg + "/" + run));
      }
    writeSummary(root, runs, cpp, cppSource);
    std::cout << "pnr-summary: " << runs.size() << " run(s) -> " << root << "/summary.json, summary.md\n";
    for (const auto& c : checks) {
      const auto it = std::find_if(runs.begin(), runs.end(), [&](const Run& r) { return r.name == c; });
      if (it == runs.end())
        throw Error("pnr-summary: --check " + c + ": no routed run (missing done stamp or report.json)");
      if (!(it->fmax > 0)) throw Error("pnr-summary: --check " + c + ": nextpnr reported no fmax");
      std::cout << "pnr-summary: " << c << " routed, fmax " << fixed(it->fmax, 1) << " MHz, " << it->lut4 << " LUT4, "
                << it->ff << " FF, " << it->ebr << " EBR\n";
    }
  } catch (const std::exception& e) {
    std::cerr << e.what() << "\n";
    return 1;
  }
  return 0;
}
