// SPDX-License-Identifier: Apache-2.0
#include "datasheet.hpp"

#include "json_read.hpp"
#include "report_util.hpp"
#include "video_formats.hpp"

#include "sgm/params.hpp"

#include <algorithm>
#include <map>
#include <filesystem>
#include <optional>
#include <sstream>
#include <vector>

namespace sgm::eval {

namespace {

// One report file: its path as shown on the page, the make target that writes it,
// and its parsed contents when present.
struct Report {
  std::string path;
  std::string target;
  std::optional<Json> json;

  bool present() const { return json.has_value(); }
  std::string notMeasured() const { return "not measured: run `make " + target + "` (" + path + " is absent)"; }
};

Report loadReport(const std::string& path, const std::string& target) {
  Report r{path, target, std::nullopt};
  if (isFile(path)) r.json = readJsonFile(path);
  return r;
}

// A field a report must have: throws Error naming the file and the field.
const Json& need(const Json& object, const char* key, const std::string& file) {
  const Json* v = object.get(key);
  if (!v) throw Error(file + ": no field '" + key + "' (datasheet)");
  return *v;
}

const Json& needArray(const Json& object, const char* key, const std::string& file) {
  const Json& v = need(object, key, file);
  if (!v.isArray()) throw Error(file + ": field '" + key + "' is not an array (datasheet)");
  return v;
}

// A scalar as the report wrote it: numbers and literals verbatim, strings decoded,
// null (and an absent optional field) as "-".
std::string text(const Json* v) {
  if (!v || v->isNull()) return "-";
  if (v->isString()) return v->text.empty() ? "-" : v->text;
  if (v->isObject() || v->isArray()) return "-";
  return v->text;
}

std::string text(const Json& v) { return text(&v); }

std::string text(const Json& object, const char* key) { return text(object.get(key)); }

// A number field, nullopt when absent or null.
std::optional<double> number(const Json& object, const char* key) {
  const Json* v = object.get(key);
  if (!v || !v->isNumber()) return std::nullopt;
  return v->number;
}

// A tool's version as the page shows it: Yosys without its build's git hash, nextpnr as
// the version its banner names ("... (Version nextpnr-0.11.1)" -> "nextpnr-0.11.1").
std::string toolVersion(const std::string& banner) {
  std::string v = banner.substr(0, banner.find(" (git sha1"));
  const size_t at = v.find("(Version ");
  if (at != std::string::npos) v = v.substr(at + 9, v.find(')', at) - at - 9);
  return v;
}

// "used / available" when the report has the available count.
std::string usedOf(const Json& run, const char* used, const char* available) {
  const std::string a = text(run, available);
  return a == "-" ? text(run, used) : text(run, used) + " / " + a;
}

// Every summary.json below root (recursively), sorted by path.
std::vector<std::string> synthSummaries(const std::string& root) {
  std::vector<std::string> out;
  std::error_code ec;
  if (!std::filesystem::is_directory(root, ec)) return out;
  for (std::filesystem::recursive_directory_iterator it(root, ec), end; !ec && it != end; it.increment(ec))
    if (it->path().filename() == "summary.json" && it->is_regular_file(ec)) out.push_back(it->path().string());
  std::sort(out.begin(), out.end());
  return out;
}

// ------------------------------------------------------------------ sections
void sourcesSection(std::ostringstream& md, const std::vector<Report>& synth, const std::string& synthRoot,
                    const std::vector<const Report*>& others) {
  md << "## Sources\n\n";
  if (synth.empty())
    md << "- Yosys synthesis: not measured: run `make synth` (no summary.json under " << synthRoot << ")\n";
  for (const Report& r : synth) md << "- Yosys synthesis: " << r.path << "\n";
  for (const Report* r : others) md << "- " << (r->present() ? r->path : r->notMeasured()) << "\n";
  md << "\n";
}

void pnrSection(std::ostringstream& md, const Report& pnr) {
  md << "## Place and route (nextpnr-ecp5, routed)\n\n";
  if (!pnr.present()) {
    md << pnr.notMeasured() << "\n\n";
    return;
  }
  const Json& runs = needArray(*pnr.json, "runs", pnr.path);
  if (runs.items.empty()) {
    md << "No routed build in " << pnr.path << ": run `make pnr`.\n\n";
  } else {
    md << "| build | device | speed | D | MAX_WIDTH | lanes | LUT4 | FF | EBR | DSP | fmax (MHz) | seed | nextpnr | "
          "Yosys | date |\n|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|---|---|\n";
    for (const Json& r : runs.items) {
      md << "| " << text(need(r, "run", pnr.path)) << " | " << text(r, "device") << "-" << text(r, "package") << " | "
         << text(r, "speed") << " | " << text(need(r, "d", pnr.path)) << " | " << text(need(r, "max_width", pnr.path))
         << " | " << text(r, "lanes") << " | " << usedOf(r, "lut4", "lut4_available") << " | "
         << usedOf(r, "ff", "ff_available") << " | " << usedOf(r, "ebr", "ebr_available") << " | " << text(r, "dsp")
         << " | **" << text(need(r, "fmax_mhz", pnr.path)) << "** | " << text(r, "seed") << " | "
         << toolVersion(text(r, "nextpnr")) << " | " << toolVersion(text(r, "yosys")) << " | " << text(r, "date")
         << " |\n";
    }
    md << "\nSource: " << pnr.path
       << " (runs[]: lut4, ff, ebr with their _available, dsp, fmax_mhz, seed, nextpnr, yosys, date).\n\n";
  }
  const Json* loops = pnr.json->get("loop_runs");
  if (loops && loops->isArray() && !loops->items.empty()) {
    md << "The 0 degree loop alone (`make pnr-loop`):\n\n| run | device | speed | D | LANES | LUT4 | FF | fmax (MHz) | "
          "date |\n|---|---|---|---:|---:|---:|---:|---:|---|\n";
    for (const Json& r : loops->items)
      md << "| " << text(r, "run") << " | " << text(r, "device") << "-" << text(r, "package") << " | "
         << text(r, "speed") << " | " << text(r, "d") << " | " << text(r, "lanes") << " | " << text(r, "lut4") << " | "
         << text(r, "ff") << " | " << text(need(r, "fmax_mhz", pnr.path)) << " | " << text(r, "date") << " |\n";
    md << "\nSource: " << pnr.path << " (loop_runs[]).\n\n";
  }
}

void synthSection(std::ostringstream& md, const std::vector<Report>& synth, const std::string& synthRoot) {
  md << "## Synthesis (Yosys, per configuration)\n\n";
  if (synth.empty()) {
    md << "not measured: run `make synth` (no summary.json under " << synthRoot << ")\n\n";
    return;
  }
  for (const Report& s : synth) {
    const Json& results = needArray(*s.json, "results", s.path);
    std::vector<const Json*> cores, loops;
    for (const Json& r : results.items) (text(r, "target") == "ice40-loop" ? loops : cores).push_back(&r);
    if (!cores.empty()) {
      md << "| configuration | target | D | MAX_WIDTH | census | LUTs | FF | block RAM (Kbit) | DSP | fmax (MHz) | Yosys | "
            "date |\n|---|---|---:|---:|---|---:|---:|---:|---:|---:|---|---|\n";
      for (const Json* r : cores) {
        // Xilinx: slice LUTs (logic + distributed RAM + SRL); iCE40: LUT4; generic: not mapped.
        const std::string sliceLuts = text(*r, "slice_luts");
        const std::string luts = sliceLuts != "-" ? sliceLuts + " slice LUTs" : text(*r, "lut");
        std::string fmax = text(*r, "fmax_mhz");
        if (fmax != "-" && text(*r, "fmax_source") != "-") fmax += " (" + text(*r, "fmax_source") + ")";
        md << "| " << text(need(*r, "config", s.path)) << " | " << text(need(*r, "target", s.path)) << " | "
           << text(*r, "d") << " | " << text(*r, "max_width") << " | " << text(*r, "census") << " | " << luts << " | "
           << text(*r, "ff") << " | " << text(*r, "bram_kbit") << " | " << text(*r, "dsp") << " | " << fmax << " | "
           << toolVersion(text(*r, "yosys")) << " | " << text(*r, "date") << " |\n";
      }
      md << "\nSource: " << s.path
         << " (results[]: slice_luts or lut, ff, bram_kbit, dsp, fmax_mhz and fmax_source, yosys, date). "
            "Yosys figures are before place and route.\n\n";
    }
    if (!loops.empty()) {
      md << "| iCE40 loop harness | D | device | LUT4 | FF | fmax nextpnr (MHz) | fmax icetime (MHz) |\n"
            "|---|---:|---|---:|---:|---:|---:|\n";
      for (const Json* r : loops)
        md << "| " << text(*r, "config") << " | " << text(*r, "d") << " | " << text(*r, "device") << " | "
           << text(*r, "lut") << " | " << text(*r, "ff") << " | " << text(*r, "fmax_mhz") << " | "
           << text(*r, "fmax_icetime_mhz") << " |\n";
      md << "\nSource: " << s.path << " (results[] with target ice40-loop).\n\n";
    }
  }
}

void accuracySection(std::ostringstream& md, const Report& bench, const Report& eval, const Report& pool) {
  md << "## Accuracy\n\n";
  md << "### The core (RTL, verilated, every pixel compared with the golden model)\n\n";
  if (!bench.present()) {
    md << bench.notMeasured() << "\n\n";
  } else {
    const Json& accuracy = need(*bench.json, "accuracy", bench.path);
    md << "D = " << text(need(*bench.json, "d", bench.path))
       << ", error threshold delta = " << text(bench.json->get("delta")) << " px, invalid pixels counted as errors.\n\n"
       << "| scene | RTL nonocc (%) | RTL all (%) | bit-exact | golden nonocc (%) | goal (%) |\n"
          "|---|---:|---:|---|---:|---:|\n";
    for (const auto& [scene, a] : accuracy.members) {
      const Json& rtl = need(a, "rtl", bench.path);
      const Json* golden = a.get("golden");
      md << "| " << scene << " | **" << text(need(rtl, "err_nonocc", bench.path)) << "** | " << text(rtl, "err_all")
         << " | " << (need(a, "bit_exact", bench.path).boolean() ? "yes" : "NO (" + text(a, "mismatches") + " px)")
         << " | " << (golden ? text(*golden, "err_nonocc") : "-") << " | " << text(a, "goal") << " |\n";
    }
    md << "\nSource: " << bench.path << " (accuracy.<scene>: rtl.err_nonocc, rtl.err_all, bit_exact, "
       << "golden.err_nonocc, goal).\n\n";
    const Json* poolPart = bench.json->get("pool");
    if (poolPart && poolPart->isObject())
      if (const Json* rtl = poolPart->get("rtl"); rtl && rtl->isArray() && !rtl->items.empty()) {
        md << "| pool scene | size | D | bit-exact | cycles/pixel |\n|---|---|---:|---|---:|\n";
        for (const Json& r : rtl->items)
          md << "| " << text(r, "scene") << " | " << text(r, "width") << "x" << text(r, "height") << " | "
             << text(r, "disparities") << " | " << (need(r, "bit_exact", bench.path).boolean() ? "yes" : "NO") << " | "
             << text(r, "cycles_per_pixel") << " |\n";
        md << "\nSource: " << bench.path << " (pool.rtl[]).\n\n";
      }
  }
  md << "### The golden model (bit-exact with the core), Table I scenes\n\n";
  if (!eval.present()) {
    md << eval.notMeasured() << "\n\n";
  } else {
    const std::string key = text(need(*eval.json, "hardware_default", eval.path));
    const Json* method = nullptr;
    for (const Json& m : needArray(*eval.json, "methods", eval.path).items)
      if (text(m, "key") == key) method = &m;
    if (!method) throw Error(eval.path + ": no method with key '" + key + "' (hardware_default) (datasheet)");
    md << text(*method, "label") << " (key `" << key << "`), D = " << text(eval.json->get("disparities"))
       << ", delta = " << text(eval.json->get("delta")) << " px:\n\n"
       << "| scene | nonocc (%) | all (%) | disc (%) | density (%) |\n|---|---:|---:|---:|---:|\n";
    for (const auto& [scene, f] : need(*method, "results", eval.path).members) {
      if (f.isNull()) continue;
      md << "| " << scene << " | **" << text(f, "err_nonocc") << "** | " << text(f, "err_all") << " | "
         << text(f, "err_disc") << " | " << text(f, "density") << " |\n";
    }
    md << "\nSource: " << eval.path << " (methods[key = hardware_default].results).\n\n";
  }
  md << "### The golden model on the scene pool\n\n";
  if (!pool.present()) {
    md << pool.notMeasured() << "\n\n";
  } else {
    md << "Middlebury: bad-" << text(pool.json->get("delta"))
       << " over the non-occluded pixels; KITTI: D1; invalid = error.\n\n"
          "| mean over | scenes | ours (%) | OpenCV SGBM strict (%) |\n|---|---:|---:|---:|\n";
    for (const char* part : {"groups", "sets"}) {
      const Json* means = pool.json->get(part);
      if (!means || !means->isArray()) continue;
      for (const Json& m : means->items)
        md << "| " << text(m, "name") << " | " << text(m, "scenes") << " | **" << text(need(m, "ours", pool.path))
           << "** | " << text(m, "opencv_strict") << " |\n";
    }
    md << "\nSource: " << pool.path << " (groups[], sets[]: ours, opencv_strict).\n\n";
  }
}

// Cycles per pixel for one video format: the bench's own frame of that format when it
// simulated one, else the largest figure the bench measured, else pnr-summary's.
struct CyclesPerPixel {
  double value = 0;
  std::string source;
};

std::optional<CyclesPerPixel> cyclesPerPixel(const VideoFormat& f, const Report& bench, const Report& pnr) {
  if (bench.present()) {
    std::optional<CyclesPerPixel> largest;
    for (const char* part : {"formats", "core"}) {
      const Json* list = bench.json->get(part);
      if (!list || !list->isArray()) continue;
      for (const Json& e : list->items) {
        const std::optional<double> cpp = number(e, "cycles_per_pixel");
        if (!cpp) continue;
        if (std::string(part) == "formats" && text(e, "width") == std::to_string(f.width) &&
            text(e, "height") == std::to_string(f.height))
          return CyclesPerPixel{*cpp, bench.path + " formats[" + text(e, "format") + "]"};
        if (!largest || *cpp > largest->value)
          largest = CyclesPerPixel{*cpp, bench.path + " " + part + "[" +
                                             text(e, std::string(part) == "formats" ? "format" : "scene") +
                                             "], the largest measured"};
      }
    }
    if (largest) return largest;
  }
  if (pnr.present())
    if (const std::optional<double> cpp = number(*pnr.json, "cycles_per_pixel"))
      return CyclesPerPixel{
          *cpp, pnr.path + " cycles_per_pixel (from " + text(pnr.json->get("cycles_per_pixel_source")) + ")"};
  return std::nullopt;
}

void videoSection(std::ostringstream& md, const Report& pnr, const Report& bench) {
  md << "## Video formats each build carries\n\n";
  if (!pnr.present()) {
    md << pnr.notMeasured() << " (the routed fmax of each build)\n\n";
    return;
  }
  const Json& runs = needArray(*pnr.json, "runs", pnr.path);
  if (runs.items.empty()) {
    md << "No routed build in " << pnr.path << ": run `make pnr`.\n\n";
    return;
  }
  if (!bench.present())
    md << "Cycles per pixel: " << bench.notMeasured() << "; the figure pnr-summary used instead.\n\n";
  md << "A build carries a format when its routed fmax reaches the clock the format needs (active pixels per second x "
        "cycles per pixel) and the frame is no wider than its MAX_WIDTH.\n\n| format | cycles/pixel | needed (MHz) |";
  for (const Json& r : runs.items)
    md << " " << text(r, "run") << " (" << text(need(r, "fmax_mhz", pnr.path)) << " MHz, MAX_WIDTH "
       << text(r, "max_width") << ") |";
  md << "\n|---|---:|---:|";
  for (size_t i = 0; i < runs.items.size(); ++i) md << "---|";
  md << "\n";
  std::vector<std::string> sources;
  for (const VideoFormat& f : kVideoFormats) {
    const std::optional<CyclesPerPixel> cpp = cyclesPerPixel(f, bench, pnr);
    if (!cpp) {
      md << "| " << f.name << " | not measured: run `make bench` | |";
      for (size_t i = 0; i < runs.items.size(); ++i) md << " |";
      md << "\n";
      continue;
    }
    if (std::find(sources.begin(), sources.end(), cpp->source) == sources.end()) sources.push_back(cpp->source);
    const double needed = neededMhz(f, cpp->value);
    md << "| " << f.name << " | " << fixed(cpp->value, 4) << " | " << fixed(needed, 1) << " |";
    for (const Json& r : runs.items) {
      const std::optional<double> fmax = number(r, "fmax_mhz"), width = number(r, "max_width");
      const bool clock = fmax && *fmax >= needed, wide = width && f.width > *width;
      md << " " << (clock && !wide ? "**yes**" : "no") << (clock ? "" : " (clock)") << (wide ? " (width)" : "") << " |";
    }
    md << "\n";
  }
  md << "\nSource: fmax_mhz and max_width from " << pnr.path << " (runs[]); cycles per pixel from ";
  for (size_t i = 0; i < sources.size(); ++i) md << (i ? "; " : "") << sources[i];
  md << ". The formats: tools/video_formats.hpp.\n\n";
}

// The reference builds (scripts/refs.mk): the ECP5 ones routed (pnr summary's refs[], the
// median of their seeds), the xc7 ones as Yosys estimates (synth summaries' results[] with a
// ref) with the smallest part that holds them.
void refsSection(std::ostringstream& md, const Report& pnr, const std::vector<Report>& synth) {
  md << "## Reference builds\n\n"
     << "The configurations scripts/refs.mk names (`make refs`). Each is also a whole-core test build "
        "(`rtl-ref-<name>` in `make rtl-tests`), bit-exact against the golden model. ECP5: placed and routed by "
        "`make pnr-ref`; fmax is the median of the seeds' (each seed's beside it), the rest the median run's. "
        "Xilinx 7-series: Yosys' estimate before place and route (`make synth-ref`).\n\n";
  const Json* refs = pnr.present() ? pnr.json->get("refs") : nullptr;
  if (!refs || !refs->isArray() || refs->items.empty()) {
    md << "ECP5: not measured: run `make pnr-ref` (no refs[] in " << pnr.path << ").\n\n";
  } else {
    md << "| build | device | speed | D | MAX_WIDTH | lanes | fifth path (block) | LUT4 | FF | EBR | DSP | fmax, median "
          "(MHz) | seeds: fmax (MHz) | critical path through | formats carried |\n"
          "|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|---|---|\n";
    for (const Json& r : refs->items) {
      std::string seeds, met, through;
      for (const Json& sd : needArray(r, "seeds", pnr.path).items)
        seeds += (seeds.empty() ? "" : ", ") + text(sd, "seed") + ": " + text(need(sd, "fmax_mhz", pnr.path));
      for (const Json& f : needArray(r, "formats", pnr.path).items)
        if (need(f, "clock_met", pnr.path).boolean() && need(f, "width_fits", pnr.path).boolean())
          met += (met.empty() ? "" : ", ") + text(f, "format");
      if (const Json* cp = r.get("critical_path"))
        if (const Json* mods = cp->get("modules"); mods && mods->isArray())
          for (const Json& m : mods->items) through += (through.empty() ? "" : " > ") + text(m);
      const std::string block = text(r, "right_block");
      md << "| " << text(need(r, "ref", pnr.path)) << " | " << text(r, "device") << "-" << text(r, "package") << " | "
         << text(r, "speed") << " | " << text(r, "d") << " | " << text(r, "max_width") << " | " << text(r, "lanes")
         << " | " << (block == "0" ? std::string("none") : block) << " | " << text(r, "lut4") << " / "
         << text(r, "lut4_available") << " | " << text(r, "ff") << " | " << text(r, "ebr") << " / "
         << text(r, "ebr_available") << " | " << text(r, "dsp") << " | **" << text(need(r, "fmax_median_mhz", pnr.path))
         << "** | " << seeds << " | " << (through.empty() ? "-" : through) << " | " << (met.empty() ? "none" : met)
         << " |\n";
    }
    md << "\nSource: " << pnr.path
       << " (refs[]: fmax_median_mhz, seeds[], lut4, ff, ebr, dsp, critical_path.modules, formats[] with clock_met "
          "and width_fits).\n\n";
  }
  std::string rows, sources;
  for (const Report& s : synth) {
    bool fromThis = false;
    for (const Json& r : needArray(*s.json, "results", s.path).items) {
      const Json* ref = r.get("ref");
      if (!ref || !ref->isString()) continue;
      fromThis = true;
      const Json* part = r.get("smallest_part");
      rows += "| " + text(*ref) + " | " + text(r, "target") + " | " + text(r, "d") + " | " + text(r, "max_width") +
              " | " + text(r, "slice_luts") + " | " + text(r, "ff") + " | " + text(r, "bram36") + " + " +
              text(r, "bram18") + " | " + text(r, "dsp") + " | " +
              (part && part->isObject()
                   ? text(*part, "name") + " (" + text(*part, "luts") + ", " + text(*part, "bram36") + ")"
                   : std::string("none of tools/xc7_parts.hpp")) +
              " |\n";
    }
    if (fromThis) sources += (sources.empty() ? "" : ", ") + s.path;
  }
  if (rows.empty()) {
    md << "Xilinx 7-series: not measured: run `make synth-ref`.\n\n";
    return;
  }
  md << "| build | target | D | MAX_WIDTH | slice LUTs | FF | RAMB36 + RAMB18 | DSP | smallest part (LUTs, RAMB36) "
        "|\n|---|---|---:|---:|---:|---:|---:|---:|---|\n"
     << rows << "\nSource: " << sources
     << " (results[] with a ref: slice_luts, ff, bram36, bram18, dsp, smallest_part).\n\n";
}

// The README's short table: the core's accuracy per scene beside the paper and OpenCV,
// with its cycles per pixel (bench), the pool means (eval-pool) and each routed build (pnr).
void summaryTables(std::ostringstream& md, const Report& bench, const Report& pool, const Report& pnr) {
  if (!bench.present()) {
    md << "Accuracy: " << bench.notMeasured() << ".\n\n";
  } else {
    std::map<std::string, std::string> cycles;
    if (const Json* core = bench.json->get("core"); core && core->isArray())
      for (const Json& c : core->items) cycles[text(c, "scene")] = text(c, "cycles_per_pixel");
    const std::optional<double> delta = number(*bench.json, "delta");
    md << "Bad-" << (delta ? fixed(*delta, 1) : "-")
       << " error (%) over the non-occluded pixels, invalid pixels counted as "
       << "errors, D = " << text(need(*bench.json, "d", bench.path))
       << ", the default configuration; the core's output "
       << "is compared with the golden model on every pixel.\n\n"
       << "| scene | this core (RTL) | bit-exact | paper, Table I | OpenCV StereoSGBM | cycles / pixel |\n"
          "|---|---:|---|---:|---:|---:|\n";
    for (const auto& [scene, a] : need(*bench.json, "accuracy", bench.path).members) {
      const Json* opencv = a.get("opencv-sgbm");
      md << "| " << scene << " | **" << text(need(need(a, "rtl", bench.path), "err_nonocc", bench.path)) << "** | "
         << (need(a, "bit_exact", bench.path).boolean() ? "yes" : "NO") << " | " << text(a, "paper_rank_sad") << " | "
         << (opencv ? text(*opencv, "err_nonocc") : "-") << " | " << (cycles.count(scene) ? cycles[scene] : "-")
         << " |\n";
    }
    md << "\nSource: " << bench.path << " (`make bench`).\n\n";
  }
  if (!pool.present()) {
    md << "Scene pool: " << pool.notMeasured() << ".\n\n";
  } else {
    md << "| scene pool, mean over | scenes | this core (%) | OpenCV StereoSGBM (%) |\n|---|---:|---:|---:|\n";
    if (const Json* means = pool.json->get("groups"); means && means->isArray())
      for (const Json& m : means->items)
        md << "| " << text(m, "name") << " | " << text(m, "scenes") << " | **" << text(need(m, "ours", pool.path))
           << "** | " << text(m, "opencv_strict") << " |\n";
    const std::optional<double> delta = number(*pool.json, "delta");
    md << "\nSource: " << pool.path << " (`make eval-pool`, groups[]; Middlebury bad-"
       << (delta ? fixed(*delta, 1) : "-") << ", KITTI D1; OpenCV with its invalid pixels counted as errors).\n\n";
  }
  const Json* runs = pnr.present() ? pnr.json->get("runs") : nullptr;
  const Json* refs = pnr.present() ? pnr.json->get("refs") : nullptr;
  if (refs && refs->isArray() && !refs->items.empty()) {
    // The reference builds (scripts/refs.mk) when routed: the median of their seeds.
    md << "| reference build | device | D | MAX_WIDTH | lanes | LUT4 | FF | EBR | fmax, median of seeds (MHz) |\n"
          "|---|---|---:|---:|---:|---:|---:|---:|---:|\n";
    for (const Json& r : refs->items)
      md << "| " << text(need(r, "ref", pnr.path)) << " | " << text(r, "device") << "-" << text(r, "speed") << " | "
         << text(r, "d") << " | " << text(r, "max_width") << " | " << text(r, "lanes") << " | " << text(r, "lut4")
         << " | " << text(r, "ff") << " | " << text(r, "ebr") << " | **" << text(need(r, "fmax_median_mhz", pnr.path))
         << "** |\n";
    md << "\nSource: " << pnr.path << " (`make pnr-ref`, refs[]).\n\n";
  } else if (!runs || !runs->isArray() || runs->items.empty()) {
    md << "Routed builds: " << pnr.notMeasured() << ".\n\n";
  } else {
    md << "| routed build | LUT4 | FF | EBR | fmax (MHz) |\n|---|---:|---:|---:|---:|\n";
    for (const Json& r : runs->items)
      md << "| " << text(r, "run") << " | " << text(r, "lut4") << " | " << text(r, "ff") << " | " << text(r, "ebr")
         << " | **" << text(need(r, "fmax_mhz", pnr.path)) << "** |\n";
    md << "\nSource: " << pnr.path << " (`make pnr`).\n\n";
  }
}

}  // namespace

std::string datasheetMarkdown(const std::string& buildDir) {
  const std::string synthRoot = buildDir + "/synth";
  std::vector<Report> synth;
  for (const std::string& path : synthSummaries(synthRoot)) {
    Report r = loadReport(path, "synth");
    if (r.json->get("results")) synth.push_back(std::move(r));  // levers/right-path tables have no results
  }
  const Report pnr = loadReport(buildDir + "/pnr/summary.json", "pnr");
  const Report bench = loadReport(buildDir + "/bench/report.json", "bench");
  const Report eval = loadReport(buildDir + "/eval/report.json", "eval");
  const Report pool = loadReport(buildDir + "/eval/pool.json", "eval-pool");

  std::ostringstream md;
  md << "# sgm-core datasheet\n\n"
     << "Written by `make datasheet` (sgm-eval datasheet) from the measured reports under " << buildDir
     << "/ and nothing else: every figure below is copied from the JSON report named under its table. Do not edit by "
        "hand; run the measurements and `make datasheet` again.\n\n";
  sourcesSection(md, synth, synthRoot, {&pnr, &bench, &eval, &pool});
  refsSection(md, pnr, synth);
  pnrSection(md, pnr);
  videoSection(md, pnr, bench);
  synthSection(md, synth, synthRoot);
  accuracySection(md, bench, eval, pool);
  return md.str();
}

std::string summaryMarkdown(const std::string& buildDir) {
  std::ostringstream md;
  summaryTables(md, loadReport(buildDir + "/bench/report.json", "bench"),
                loadReport(buildDir + "/eval/pool.json", "eval-pool"),
                loadReport(buildDir + "/pnr/summary.json", "pnr"));
  return md.str();
}

std::string replaceGeneratedSection(const std::string& page, const std::string& name, const std::string& body,
                                    const std::string& file) {
  const std::string begin = "<!-- BEGIN " + name + " (generated by make datasheet; do not edit) -->\n";
  const std::string end = "<!-- END " + name + " -->";
  const size_t b = page.find(begin);
  const size_t e = b == std::string::npos ? b : page.find(end, b + begin.size());
  if (b == std::string::npos || e == std::string::npos || page.find(begin, b + 1) != std::string::npos)
    throw Error(file + ": needs exactly one section '" + begin.substr(0, begin.size() - 1) + "' ... '" + end + "'");
  return page.substr(0, b + begin.size()) + body + page.substr(e);
}

}  // namespace sgm::eval
