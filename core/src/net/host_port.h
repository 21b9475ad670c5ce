// SPDX-License-Identifier: Apache-2.0
// "HOST:PORT" split into its parts, the one way every program here reads an address (rci-cli's
// --robot and --sensor, rci-sim's --rsi-target, the window's robot field); each caller words its
// own message from the problem. Any thread; allocates.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

namespace xmate::net {

enum class HostPortProblem {
  kNone,
  kNoHost,   // nothing before the colon (or the text is empty)
  kNoPort,   // no colon, and a port is required
  kBadPort,  // the port is not a whole number from 1 to 65535
};

struct HostPort {
  std::string host;
  uint16_t port = 0;
  std::string port_text;  // as written after the last colon ("" without one)
};

// The text after the last colon is the port; without a colon the port is `default_port`, or
// kNoPort when that is 0. Surrounding white space is not trimmed.
HostPortProblem splitHostPort(std::string_view text, uint16_t default_port, HostPort& out);

}  // namespace xmate::net
