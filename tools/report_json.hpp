// SPDX-License-Identifier: Apache-2.0
// Minimal hand-written JSON output (no JSON library in the project; the reader
// is json_read.hpp) and an all-or-nothing text file writer, shared by the
// table, pool, bench, synthesis and place-and-route reports.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace sgm::eval {

// Streaming JSON writer with two-space indentation. Keys and values are added
// in order; commas and nesting are handled here. Reals print with 3 decimals
// (non-finite values as null).
class JsonWriter {
 public:
  JsonWriter& beginObject();
  JsonWriter& endObject();
  JsonWriter& beginArray();
  JsonWriter& endArray();
  JsonWriter& key(const std::string& name);  // next value belongs to this key

  JsonWriter& string(const std::string& text);
  JsonWriter& real(double value);                        // 3 decimals
  JsonWriter& real(double value, int decimals);          // that many decimals
  JsonWriter& real(const std::optional<double>& value);  // null when empty
  JsonWriter& integer(long value);
  JsonWriter& boolean(bool value);
  JsonWriter& null();

  // The document, newline-terminated. Throws Error when objects/arrays are unbalanced.
  std::string str() const;

 private:
  void beforeValue();
  JsonWriter& open(char bracket);
  JsonWriter& close(char bracket);
  JsonWriter& raw(const std::string& token);

  std::string out_;
  std::vector<bool> hasItems_;  // one per open object/array
  bool afterKey_ = false;
};

std::string jsonEscape(const std::string& text);  // with the surrounding quotes

// Writes text to path via a temporary file and a rename, so readers never see
// a partial file. Throws Error on failure.
void writeTextFile(const std::string& path, const std::string& text);

// Reads a flat JSON object ({"key": number | string | true | false | null, ...}, as
// the tools write for one run) into key -> text (strings without their quotes).
// Throws Error naming the file on anything else (nested values included).
std::map<std::string, std::string> readFlatJson(const std::string& path);

}  // namespace sgm::eval
