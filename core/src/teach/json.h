// SPDX-License-Identifier: Apache-2.0
// A small, strict JSON reader and writer for the teach files (programs, run reports): objects,
// arrays, numbers, strings with escapes, true/false/null. Parse errors say line:column and what
// was expected. No Qt, no dependency beyond the standard library.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

namespace xmate::teach {

// Thrown by parseJson; what() reads "line L, column C: <what was wrong>".
class JsonError : public std::runtime_error {
 public:
  JsonError(int line, int column, const std::string& message);
  int line, column;
};

class JsonValue {
 public:
  enum class Kind { kNull, kBool, kNumber, kString, kArray, kObject };

  JsonValue() = default;  // null
  static JsonValue boolean(bool b);
  static JsonValue number(double d);
  static JsonValue string(std::string s);
  static JsonValue array();
  static JsonValue object();
  static JsonValue numbers(const double* values, size_t count);  // an array of numbers

  Kind kind() const { return kind_; }
  bool isNumber() const { return kind_ == Kind::kNumber; }
  bool isString() const { return kind_ == Kind::kString; }
  bool isArray() const { return kind_ == Kind::kArray; }
  bool isObject() const { return kind_ == Kind::kObject; }
  bool isBool() const { return kind_ == Kind::kBool; }

  // Scalars: the stored value (false / 0 / "" for another kind).
  bool asBool() const { return bool_; }
  double asNumber() const { return number_; }
  const std::string& asString() const { return string_; }

  // Arrays and objects: elements in order (an object's values pair with keys()).
  size_t size() const { return values_.size(); }
  const JsonValue& at(size_t i) const { return values_.at(i); }
  const std::vector<std::string>& keys() const { return keys_; }
  // Object member by key, nullptr if absent (or not an object).
  const JsonValue* find(const std::string& key) const;

  // Building: push onto an array, add a member to an object (keys are not checked for duplicates).
  JsonValue& push(JsonValue value);
  JsonValue& set(const std::string& key, JsonValue value);

 private:
  Kind kind_ = Kind::kNull;
  bool bool_ = false;
  double number_ = 0;
  std::string string_;
  std::vector<std::string> keys_;   // object only
  std::vector<JsonValue> values_;   // array elements or object values
};

// "null", "a boolean", "a number", "a string", "an array", "an object".
const char* kindName(JsonValue::Kind kind);

// Parses one JSON document (surrounding whitespace allowed). Throws JsonError on anything else:
// trailing text, duplicate keys, numbers that overflow to infinity, NaN/Infinity literals, control
// characters in strings, invalid escapes, nesting deeper than 200 levels.
JsonValue parseJson(const std::string& text);

// Writes the value as indented JSON (2 spaces; arrays of numbers on one line), numbers with 17
// significant digits so doubles round-trip. Throws std::invalid_argument for a non-finite number.
std::string writeJson(const JsonValue& value);

}  // namespace xmate::teach
