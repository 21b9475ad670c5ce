// SPDX-License-Identifier: Apache-2.0
// rci-cli bench client: what one cycle costs the client -- decode the RobotState, publish it,
// call a JointControl callback, check and encode the RobotCommand, send it -- timed on the exact
// production path (client::processDatagram) with states fed from memory, against two references
// measured in the same run: a bare memcpy of the datagram and a raw sendto of 290 bytes.
#include <algorithm>
#include <cstdio>
#include <cstring>
#include <memory>
#include <vector>

#include "bench_stats.h"
#include "cli.h"
#include "client/connection_rt.h"
#include "net/clock.h"
#include "net/udp_socket.h"
#include "protocol/realtime_codec.h"

namespace rci_cli {

int runBenchClient(long cycles) {
  using namespace xmate;
  // The "controller": a UDP socket the commands go to, drained between measurements.
  net::UdpSocket sink;
  sink.bind("127.0.0.1", 0);
  sink.setBufferSizes(4 << 20, 4 << 20);
  const net::Endpoint controller = net::makeEndpoint("127.0.0.1", sink.localPort());

  auto samples = std::make_unique<client::SampleRing>();
  auto rt = std::make_unique<client::Connection::Realtime>();
  rt->udp.bind("127.0.0.1", 0);
  rt->controller = controller;
  rt->samples = samples.get();
  rt->silence_limit_ns = int64_t(1) << 62;

  // A run in progress with a callback like the manual's: start + an offset from a cheap formula.
  std::array<double, 7> start{0, 0.5, 0, 1.0, 0, 1.5, 0};
  const JointControl callback = [&](RCI::robot::RobotState s) -> JointPositions {
    JointPositions out{start, false};
    out.q[0] += 1e-6 * double(s.message_id % 1000);
    return out;
  };
  rt->kind = client::ControlKind::kJoint;
  rt->callback = &callback;
  rt->run_state.store(client::kRunArmed);
  client::beginRunIfArmed(*rt, net::monotonicNs());

  RCI::robot::RobotState state;
  state.q = start;
  state.q_c = start;
  state.toolTobase_pos_m = {1, 0, 0, 0.5, 0, 1, 0, 0, 0, 0, 1, 0.5, 0, 0, 0, 1};
  state.toolTobase_pos_c = state.toolTobase_pos_m;
  state.control_command_success_rate = 1;
  state.robot_mode = RCI::robot::RobotMode::kMove;
  state.motion_generator_mode = RCI::robot::MotionGeneratorMode::kJointPosition;
  protocol::RobotStateBuffer encoded;
  protocol::RobotCommandBuffer command_bytes{};

  const size_t n = static_cast<size_t>(cycles);
  std::vector<int64_t> client_ns(n), memcpy_ns(n), sendto_ns(n);
  for (long k = 0; k < cycles; ++k) {
    if (k % 256 == 0) {
      drain(sink);
      client::StateSample scratch[256];
      while (samples->popBatch(scratch, 256) > 0) {
      }
    }
    state.message_id = uint64_t(k + 1);
    protocol::encodeRobotState(state, encoded);  // the controller's work, not timed

    int64_t t0 = net::monotonicNs();
    std::memcpy(rt->datagram.data(), encoded.data(), encoded.size());  // reference 1: copy the datagram
    int64_t t1 = net::monotonicNs();
    memcpy_ns[size_t(k)] = t1 - t0;

    t0 = net::monotonicNs();
    client::processDatagram(*rt, long(encoded.size()), controller, t0);  // the client's whole cycle
    t1 = net::monotonicNs();
    client_ns[size_t(k)] = t1 - t0;

    t0 = net::monotonicNs();
    rt->udp.sendTo(controller, command_bytes.data(), command_bytes.size());  // reference 2: a raw sendto
    t1 = net::monotonicNs();
    sendto_ns[size_t(k)] = t1 - t0;
  }
  if (rt->run_state.load() != client::kRunArmed || rt->counters.commands_sent != uint64_t(cycles)) {
    std::fprintf(stderr, "rci-cli: bench client: the loop did not answer every state (%llu of %ld)\n",
                 static_cast<unsigned long long>(rt->counters.commands_sent), cycles);
    return 1;
  }

  const Percentiles c = percentilesOf(client_ns), m = percentilesOf(memcpy_ns), s = percentilesOf(sendto_ns);
  std::printf("rci-cli bench client: %ld cycles, one thread, loopback\n", cycles);
  printPercentilesHeader();
  printPercentilesRow("client cycle: decode+publish+callback+encode+send", c);
  printPercentilesRow("reference: memcpy of the 1247-byte datagram", m);
  printPercentilesRow("reference: raw sendto of 290 bytes", s);
  std::printf("  client cost above a raw sendto (medians): %.3f us\n", c.median - s.median);
  std::printf("  budget: median <= 5 us -> %s\n", c.median <= 5.0 ? "met" : "NOT met");
  return 0;
}

}  // namespace rci_cli
