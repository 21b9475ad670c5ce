// SPDX-License-Identifier: Apache-2.0
// INIParser (xmate/ini.h) on inih: inih splits the file into sections and "key = value" lines; this
// adapter keeps the class's documented rules on top of it: surrounding whitespace and quotes
// trimmed, comments starting with ';' or '#' (whole lines, or after whitespace at the end of a
// value), no continuation lines, and the line number with what was wrong when a line is malformed.
#include <xmate/ini.h>

#include <ini.h>  // inih's C API (not our xmate/ini.h)

#include <cctype>
#include <cerrno>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <sstream>

namespace xmate {
namespace {

// inih reads a line into a fixed buffer of INI_MAX_LINE bytes (with its '\n'); a longer line would
// be split in two, so it is refused instead.
constexpr size_t kMaxLine = INI_MAX_LINE - 2;

using Values = std::map<std::string, std::map<std::string, std::string>>;

std::string trim(const std::string& s) {
  const auto first = s.find_first_not_of(" \t\r\n");
  if (first == std::string::npos) return {};
  const auto last = s.find_last_not_of(" \t\r\n");
  return s.substr(first, last - first + 1);
}

// inih cuts ';' comments after whitespace itself; '#' after whitespace is a comment here too.
std::string withoutHashComment(const std::string& value) {
  for (size_t i = 1; i < value.size(); ++i)
    if (value[i] == '#' && (value[i - 1] == ' ' || value[i - 1] == '\t')) return value.substr(0, i);
  return value;
}

std::string unquote(const std::string& v) {
  if (v.size() >= 2 && (v.front() == '"' || v.front() == '\'') && v.back() == v.front())
    return v.substr(1, v.size() - 2);
  return v;
}

// Called by inih for each "key = value" line; 0 marks the line as malformed (an empty key).
int onValue(void* user, const char* section, const char* name, const char* value) {
  const std::string key = trim(name);
  if (key.empty()) return 0;
  (*static_cast<Values*>(user))[trim(section)][key] = unquote(trim(withoutHashComment(value)));
  return 1;
}

// The file's lines without their leading whitespace: an indented line is a line of its own, not
// the continuation of the previous value that inih would make of it.
std::string withoutIndentation(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  bool line_start = true;
  for (const char c : text) {
    if (line_start && (c == ' ' || c == '\t')) continue;
    out += c;
    line_start = c == '\n';
  }
  return out;
}

// Line `number` (1-based) of text, without its line break.
std::string lineOf(const std::string& text, int number) {
  std::istringstream in(text);
  std::string line;
  for (int n = 1; std::getline(in, line); ++n)
    if (n == number) return line;
  return {};
}

}  // namespace

bool INIParser::ReadINI(const std::string& file) {
  values_.clear();
  error_.clear();
  std::ifstream in(file, std::ios::binary);
  if (!in) {
    error_ = file + ": cannot open the file";
    return false;
  }
  const std::string text = withoutIndentation(std::string(std::istreambuf_iterator<char>(in), {}));
  std::istringstream lines(text);
  std::string line;
  for (int number = 1; std::getline(lines, line); ++number)
    if (line.size() > kMaxLine) {
      error_ = file + ":" + std::to_string(number) + ": the line is longer than " + std::to_string(kMaxLine) +
               " characters; shorten it";
      return false;
    }
  Values values;
  const int bad_line = ini_parse_string(text.c_str(), onValue, &values);
  if (bad_line != 0) {
    const std::string where = file + ":" + std::to_string(bad_line) + ": ";
    const std::string content = trim(lineOf(text, bad_line));
    if (bad_line < 0)
      error_ = file + ": out of memory while reading the file";
    else if (!content.empty() && content.front() == '[')
      error_ = where + "a section header must look like [name]";
    else
      error_ = where + "expected key = value, got '" + content + "'";
    return false;
  }
  values_ = std::move(values);
  return true;
}

std::string INIParser::GetString(const std::string& section, const std::string& key) const {
  const auto s = values_.find(section);
  if (s == values_.end()) return {};
  const auto k = s->second.find(key);
  return k == s->second.end() ? std::string() : k->second;
}

int INIParser::GetInt(const std::string& section, const std::string& key) const {
  const std::string v = GetString(section, key);
  char* end = nullptr;
  errno = 0;
  const long n = std::strtol(v.c_str(), &end, 0);
  if (v.empty() || *end != '\0' || errno == ERANGE || n < INT32_MIN || n > INT32_MAX) return 0;
  return int(n);
}

double INIParser::GetDouble(const std::string& section, const std::string& key) const {
  const std::string v = GetString(section, key);
  char* end = nullptr;
  const double d = std::strtod(v.c_str(), &end);
  return v.empty() || *end != '\0' ? 0.0 : d;
}

bool INIParser::GetBool(const std::string& section, const std::string& key) const {
  std::string v = GetString(section, key);
  for (char& c : v) c = char(std::tolower(static_cast<unsigned char>(c)));
  return v == "1" || v == "true" || v == "yes" || v == "on";
}

}  // namespace xmate
