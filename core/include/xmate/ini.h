// SPDX-License-Identifier: Apache-2.0
// INIParser: reads the user's xmate.ini ([network] ip=... port=...) as the vendor examples do.
#pragma once

#include <map>
#include <string>

namespace xmate {

// Threads: any, one parser per thread; reads a file (not real-time safe).
class INIParser {
 public:
  // Reads file; false if it cannot be opened or a line is malformed (see LastError()).
  bool ReadINI(const std::string& file);
  // Missing keys give "" / 0 / 0.0 / false.
  std::string GetString(const std::string& section, const std::string& key) const;
  int GetInt(const std::string& section, const std::string& key) const;
  double GetDouble(const std::string& section, const std::string& key) const;
  bool GetBool(const std::string& section, const std::string& key) const;
  // Extension: what went wrong in the last ReadINI, with the line number.
  const std::string& LastError() const { return error_; }

 private:
  std::map<std::string, std::map<std::string, std::string>> values_;
  std::string error_;
};

}  // namespace xmate
