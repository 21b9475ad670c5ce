// SPDX-License-Identifier: Apache-2.0
// The control ports' line protocol, shared by the simulated xMate (server_control.h) and the
// simulated KRC (krc_control.h): a line split into words, argument parsers whose errors say what
// was wrong, and a command table that answers each line with "ok ..." or "error <what>; usage: ...".
// Any thread; allocates.
#pragma once

#include <array>
#include <functional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace xmate::sim {

using Words = std::vector<std::string_view>;

// The words of a line, split at white space.
Words splitWords(std::string_view line);

// A command's mistake: the message says what was wrong; the dispatcher adds the usage.
struct ControlUsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Each throws ControlUsageError naming `what` and what it takes.
double parseNumber(std::string_view word, const char* what);
int parseInteger(std::string_view word, const char* what, int min, int max);
bool parseOnOff(std::string_view word);
void expectWords(const Words& words, size_t count);  // the command and count - 1 arguments

// A fault for the next N datagrams, "VERB NOUN N" ("drop answers 5", "corrupt states 3"): applies
// `apply(N)` (N from 1 to `max`) and answers "DOING the next N NOUN". Throws ControlUsageError for
// another noun or a bad N.
template <class Apply>
std::string runCountFault(const Words& words, const char* noun, const char* doing, int max, Apply apply);

// "wrench FX FY FZ TX TY TZ": the six numbers (N, Nm), and the answer's text naming `where` it acts
// ("at the TCP", "at the flange").
std::array<double, 6> parseWrench(const Words& words);
std::string wrenchText(const std::array<double, 6>& wrench, const char* where);

template <class Apply>
std::string runCountFault(const Words& words, const char* noun, const char* doing, int max, Apply apply) {
  expectWords(words, 3);
  if (words[1] != noun)
    throw ControlUsageError("this fault applies to " + std::string(noun) + " only, got '" + std::string(words[1]) + "'");
  const int n = parseInteger(words[2], "N", 1, max);
  apply(n);
  return std::string(doing) + " the next " + std::to_string(n) + " " + noun;
}

template <class Target>
struct ControlCommand {
  const char* name;
  const char* usage;
  std::function<std::string(Target&, const Words&)> run;  // returns the text after "ok"
};

// "commands: usage | usage | ... | quit".
template <class Target>
std::string commandsHelp(const std::vector<ControlCommand<Target>>& commands) {
  std::string text = "commands:";
  for (const ControlCommand<Target>& c : commands) text += std::string(" | ") + c.usage;
  return text + " | quit";
}

// Runs the command the line names; never throws.
template <class Target>
std::string executeCommand(Target& target, const std::vector<ControlCommand<Target>>& commands, std::string_view line) {
  const Words words = splitWords(line);
  if (words.empty()) return "error empty line; type help";
  for (const ControlCommand<Target>& c : commands) {
    if (words[0] != c.name) continue;
    try {
      return "ok " + c.run(target, words);
    } catch (const ControlUsageError& e) {
      return std::string("error ") + c.name + ": " + e.what() + "; usage: " + c.usage;
    } catch (const std::exception& e) {
      return std::string("error ") + c.name + ": " + e.what();
    }
  }
  return "error unknown command '" + std::string(words[0]) + "'; type help for the list";
}

}  // namespace xmate::sim
