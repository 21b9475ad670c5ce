// SPDX-License-Identifier: Apache-2.0
// The program file format (docs/teach.md): JSON with "format": "rci-program", "version": 2 (1 is
// still read), the robot model, the tool and load, and the instructions (PATH needs version 2).
// Loading checks everything and names the instruction (number and type) and the field of the first
// problem; saving is atomic.
#pragma once

#include <stdexcept>
#include <string>

#include <nlohmann/json_fwd.hpp>

#include "teach/program.h"

namespace xmate::teach {

// A file that is not a valid program; what() says where (line:column, or instruction and field),
// what was found and what is expected.
class ProgramError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

inline constexpr const char* kProgramFormat = "rci-program";
inline constexpr int kProgramVersion = 2;         // what saving writes: adds "tool", "load" and PATH
inline constexpr int kOldestProgramVersion = 1;   // still read

// A parsed document (teach/json_text.h) <-> program.
Program programFromJson(const nlohmann::ordered_json& document);
nlohmann::ordered_json programToJson(const Program& program);

// Text <-> program. parseProgram throws ProgramError (JSON syntax errors included, as "not valid
// JSON: line L, column C: ..."); programText is indented JSON, the same text for the same program.
Program parseProgram(const std::string& text);
std::string programText(const Program& program);

// Files. loadProgram throws ProgramError for bad contents, std::runtime_error when the file cannot
// be read; the message starts with the path. saveProgram writes atomically (atomic_file.h) and
// throws std::runtime_error, leaving the old file, on failure.
Program loadProgram(const std::string& path);
void saveProgram(const std::string& path, const Program& program);

// Checks one instruction as loading would (kinds, ranges, finiteness, homogeneous poses); throws
// ProgramError naming it as instruction index + 1. For programs built in memory (the GUI).
void validateInstruction(const Instruction& instruction, size_t index, const model::RobotSpec& robot);

// Throws ProgramError unless the program was taught for `robot` ("the program is for xMate Pro 7,
// the robot is an xMate 3: ...").
void requireRobot(const Program& program, const model::RobotSpec& robot);
inline void requireRobot(const Program& program, XmateType type) { requireRobot(program, model::robotSpec(type)); }

}  // namespace xmate::teach
