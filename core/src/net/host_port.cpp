// SPDX-License-Identifier: Apache-2.0
// splitHostPort (host_port.h).
#include "net/host_port.h"

#include <charconv>

namespace xmate::net {

HostPortProblem splitHostPort(std::string_view text, uint16_t default_port, HostPort& out) {
  const size_t colon = text.rfind(':');
  out.host = std::string(text.substr(0, colon));
  out.port_text = colon == std::string_view::npos ? std::string() : std::string(text.substr(colon + 1));
  out.port = default_port;
  if (out.host.empty()) return HostPortProblem::kNoHost;
  if (colon == std::string_view::npos) return default_port == 0 ? HostPortProblem::kNoPort : HostPortProblem::kNone;
  long port = 0;
  const char* end = out.port_text.data() + out.port_text.size();
  const auto [ptr, ec] = std::from_chars(out.port_text.data(), end, port);
  if (out.port_text.empty() || ec != std::errc() || ptr != end || port < 1 || port > 65535)
    return HostPortProblem::kBadPort;
  out.port = uint16_t(port);
  return HostPortProblem::kNone;
}

}  // namespace xmate::net
