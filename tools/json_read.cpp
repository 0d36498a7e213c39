// SPDX-License-Identifier: Apache-2.0
#include "json_read.hpp"

#include "report_util.hpp"
#include "sgm/params.hpp"

#include <cstdlib>
#include <cstring>

namespace sgm::eval {

const Json* Json::get(const std::string& key) const {
  if (kind != kObject) return nullptr;
  for (const auto& m : members)
    if (m.first == key) return &m.second;
  return nullptr;
}

const Json* Json::find(std::initializer_list<const char*> path) const {
  const Json* at = this;
  for (const char* key : path)
    if (!at || !(at = at->get(key))) return nullptr;
  return at;
}

namespace {

class Parser {
 public:
  Parser(const std::string& text, const std::string& source) : s_(text), source_(source) {}

  Json document() {
    skip();
    Json v = value(0);
    skip();
    if (i_ != s_.size()) fail("trailing characters after the value");
    return v;
  }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    size_t line = 1, column = 1;
    for (size_t k = 0; k < i_ && k < s_.size(); ++k) {
      if (s_[k] == '\n') {
        ++line;
        column = 1;
      } else {
        ++column;
      }
    }
    throw Error(source_ + ": JSON: " + what + " at line " + std::to_string(line) + ", column " +
                std::to_string(column));
  }

  void skip() {
    while (i_ < s_.size() && (s_[i_] == ' ' || s_[i_] == '\t' || s_[i_] == '\n' || s_[i_] == '\r')) ++i_;
  }

  bool at(char c) const { return i_ < s_.size() && s_[i_] == c; }

  void expect(char c) {
    skip();
    if (!at(c)) fail(std::string("expected '") + c + "'");
    ++i_;
  }

  unsigned hex4() {
    if (i_ + 4 > s_.size()) fail("truncated \\u escape");
    unsigned v = 0;
    for (int k = 0; k < 4; ++k, ++i_) {
      const char c = s_[i_];
      v <<= 4;
      if (c >= '0' && c <= '9')
        v |= unsigned(c - '0');
      else if (c >= 'a' && c <= 'f')
        v |= unsigned(c - 'a' + 10);
      else if (c >= 'A' && c <= 'F')
        v |= unsigned(c - 'A' + 10);
      else
        fail("bad \\u escape");
    }
    return v;
  }

  static void utf8(std::string& out, unsigned cp) {
    if (cp < 0x80) {
      out += char(cp);
    } else if (cp < 0x800) {
      out += char(0xC0 | (cp >> 6));
      out += char(0x80 | (cp & 0x3F));
    } else if (cp < 0x10000) {
      out += char(0xE0 | (cp >> 12));
      out += char(0x80 | ((cp >> 6) & 0x3F));
      out += char(0x80 | (cp & 0x3F));
    } else {
      out += char(0xF0 | (cp >> 18));
      out += char(0x80 | ((cp >> 12) & 0x3F));
      out += char(0x80 | ((cp >> 6) & 0x3F));
      out += char(0x80 | (cp & 0x3F));
    }
  }

  std::string string() {
    if (!at('"')) fail("expected a string");
    ++i_;
    std::string out;
    for (;;) {
      if (i_ >= s_.size()) fail("unterminated string");
      const unsigned char c = static_cast<unsigned char>(s_[i_]);
      if (c == '"') {
        ++i_;
        return out;
      }
      if (c < 0x20) fail("control character in a string");
      if (c != '\\') {
        out += char(c);
        ++i_;
        continue;
      }
      if (++i_ >= s_.size()) fail("unterminated string");
      const char e = s_[i_++];
      switch (e) {
        case '"': out += '"'; break;
        case '\\': out += '\\'; break;
        case '/': out += '/'; break;
        case 'b': out += '\b'; break;
        case 'f': out += '\f'; break;
        case 'n': out += '\n'; break;
        case 'r': out += '\r'; break;
        case 't': out += '\t'; break;
        case 'u': {
          unsigned cp = hex4();
          if (cp >= 0xDC00 && cp <= 0xDFFF) fail("lone low surrogate");
          if (cp >= 0xD800 && cp <= 0xDBFF) {
            if (s_.compare(i_, 2, "\\u") != 0) fail("lone high surrogate");
            i_ += 2;
            const unsigned low = hex4();
            if (low < 0xDC00 || low > 0xDFFF) fail("lone high surrogate");
            cp = 0x10000 + ((cp - 0xD800) << 10) + (low - 0xDC00);
          }
          utf8(out, cp);
          break;
        }
        default: --i_; fail(std::string("bad escape '\\") + e + "'");
      }
    }
  }

  static bool digit(char c) { return c >= '0' && c <= '9'; }

  Json number() {
    const size_t start = i_;
    if (at('-')) ++i_;
    if (at('0')) {
      ++i_;
      if (i_ < s_.size() && digit(s_[i_])) fail("leading zero in a number");
    } else if (i_ < s_.size() && digit(s_[i_])) {
      while (i_ < s_.size() && digit(s_[i_])) ++i_;
    } else {
      fail("unexpected character");
    }
    if (at('.')) {
      ++i_;
      if (!(i_ < s_.size() && digit(s_[i_]))) fail("digit expected after '.'");
      while (i_ < s_.size() && digit(s_[i_])) ++i_;
    }
    if (at('e') || at('E')) {
      ++i_;
      if (at('+') || at('-')) ++i_;
      if (!(i_ < s_.size() && digit(s_[i_]))) fail("digit expected in the exponent");
      while (i_ < s_.size() && digit(s_[i_])) ++i_;
    }
    Json v;
    v.kind = Json::kNumber;
    v.text = s_.substr(start, i_ - start);
    v.number = std::strtod(v.text.c_str(), nullptr);
    return v;
  }

  Json value(int depth) {
    if (depth > 256) fail("nesting deeper than 256");
    skip();
    if (i_ >= s_.size()) fail("unexpected end");
    Json v;
    const char c = s_[i_];
    if (c == '{') {
      v.kind = Json::kObject;
      ++i_;
      skip();
      if (at('}')) {
        ++i_;
        return v;
      }
      for (;;) {
        skip();
        std::string key = string();
        expect(':');
        v.members.emplace_back(std::move(key), value(depth + 1));
        skip();
        if (at(',')) {
          ++i_;
          continue;
        }
        expect('}');
        return v;
      }
    }
    if (c == '[') {
      v.kind = Json::kArray;
      ++i_;
      skip();
      if (at(']')) {
        ++i_;
        return v;
      }
      for (;;) {
        v.items.push_back(value(depth + 1));
        skip();
        if (at(',')) {
          ++i_;
          continue;
        }
        expect(']');
        return v;
      }
    }
    if (c == '"') {
      v.kind = Json::kString;
      v.text = string();
      return v;
    }
    for (const char* literal : {"true", "false", "null"}) {
      const size_t n = std::strlen(literal);
      if (s_.compare(i_, n, literal) == 0) {
        i_ += n;
        v.kind = literal[0] == 'n' ? Json::kNull : Json::kBool;
        v.number = literal[0] == 't';
        v.text = literal;
        return v;
      }
    }
    return number();
  }

  const std::string& s_;
  const std::string& source_;
  size_t i_ = 0;
};

}  // namespace

Json parseJson(const std::string& text, const std::string& source) { return Parser(text, source).document(); }

Json readJsonFile(const std::string& path) { return parseJson(readTextFile(path), path); }

}  // namespace sgm::eval
