// SPDX-License-Identifier: Apache-2.0
// rci-cli ft: reads an ATI Net F/T sensor (ft::NetFtClient) and prints one line per new sample:
// sequence, Fx Fy Fz in N, Tx Ty Tz in Nm, the sensor's status word.
#include <chrono>
#include <cstdio>
#include <thread>

#include "cli.h"
#include "ft/netft.h"

namespace rci_cli {

int runFt(const FtOptions& options) {
  xmate::ft::NetFtOptions o;
  o.host = options.host;
  o.port = options.port;
  o.counts_per_force = o.counts_per_torque = options.counts_per_unit;
  xmate::ft::NetFtClient client(o);
  client.start();
  constexpr auto kFirstSampleWithin = std::chrono::seconds(2);
  const auto deadline = std::chrono::steady_clock::now() + kFirstSampleWithin;
  xmate::ft::Wrench w;
  while (!client.latest(w)) {
    if (std::chrono::steady_clock::now() > deadline) {
      std::fprintf(stderr,
                   "rci-cli: no data from the F/T sensor at %s:%u within 2 s; check its address and port, that it is "
                   "switched on and that RDT output is enabled in its web page\n",
                   options.host.c_str(), unsigned(options.port));
      return 1;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  std::printf("# sequence  Fx Fy Fz [N]  Tx Ty Tz [Nm]  status\n");
  uint32_t last = w.rdt_sequence - 1;
  for (long printed = 0; options.count == 0 || printed < options.count;) {
    if (client.latest(w) && w.rdt_sequence != last) {
      last = w.rdt_sequence;
      std::printf("%10u  %9.4f %9.4f %9.4f  %8.5f %8.5f %8.5f  0x%08x\n", w.rdt_sequence, w.values[0], w.values[1],
                  w.values[2], w.values[3], w.values[4], w.values[5], w.status);
      ++printed;
    } else {
      std::this_thread::sleep_for(std::chrono::microseconds(500));
    }
  }
  const xmate::ft::NetFtStatistics s = client.statistics();
  std::printf("# %llu records, %llu lost, %.0f Hz\n", (unsigned long long)s.records, (unsigned long long)s.lost,
              s.rate_hz);
  return 0;
}

}  // namespace rci_cli
