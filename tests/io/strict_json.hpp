#pragma once
// A strict JSON reader for tests (RFC 8259: no NaN, Infinity, trailing commas, bare
// words): says whether a text is one JSON value and, if not, where it stops being one.
#include <cctype>
#include <cstddef>
#include <string>

namespace mpmx::test {

class StrictJson {
 public:
  explicit StrictJson(const std::string& s) : s_(s) {}

  // True when the whole text is one JSON value; else `error()` says where.
  bool valid() {
    ws();
    if (!value()) return false;
    ws();
    return at_end() || fail("text after the value");
  }
  const std::string& error() const { return error_; }

 private:
  bool at_end() const { return i_ >= s_.size(); }
  char peek() const { return at_end() ? '\0' : s_[i_]; }
  void ws() {
    while (!at_end() && (s_[i_] == ' ' || s_[i_] == '\n' || s_[i_] == '\r' || s_[i_] == '\t')) ++i_;
  }
  bool fail(const char* what) {
    if (error_.empty()) error_ = std::string(what) + " at byte " + std::to_string(i_) + ": '" + s_.substr(i_, 20) + "'";
    return false;
  }
  bool literal(const char* w) {
    const std::string t(w);
    if (s_.compare(i_, t.size(), t) != 0) return fail("unknown word");
    i_ += t.size();
    return true;
  }
  bool value() {
    switch (peek()) {
      case '{': return object();
      case '[': return array();
      case '"': return string();
      case 't': return literal("true");
      case 'f': return literal("false");
      case 'n': return literal("null");
      default: return number();
    }
  }
  bool object() {
    ++i_;
    ws();
    if (peek() == '}') return ++i_, true;
    for (;;) {
      ws();
      if (peek() != '"' || !string()) return fail("expected a key");
      ws();
      if (peek() != ':') return fail("expected ':'");
      ++i_;
      ws();
      if (!value()) return false;
      ws();
      if (peek() == ',') { ++i_; continue; }
      if (peek() == '}') return ++i_, true;
      return fail("expected ',' or '}'");
    }
  }
  bool array() {
    ++i_;
    ws();
    if (peek() == ']') return ++i_, true;
    for (;;) {
      ws();
      if (!value()) return false;
      ws();
      if (peek() == ',') { ++i_; continue; }
      if (peek() == ']') return ++i_, true;
      return fail("expected ',' or ']'");
    }
  }
  bool string() {
    ++i_;
    while (!at_end() && s_[i_] != '"') {
      if (static_cast<unsigned char>(s_[i_]) < 0x20) return fail("control character in a string");
      if (s_[i_] == '\\') ++i_;
      ++i_;
    }
    if (at_end()) return fail("unterminated string");
    ++i_;
    return true;
  }
  bool digits() {
    const std::size_t start = i_;
    while (std::isdigit(static_cast<unsigned char>(peek()))) ++i_;
    return i_ > start;
  }
  bool number() {
    if (peek() == '-') ++i_;
    if (peek() == '0') ++i_;
    else if (!digits()) return fail("expected a value");
    if (peek() == '.') {
      ++i_;
      if (!digits()) return fail("expected digits after '.'");
    }
    if (peek() == 'e' || peek() == 'E') {
      ++i_;
      if (peek() == '+' || peek() == '-') ++i_;
      if (!digits()) return fail("expected exponent digits");
    }
    return true;
  }

  const std::string& s_;
  std::size_t i_ = 0;
  std::string error_;
};

}  // namespace mpmx::test
