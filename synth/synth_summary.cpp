// SPDX-License-Identifier: Apache-2.0
// synth_summary: collects the `make synth` reports under build/synth into
// summary.json and summary.md (synth/README.md describes the layout).
//
//   synth-summary ROOT [--check CONFIG/TARGET]...
//
// ROOT holds one directory per configuration, named by its build tag (scripts/build.mk), with one
// directory per target (xc7, xc6s, generic, ice40) written by synth/*.tcl,
// and ice40-loop-d<D> directories (the routed loop harness). Every target
// directory has a meta.txt (key=value, written by synth/synth.mk) and is
// skipped without its "done" stamp. --check CONFIG/TARGET fails (exit 1, with
// the reason on stderr) unless that target is in the summary and its path
// buffers (sgm_path_engine mem45 / mem90 / mem135) were mapped to block RAM
// only, and `check` found no problem; --check ice40-loop-d<D> fails unless that
// loop harness was routed and both nextpnr-ice40 and icetime gave an fmax.
#include "report_json.hpp"
#include "report_util.hpp"
#include "xc7_parts.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace {

// ------------------------------------------------------------------ paper
// Table III of the paper: Spartan-6 xc6slx150.
constexpr long kPaperLut = 31495;
constexpr long kPaperFf = 13084;
constexpr double kPaperSramKB = 183.0;
constexpr double kPaperPixelsPerClock = 1.0 / 9.0;
constexpr int kLw = 9;  // path-cost width of the core = ceil(log2(Lmax + 1)), Lmax = 343

// Eq. (7): path-cost buffer bits (D + 5)(3W + 1) ceil(log2(Lmax + 1)).
long eq7Bits(long d, long w) { return (d + 5) * (3 * w + 1) * kLw; }

// ------------------------------------------------------------------ helpers
using sgm::eval::fixed;
using sgm::eval::isFile;
using sgm::eval::JsonWriter;
using sgm::eval::listDir;
using sgm::eval::readLines;
using sgm::eval::readMeta;
bool isDir(const std::string &p) { return sgm::eval::isDirectory(p); }
std::string metaGet(const std::map<std::string, std::string> &m, const std::string &k) {
  return sgm::eval::metaValue(m, k);
}
long toLong(const std::string &s, long dflt = 0) {
  try {
    return std::stol(s);
  } catch (...) {
    return dflt;
  }
}
double toDouble(const std::string &s, double dflt = NAN) {
  try {
    return std::stod(s);
  } catch (...) {
    return dflt;
  }
}
// The module's own name: $paramod$<hash>\sgm_wta -> sgm_wta; with one parameter Yosys names it
// $paramod\sgm_depth\DW=s32'... -> sgm_depth.
std::string baseName(const std::string &mod) {
  const auto i = mod.find("\\sgm_");
  if (i != std::string::npos) return mod.substr(i + 1, mod.find('\\', i + 1) - (i + 1));
  const auto j = mod.rfind('\\');
  return j == std::string::npos ? mod : mod.substr(j + 1);
}
bool startsWith(const std::string &s, const std::string &p) { return s.compare(0, p.size(), p) == 0; }

// 31495 -> "31,495"
std::string grouped(long v) {
  std::string s = std::to_string(v < 0 ? -v : v), o;
  int n = 0;
  for (auto it = s.rbegin(); it != s.rend(); ++it, ++n) {
    if (n && n % 3 == 0) o += ',';
    o += *it;
  }
  if (v < 0) o += '-';
  return std::string(o.rbegin(), o.rend());
}
// ------------------------------------------------------------------ cell classes
enum class Tech { Xilinx, Ice40, Generic };

Tech techOf(const std::string &target) {
  if (target == "xc7" || target == "xc6s" || startsWith(target, "xc")) return Tech::Xilinx;
  if (target == "ice40") return Tech::Ice40;
  return Tech::Generic;
}

// LUT6 sites a distributed-RAM primitive occupies.
int lutramLuts(const std::string &t) {
  static const std::map<std::string, int> k = {
      {"RAM16X1S", 1},  {"RAM16X1D", 2},  {"RAM32X1S", 1},  {"RAM32X1D", 2},    {"RAM64X1S", 1},  {"RAM64X1D", 2},
      {"RAM128X1S", 2}, {"RAM128X1D", 4}, {"RAM256X1S", 4}, {"RAM256X1D", 8},   {"RAM512X1S", 8}, {"RAM32M", 4},
      {"RAM64M", 4},    {"RAM32M16", 8},  {"RAM64M8", 8},   {"RAM32X16DR8", 8}, {"RAM64X8SW", 8}};
  auto it = k.find(t);
  return it == k.end() ? 0 : it->second;
}
// Block RAM capacity in Kbit (18 Kbit primitives include the parity bits).
int bramKbitOf(const std::string &t) {
  if (t == "RAMB36E1" || t == "RAMB36E2" || t == "RAMB36") return 36;
  if (t == "RAMB18E1" || t == "RAMB18E2" || t == "RAMB16BWER" || t == "RAMB16") return 18;
  if (t == "RAMB8BWER") return 9;
  if (t == "SB_RAM40_4K") return 4;
  if (t == "SB_SPRAM256KA") return 256;
  return 0;
}
bool isFf(Tech tech, const std::string &t) {
  switch (tech) {
    case Tech::Xilinx: return startsWith(t, "FD") || startsWith(t, "LD");
    case Tech::Ice40: return startsWith(t, "SB_DFF");
    case Tech::Generic:
      return startsWith(t, "$_") && (t.find("DFF") != std::string::npos || t.find("LATCH") != std::string::npos);
  }
  return false;
}
bool isLut(Tech tech, const std::string &t) {
  if (tech == Tech::Xilinx) return std::regex_match(t, std::regex("LUT[1-6](_2)?"));
  if (tech == Tech::Ice40) return t == "SB_LUT4";
  return false;
}
bool isSrl(const std::string &t) { return startsWith(t, "SRL"); }
bool isDsp(const std::string &t) { return startsWith(t, "DSP48") || t == "SB_MAC16"; }
bool isCarry(const std::string &t) { return t == "CARRY4" || t == "CARRY8" || t == "SB_CARRY"; }
bool isMuxf(const std::string &t) { return startsWith(t, "MUXF"); }

// ------------------------------------------------------------------ data
struct Memory {
  std::string stage, name;
  long width = 0, depth = 0, instances = 1;
  std::map<std::string, long> cells;  // primitive type -> count (per instance)
  long bits() const { return width * depth * instances; }
  bool pathBuffer() const {
    if (stage == "sgm_path_engine") return name == "mem45" || name == "mem90" || name == "mem135";
    return stage == "sgm_top" && (name == "u_paths.mem45" || name == "u_paths.mem90" || name == "u_paths.mem135");
  }
};

struct Counts {
  std::map<std::string, long> cells;  // type -> count, already times instances where summed
  long lut = 0, lutram = 0, srl = 0, ff = 0, dsp = 0, carry = 0, muxf = 0, total = 0;
  long bram36 = 0, bram18 = 0, bram9 = 0, bram4 = 0, bramKbit = 0, mems = 0;
  std::map<int, long> lutBySize;
  void add(Tech tech, const std::string &t, long n) {
    cells[t] += n;
    total += n;
    if (isLut(tech, t)) {
      lut += n;
      lutBySize[tech == Tech::Ice40 ? 4 : t[3] - '0'] += n;
    } else if (lutramLuts(t)) {
      lutram += n * lutramLuts(t);
    } else if (isSrl(t)) {
      srl += n;
    } else if (isFf(tech, t)) {
      ff += n;
    } else if (isDsp(t)) {
      dsp += n;
    } else if (isCarry(t)) {
      carry += n;
    } else if (isMuxf(t)) {
      muxf += n;
    } else if (t == "$mem_v2" || t == "$mem") {
      mems += n;
    }
    int kb = bramKbitOf(t);
    if (kb) {
      bramKbit += n * kb;
      if (kb == 36)
        bram36 += n;
      else if (kb == 18)
        bram18 += n;
      else if (kb == 9)
        bram9 += n;
      else if (kb == 4)
        bram4 += n;
    }
  }
  void add(Tech tech, const Counts &o, long times) {
    for (auto &kv : o.cells) add(tech, kv.first, kv.second * times);
  }
  long sliceLuts() const { return lut + lutram + srl; }
};

struct Ltp {
  int length = -1;
  std::string from, to;
};

struct Stage {
  std::string module, name;
  long instances = 1;
  Counts counts;  // one instance
  Ltp ltp;
  double seconds = NAN;
};

struct Target {
  std::string config, target, dir;
  Tech tech = Tech::Generic;
  std::map<std::string, std::string> meta;
  long d = 0, w = 0, h = 0;
  std::string census = "9x5";  // census window of the core (meta "census"; runs before it: 9x5)
  std::vector<Stage> stages;
  std::vector<Memory> memories;
  Counts total;
  Ltp ltp;
  std::string ltpStage;
  long checkProblems = -1;
  double seconds = NAN;
  // path buffers
  long pbBits = 0, pbBram18 = 0, pbBram36 = 0, pbBram9 = 0, pbBram4 = 0, pbBramKbit = 0, pbLutram = 0;
  bool pbFound = false, pbInBram = false;
  std::vector<std::string> notes;
};

struct Loop {
  std::string dir;
  std::map<std::string, std::string> meta;
  long d = 0;
  double fmaxNextpnr = NAN, fmaxIcetime = NAN, targetMhz = NAN;
  long lc = -1, lcTotal = -1, lut = -1, ff = -1, carry = -1, icetimeLevels = -1;
  double seconds = NAN;
};

// ------------------------------------------------------------------ parsers
// `stat` output: the cell-type lines after "Number of cells:" of the first
// (or only) module section.
Counts parseStat(Tech tech, const std::string &path) {
  Counts c;
  bool in = false;
  static const std::regex cellLine(R"(^\s+(\S+)\s+([0-9]+)\s*$)");
  for (auto &l : readLines(path)) {
    if (l.find("Number of cells:") != std::string::npos) {
      in = true;
      continue;
    }
    if (!in) continue;
    std::smatch m;
    if (std::regex_match(l, m, cellLine)) {
      c.add(tech, m[1], toLong(m[2]));
    } else if (!l.empty() && l.find_first_not_of(" \t") != std::string::npos) {
      break;
    } else if (!c.cells.empty()) {
      break;
    }
  }
  return c;
}

// "design hierarchy" section of `stat -top sgm_top`: direct children of the top.
std::map<std::string, long> parseInstances(const std::string &path) {
  std::map<std::string, long> out;
  bool in = false;
  static const std::regex child(R"(^     (\S+)\s+([0-9]+)\s*$)");
  for (auto &l : readLines(path)) {
    if (startsWith(l, "=== design hierarchy ===")) {
      in = true;
      continue;
    }
    if (!in) continue;
    if (l.find("Number of wires") != std::string::npos) break;
    std::smatch m;
    if (std::regex_match(l, m, child)) out[m[1]] += toLong(m[2]);
  }
  return out;
}

// `dump t:$mem_v2`: memories with width and depth.
std::vector<Memory> parseMemories(const std::string &stage, const std::string &path) {
  std::vector<Memory> out;
  static const std::regex cell(R"(^\s*cell \$mem(_v2)? (\S+)\s*$)");
  static const std::regex param(R"(^\s*parameter \\(WIDTH|SIZE|MEMID) (.*)$)");
  for (auto &l : readLines(path)) {
    std::smatch m;
    if (std::regex_match(l, m, cell)) {
      Memory mem;
      mem.stage = stage;
      mem.name = m[2];
      if (!mem.name.empty() && mem.name[0] == '\\') mem.name = mem.name.substr(1);
      out.push_back(mem);
    } else if (!out.empty() && std::regex_match(l, m, param)) {
      std::string v = m[2];
      if (m[1] == "WIDTH") out.back().width = toLong(v);
      if (m[1] == "SIZE") out.back().depth = toLong(v);
      if (m[1] == "MEMID") {
        // "\\u_p2_lut.table_q" -> u_p2_lut.table_q
        std::string id;
        for (char ch : v)
          if (ch != '"' && ch != '\\') id += ch;
        out.back().name = id;
      }
    }
  }
  return out;
}

// "TYPE module/cell" lines; the memory of a cell is its name without the
// trailing ".<i>.<j>" that memory_libmap appends.
std::vector<std::pair<std::string, std::string>> parseRamCells(const std::string &path) {
  std::vector<std::pair<std::string, std::string>> out;
  static const std::regex suffix(R"((\.[0-9]+)+$)");
  for (auto &l : readLines(path)) {
    std::istringstream is(l);
    std::string type, full;
    if (!(is >> type >> full)) continue;
    auto slash = full.rfind('/');
    std::string cell = slash == std::string::npos ? full : full.substr(slash + 1);
    out.emplace_back(type, std::regex_replace(cell, suffix, ""));
  }
  return out;
}

Ltp parseLtp(const std::string &path) {
  Ltp r;
  static const std::regex head(R"(Longest topological path in .* \(length=(-?[0-9]+)\):)");
  static const std::regex step(R"(^\s*([0-9]+): (\S+(?: \[[0-9]+\])?)(?: \(via .*\))?\s*$)");
  bool in = false;
  for (auto &l : readLines(path)) {
    std::smatch m;
    if (std::regex_search(l, m, head)) {
      r.length = static_cast<int>(toLong(m[1], -1));
      in = true;
      continue;
    }
    if (in && std::regex_match(l, m, step)) {
      std::string sig = m[2];
      if (!sig.empty() && sig[0] == '\\') sig = sig.substr(1);
      if (r.from.empty()) r.from = sig;
      r.to = sig;
    }
  }
  return r;
}

long parseCheck(const std::string &path) {
  static const std::regex found(R"(Found and reported ([0-9]+) problems)");
  for (auto &l : readLines(path)) {
    std::smatch m;
    if (std::regex_search(l, m, found)) return toLong(m[1]);
  }
  return -1;
}

double readSeconds(const std::string &path) {
  auto lines = readLines(path);
  return lines.empty() ? NAN : toDouble(lines[0]);
}

// ------------------------------------------------------------------ collect
bool loadTarget(const std::string &root, const std::string &config, const std::string &name, Target &t) {
  t.config = config;
  t.target = name;
  t.dir = root + "/" + config + "/" + name;
  if (!isFile(t.dir + "/done")) return false;
  t.tech = techOf(name);
  t.meta = readMeta(t.dir + "/meta.txt");
  t.d = toLong(metaGet(t.meta, "d"));
  t.w = toLong(metaGet(t.meta, "max_width"));
  t.h = toLong(metaGet(t.meta, "max_height"));
  if (!metaGet(t.meta, "census").empty()) t.census = metaGet(t.meta, "census");
  t.seconds = toDouble(metaGet(t.meta, "seconds"));
  t.checkProblems = parseCheck(t.dir + "/check.txt");

  // synth/xilinx_flat.tcl: the whole core as one "stage" sgm_top.
  auto inst = isFile(t.dir + "/sgm_top.stat.txt") ? std::map<std::string, long>{{"sgm_top", 1}}
                                                  : parseInstances(t.dir + "/hierarchy.txt");
  std::set<std::string> used;  // a second parametrisation of a module: name_2 (synth/common.tcl foreach_stage)
  for (auto &kv : inst) {
    Stage s;
    s.module = kv.first;
    s.name = baseName(kv.first);
    for (int n = 2; used.count(s.name); ++n) s.name = baseName(kv.first) + "_" + std::to_string(n);
    used.insert(s.name);
    s.instances = kv.second;
    std::string p = t.dir + "/" + s.name;
    s.counts = parseStat(t.tech, p + ".stat.txt");
    s.ltp = parseLtp(p + ".ltp.txt");
    s.seconds = readSeconds(p + ".seconds");
    t.total.add(t.tech, s.counts, s.instances);
    if (s.ltp.length > t.ltp.length) {
      t.ltp = s.ltp;
      t.ltpStage = s.name;
    }
    auto mems = parseMemories(s.name, p + ".memories.txt");
    auto cells = parseRamCells(p + ".ramcells.txt");
    for (auto &m : mems) {
      m.instances = s.instances;
      for (auto &c : cells)
        if (c.second == m.name) m.cells[c.first]++;
      t.memories.push_back(m);
    }
    t.stages.push_back(s);
  }
  std::sort(t.stages.begin(), t.stages.end(), [](const Stage &a, const Stage &b) {
    return a.counts.sliceLuts() * a.instances > b.counts.sliceLuts() * b.instances;
  });

  // Path buffers.
  int found = 0;
  bool allBram = true;
  for (auto &m : t.memories) {
    if (!m.pathBuffer()) continue;
    ++found;
    t.pbBits += m.bits();
    long bram = 0, lr = 0;
    for (auto &c : m.cells) {
      int kb = bramKbitOf(c.first);
      long n = c.second * m.instances;
      if (kb == 36) t.pbBram36 += n;
      if (kb == 18) t.pbBram18 += n;
      if (kb == 9) t.pbBram9 += n;
      if (kb == 4) t.pbBram4 += n;
      t.pbBramKbit += n * kb;
      if (kb) bram += n;
      if (lutramLuts(c.first)) lr += n * lutramLuts(c.first);
    }
    t.pbLutram += lr;
    if (bram == 0 || lr != 0) allBram = false;
  }
  t.pbFound = found == 3;
  t.pbInBram = t.pbFound && allBram && t.tech != Tech::Generic;
  return true;
}

bool loadLoop(const std::string &dir, Loop &l) {
  l.dir = dir;
  if (!isFile(dir + "/done")) return false;
  l.meta = readMeta(dir + "/meta.txt");
  l.d = toLong(metaGet(l.meta, "d"));
  l.seconds = toDouble(metaGet(l.meta, "seconds"));
  l.targetMhz = toDouble(metaGet(l.meta, "freq_mhz"));
  static const std::regex fmax(R"(Max frequency for clock '[^']*': ([0-9.]+) MHz)");
  static const std::regex lc(R"(ICESTORM_LC:\s*([0-9]+)\s*/\s*([0-9]+))");
  // nextpnr prints the estimate before routing and the routed figure last.
  for (auto &s : readLines(dir + "/nextpnr.log")) {
    std::smatch m;
    if (std::regex_search(s, m, fmax)) l.fmaxNextpnr = toDouble(m[1]);
    if (std::regex_search(s, m, lc)) {
      l.lc = toLong(m[1]);
      l.lcTotal = toLong(m[2]);
    }
  }
  static const std::regex ice(R"(Total path delay: [0-9.]+ ns \(([0-9.]+) MHz\))");
  static const std::regex lev(R"(Total number of logic levels: ([0-9]+))");
  for (auto &s : readLines(dir + "/icetime.txt")) {
    std::smatch m;
    if (std::regex_search(s, m, ice)) l.fmaxIcetime = toDouble(m[1]);
    if (std::regex_search(s, m, lev)) l.icetimeLevels = toLong(m[1]);
  }
  Counts c = parseStat(Tech::Ice40, dir + "/stat.txt");
  l.lut = c.lut;
  l.ff = c.ff;
  l.carry = c.carry;
  return true;
}

// ------------------------------------------------------------------ JSON
// A count only the given technologies have (null for the others).
void countOrNull(JsonWriter &j, const char *key, bool has, long value) {
  j.key(key);
  has ? j.integer(value) : j.null();
}

void countsJson(JsonWriter &j, const Counts &c, Tech tech) {
  const bool x = tech == Tech::Xilinx, i = tech == Tech::Ice40, mapped = tech != Tech::Generic;
  countOrNull(j, "lut", mapped, c.lut);
  j.key("ff").integer(c.ff);
  countOrNull(j, "bram18", x, c.bram18);
  countOrNull(j, "bram36", x, c.bram36);
  if (x) j.key("ramb8").integer(c.bram9);
  if (i) j.key("sb_ram40_4k").integer(c.bram4);
  j.key("bram_kbit").integer(c.bramKbit);
  countOrNull(j, "lutram", x, c.lutram);
  countOrNull(j, "srl", x, c.srl);
  countOrNull(j, "slice_luts", x, c.sliceLuts());
  countOrNull(j, "dsp", mapped, c.dsp);
  countOrNull(j, "carry", mapped, c.carry);
  j.key("cells").integer(c.total);
}

void targetJson(JsonWriter &j, const Target &t, const std::vector<Loop> &loops) {
  j.beginObject();
  j.key("target").string(t.target);
  j.key("config").string(t.config);
  j.key("d").integer(t.d);
  j.key("max_width").integer(t.w);
  j.key("max_height").integer(t.h);
  j.key("census").string(t.census);
  j.key("pixels_per_clock").integer(1);
  // The reference build (scripts/refs.mk) this run is, when `make synth-ref` made it.
  j.key("ref");
  metaGet(t.meta, "ref").empty() ? j.null() : j.string(metaGet(t.meta, "ref"));
  countsJson(j, t.total, t.tech);
  // xc7: the smallest Artix-7 / Kintex-7 that holds the estimate (tools/xc7_parts.hpp).
  if (t.target == "xc7") {
    const long bram36 = t.total.bram36 + (t.total.bram18 + 1) / 2;
    const sgm::eval::Xc7Part *part = sgm::eval::smallestXc7Part(t.total.sliceLuts(), t.total.ff, bram36, t.total.dsp);
    j.key("smallest_part");
    if (!part) {
      j.null();
    } else {
      j.beginObject();
      j.key("name").string(part->name);
      j.key("luts").integer(part->luts);
      j.key("ffs").integer(part->ffs);
      j.key("bram36").integer(part->bram36);
      j.key("dsp").integer(part->dsp);
      j.key("bram36_needed").integer(bram36);
      j.endObject();
    }
  }
  if (t.tech == Tech::Xilinx) {
    j.key("lut_by_size").beginObject();
    for (auto &kv : t.total.lutBySize) j.key("LUT" + std::to_string(kv.first)).integer(kv.second);
    j.endObject();
    j.key("muxf").integer(t.total.muxf);
  }
  if (t.tech == Tech::Generic) j.key("memories").integer(t.total.mems);
  long memBits = 0;
  for (auto &m : t.memories) memBits += m.bits();
  j.key("memory_bits").integer(memBits);
  countOrNull(j, "logic_levels", t.ltp.length >= 0, t.ltp.length);
  j.key("logic_levels_path").beginObject();
  j.key("stage").string(t.ltpStage);
  j.key("from").string(t.ltp.from);
  j.key("to").string(t.ltp.to);
  j.endObject();
  // iCE40: the routed loop harness of the same D if there is one, else the smallest D.
  double fmax = NAN;
  long fmaxD = 0;
  if (t.tech == Tech::Ice40)
    for (auto &l : loops)
      if (!std::isnan(l.fmaxNextpnr) && (std::isnan(fmax) || l.d == t.d)) {
        fmax = l.fmaxNextpnr;
        fmaxD = l.d;
      }
  j.key("fmax_mhz").real(fmax, 2);
  if (t.tech == Tech::Ice40) {
    j.key("fmax_source");
    fmaxD ? j.string("ice40-loop-d" + std::to_string(fmaxD)) : j.null();
  }
  if (t.tech == Tech::Xilinx) j.key("lut_per_pixel_per_clock").integer(t.total.sliceLuts());
  j.key("path_buffers").beginObject();
  j.key("bits").integer(t.pbBits);
  j.key("eq7_bits").integer(eq7Bits(t.d, t.w));
  j.key("bram18").integer(t.pbBram18);
  j.key("bram36").integer(t.pbBram36);
  j.key("ramb8").integer(t.pbBram9);
  j.key("sb_ram40_4k").integer(t.pbBram4);
  j.key("bram_kbit").integer(t.pbBramKbit);
  j.key("lutram").integer(t.pbLutram);
  j.key("in_block_ram").boolean(t.pbInBram);
  j.endObject();
  j.key("check_problems").integer(t.checkProblems);
  j.key("seconds").real(t.seconds, 0);
  j.key("yosys").string(metaGet(t.meta, "yosys"));
  j.key("rtl_commit").string(metaGet(t.meta, "rtl_commit"));
  j.key("date").string(metaGet(t.meta, "date"));  // of the Yosys run (meta.txt)
  j.key("stages").beginArray();
  for (const Stage &st : t.stages) {
    j.beginObject();
    j.key("name").string(st.name);
    j.key("instances").integer(st.instances);
    countsJson(j, st.counts, t.tech);
    j.key("logic_levels").integer(st.ltp.length);
    j.key("seconds").real(st.seconds, 1);
    j.endObject();
  }
  j.endArray();
  j.key("memory_list").beginArray();
  for (const Memory &me : t.memories) {
    j.beginObject();
    j.key("stage").string(me.stage);
    j.key("name").string(me.name);
    j.key("width").integer(me.width);
    j.key("depth").integer(me.depth);
    j.key("instances").integer(me.instances);
    j.key("bits").integer(me.bits());
    j.key("cells").beginObject();
    for (auto &c : me.cells) j.key(c.first).integer(c.second);
    j.endObject();
    j.endObject();
  }
  j.endArray();
  j.endObject();
}

void loopJson(JsonWriter &j, const Loop &l) {
  j.beginObject();
  j.key("target").string("ice40-loop");
  j.key("config").string("loop-d" + std::to_string(l.d));
  j.key("d").integer(l.d);
  j.key("max_width").null();
  j.key("pixels_per_clock").integer(1);
  j.key("device").string(metaGet(l.meta, "device"));
  j.key("lut").integer(l.lut);
  j.key("ff").integer(l.ff);
  j.key("carry").integer(l.carry);
  j.key("lc").integer(l.lc);
  j.key("lc_available").integer(l.lcTotal);
  j.key("fmax_mhz").real(l.fmaxNextpnr, 2);
  j.key("fmax_icetime_mhz").real(l.fmaxIcetime, 2);
  j.key("icetime_logic_levels").integer(l.icetimeLevels);
  j.key("seconds").real(l.seconds, 0);
  j.endObject();
}

void writeJson(const std::string &path, const std::vector<Target> &ts, const std::vector<Loop> &loops) {
  JsonWriter j;
  j.beginObject();
  j.key("paper").beginObject();
  j.key("device").string("xc6slx150");
  j.key("lut").integer(kPaperLut);
  j.key("ff").integer(kPaperFf);
  j.key("sram_kbyte").real(kPaperSramKB, 0);
  j.key("pixels_per_clock").real(kPaperPixelsPerClock, 4);
  j.key("lut_per_pixel_per_clock").real(kPaperLut / kPaperPixelsPerClock, 0);
  j.endObject();
  j.key("results").beginArray();
  for (const Target &t : ts) targetJson(j, t, loops);
  for (const Loop &l : loops) loopJson(j, l);
  j.endArray();
  j.endObject();
  sgm::eval::writeTextFile(path, j.str());
}

// ------------------------------------------------------------------ Markdown
std::string stageShort(const std::string &s) { return startsWith(s, "sgm_") ? s.substr(4) : s; }

std::string bramText(const Target &t) {
  const Counts &c = t.total;
  std::ostringstream o;
  if (t.tech == Tech::Ice40) {
    o << c.bram4 << " SB_RAM40_4K";
  } else if (t.target == "xc6s") {
    o << c.bram18 << " RAMB16 + " << c.bram9 << " RAMB8";
  } else {
    o << c.bram18 << " RAMB18 + " << c.bram36 << " RAMB36";
  }
  o << " (" << fixed(c.bramKbit / 8.0, 0) << " KB)";
  return o.str();
}

void writeMarkdown(const std::string &path, const std::vector<Target> &ts, const std::vector<Loop> &loops) {
  std::ofstream o(path);
  o << "# Synthesis summary\n\n";
  o << "Written by `make synth` (synth/README.md). Yosys synthesizes every pipeline stage of `sgm_top` as its own "
       "top with everything inside the stage flattened; totals are the sum over the stage instances (the census "
       "unit twice); the xc7-flat column, when present, is `make synth-flat`, the whole core in one flattened "
       "run (optimisation across stages, longest path across stages). LUT figures for Xilinx: *slice LUTs* = LUTs as logic + LUTs as distributed RAM + SRLs, the "
       "figure ISE reports as \"Number of Slice LUTs\". Logic levels = `ltp` on the mapped netlist: LUT, carry and "
       "wide-mux cells between sequential cells (FF, RAM, SRL, DSP). Block RAM in KB = primitive capacity "
       "(18 Kbit per RAMB18/RAMB16, parity bits included) / 8 / 1024.\n\n";
  o << "Yosys 0.23 supports `synth_xilinx -family xc6s` (Spartan-6: RAMB16BWER / RAMB8BWER, DSP48A1); the xc6s column "
       "is that run. The paper's figures are Table III (Spartan-6 xc6slx150, 1/9 pixel per clock).\n\n";

  std::set<std::string> configs;
  for (auto &t : ts) configs.insert(t.config);
  std::vector<std::string> cfgs(configs.begin(), configs.end());
  auto cfgKey = [&](const std::string &c) {
    for (auto &t : ts)
      if (t.config == c) return std::make_tuple(t.d, t.w, t.census);
    return std::make_tuple(0L, 0L, std::string());
  };
  std::sort(cfgs.begin(), cfgs.end(), [&](auto &a, auto &b) { return cfgKey(a) > cfgKey(b); });

  const Loop *bestLoop = nullptr;
  for (auto &l : loops)
    if (!bestLoop || l.d < bestLoop->d) bestLoop = &l;

  for (auto &cfg : cfgs) {
    std::vector<const Target *> cols;
    for (const char *want : {"xc6s", "xc7", "xc7-flat", "ice40", "generic"})
      for (auto &t : ts)
        if (t.config == cfg && t.target == want) cols.push_back(&t);
    if (cols.empty()) continue;
    const Target &f = *cols[0];
    // The build-time levers (sgm_top UNIQUENESS, AD_TERM): named when a lever is not built;
    // the fifth path's block (RIGHT_BLOCK) when it is.
    const std::string rightBlock = metaGet(f.meta, "right_block");
    const std::string levers = std::string(metaGet(f.meta, "uniqueness") == "0" ? ", UNIQUENESS = 0" : "") +
                               (metaGet(f.meta, "ad_term") == "0" ? ", AD_TERM = 0" : "") +
                               (!rightBlock.empty() && rightBlock != "0" ? ", RIGHT_BLOCK = " + rightBlock : "");
    o << "## D = " << f.d << ", MAX_WIDTH = " << f.w << ", census " << f.census << levers << " (MAX_HEIGHT = " << f.h
      << ")\n\n";
    o << "| | paper, Table III (xc6slx150) |";
    for (auto *c : cols) o << " " << c->target << " (this core, census " << c->census << ") |";
    o << "\n| --- | --- |";
    for (size_t i = 0; i < cols.size(); ++i) o << " --- |";
    o << "\n";
    auto row = [&](const std::string &label, const std::string &paper, auto fn) {
      o << "| " << label << " | " << paper << " |";
      for (auto *c : cols) o << " " << fn(*c) << " |";
      o << "\n";
    };
    auto na = std::string("n/a");
    row("slice LUTs (logic + memory + SRL)", grouped(kPaperLut), [&](const Target &t) {
      return t.tech == Tech::Xilinx  ? "**" + grouped(t.total.sliceLuts()) + "**"
             : t.tech == Tech::Ice40 ? grouped(t.total.lut) + " LUT4"
                                     : na;
    });
    row("LUTs as logic (LUT1..6)", "", [&](const Target &t) {
      if (t.tech != Tech::Xilinx) return t.tech == Tech::Ice40 ? grouped(t.total.lut) : na;
      std::string s = grouped(t.total.lut) + " (";
      bool first = true;
      for (auto it = t.total.lutBySize.rbegin(); it != t.total.lutBySize.rend(); ++it) {
        s += (first ? "" : " / ") + std::string("L") + std::to_string(it->first) + " " + grouped(it->second);
        first = false;
      }
      return s + ")";
    });
    row("LUTs as distributed RAM / SRL", "", [&](const Target &t) {
      return t.tech == Tech::Xilinx ? grouped(t.total.lutram) + " / " + grouped(t.total.srl) : na;
    });
    row("flip-flops", grouped(kPaperFf), [&](const Target &t) { return grouped(t.total.ff); });
    row("block RAM", fixed(kPaperSramKB, 0) + " KB on-chip SRAM", [&](const Target &t) {
      return t.tech == Tech::Generic ? grouped(t.total.mems) + " memories, not mapped" : bramText(t);
    });
    row("memory bits inferred", "", [&](const Target &t) {
      long b = 0;
      for (auto &m : t.memories) b += m.bits();
      return grouped(b) + " (" + fixed(b / 8.0 / 1024.0, 0) + " KB)";
    });
    row("DSP / carry cells", "", [&](const Target &t) {
      return t.tech == Tech::Generic ? na : grouped(t.total.dsp) + " / " + grouped(t.total.carry);
    });
    row("gate-level cells", "", [&](const Target &t) { return grouped(t.total.total); });
    row("logic levels (longest path)", "", [&](const Target &t) {
      return t.ltp.length < 0 ? na : std::to_string(t.ltp.length) + " (" + stageShort(t.ltpStage) + ")";
    });
    row("fmax", "", [&](const Target &t) {
      const Loop *lp = bestLoop;
      for (auto &l : loops)
        if (l.d == t.d) lp = &l;
      if (t.tech != Tech::Ice40 || !lp || std::isnan(lp->fmaxNextpnr)) return std::string("");
      return fixed(lp->fmaxNextpnr, 1) + " MHz (0 degree loop, D = " + std::to_string(lp->d) + ", routed)";
    });
    row("fits the largest iCE40 (HX8K: 7,680 LCs, 32 RAM)", "", [&](const Target &t) {
      if (t.tech != Tech::Ice40) return std::string("");
      bool fits = t.total.lut <= 7680 && t.total.bram4 <= 32;
      return std::string(fits ? "by LUT4 and RAM count" : "**no**") + " (" + grouped(t.total.lut) + " LUT4, " +
             std::to_string(t.total.bram4) + " RAM)";
    });
    row("pixels per clock", "1/9", [&](const Target &) { return std::string("1"); });
    row("LUTs per (pixel/clock)", grouped(static_cast<long>(kPaperLut / kPaperPixelsPerClock)),
        [&](const Target &t) { return t.tech == Tech::Xilinx ? grouped(t.total.sliceLuts()) : na; });
    row("bar: at most 31,495 LUTs at 1 pixel/clock", "", [&](const Target &t) {
      if (t.tech != Tech::Xilinx) return std::string("");
      long l = t.total.sliceLuts();
      return l <= kPaperLut ? "met (" + fixed(100.0 * l / kPaperLut, 0) + " %)"
                            : "**missed** (" + fixed(100.0 * l / kPaperLut, 0) + " %)";
    });
    row("Yosys run time", "", [&](const Target &t) { return std::isnan(t.seconds) ? na : fixed(t.seconds, 0) + " s"; });
    // Columns synthesized from different RTL are not comparable: say which RTL each one is.
    row("RTL (last commit touching rtl/)", "", [&](const Target &t) {
      const std::string c = metaGet(t.meta, "rtl_commit");
      return c.empty() ? na : "`" + c + "`";
    });
    o << "\n";

    // Path buffers.
    o << "**Path buffers** (`sgm_path_engine` mem45 / mem90 / mem135, 3 x " << f.w << " x " << (f.d + 1) << " x " << kLw
      << " bit) against eq. (7), (D + 5)(3W + 1) ceil(log2(Lmax + 1)) with Lmax = 343:\n\n";
    o << "| target | bits | eq. (7) bits | ratio | blocks | block capacity | in block RAM |\n| --- | --- | --- | --- | --- | --- | --- |\n";
    for (auto *c : cols) {
      if (c->tech == Tech::Generic) continue;
      std::string blocks;
      if (c->tech == Tech::Ice40)
        blocks = std::to_string(c->pbBram4) + " SB_RAM40_4K";
      else if (c->target == "xc6s")
        blocks = std::to_string(c->pbBram18) + " RAMB16 + " + std::to_string(c->pbBram9) + " RAMB8";
      else
        blocks = std::to_string(c->pbBram18) + " RAMB18 + " + std::to_string(c->pbBram36) + " RAMB36";
      long e = eq7Bits(c->d, c->w);
      o << "| " << c->target << " | " << grouped(c->pbBits) << " | " << grouped(e) << " | "
        << fixed(double(c->pbBits) / e, 3) << " | " << blocks << " | " << grouped(c->pbBramKbit) << " Kbit ("
        << fixed(100.0 * c->pbBits / (c->pbBramKbit * 1024.0 > 0 ? c->pbBramKbit * 1024.0 : 1), 0) << " % used) | "
        << (c->pbInBram ? "yes" : "**NO**") << (c->pbLutram ? " (" + std::to_string(c->pbLutram) + " LUTRAM LUTs)" : "")
        << " |\n";
    }
    o << "\n";

    // Per stage.
    for (auto *c : cols) {
      if (c->tech != Tech::Xilinx || c->target == "xc7-flat") continue;
      o << "**Where the area goes** (" << c->target << ", per stage, all instances):\n\n";
      o << "| stage | inst. | slice LUTs | share | LUT logic | LUTRAM | SRL | FF | block RAM | carry | levels | Yosys s |\n";
      o << "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |\n";
      for (auto &s : c->stages) {
        long n = s.instances;
        long sl = s.counts.sliceLuts() * n;
        std::string br = c->target == "xc6s"
                             ? std::to_string(s.counts.bram18 * n) + " / " + std::to_string(s.counts.bram9 * n)
                             : std::to_string(s.counts.bram18 * n) + " / " + std::to_string(s.counts.bram36 * n);
        o << "| " << stageShort(s.name) << " | " << n << " | " << grouped(sl) << " | "
          << fixed(c->total.sliceLuts() ? 100.0 * sl / c->total.sliceLuts() : 0.0, 1) << " % | "
          << grouped(s.counts.lut * n) << " | " << grouped(s.counts.lutram * n) << " | " << grouped(s.counts.srl * n)
          << " | " << grouped(s.counts.ff * n) << " | " << br << " | " << grouped(s.counts.carry * n) << " | "
          << s.ltp.length << " | " << (std::isnan(s.seconds) ? na : fixed(s.seconds, 0)) << " |\n";
      }
      o << "\n(block RAM column: " << (c->target == "xc6s" ? "RAMB16 / RAMB8" : "RAMB18 / RAMB36")
        << "; levels: longest LUT/carry/mux path inside the stage)\n\n";
    }

    // Memories.
    for (auto *c : cols) {
      if (c->target != "xc7" && !(c->target == "xc6s" && cols.size() == 1)) continue;
      o << "**Memories** (" << c->target << "): where each inferred memory went\n\n";
      o << "| stage | memory | words x bits | inst. | bits | primitives (per instance) |\n| --- | --- | --- | --- | --- | --- |\n";
      for (auto &m : c->memories) {
        std::string cells;
        for (auto &kv : m.cells) cells += (cells.empty() ? "" : ", ") + std::to_string(kv.second) + " " + kv.first;
        if (cells.empty()) cells = "flip-flops / logic";
        o << "| " << stageShort(m.stage) << " | " << m.name << " | " << m.depth << " x " << m.width << " | "
          << m.instances << " | " << grouped(m.bits()) << " | " << cells << " |\n";
      }
      o << "\n";
    }
    for (auto *c : cols)
      if (c->tech == Tech::Xilinx && !c->ltp.from.empty())
        o << "Longest path (" << c->target << ", " << c->ltp.length << " cells, in " << c->ltpStage << "): `"
          << c->ltp.from << "` -> `" << c->ltp.to << "`.\n\n";
    for (auto *c : cols)
      if (c->checkProblems != 0)
        o << "**`check` reported " << c->checkProblems << " problem(s) for " << c->target << "**: see " << c->dir
          << "/check.txt.\n\n";
  }

  if (!loops.empty()) {
    o << "## iCE40: routed fmax of the single-cycle loop\n\n";
    o << "The whole core does not fit any iCE40 (see the ice40 column: LUT4s and SB_RAM40_4K against the "
         "largest part, iCE40HX8K: 7,680 LCs, 32 SB_RAM40_4K), so `nextpnr-ice40` routes the harness "
         "synth/sgm_path_loop.sv: the 0 degree path recursion of sgm_path_engine (D sub-PEs, "
         "add-compare-select, and the D-input minimum tree, registered back), the one single-cycle loop of "
         "the design.\n\n";
    o << "| D | device | LCs | LUT4 / FF / carry | fmax (nextpnr, routed) | fmax (icetime) | icetime levels | run time |\n";
    o << "| --- | --- | --- | --- | --- | --- | --- | --- |\n";
    for (auto &l : loops)
      o << "| " << l.d << " | " << metaGet(l.meta, "device") << " | " << l.lc << " / " << l.lcTotal << " | " << l.lut
        << " / " << l.ff << " / " << l.carry << " | **" << fixed(l.fmaxNextpnr, 1) << " MHz** | "
        << fixed(l.fmaxIcetime, 1) << " MHz | " << l.icetimeLevels << " | " << fixed(l.seconds, 0) << " s |\n";
    o << "\n";
  }
}

}  // namespace

int main(int argc, char **argv) {
  if (argc < 2) {
    std::cerr << "usage: synth-summary ROOT [--check CONFIG/TARGET]...\n";
    return 2;
  }
  std::string root = argv[1];
  std::vector<std::string> checks;
  for (int i = 2; i < argc; ++i) {
    std::string a = argv[i];
    if (a == "--check" && i + 1 < argc)
      checks.push_back(argv[++i]);
    else {
      std::cerr << "synth-summary: unknown argument " << a << "\n";
      return 2;
    }
  }
  std::vector<Target> targets;
  std::vector<Loop> loops;
  // A build tag (scripts/build.mk, core_tag): d<D>-w<MAX_WIDTH>, then one -<letters><value> part per
  // parameter that differs from sgm_top's default (whichever the build names).
  static const std::regex cfgRe(R"(d[0-9]+-w[0-9]+(-[a-z][a-z0-9]*)*)");
  static const std::regex loopRe(R"(ice40-loop-d[0-9]+)");
  for (auto &cfg : listDir(root)) {
    std::string p = root + "/" + cfg;
    if (!isDir(p)) continue;
    if (std::regex_match(cfg, cfgRe)) {
      for (auto &tn : listDir(p)) {
        Target t;
        if (isDir(p + "/" + tn) && loadTarget(root, cfg, tn, t)) targets.push_back(t);
      }
    } else if (std::regex_match(cfg, loopRe)) {
      Loop l;
      if (loadLoop(p, l)) loops.push_back(l);
    }
  }
  std::sort(loops.begin(), loops.end(), [](const Loop &a, const Loop &b) { return a.d < b.d; });
  writeJson(root + "/summary.json", targets, loops);
  writeMarkdown(root + "/summary.md", targets, loops);
  std::cout << "synth-summary: " << targets.size() << " synthesis results, " << loops.size() << " routed loop(s) -> "
            << root << "/summary.json, " << root << "/summary.md\n";

  int rc = 0;
  for (auto &c : checks) {
    if (std::regex_match(c, loopRe)) {  // a routed loop harness: both fmax figures must be there
      const Loop *l = nullptr;
      for (auto &x : loops)
        if (x.dir.size() >= c.size() && x.dir.compare(x.dir.size() - c.size(), c.size(), c) == 0) l = &x;
      if (!l || !(l->fmaxNextpnr > 0) || !(l->fmaxIcetime > 0)) {
        std::cerr << "synth-summary: FAIL: " << c << ": no routed result with an fmax from nextpnr-ice40 and icetime\n";
        rc = 1;
      } else {
        std::cout << "synth-summary: " << c << ": routed, fmax " << fixed(l->fmaxNextpnr, 1) << " MHz (nextpnr-ice40), "
                  << fixed(l->fmaxIcetime, 1) << " MHz (icetime)\n";
      }
      continue;
    }
    auto slash = c.find('/');
    std::string cfg = c.substr(0, slash), tn = slash == std::string::npos ? "" : c.substr(slash + 1);
    const Target *t = nullptr;
    for (auto &x : targets)
      if (x.config == cfg && x.target == tn) t = &x;
    if (!t) {
      std::cerr << "synth-summary: FAIL: no " << c << " result in " << root << "/summary.json\n";
      rc = 1;
      continue;
    }
    if (!t->pbFound) {
      std::cerr << "synth-summary: FAIL: " << c << ": the path buffers mem45 / mem90 / mem135 of sgm_path_engine were "
                << "not found among the inferred memories (renamed, or no longer inferred as memories)\n";
      rc = 1;
    } else if (t->tech == Tech::Generic) {
      std::cerr << "synth-summary: FAIL: " << c
                << ": the generic target does not map memories; check an xc7, xc6s or ice40 result\n";
      rc = 1;
    } else if (!t->pbInBram) {
      std::cerr << "synth-summary: FAIL: " << c << ": the path buffers are not (only) in block RAM: "
                << t->pbBram18 + t->pbBram36 + t->pbBram9 + t->pbBram4 << " block RAM primitives, " << t->pbLutram
                << " LUTs of distributed RAM (a memory with neither went to flip-flops)\n";
      rc = 1;
    } else {
      std::cout << "synth-summary: " << c << ": path buffers in block RAM (" << t->pbBram18 << " x 18K + "
                << t->pbBram36 << " x 36K + " << t->pbBram9 << " x 9K), " << t->total.sliceLuts() << " slice LUTs, "
                << t->total.ff << " FFs\n";
    }
    if (t->checkProblems != 0) {
      std::cerr << "synth-summary: FAIL: " << c << ": `check` reported " << t->checkProblems << " problem(s), see "
                << t->dir << "/check.txt\n";
      rc = 1;
    }
  }
  return rc;
}
