// SPDX-License-Identifier: Apache-2.0
// INIParser: "[section]" headers, "key = value" lines, comments starting with ';' or '#' (whole
// lines, or after whitespace at the end of a value), surrounding whitespace and quotes trimmed.
#include <xmate/ini.h>

#include <cctype>
#include <cerrno>
#include <cstdint>
#include <cstdlib>
#include <fstream>

namespace xmate {
namespace {

std::string trim(const std::string& s) {
  const auto first = s.find_first_not_of(" \t\r\n");
  if (first == std::string::npos) return {};
  const auto last = s.find_last_not_of(" \t\r\n");
  return s.substr(first, last - first + 1);
}

// Cuts a trailing comment: ';' or '#' at the start or preceded by whitespace.
std::string withoutComment(const std::string& line) {
  for (size_t i = 0; i < line.size(); ++i)
    if ((line[i] == ';' || line[i] == '#') && (i == 0 || line[i - 1] == ' ' || line[i - 1] == '\t'))
      return line.substr(0, i);
  return line;
}

std::string unquote(const std::string& v) {
  if (v.size() >= 2 && (v.front() == '"' || v.front() == '\'') && v.back() == v.front())
    return v.substr(1, v.size() - 2);
  return v;
}

}  // namespace

bool INIParser::ReadINI(const std::string& file) {
  values_.clear();
  error_.clear();
  std::ifstream in(file);
  if (!in) {
    error_ = file + ": cannot open the file";
    return false;
  }
  std::string section;
  std::string raw;
  for (int number = 1; std::getline(in, raw); ++number) {
    const std::string line = trim(withoutComment(raw));
    if (line.empty()) continue;
    if (line.front() == '[') {
      if (line.back() != ']' || line.size() < 3) {
        error_ = file + ":" + std::to_string(number) + ": a section header must look like [name]";
        return false;
      }
      section = trim(line.substr(1, line.size() - 2));
      continue;
    }
    const auto eq = line.find('=');
    if (eq == std::string::npos || trim(line.substr(0, eq)).empty()) {
      error_ = file + ":" + std::to_string(number) + ": expected key = value, got '" + line + "'";
      return false;
    }
    values_[section][trim(line.substr(0, eq))] = unquote(trim(line.substr(eq + 1)));
  }
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
