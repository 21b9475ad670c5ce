// SPDX-License-Identifier: Apache-2.0
// JSON text for the teach files (programs, run reports), on nlohmann-json: a strict parse of a whole
// document and a stable, indented layout for writing. The format checks of a program are
// program_io's; this only turns text into a nlohmann::ordered_json (member order kept) and back.
#pragma once

#include <stdexcept>
#include <string>

#include <nlohmann/json.hpp>

namespace xmate::teach {

using Json = nlohmann::ordered_json;

// Thrown by parseJsonText; what() reads "line L, column C: <what was wrong>".
class JsonSyntaxError : public std::runtime_error {
 public:
  JsonSyntaxError(int line, int column, const std::string& message);
  int line, column;
};

// Parses one JSON document (surrounding whitespace allowed). Beyond nlohmann's own syntax checks
// (trailing text, control characters in strings, invalid escapes and UTF-8, NaN/Infinity) it
// refuses duplicate member names, numbers that overflow a double and nesting deeper than 200
// levels. Every error is a JsonSyntaxError with the line and column of the problem (1-based; the
// column counts bytes): for a syntax error the byte where nlohmann's parser stopped (of an
// unexpected token, its last byte), for a duplicate member its name's opening quote, for an
// overflowing number its first character, for invalid UTF-8 the first byte of the bad sequence.
Json parseJsonText(const std::string& text);

// The value as indented JSON (2 spaces per level; arrays of scalars on one line), member order as
// built, numbers with the shortest text that reads back as the same double, strings in UTF-8 (an
// invalid byte sequence is written as U+FFFD so that the file always reads back). Ends with a
// newline. Throws std::invalid_argument for a non-finite number.
std::string jsonText(const Json& value);

// "null", "a boolean", "a number", "a string", "an array", "an object".
const char* kindName(const Json& value);

}  // namespace xmate::teach
