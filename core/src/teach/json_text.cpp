// SPDX-License-Identifier: Apache-2.0
// Strict JSON text on nlohmann-json (json_text.h). nlohmann does the parsing; this adds what the
// teach files promise on top of it: duplicate member names, overflowing numbers and deep nesting
// refused, and every error located as "line L, column C".
#include "teach/json_text.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <set>
#include <vector>

namespace xmate::teach {
namespace {

constexpr int kMaxDepth = 200;

// A char iterator that records how many bytes the parser has read: nlohmann reads its input one
// character at a time, so when the parser callback runs, `*consumed` is the offset just past the
// token the callback is about (a member name: its closing quote).
class CountingIterator {
 public:
  using iterator_category = std::forward_iterator_tag;
  using value_type = char;
  using difference_type = std::ptrdiff_t;
  using pointer = const char*;
  using reference = const char&;

  CountingIterator() = default;
  CountingIterator(const char* at, const char* begin, size_t* consumed) : at_(at), begin_(begin), consumed_(consumed) {}
  reference operator*() const { return *at_; }
  CountingIterator& operator++() {
    ++at_;
    *consumed_ = size_t(at_ - begin_);
    return *this;
  }
  CountingIterator operator++(int) {
    CountingIterator before = *this;
    ++*this;
    return before;
  }
  bool operator==(const CountingIterator& other) const { return at_ == other.at_; }
  bool operator!=(const CountingIterator& other) const { return at_ != other.at_; }

 private:
  const char* at_ = nullptr;
  const char* begin_ = nullptr;
  size_t* consumed_ = nullptr;
};

// The line and column (1-based) of byte `offset` of `text` (offset == size: just past the end).
JsonSyntaxError errorAt(const std::string& text, size_t offset, const std::string& message) {
  offset = std::min(offset, text.size());
  int line = 1;
  size_t line_start = 0;
  for (size_t i = 0; i < offset; ++i)
    if (text[i] == '\n') {
      ++line;
      line_start = i + 1;
    }
  return JsonSyntaxError(line, int(offset - line_start) + 1, message);
}

// Bytes that are not valid UTF-8 shown as \xNN, so that an error message quoting the input is text.
std::string printable(const std::string& s) {
  std::string out;
  for (size_t i = 0; i < s.size();) {
    const auto c = static_cast<unsigned char>(s[i]);
    size_t n = c < 0x80 ? 1 : (c >> 5) == 0x6 ? 2 : (c >> 4) == 0xE ? 3 : (c >> 3) == 0x1E ? 4 : 0;
    for (size_t k = 1; n > 1 && k < n; ++k)
      if (i + k >= s.size() || (static_cast<unsigned char>(s[i + k]) & 0xC0) != 0x80) n = 0;
    if (n == 0) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\x%02X", unsigned(c));
      out += buf;
      ++i;
    } else {
      out.append(s, i, n);
      i += n;
    }
  }
  return out;
}

// nlohmann's parse_error text without its own prefix ("[json.exception.parse_error.101] parse error
// at line 1, column 4: "), which counts columns differently from ours.
std::string description(const std::string& what) {
  const auto at = what.find("parse error");
  const auto colon = at == std::string::npos ? std::string::npos : what.find(": ", at);
  return colon == std::string::npos ? what : what.substr(colon + 2);
}

// The error for a nlohmann parse error found at byte `offset` (where the parser stopped).
JsonSyntaxError syntaxError(const std::string& text, size_t offset, const std::string& what) {
  const std::string detail = description(what);
  if (detail.find("ill-formed UTF-8") != std::string::npos) {
    // The bad sequence: the run of non-ASCII bytes that ends at the byte the parser refused.
    size_t start = std::min(offset, text.size() ? text.size() - 1 : 0);
    while (start > 0 && offset - start < 3 && static_cast<unsigned char>(text[start - 1]) >= 0x80) --start;
    std::string bytes;
    for (size_t i = start; i <= offset && i < text.size(); ++i) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "%s0x%02X", bytes.empty() ? "" : " ", unsigned(static_cast<unsigned char>(text[i])));
      bytes += buf;
    }
    return errorAt(text, start, "invalid UTF-8 in a string (bytes " + bytes + "): the file must be saved as UTF-8 text");
  }
  std::string message = printable(detail);
  if (text.compare(offset, 3, "NaN") == 0 || text.compare(offset, 8, "Infinity") == 0)
    message += " (NaN and Infinity are not JSON numbers: write a finite number)";
  return errorAt(text, offset, message);
}

// The offset where the member name that ends just before `end` (its closing quote at end - 1)
// starts: its opening quote, the previous quote not escaped by a backslash.
size_t memberNameStart(const std::string& text, size_t end) {
  for (size_t i = end >= 2 ? end - 2 : 0; i > 0; --i) {
    if (text[i] != '"') continue;
    size_t backslashes = 0;
    while (backslashes < i && text[i - 1 - backslashes] == '\\') ++backslashes;
    if (backslashes % 2 == 0) return i;
  }
  return 0;
}

void writeNumber(std::string& out, double d) {
  if (!std::isfinite(d)) throw std::invalid_argument("jsonText: a number is not finite (JSON cannot hold NaN or infinity)");
  char buf[40];
  const auto r = std::to_chars(buf, buf + sizeof buf, d);  // shortest text that reads back the same
  out.append(buf, r.ptr);
}

void writeScalar(std::string& out, const Json& v) {
  if (v.is_number_float())
    writeNumber(out, v.get<double>());
  else
    out += v.dump(-1, ' ', false, Json::error_handler_t::replace);
}

bool allScalars(const Json& v) {
  for (const Json& e : v)
    if (e.is_structured()) return false;
  return true;
}

void write(std::string& out, const Json& v, int indent) {
  const std::string pad(size_t(indent + 2), ' ');
  if (v.is_array()) {
    if (v.empty() || allScalars(v)) {
      out += '[';
      for (size_t i = 0; i < v.size(); ++i) {
        if (i) out += ", ";
        writeScalar(out, v[i]);
      }
      out += ']';
      return;
    }
    out += "[\n";
    for (size_t i = 0; i < v.size(); ++i) {
      out += pad;
      write(out, v[i], indent + 2);
      out += i + 1 < v.size() ? ",\n" : "\n";
    }
    out += std::string(size_t(indent), ' ') + "]";
  } else if (v.is_object()) {
    if (v.empty()) {
      out += "{}";
      return;
    }
    out += "{\n";
    size_t i = 0;
    for (const auto& [key, value] : v.items()) {
      out += pad;
      writeScalar(out, Json(key));
      out += ": ";
      write(out, value, indent + 2);
      out += ++i < v.size() ? ",\n" : "\n";
    }
    out += std::string(size_t(indent), ' ') + "}";
  } else {
    writeScalar(out, v);
  }
}

}  // namespace

JsonSyntaxError::JsonSyntaxError(int l, int c, const std::string& message)
    : std::runtime_error("line " + std::to_string(l) + ", column " + std::to_string(c) + ": " + message),
      line(l), column(c) {}

Json parseJsonText(const std::string& text) {
  size_t consumed = 0;  // bytes the parser has read so far
  // Member names seen in each object being parsed, innermost last (nlohmann keeps the last of
  // duplicate members silently).
  std::vector<std::set<std::string>> names;
  const Json::parser_callback_t check = [&](int depth, Json::parse_event_t event, Json& parsed) {
    switch (event) {
      case Json::parse_event_t::object_start:
      case Json::parse_event_t::array_start:
        if (depth > kMaxDepth) throw errorAt(text, consumed - 1, "nesting deeper than 200 levels");
        if (event == Json::parse_event_t::object_start) names.emplace_back();
        break;
      case Json::parse_event_t::object_end:
        names.pop_back();
        break;
      case Json::parse_event_t::key: {
        const std::string& name = parsed.get_ref<const std::string&>();
        if (!names.back().insert(name).second)
          throw errorAt(text, memberNameStart(text, consumed),
                        "duplicate member \"" + printable(name) + "\" (each name may appear once in an object)");
        break;
      }
      default:
        break;
    }
    return true;
  };
  const CountingIterator first(text.data(), text.data(), &consumed);
  const CountingIterator last(text.data() + text.size(), text.data(), &consumed);
  try {
    return Json::parse(first, last, check);
  } catch (const Json::parse_error& e) {
    // e.byte: 1-based index of the byte the parser stopped at (size + 1: the end of the text).
    const size_t offset = std::min(e.byte > 0 ? size_t(e.byte) - 1 : size_t(0), text.size());
    throw syntaxError(text, offset, e.what());
  } catch (const Json::out_of_range& e) {
    // Error 406, "number overflow parsing '1e999'": locate the number, the last token read.
    const std::string what = e.what();
    const auto open = what.find('\'');
    const auto close = what.rfind('\'');
    const std::string number = open != std::string::npos && close > open ? what.substr(open + 1, close - open - 1) : "";
    const size_t at = number.empty() ? std::string::npos : text.rfind(number, consumed);
    throw errorAt(text, at == std::string::npos ? consumed : at,
                  "number " + printable(number) + " is out of range: a double holds magnitudes up to about 1.8e308");
  }
}

std::string jsonText(const Json& value) {
  std::string out;
  write(out, value, 0);
  out += '\n';
  return out;
}

const char* kindName(const Json& value) {
  switch (value.type()) {
    case Json::value_t::null: return "null";
    case Json::value_t::boolean: return "a boolean";
    case Json::value_t::number_integer:
    case Json::value_t::number_unsigned:
    case Json::value_t::number_float: return "a number";
    case Json::value_t::string: return "a string";
    case Json::value_t::array: return "an array";
    case Json::value_t::object: return "an object";
    default: return "an unsupported value";
  }
}

}  // namespace xmate::teach
