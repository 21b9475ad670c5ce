// SPDX-License-Identifier: Apache-2.0
// The strict JSON reader and writer of json.h: a recursive-descent parser that tracks line and
// column for its errors, and an indenting writer with shortest round-trip numbers.
#include "teach/json.h"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>

namespace xmate::teach {
namespace {

constexpr int kMaxDepth = 200;

class Parser {
 public:
  explicit Parser(const std::string& text) : text_(text) {}

  JsonValue document() {
    skipSpace();
    JsonValue v = value(0);
    skipSpace();
    if (pos_ < text_.size()) fail("unexpected text after the end of the document");
    return v;
  }

 private:
  const std::string& text_;
  size_t pos_ = 0;
  int line_ = 1;
  size_t line_start_ = 0;

  [[noreturn]] void fail(const std::string& message) const {
    throw JsonError(line_, int(pos_ - line_start_) + 1, message);
  }
  bool atEnd() const { return pos_ >= text_.size(); }
  char peek() const { return atEnd() ? '\0' : text_[pos_]; }
  void advance() {
    if (text_[pos_] == '\n') {
      ++line_;
      line_start_ = pos_ + 1;
    }
    ++pos_;
  }
  void skipSpace() {
    while (!atEnd() && (peek() == ' ' || peek() == '\t' || peek() == '\n' || peek() == '\r')) advance();
  }
  void expect(char c, const char* what) {
    if (peek() != c) fail(std::string("expected ") + what);
    advance();
  }

  JsonValue value(int depth) {
    if (depth > kMaxDepth) fail("nesting deeper than 200 levels");
    if (atEnd()) fail("unexpected end of the text: expected a value");
    const char c = peek();
    if (c == '{') return object(depth);
    if (c == '[') return array(depth);
    if (c == '"') return JsonValue::string(string());
    if (c == '-' || (c >= '0' && c <= '9')) return number();
    if (word("true")) return JsonValue::boolean(true);
    if (word("false")) return JsonValue::boolean(false);
    if (word("null")) return JsonValue();
    if (text_.compare(pos_, 3, "NaN") == 0 || text_.compare(pos_, 8, "Infinity") == 0)
      fail("NaN and Infinity are not JSON numbers: write a finite number");
    fail(std::string("unexpected character '") + c + "': expected a value (object, array, string, number, true, false or null)");
  }

  bool word(const char* w) {
    const std::string s(w);
    if (text_.compare(pos_, s.size(), s) != 0) return false;
    for (size_t i = 0; i < s.size(); ++i) advance();
    return true;
  }

  JsonValue object(int depth) {
    JsonValue obj = JsonValue::object();
    advance();  // {
    skipSpace();
    if (peek() == '}') {
      advance();
      return obj;
    }
    for (;;) {
      skipSpace();
      if (peek() != '"') fail("expected a member name in double quotes");
      const int key_line = line_;
      const int key_column = int(pos_ - line_start_) + 1;
      std::string key = string();
      if (obj.find(key)) throw JsonError(key_line, key_column, "duplicate member \"" + key + "\"");
      skipSpace();
      expect(':', "':' after the member name");
      skipSpace();
      obj.set(key, value(depth + 1));
      skipSpace();
      if (peek() == ',') {
        advance();
        continue;
      }
      expect('}', "',' or '}' after a member");
      return obj;
    }
  }

  JsonValue array(int depth) {
    JsonValue arr = JsonValue::array();
    advance();  // [
    skipSpace();
    if (peek() == ']') {
      advance();
      return arr;
    }
    for (;;) {
      skipSpace();
      arr.push(value(depth + 1));
      skipSpace();
      if (peek() == ',') {
        advance();
        continue;
      }
      expect(']', "',' or ']' after an array element");
      return arr;
    }
  }

  unsigned hex4() {
    unsigned v = 0;
    for (int i = 0; i < 4; ++i) {
      const char c = peek();
      int d;
      if (c >= '0' && c <= '9') d = c - '0';
      else if (c >= 'a' && c <= 'f') d = c - 'a' + 10;
      else if (c >= 'A' && c <= 'F') d = c - 'A' + 10;
      else fail("expected 4 hex digits after \\u");
      v = v * 16 + unsigned(d);
      advance();
    }
    return v;
  }

  static void appendUtf8(std::string& out, uint32_t cp) {
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

  void escape(std::string& out) {
    advance();  // backslash
    if (atEnd()) fail("unexpected end of the text inside a string");
    const char c = peek();
    switch (c) {
      case '"': out += '"'; break;
      case '\\': out += '\\'; break;
      case '/': out += '/'; break;
      case 'b': out += '\b'; break;
      case 'f': out += '\f'; break;
      case 'n': out += '\n'; break;
      case 'r': out += '\r'; break;
      case 't': out += '\t'; break;
      case 'u': {
        advance();
        uint32_t cp = hex4();
        if (cp >= 0xD800 && cp <= 0xDBFF) {
          if (!word("\\u")) fail("a high surrogate \\u escape must be followed by a low surrogate");
          const uint32_t low = hex4();
          if (low < 0xDC00 || low > 0xDFFF) fail("invalid low surrogate in a \\u escape");
          cp = 0x10000 + ((cp - 0xD800) << 10) + (low - 0xDC00);
        } else if (cp >= 0xDC00 && cp <= 0xDFFF) {
          fail("a low surrogate \\u escape without a high one");
        }
        appendUtf8(out, cp);
        return;
      }
      default: fail(std::string("invalid escape '\\") + c + "' (valid: \\\" \\\\ \\/ \\b \\f \\n \\r \\t \\uXXXX)");
    }
    advance();
  }

  std::string string() {
    advance();  // opening quote
    std::string out;
    for (;;) {
      if (atEnd()) fail("unexpected end of the text inside a string: missing closing '\"'");
      const char c = peek();
      if (c == '"') {
        advance();
        return out;
      }
      if (static_cast<unsigned char>(c) < 0x20) fail("control character inside a string: escape it (e.g. \\n)");
      if (c == '\\') {
        escape(out);
        continue;
      }
      out += c;
      advance();
    }
  }

  void digits() {
    if (!(peek() >= '0' && peek() <= '9')) fail("expected a digit");
    while (peek() >= '0' && peek() <= '9') advance();
  }

  JsonValue number() {
    const size_t start = pos_;
    if (peek() == '-') advance();
    if (peek() == '0') {
      advance();
      if (peek() >= '0' && peek() <= '9') fail("leading zeros are not allowed in numbers");
    } else {
      digits();
    }
    if (peek() == '.') {
      advance();
      digits();
    }
    if (peek() == 'e' || peek() == 'E') {
      advance();
      if (peek() == '+' || peek() == '-') advance();
      digits();
    }
    double v = 0;
    const auto r = std::from_chars(text_.data() + start, text_.data() + pos_, v);
    if (r.ec == std::errc::result_out_of_range) {
      // Underflow to zero is harmless; overflow would be infinite.
      const std::string s = text_.substr(start, pos_ - start);
      const auto e = s.find_first_of("eE");
      if (e != std::string::npos && s[e + 1] == '-') return JsonValue::number(0.0);
      fail("number " + s + " is too large for a double");
    }
    if (r.ec != std::errc() || !std::isfinite(v)) fail("invalid number");
    return JsonValue::number(v);
  }
};

void writeString(std::string& out, const std::string& s) {
  out += '"';
  for (const char c : s) {
    switch (c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '\r': out += "\\r"; break;
      case '\t': out += "\\t"; break;
      case '\b': out += "\\b"; break;
      case '\f': out += "\\f"; break;
      default:
        if (static_cast<unsigned char>(c) < 0x20) {
          char buf[8];
          std::snprintf(buf, sizeof buf, "\\u%04x", unsigned(c));
          out += buf;
        } else {
          out += c;
        }
    }
  }
  out += '"';
}

void writeNumber(std::string& out, double d) {
  if (!std::isfinite(d)) throw std::invalid_argument("writeJson: a number is not finite (JSON cannot hold NaN or infinity)");
  char buf[40];
  const auto r = std::to_chars(buf, buf + sizeof buf, d);
  out.append(buf, r.ptr);
}

bool allScalars(const JsonValue& v) {
  for (size_t i = 0; i < v.size(); ++i)
    if (v.at(i).isArray() || v.at(i).isObject()) return false;
  return true;
}

void write(std::string& out, const JsonValue& v, int indent) {
  const std::string pad(size_t(indent + 2), ' ');
  switch (v.kind()) {
    case JsonValue::Kind::kNull: out += "null"; return;
    case JsonValue::Kind::kBool: out += v.asBool() ? "true" : "false"; return;
    case JsonValue::Kind::kNumber: writeNumber(out, v.asNumber()); return;
    case JsonValue::Kind::kString: writeString(out, v.asString()); return;
    case JsonValue::Kind::kArray:
      if (v.size() == 0 || allScalars(v)) {
        out += '[';
        for (size_t i = 0; i < v.size(); ++i) {
          if (i) out += ", ";
          write(out, v.at(i), indent);
        }
        out += ']';
        return;
      }
      out += "[\n";
      for (size_t i = 0; i < v.size(); ++i) {
        out += pad;
        write(out, v.at(i), indent + 2);
        out += i + 1 < v.size() ? ",\n" : "\n";
      }
      out += std::string(size_t(indent), ' ') + "]";
      return;
    case JsonValue::Kind::kObject:
      if (v.size() == 0) {
        out += "{}";
        return;
      }
      out += "{\n";
      for (size_t i = 0; i < v.size(); ++i) {
        out += pad;
        writeString(out, v.keys()[i]);
        out += ": ";
        write(out, v.at(i), indent + 2);
        out += i + 1 < v.size() ? ",\n" : "\n";
      }
      out += std::string(size_t(indent), ' ') + "}";
      return;
  }
}

}  // namespace

JsonError::JsonError(int l, int c, const std::string& message)
    : std::runtime_error("line " + std::to_string(l) + ", column " + std::to_string(c) + ": " + message),
      line(l), column(c) {}

JsonValue JsonValue::boolean(bool b) {
  JsonValue v;
  v.kind_ = Kind::kBool;
  v.bool_ = b;
  return v;
}

JsonValue JsonValue::number(double d) {
  JsonValue v;
  v.kind_ = Kind::kNumber;
  v.number_ = d;
  return v;
}

JsonValue JsonValue::string(std::string s) {
  JsonValue v;
  v.kind_ = Kind::kString;
  v.string_ = std::move(s);
  return v;
}

JsonValue JsonValue::array() {
  JsonValue v;
  v.kind_ = Kind::kArray;
  return v;
}

JsonValue JsonValue::object() {
  JsonValue v;
  v.kind_ = Kind::kObject;
  return v;
}

JsonValue JsonValue::numbers(const double* values, size_t count) {
  JsonValue v = array();
  for (size_t i = 0; i < count; ++i) v.push(number(values[i]));
  return v;
}

const JsonValue* JsonValue::find(const std::string& key) const {
  if (kind_ != Kind::kObject) return nullptr;
  for (size_t i = 0; i < keys_.size(); ++i)
    if (keys_[i] == key) return &values_[i];
  return nullptr;
}

JsonValue& JsonValue::push(JsonValue value) {
  values_.push_back(std::move(value));
  return values_.back();
}

JsonValue& JsonValue::set(const std::string& key, JsonValue value) {
  keys_.push_back(key);
  values_.push_back(std::move(value));
  return values_.back();
}

const char* kindName(JsonValue::Kind kind) {
  switch (kind) {
    case JsonValue::Kind::kNull: return "null";
    case JsonValue::Kind::kBool: return "a boolean";
    case JsonValue::Kind::kNumber: return "a number";
    case JsonValue::Kind::kString: return "a string";
    case JsonValue::Kind::kArray: return "an array";
    case JsonValue::Kind::kObject: return "an object";
  }
  return "unknown";
}

JsonValue parseJson(const std::string& text) { return Parser(text).document(); }

std::string writeJson(const JsonValue& value) {
  std::string out;
  write(out, value, 0);
  out += '\n';
  return out;
}

}  // namespace xmate::teach
