// SPDX-License-Identifier: Apache-2.0
// A small, strict JSON reader (RFC 8259) for the reports the tools read back:
// nextpnr's --report (synth/pnr_summary.cpp), the simulator's flat report
// (readFlatJson) and the measured reports the datasheet collects. The writer
// is JsonWriter (report_json.hpp).
#pragma once

#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

namespace sgm::eval {

struct Json {
  enum Kind { kNull, kBool, kNumber, kString, kArray, kObject };
  Kind kind = kNull;
  double number = 0;        // kNumber; kBool: 1 or 0
  std::string text;         // kString: the decoded string; kNumber, kBool, kNull: the literal as written
  std::vector<Json> items;  // kArray
  std::vector<std::pair<std::string, Json>> members;  // kObject, in document order

  bool isNull() const { return kind == kNull; }
  bool isNumber() const { return kind == kNumber; }
  bool isString() const { return kind == kString; }
  bool isObject() const { return kind == kObject; }
  bool isArray() const { return kind == kArray; }
  bool boolean() const { return kind == kBool && number != 0; }

  // The member named key (the first if repeated); nullptr when absent or not an object.
  const Json* get(const std::string& key) const;
  // The member at a path of keys ("a", "b" -> a.b); nullptr when any step is absent.
  const Json* find(std::initializer_list<const char*> path) const;
};

// Parses text (named `source` in errors). Throws Error "<source>: JSON: <what> at
// line L, column C" on anything that is not exactly one JSON value: trailing
// commas, comments, single quotes, leading zeros, bare control characters in
// strings, bad escapes and lone surrogates are errors. Nesting is limited to 256.
Json parseJson(const std::string& text, const std::string& source);

// parseJson of a file's contents. Throws Error when the file cannot be read.
Json readJsonFile(const std::string& path);

}  // namespace sgm::eval
