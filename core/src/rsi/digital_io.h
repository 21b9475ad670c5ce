// SPDX-License-Identifier: Apache-2.0
// The robot's digital inputs and outputs the PC reaches over RSI: those the context wires between a
// DIGIN/DIGOUT object and the ETHERNET object, read from the <Rob> and set in the <Sen>. docs/rsi.md,
// "Digital IO".
#pragma once

#include <string>
#include <vector>

#include "rsi/config.h"
#include "rsi/link.h"

namespace xmate::rsi {

// One wired signal: the controller's $IN[signal] or $OUT[signal] and the datagram value carrying it.
struct DigitalSignal {
  int signal = 0;         // $IN / $OUT number, 1-based
  std::string tag;        // the SEND or RECEIVE element's TAG, e.g. "DiIn.I1"
  std::string element;    // its datagram element and attribute
  std::string attribute;
  std::string object;     // the DIGIN or DIGOUT object, e.g. "DIGIN1"
};

struct DigitalIoMap {
  std::vector<DigitalSignal> inputs;   // DIGIN output k -> ETHERNET input n -> SEND element with INDX n
  std::vector<DigitalSignal> outputs;  // RECEIVE element with INDX n -> ETHERNET output n -> DIGOUT input j
  const DigitalSignal* input(int signal) const;
  const DigitalSignal* output(int signal) const;
};

// The signals the context wires to the PC: output k of a DIGIN object is $IN[Index + k - 1], input
// j of a DIGOUT object sets $OUT[Index + j - 1] (Index: the object's parameter, 1 when absent), each
// with the Ethernet config's element of the ETHERNET channel wired to it. Wires to channels the
// config does not have are left out. Throws ConfigError naming file and line for an Index that is
// not a whole number from 1. Set-up; any thread.
DigitalIoMap digitalIoMap(const Context& context, const EthernetConfig& config);

// Sets and reads the wired signals through a running link.
class DigitalIo {
 public:
  // Set-up. Throws std::invalid_argument if the link's config lacks an element of the map.
  DigitalIo(Link& link, DigitalIoMap map);

  // Any thread, lock-free: $OUT[signal] in every answer from the next one on. Throws
  // std::out_of_range, saying which outputs are wired, for a signal that is not.
  void setOutput(int signal, bool level);
  // Any thread, lock-free: $IN[signal] in the newest <Rob>. Throws std::out_of_range as setOutput,
  // std::runtime_error if no <Rob> has arrived yet.
  bool input(int signal) const;

  const DigitalIoMap& map() const { return map_; }

 private:
  Link& link_;
  DigitalIoMap map_;
  std::vector<int> input_slots_, output_slots_;  // as map_.inputs / map_.outputs
};

}  // namespace xmate::rsi
