// SPDX-License-Identifier: Apache-2.0
// regmap_gen: writes the generated copies of the register map from its one description,
// regmap/sgm_regmap.def (`make regmap`; `make regmap-check` compares them):
//
//   --header FILE       the C header (sw/include/sgm_regs.h)
//   --svh FILE          the SystemVerilog localparams included by sgm_axi (rtl/sgm_regmap.svh)
//   --cfg-svh FILE      the frame configuration word (rtl/sgm_cfg.svh): its layout and checks
//   --tb FILE           the testbenches' table of the word (tb/sgm_cfg_fields.hpp)
//   --doc IN OUT        IN with its generated sections (between the markers
//                       "<!-- BEGIN regmap: NAME -->" and "<!-- END regmap: NAME -->")
//                       replaced, written to OUT (docs/registers.md)
//
// Every file is written whole or not at all; a malformed description (overlapping fields,
// a field beyond bit 31, a default outside its field, two registers at one offset, a
// CFG_FIELD that is no read-write field, a read-write field of a frame configuration
// register without its CFG_FIELD) stops the generator with one line naming it and exit
// status 2.
#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace {

enum class Access { kRO, kRW, kW1C, kW1P, kWC };

struct Field {
  std::string reg, name;
  int lsb, width;
  Access access;
  uint64_t defaultValue, fourPathValue, minValue, maxValue;
  std::string needs, svValue, description;
  uint32_t mask() const { return uint32_t(((uint64_t(1) << width) - 1) << lsb); }
};

struct Value {
  std::string reg, field, name;
  uint64_t value;
  std::string description;
};

struct Register {
  std::string name;
  uint32_t offset;
  std::string resetText, summary;
  std::vector<Field> fields;
  std::vector<Value> values;
};

// A field of the frame configuration word (CFG_FIELD).
struct CfgRow {
  std::string reg, field, golden;
};

// A field of the word, resolved: its register, its field and its position in the word.
struct WordField {
  const Register* reg;
  const Field* field;
  std::string golden;
  int lsb;
  std::string name() const { return reg->name + "_" + field->name; }
};

struct Constant {
  std::string name;
  uint64_t value;
  std::string description;
};

std::vector<Register> registers;
std::vector<Constant> constants;
std::vector<CfgRow> cfgRows;
std::vector<WordField> word;  // the frame configuration word, bit 0 first (layoutWord)
int wordWidth = 0;

void die(const std::string& what) {
  std::cerr << "regmap_gen: error: " << what << "\n";
  std::exit(2);
}

Register& registerNamed(const std::string& name) {
  for (Register& r : registers)
    if (r.name == name) return r;
  die("a field of the undeclared register " + name);
  return registers.front();
}

#define RO Access::kRO
#define RW Access::kRW
#define W1C Access::kW1C
#define W1P Access::kW1P
#define WC Access::kWC
#define REGISTER(NAME, OFFSET, RESET, SUMMARY) registers.push_back(Register{#NAME, OFFSET, RESET, SUMMARY, {}, {}});
#define FIELD(REG, NAME, LSB, WIDTH, ACCESS, DEF, FOUR, MIN, MAX, NEEDS, SV, DESC) \
  registerNamed(#REG).fields.push_back(Field{#REG, #NAME, LSB, WIDTH, ACCESS, DEF, FOUR, MIN, MAX, NEEDS, SV, DESC});
#define VALUE(REG, FIELD, NAME, VAL, DESC) registerNamed(#REG).values.push_back(Value{#REG, #FIELD, #NAME, VAL, DESC});
#define CONSTANT(NAME, VAL, DESC) constants.push_back(Constant{#NAME, VAL, DESC});
#define CFG_FIELD(REG, FIELD, GOLDEN) cfgRows.push_back(CfgRow{#REG, #FIELD, GOLDEN});

void describe() {
#include "sgm_regmap.def"
}

#undef RO
#undef RW
#undef W1C
#undef W1P
#undef WC

const char* accessName(Access a) {
  switch (a) {
    case Access::kRO: return "RO";
    case Access::kRW: return "RW";
    case Access::kW1C: return "W1C";
    case Access::kW1P: return "W1P";
    case Access::kWC: return "WC";
  }
  return "?";
}

std::string hex32(uint64_t v) {
  char b[16];
  std::snprintf(b, sizeof b, "0x%08llXu", static_cast<unsigned long long>(v));
  return b;
}

std::string hexPlain(uint64_t v, int digits) {
  char b[24];
  std::snprintf(b, sizeof b, "0x%0*llX", digits, static_cast<unsigned long long>(v));
  return b;
}

// The value a register resets to, made from its fields' defaults (four-path or full).
uint32_t resetValue(const Register& r, bool fourPath) {
  uint32_t v = 0;
  for (const Field& f : r.fields)
    if (f.svValue.empty()) v |= uint32_t((fourPath ? f.fourPathValue : f.defaultValue) << f.lsb) & f.mask();
  return v;
}

// The value of a register whose fields are all constants (ID): every field's default.
uint32_t constantValue(const Register& r) {
  uint32_t v = 0;
  for (const Field& f : r.fields) v |= uint32_t(f.defaultValue << f.lsb) & f.mask();
  return v;
}

// The bits that read back (every field but the write-1 pulses).
uint32_t readMask(const Register& r) {
  uint32_t m = 0;
  for (const Field& f : r.fields)
    if (f.access != Access::kW1P) m |= f.mask();
  return m;
}

// A register whose every field is a build value (its value is a constant of the build).
bool isBuildConstant(const Register& r) {
  for (const Field& f : r.fields)
    if (f.svValue.empty()) return false;
  return !r.fields.empty();
}

// A register with writable fields that have defaults (the configuration).
bool isConfiguration(const Register& r) {
  for (const Field& f : r.fields)
    if (f.access == Access::kRW && (f.defaultValue || f.fourPathValue)) return true;
  return false;
}

void check() {
  std::set<uint32_t> offsets;
  std::set<std::string> names;
  for (const Register& r : registers) {
    if (r.offset % 4) die("register " + r.name + ": offset not a multiple of 4");
    if (!offsets.insert(r.offset).second) die("register " + r.name + ": its offset is another register's");
    if (!names.insert(r.name).second) die("register " + r.name + " described twice");
    if (r.fields.empty()) die("register " + r.name + " has no field");
    uint32_t used = 0;
    for (const Field& f : r.fields) {
      const std::string where = r.name + "." + f.name;
      if (f.width < 1 || f.lsb < 0 || f.lsb + f.width > 32) die(where + ": bits beyond 31");
      if (used & f.mask()) die(where + ": overlaps another field");
      used |= f.mask();
      const uint64_t top = (uint64_t(1) << f.width) - 1;
      if (f.defaultValue > top || f.fourPathValue > top) die(where + ": a default does not fit the field");
      if (f.minValue > f.maxValue || f.maxValue > top) die(where + ": legal range outside the field");
      if (isConfiguration(r) && f.access == Access::kRW &&
          (f.defaultValue < f.minValue || f.defaultValue > f.maxValue) && !(f.defaultValue == 0 && !f.needs.empty()))
        die(where + ": default outside the legal range");
    }
    for (const Value& v : r.values) {
      bool found = false;
      for (const Field& f : r.fields)
        if (f.name == v.field) found = v.value <= (uint64_t(1) << f.width) - 1;
      if (!found) die(r.name + "." + v.field + "." + v.name + ": no such field, or the value does not fit");
    }
  }
}

// The frame configuration word: every CFG_FIELD at its register width, in register order
// (offset, then LSB), from bit 0 up. Run after the registers are sorted by offset.
void layoutWord() {
  std::set<std::string> named;
  for (const CfgRow& c : cfgRows) {
    const std::string where = "CFG_FIELD(" + c.reg + ", " + c.field + ")";
    if (!named.insert(c.reg + "." + c.field).second) die(where + " described twice");
    bool found = false;
    for (const Register& r : registers)
      for (const Field& f : r.fields)
        if (r.name == c.reg && f.name == c.field) {
          found = true;
          if (f.access != Access::kRW) die(where + ": the field is not read-write");
        }
    if (!found) die(where + ": no such field");
    if (c.golden.empty()) die(where + ": no golden value");
  }
  for (const Register& r : registers) {
    bool inWord = false;
    for (const CfgRow& c : cfgRows) inWord = inWord || c.reg == r.name;
    if (!inWord) continue;
    std::vector<const Field*> byLsb;
    for (const Field& f : r.fields) byLsb.push_back(&f);
    std::sort(byLsb.begin(), byLsb.end(), [](const Field* a, const Field* b) { return a->lsb < b->lsb; });
    for (const Field* f : byLsb) {
      if (f->access != Access::kRW) continue;
      const CfgRow* row = nullptr;
      for (const CfgRow& c : cfgRows)
        if (c.reg == r.name && c.field == f->name) row = &c;
      if (!row)
        die(r.name + "." + f->name + ": a read-write field of a frame configuration register without its CFG_FIELD");
      word.push_back(WordField{&r, f, row->golden, wordWidth});
      wordWidth += f->width;
    }
  }
}

// The build parameters the word's fields need (NEEDS), in the order of the word.
std::vector<std::string> wordNeeds() {
  std::vector<std::string> needs;
  for (const WordField& w : word)
    if (!w.field->needs.empty() && std::find(needs.begin(), needs.end(), w.field->needs) == needs.end())
      needs.push_back(w.field->needs);
  return needs;
}

std::string lower(std::string s) {
  for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// The registers of the word, in its order.
std::vector<const Register*> wordRegisters() {
  std::vector<const Register*> regs;
  for (const WordField& w : word)
    if (regs.empty() || regs.back() != w.reg) regs.push_back(w.reg);
  return regs;
}

std::string bitRange(int lsb, int width) {
  return "[" + std::to_string(lsb + width - 1) + (width > 1 ? ":" + std::to_string(lsb) : "") + "]";
}

const char* kNotice = "generated by `make regmap` from regmap/sgm_regmap.def: do not edit";

// ------------------------------------------------------------------ C header
std::string cHeader() {
  std::ostringstream o;
  o << "/* SPDX-License-Identifier: Apache-2.0 */\n"
    << "/* sgm_regs.h: the register map of sgm_axi (rtl/sgm_axi.sv), " << kNotice << ".\n"
    << " *\n"
    << " * All registers are 32 bits wide, at byte offsets from the slave's base. Bits not\n"
    << " * named here are reserved: they read 0 and ignore writes. Undefined offsets answer\n"
    << " * SLVERR (reads return 0, writes are ignored). docs/registers.md is the prose.\n"
    << " *\n"
    << " * For each field F of register R: SGM_R_F_SHIFT, SGM_R_F_WIDTH, SGM_R_F_MASK (in place),\n"
    << " * SGM_R_F (a one-bit field's bit), SGM_R_F_MIN / _MAX (the legal range), and for the\n"
    << " * configuration SGM_R_F_DEFAULT (a build with every lever) and SGM_R_F_FOUR_PATH (any\n"
    << " * other build). For each register: SGM_REG_R (offset), SGM_R_MASK (the bits that read\n"
    << " * back), SGM_R_RESET and SGM_R_RESET_FOUR_PATH (configuration). SGM_GET / SGM_PUT read\n"
    << " * and place a field: SGM_GET(value, PENALTY_P1), SGM_PUT(PENALTY_P1, 24).\n"
    << " * Plain C (C89 and C++, 32-bit unsigned int); no dependency. */\n"
    << "#ifndef SGM_REGS_H\n#define SGM_REGS_H\n\n"
    << "#define SGM_GET(value, FIELD) (((value) & SGM_##FIELD##_MASK) >> SGM_##FIELD##_SHIFT)\n"
    << "#define SGM_PUT(FIELD, x) ((((unsigned)(x)) << SGM_##FIELD##_SHIFT) & SGM_##FIELD##_MASK)\n\n"
    << "/* ---- offsets */\n";
  for (const Register& r : registers) {
    char b[160];
    std::snprintf(b, sizeof b, "#define SGM_REG_%-18s 0x%02Xu", r.name.c_str(), r.offset);
    o << b << "\n";
  }
  for (const Register& r : registers) {
    o << "\n/* ---- " << r.name << " (0x" << hexPlain(r.offset, 2).substr(2) << "): " << r.summary << " */\n";
    for (const Field& f : r.fields) {
      const std::string p = "SGM_" + r.name + "_" + f.name;
      o << "/* " << f.name << " [" << f.lsb + f.width - 1;
      if (f.width > 1) o << ":" << f.lsb;
      o << "] " << accessName(f.access) << ": " << f.description << " */\n";
      o << "#define " << p << "_SHIFT " << f.lsb << "\n";
      o << "#define " << p << "_WIDTH " << f.width << "\n";
      o << "#define " << p << "_MASK " << hex32(f.mask()) << "\n";
      if (f.width == 1) o << "#define " << p << " (1u << " << f.lsb << ")\n";
      if (f.access == Access::kRW || f.access == Access::kRO) {
        o << "#define " << p << "_MIN " << f.minValue << "u\n";
        o << "#define " << p << "_MAX " << f.maxValue << "u\n";
      }
      if (isConfiguration(r)) {
        o << "#define " << p << "_DEFAULT " << f.defaultValue << "u\n";
        o << "#define " << p << "_FOUR_PATH " << f.fourPathValue << "u\n";
      }
      for (const Value& v : r.values)
        if (v.field == f.name)
          o << "#define " << p << "_" << v.name << " " << v.value << "u /* " << v.description << " */\n";
    }
    o << "#define SGM_" << r.name << "_MASK " << hex32(readMask(r)) << "\n";
    if (isConfiguration(r)) {
      o << "#define SGM_" << r.name << "_RESET " << hex32(resetValue(r, false)) << "\n";
      o << "#define SGM_" << r.name << "_RESET_FOUR_PATH " << hex32(resetValue(r, true)) << "\n";
    } else if (r.name == "ID") {
      o << "#define SGM_ID_VALUE " << hex32(constantValue(r)) << "\n";
    }
  }
  o << "\n/* ---- the frame configuration word: sgm_top's cfg_i (rtl/sgm_cfg.svh), SGM_CFG_W bits, bit 0\n"
    << " * first; field F of register R at bits [SGM_CFG_R_F_LSB +: SGM_R_F_WIDTH] (docs/registers.md). */\n";
  o << "#define SGM_CFG_W " << wordWidth << "u\n";
  o << "#define SGM_CFG_WORDS " << (wordWidth + 31) / 32 << "u /* 32-bit words of the word */\n";
  for (const WordField& w : word) o << "#define SGM_CFG_" << w.name() << "_LSB " << w.lsb << "u\n";
  o << "\n/* ---- constants */\n";
  for (const Constant& c : constants)
    o << "#define SGM_" << c.name << " " << c.value << "u /* " << c.description << " */\n";
  o << "\n#endif /* SGM_REGS_H */\n";
  return o.str();
}

// ------------------------------------------------------------------ SystemVerilog
std::string svHeader() {
  std::ostringstream o;
  o << "// SPDX-License-Identifier: Apache-2.0\n"
    << "// sgm_regmap.svh: the register map of sgm_axi, " << kNotice << ".\n"
    << "// Included in the body of sgm_axi, after ADDR_W and FULL_DEFAULTS (the build has every\n"
    << "// lever: its registers reset to the golden model's defaults, else to the four-path preset).\n"
    << "// For each field F of register R: R_F_LSB and R_F_W; for each register: ADDR_R (byte\n"
    << "// offset), R_MASK (the bits that read back), R_RESET (configuration) or R_VALUE (a\n"
    << "// constant of the build); reg_defined(a) tells whether a word address is a register;\n"
    << "// cfg_from_regs packs the frame configuration word (rtl/sgm_cfg.svh) from the registers.\n"
    << "`ifndef SGM_REGMAP_SVH\n`define SGM_REGMAP_SVH\n\n";
  for (const Register& r : registers) {
    char b[200];
    std::snprintf(b, sizeof b, "localparam logic [ADDR_W-1:0] ADDR_%-12s /*verilator public*/ = ADDR_W'('h%02X);",
                  r.name.c_str(), r.offset);
    o << b << "\n";
  }
  o << "\n";
  for (const Register& r : registers) {
    for (const Field& f : r.fields) {
      o << "localparam int " << r.name << "_" << f.name << "_LSB /*verilator public*/ = " << f.lsb << ";\n";
      o << "localparam int " << r.name << "_" << f.name << "_W = " << f.width << ";\n";
    }
    o << "localparam logic [31:0] " << r.name << "_MASK = 32'h" << hexPlain(readMask(r), 8).substr(2) << ";\n";
    if (isConfiguration(r)) {
      o << "localparam logic [31:0] " << r.name << "_RESET /*verilator public*/ = FULL_DEFAULTS ? 32'h"
        << hexPlain(resetValue(r, false), 8).substr(2) << " : 32'h" << hexPlain(resetValue(r, true), 8).substr(2)
        << ";\n";
    }
    if (isBuildConstant(r)) {
      // {reserved zeros, the highest field, ..., the lowest}
      std::vector<const Field*> byLsb;
      for (const Field& f : r.fields) byLsb.push_back(&f);
      std::sort(byLsb.begin(), byLsb.end(), [](const Field* a, const Field* b) { return a->lsb > b->lsb; });
      std::ostringstream cat;
      int bit = 32;
      bool first = true;
      for (const Field* f : byLsb) {
        const int gap = bit - (f->lsb + f->width);
        if (gap > 0) cat << (first ? "" : ", ") << gap << "'d0", first = false;
        cat << (first ? "" : ", ") << f->svValue, first = false;
        bit = f->lsb;
      }
      if (bit > 0) cat << ", " << bit << "'d0";
      const std::string value = byLsb.size() == 1 && byLsb[0]->width == 32 ? byLsb[0]->svValue : "{" + cat.str() + "}";
      o << "localparam logic [31:0] " << r.name << "_VALUE /*verilator public*/ = " << value << ";\n";
    }
  }
  o << "\n";
  for (const Constant& c : constants)
    o << "localparam int " << c.name << " = " << c.value << ";  // " << c.description << "\n";
  if (!word.empty()) {
    // cfg_from_regs: the frame configuration word of the registers' values.
    std::string args;
    for (const Register* r : wordRegisters())
      args += std::string(args.empty() ? "" : ",\n") + "    input logic [31:0] reg_" + lower(r->name);
    o << "\n// The frame configuration word (rtl/sgm_cfg.svh, included before the module) of the\n"
      << "// registers' values: each field at its place, the highest first.\n"
      << "function automatic logic [CFG_W-1:0] cfg_from_regs(\n"
      << args << ");\n  cfg_from_regs = {\n";
    for (size_t i = word.size(); i-- > 0;) {
      const WordField& w = word[i];
      std::string term = "    reg_" + lower(w.reg->name) + bitRange(w.field->lsb, w.field->width) + (i ? "," : "");
      char b[200];
      std::snprintf(b, sizeof b, "%-32s // %s, word %s", term.c_str(), (w.reg->name + "." + w.field->name).c_str(),
                    bitRange(w.lsb, w.field->width).c_str());
      o << b << "\n";
    }
    o << "  };\nendfunction\n";
  }
  // An OR of comparisons, not a case: Yosys 0.70 (proc_rom) turns a case of many constant
  // items into a ROM, whose contents a k-induction leaves free.
  o << "\nfunction automatic logic reg_defined(input logic [ADDR_W-1:0] a);\n  reg_defined =";
  for (size_t i = 0; i < registers.size(); ++i)
    o << (i == 0 ? " " : i % 4 == 0 ? "\n      || " : " || ") << "a == ADDR_" << registers[i].name;
  o << ";\nendfunction\n\n`endif  // SGM_REGMAP_SVH\n";
  return o.str();
}

// ------------------------------------------------------------------ the word, SystemVerilog
std::string svCfg() {
  std::ostringstream o;
  o << "// SPDX-License-Identifier: Apache-2.0\n"
    << "// sgm_cfg.svh: the frame configuration word, " << kNotice << ".\n"
    << "//\n"
    << "// One packed word carries a frame's run-time configuration: sgm_top's cfg_i (sgm_axi packs it\n"
    << "// from its registers, cfg_from_regs of rtl/sgm_regmap.svh), checked and kept per pending frame\n"
    << "// by sgm_stream_ctrl, latched at the frame's start (its cfg_o) and sliced by sgm_top for the\n"
    << "// stages. Field F of register R is bits [CFG_R_F_LSB +: CFG_R_F_W] of the word, at its\n"
    << "// register width, legal from CFG_R_F_MIN to CFG_R_F_MAX:\n"
    << "//\n";
  for (const WordField& w : word) {
    char b[200];
    const std::string field = w.reg->name + "." + w.field->name;
    const std::string regBits = w.reg->name + bitRange(w.field->lsb, w.field->width);
    std::snprintf(b, sizeof b, "//   %-10s %-26s %s", bitRange(w.lsb, w.field->width).c_str(), field.c_str(),
                  regBits.c_str());
    o << b << "\n";
  }
  const std::vector<std::string> needs = wordNeeds();
  o << "//\n"
    << "// Declarations of the compilation unit, guarded: every file that reads the word includes\n"
    << "// this file at its top, before its module (the ports use CFG_W). Localparams and functions\n"
    << "// only, which Verilator 5.006, Yosys 0.23 and Icarus 11 all take (no package, no struct).\n"
    << "`ifndef SGM_CFG_SVH\n`define SGM_CFG_SVH\n\n"
    << "localparam int CFG_W = " << wordWidth << ";  // bits of the word\n";
  for (const WordField& w : word) {
    const std::string p = "CFG_" + w.name();
    o << "\nlocalparam int " << p << "_LSB = " << w.lsb << ";\n";
    o << "localparam int " << p << "_W = " << w.field->width << ";\n";
    o << "localparam int " << p << "_MIN = " << w.field->minValue << ";\n";
    o << "localparam int " << p << "_MAX = " << w.field->maxValue << ";\n";
  }
  // The words of the two presets (frame size 0): each field's DEFAULT or FOUR_PATH.
  for (const bool fourPath : {false, true}) {
    std::vector<int> bitsOf(size_t(wordWidth), 0);
    for (const WordField& w : word) {
      const uint64_t v = fourPath ? w.field->fourPathValue : w.field->defaultValue;
      for (int b = 0; b < w.field->width; ++b) bitsOf[size_t(w.lsb + b)] = int(v >> b & 1);
    }
    std::string hex;
    for (int d = (wordWidth + 3) / 4 - 1; d >= 0; --d) {
      int digit = 0;
      for (int b = 0; b < 4; ++b)
        if (4 * d + b < wordWidth) digit |= bitsOf[size_t(4 * d + b)] << b;
      hex += "0123456789ABCDEF"[digit];
    }
    if (!fourPath)
      o << "\n// The word of the golden model's defaults (every field's DEFAULT: what a build with every\n"
        << "// lever runs, sgm::Params{}) and of the four-path preset (FOUR_PATH: any other build), each\n"
        << "// with the frame size 0: set FRAME_SIZE's fields to use one (docs/integration.md).\n";
    o << "localparam logic [CFG_W-1:0] CFG_" << (fourPath ? "FOUR_PATH" : "DEFAULT") << " = " << wordWidth << "'h"
      << hex << ";\n";
  }
  // The MAX checks: every field whose legal range ends below its top.
  std::vector<std::string> terms;
  for (const WordField& w : word) {
    const uint64_t top = (uint64_t(1) << w.field->width) - 1;
    if (w.field->maxValue >= top) continue;
    const std::string p = "CFG_" + w.name();
    terms.push_back("c[" + p + "_LSB +: " + p + "_W] <= " + std::to_string(w.field->width) + "'d" +
                    std::to_string(w.field->maxValue));
  }
  o << "\n// Every field of c at most its MAX (the fields whose legal range ends below their top). The\n"
    << "// lower bounds above 0, the bounds of the build and the rules across fields are\n"
    << "// sgm_stream_ctrl's (docs/rtl.md, \"Adding a run-time setting\").\n"
    << "function automatic logic cfg_below_max(input logic [CFG_W-1:0] c);\n  cfg_below_max = ";
  if (terms.empty()) o << "1'b1";
  for (size_t i = 0; i < terms.size(); ++i) o << (i ? " &&\n                  " : "") << terms[i];
  o << ";\nendfunction\n";
  // The NEEDS checks.
  std::string args = "    input logic [CFG_W-1:0] c";
  for (const std::string& n : needs) args += ",\n    input logic has_" + lower(n);
  terms.clear();
  for (const WordField& w : word) {
    if (w.field->needs.empty()) continue;
    const std::string p = "CFG_" + w.name();
    terms.push_back("(has_" + lower(w.field->needs) + " || c[" + p + "_LSB +: " + p +
                    "_W] == " + std::to_string(w.field->width) + "'d0)");
  }
  o << "\n// Every field whose build parameter (NEEDS) the build lacks at 0: has_<need> is 1 when the\n"
    << "// build has sgm_top's parameter <NEED>.\n"
    << "function automatic logic cfg_levers_built(\n"
    << args << ");\n  cfg_levers_built = ";
  if (terms.empty()) o << "1'b1";
  for (size_t i = 0; i < terms.size(); ++i) o << (i ? " &&\n                     " : "") << terms[i];
  o << ";\nendfunction\n\n`endif  // SGM_CFG_SVH\n";
  return o.str();
}

// ------------------------------------------------------------------ the word, testbenches
std::string tbHeader() {
  std::ostringstream o;
  o << "// SPDX-License-Identifier: Apache-2.0\n"
    << "// sgm_cfg_fields.hpp: the frame configuration word for the testbenches, " << kNotice << ".\n"
    << "// Each field of sgm_top's cfg_i (rtl/sgm_cfg.svh) with its register in sgm_axi and its value\n"
    << "// for a frame of the golden model's parameters; tb/hardware_config.hpp packs the word and the\n"
    << "// registers by this table.\n"
    << "#pragma once\n\n"
    << "#include \"hardware_codes.hpp\"\n\n"
    << "#include \"sgm/params.hpp\"\n\n"
    << "#include <algorithm>\n#include <array>\n#include <cstdint>\n\n"
    << "namespace sgm::tb {\n\n"
    << "struct CfgField {\n"
    << "  const char* name;  // REGISTER_FIELD (sgm_regs.h SGM_REGISTER_FIELD_*)\n"
    << "  uint32_t reg;      // the register's byte offset in sgm_axi\n"
    << "  int shift, width;  // the field's bits in the register: [shift +: width]\n"
    << "  int lsb;           // and in the word: [lsb +: width]\n"
    << "  // The field's value for a frame of the golden model's parameters p, w x h pixels.\n"
    << "  uint32_t (*golden)(const Params& p, int w, int h);\n"
    << "};\n\n"
    << "constexpr int kCfgWidth = " << wordWidth << ";  // CFG_W, SGM_CFG_W\n\n"
    << "inline const std::array<CfgField, " << word.size() << "> kCfgFields = {{\n";
  for (const WordField& w : word) {
    o << "    {\"" << w.name() << "\", 0x" << hexPlain(w.reg->offset, 2).substr(2) << ", " << w.field->lsb << ", "
      << w.field->width << ", " << w.lsb << ",\n"
      << "     []([[maybe_unused]] const Params& p, [[maybe_unused]] int w, [[maybe_unused]] int h) { return uint32_t("
      << w.golden << "); }},\n";
  }
  o << "}};\n\n}  // namespace sgm::tb\n";
  return o.str();
}

// ------------------------------------------------------------------ documentation
std::string mdEscape(std::string s) {
  std::string out;
  for (char c : s) out += c == '|' ? std::string("\\|") : std::string(1, c);
  return out;
}

std::string bits(const Field& f) {
  std::ostringstream o;
  o << "[" << f.lsb + f.width - 1;
  if (f.width > 1) o << ":" << f.lsb;
  o << "]";
  return o.str();
}

std::string docMap() {
  std::ostringstream o;
  o << "| offset | register | access | reset | what it holds |\n|---|---|---|---|---|\n";
  for (const Register& r : registers) {
    std::set<std::string> acc;
    for (const Field& f : r.fields) acc.insert(accessName(f.access));
    std::string access;
    for (const std::string& a : acc) access += (access.empty() ? "" : ", ") + a;
    std::string reset;
    if (isConfiguration(r))
      reset = hexPlain(resetValue(r, false), 8) + " (four-path: " + hexPlain(resetValue(r, true), 8) + ")";
    else if (r.name == "ID")
      reset = hexPlain(constantValue(r), 8);
    else if (!r.resetText.empty())
      reset = r.resetText;
    else
      reset = "0";
    o << "| " << hexPlain(r.offset, 2) << " | " << r.name << " | " << access << " | " << mdEscape(reset) << " | "
      << mdEscape(r.summary) << " |\n";
  }
  return o.str();
}

std::string docFields() {
  std::ostringstream o;
  o << "| register | field | bits | access | default | four-path | legal | needs | what it does |\n"
    << "|---|---|---|---|---|---|---|---|---|\n";
  for (const Register& r : registers) {
    const bool cfg = isConfiguration(r);
    for (const Field& f : r.fields) {
      std::string desc = f.description;
      for (const Value& v : r.values)
        if (v.field == f.name) desc += "; " + std::to_string(v.value) + " " + v.name + " (" + v.description + ")";
      std::string legal;
      if (f.access == Access::kRW && !(f.minValue == 0 && f.maxValue == (uint64_t(1) << f.width) - 1))
        legal = std::to_string(f.minValue) + " .. " + std::to_string(f.maxValue);
      o << "| " << r.name << " | " << f.name << " | " << bits(f) << " | " << accessName(f.access) << " | "
        << (cfg ? std::to_string(f.defaultValue) : "") << " | " << (cfg ? std::to_string(f.fourPathValue) : "") << " | "
        << legal << " | " << (f.needs.empty() ? "" : "`" + f.needs + "`") << " | " << mdEscape(desc) << " |\n";
    }
  }
  return o.str();
}

std::string docWord() {
  std::ostringstream o;
  o << "| bits of `cfg_i` | field | register bits | legal | needs | what it does |\n|---|---|---|---|---|---|\n";
  for (const WordField& w : word) {
    std::string legal;
    if (!(w.field->minValue == 0 && w.field->maxValue == (uint64_t(1) << w.field->width) - 1))
      legal = std::to_string(w.field->minValue) + " .. " + std::to_string(w.field->maxValue);
    o << "| " << bitRange(w.lsb, w.field->width) << " | " << w.reg->name << "." << w.field->name << " | " << w.reg->name
      << bitRange(w.field->lsb, w.field->width) << " | " << legal << " | "
      << (w.field->needs.empty() ? "" : "`" + w.field->needs + "`") << " | " << mdEscape(w.field->description)
      << " |\n";
  }
  o << "\n" << wordWidth << " bits (`CFG_W`, `SGM_CFG_W`).\n";
  return o.str();
}

std::string replaceSection(const std::string& text, const std::string& name, const std::string& body) {
  const std::string begin = "<!-- BEGIN regmap: " + name + " (generated by make regmap; do not edit) -->\n";
  const std::string end = "<!-- END regmap: " + name + " -->";
  const size_t b = text.find(begin);
  const size_t e = text.find(end);
  if (b == std::string::npos || e == std::string::npos || e < b) die("the documentation has no section '" + name + "'");
  return text.substr(0, b + begin.size()) + body + text.substr(e);
}

std::string readFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) die("cannot read " + path);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

void writeFile(const std::string& path, const std::string& text) {
  const std::string tmp = path + ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary);
    if (!out) die("cannot write " + path);
    out << text;
    if (!out) die("cannot write " + path);
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) die("cannot write " + path);
}

}  // namespace

int main(int argc, char** argv) {
  describe();
  check();
  std::stable_sort(registers.begin(), registers.end(),
                   [](const Register& a, const Register& b) { return a.offset < b.offset; });
  layoutWord();
  std::vector<std::string> args(argv + 1, argv + argc);
  if (args.empty()) die("usage: regmap_gen [--header FILE] [--svh FILE] [--cfg-svh FILE] [--tb FILE] [--doc IN OUT]");
  for (size_t i = 0; i < args.size(); ++i) {
    if (args[i] == "--header" && i + 1 < args.size()) {
      writeFile(args[++i], cHeader());
    } else if (args[i] == "--svh" && i + 1 < args.size()) {
      writeFile(args[++i], svHeader());
    } else if (args[i] == "--cfg-svh" && i + 1 < args.size()) {
      writeFile(args[++i], svCfg());
    } else if (args[i] == "--tb" && i + 1 < args.size()) {
      writeFile(args[++i], tbHeader());
    } else if (args[i] == "--doc" && i + 2 < args.size()) {
      std::string text = readFile(args[i + 1]);
      text = replaceSection(text, "map", docMap());
      text = replaceSection(text, "fields", docFields());
      text = replaceSection(text, "word", docWord());
      writeFile(args[i + 2], text);
      i += 2;
    } else {
      die("unknown argument '" + args[i] +
          "' (usage: regmap_gen [--header FILE] [--svh FILE] [--cfg-svh FILE] [--tb FILE] [--doc IN OUT])");
    }
  }
  return 0;
}
