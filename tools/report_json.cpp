// SPDX-License-Identifier: Apache-2.0
#include "report_json.hpp"

#include "json_read.hpp"
#include "report_util.hpp"

#include "sgm/params.hpp"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>

namespace sgm::eval {

std::string jsonEscape(const std::string& text) {
  std::string out = "\"";
  for (const unsigned char c : text) {
    switch (c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '\r': out += "\\r"; break;
      case '\t': out += "\\t"; break;
      default:
        if (c < 0x20) {
          char buf[8];
          std::snprintf(buf, sizeof buf, "\\u%04x", c);
          out += buf;
        } else {
          out += char(c);
        }
    }
  }
  return out + "\"";
}

void JsonWriter::beforeValue() {
  if (afterKey_) {
    afterKey_ = false;
    return;
  }
  if (hasItems_.empty()) {
    if (!out_.empty()) throw Error("internal: JSON document has more than one top-level value");
    return;
  }
  if (hasItems_.back()) out_ += ",";
  hasItems_.back() = true;
  out_ += "\n" + std::string(2 * hasItems_.size(), ' ');
}

JsonWriter& JsonWriter::raw(const std::string& token) {
  beforeValue();
  out_ += token;
  return *this;
}

JsonWriter& JsonWriter::open(char bracket) {
  raw(std::string(1, bracket));
  hasItems_.push_back(false);
  return *this;
}

JsonWriter& JsonWriter::close(char bracket) {
  if (hasItems_.empty() || afterKey_) throw Error("internal: unbalanced JSON");
  const bool hadItems = hasItems_.back();
  hasItems_.pop_back();
  if (hadItems) out_ += "\n" + std::string(2 * hasItems_.size(), ' ');
  out_ += bracket;
  return *this;
}

JsonWriter& JsonWriter::beginObject() { return open('{'); }
JsonWriter& JsonWriter::endObject() { return close('}'); }
JsonWriter& JsonWriter::beginArray() { return open('['); }
JsonWriter& JsonWriter::endArray() { return close(']'); }

JsonWriter& JsonWriter::key(const std::string& name) {
  raw(jsonEscape(name) + ": ");
  afterKey_ = true;
  return *this;
}

JsonWriter& JsonWriter::string(const std::string& text) { return raw(jsonEscape(text)); }

JsonWriter& JsonWriter::real(double value) { return real(value, 3); }

JsonWriter& JsonWriter::real(double value, int decimals) {
  if (!std::isfinite(value)) return null();
  const std::string text = fixed(value, decimals);
  // -0.000 (a negative value that rounds to zero) prints as 0.000.
  return raw(text.find_first_not_of("-0.") == std::string::npos && text[0] == '-' ? text.substr(1) : text);
}

JsonWriter& JsonWriter::real(const std::optional<double>& value) { return value ? real(*value) : null(); }
JsonWriter& JsonWriter::integer(long value) { return raw(std::to_string(value)); }
JsonWriter& JsonWriter::boolean(bool value) { return raw(value ? "true" : "false"); }
JsonWriter& JsonWriter::null() { return raw("null"); }

std::string JsonWriter::str() const {
  if (!hasItems_.empty() || afterKey_ || out_.empty()) throw Error("internal: unbalanced JSON");
  return out_ + "\n";
}

void writeTextFile(const std::string& path, const std::string& text) {
  const std::string tmp = path + ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    out << text;
    out.flush();
    if (!out) {
      std::error_code ignored;
      std::filesystem::remove(tmp, ignored);
      throw Error("cannot write '" + path + "'");
    }
  }
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) {
    std::filesystem::remove(tmp, ec);
    throw Error("cannot write '" + path + "': " + ec.message());
  }
}

}  // namespace sgm::eval

namespace sgm::eval {

std::map<std::string, std::string> readFlatJson(const std::string& path) {
  const Json doc = readJsonFile(path);
  if (!doc.isObject()) throw Error("'" + path + "' is not a flat JSON object: the document is not an object");
  std::map<std::string, std::string> out;
  for (const auto& [key, value] : doc.members) {
    if (value.isObject() || value.isArray())
      throw Error("'" + path + "' is not a flat JSON object: nested value at key '" + key + "'");
    out[key] = value.text;  // strings decoded, numbers and literals as written
  }
  return out;
}

}  // namespace sgm::eval
