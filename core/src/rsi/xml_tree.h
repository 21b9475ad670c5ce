// SPDX-License-Identifier: Apache-2.0
// A small element tree of an XML file, read with expat, that remembers the line of every element:
// the RSI config readers check it and name the file and line of whatever is wrong. For set-up only
// (it allocates); the datagram codec does not use it.
#pragma once

#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace xmate::rsi {

// A problem in an RSI file: what() is "FILE:LINE: what is wrong; what to do".
class ConfigError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct XmlElement {
  std::string name;
  std::vector<std::pair<std::string, std::string>> attributes;  // in document order
  std::string text;                                              // character data, trimmed
  int line = 0;
  std::vector<XmlElement> children;

  // The attribute's value, or nullptr. Exact name.
  const std::string* attribute(std::string_view attribute_name) const;
  // The first child element of that name, or nullptr.
  const XmlElement* child(std::string_view child_name) const;
};

// The whole file; ConfigError "PATH: cannot open the <what>; ..." if it cannot be read.
std::string readTextFile(const std::string& path, const char* what);

// Reads and parses `path` (UTF-8, a byte-order mark allowed). Throws ConfigError naming the file
// and line of a syntax error, or saying why the file cannot be read.
XmlElement readXmlFile(const std::string& path);

// The same for text in memory; `name` stands for the file in messages.
XmlElement parseXml(std::string_view text, const std::string& name);

}  // namespace xmate::rsi
