// SPDX-License-Identifier: Apache-2.0
#include "report_json.hpp"

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

JsonWriter& JsonWriter::real(double value) {
  if (!std::isfinite(value)) return null();
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.3f", value);
  return raw(std::string(buf) == "-0.000" ? "0.000" : buf);
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
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error("cannot open '" + path + "'");
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  size_t i = 0;
  const auto fail = [&](const char* what) -> Error {
    return Error("'" + path + "' is not a flat JSON object: " + what + " at byte " + std::to_string(i));
  };
  const auto skipSpace = [&] {
    while (i < text.size() && std::isspace((unsigned char)text[i])) ++i;
  };
  const auto readString = [&]() {
    if (text[i] != '"') throw fail("expected a string");
    std::string s;
    for (++i; i < text.size() && text[i] != '"'; ++i) {
      if (text[i] == '\\') {
        if (++i >= text.size()) break;
        const char c = text[i];
        s += c == 'n' ? '\n' : c == 't' ? '\t' : c;
      } else {
        s += text[i];
      }
    }
    if (i >= text.size()) throw fail("unterminated string");
    ++i;
    return s;
  };
  std::map<std::string, std::string> out;
  skipSpace();
  if (i >= text.size() || text[i++] != '{') throw fail("expected '{'");
  for (;;) {
    skipSpace();
    if (i < text.size() && text[i] == '}') break;
    if (i >= text.size()) throw fail("unexpected end");
    const std::string key = readString();
    skipSpace();
    if (i >= text.size() || text[i++] != ':') throw fail("expected ':'");
    skipSpace();
    if (i >= text.size()) throw fail("unexpected end");
    if (text[i] == '"') {
      out[key] = readString();
    } else {
      const size_t start = i;
      while (i < text.size() && (std::isalnum((unsigned char)text[i]) || std::strchr("+-.", text[i]))) ++i;
      if (i == start) throw fail("nested or empty value");
      out[key] = text.substr(start, i - start);
    }
    skipSpace();
    if (i < text.size() && text[i] == ',') {
      ++i;
      continue;
    }
    skipSpace();
    if (i >= text.size() || text[i] != '}') throw fail("expected ',' or '}'");
  }
  return out;
}

}  // namespace sgm::eval
