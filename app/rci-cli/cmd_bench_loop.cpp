// SPDX-License-Identifier: Apache-2.0
// rci-cli bench loop: a 1 kHz JointControl loop (a slow out-and-back swing of joint 1) against an
// in-process simulator (sim::Server, real-time clock by default) or a given robot. Prints the cycle
// period statistics, jitter, late and lost cycles, the command success rate, and the KUKA RSI
// paper's min/max/mean table (docs/performance.md) over the whole run.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <numbers>
#include <vector>

#include <xmate/robot.h>

#include "cli.h"
#include "client/connection.h"
#include "net/clock.h"
#include "sim/server.h"

namespace rci_cli {
namespace {

using CM = RCI::robot::StartMoveRequest::ControllerMode;
using MM = RCI::robot::StartMoveRequest::MotionGeneratorMode;

// What the callback records, preallocated before the loop so that it allocates nothing.
struct Recording {
  std::vector<int64_t> arrival_ns;  // when each state reached the callback
  std::vector<uint64_t> message_id;
  double min_success_rate = 1.0;
  long cycles = 0;
};

std::unique_ptr<xmate::sim::Server> startSimulator(const LoopOptions& o) {
  auto config = xmate::sim::embeddedConfig(
      o.type, o.lockstep ? xmate::sim::ClockMode::kLockStep : xmate::sim::ClockMode::kRealTime);
  config.realtime = true;
  config.sim.motors_on_at_start = true;
  return xmate::sim::startEmbedded(std::move(config));
}

// Runs the loop: q1(t) = q1(0) + A sin^2(pi t / T), at rest at both ends.
void runLoop(xmate::Robot& robot, Recording& rec, long cycles) {
  rec.arrival_ns.assign(size_t(cycles), 0);
  rec.message_id.assign(size_t(cycles), 0);
  std::array<double, 7> start{};
  const double duration = double(cycles) * 1e-3;
  robot.startMove(CM::kJointPosition, MM::kJointPosition);
  robot.Control(xmate::JointControl([&](RCI::robot::RobotState s) -> xmate::JointPositions {
    const long k = rec.cycles++;
    rec.arrival_ns[size_t(k)] = xmate::net::monotonicNs();
    rec.message_id[size_t(k)] = s.message_id;
    // The controller's window of the last 100 commands starts empty with the motion.
    if (k >= 100) rec.min_success_rate = std::min(rec.min_success_rate, s.control_command_success_rate);
    if (k == 0) start = s.q_c;
    const double t = double(s.message_id - rec.message_id[0] + 1) * 1e-3;
    const double x = std::sin(std::numbers::pi * std::min(t, duration) / duration);
    xmate::JointPositions out{start, false};
    out.q[0] += 0.05 * x * x;
    return k + 1 >= cycles ? xmate::MotionFinished(out) : out;
  }));
}

struct Stats {
  double min = 0, max = 0, mean = 0, p50 = 0, p99 = 0, p999 = 0;
};

Stats statsOf(std::vector<double> v) {
  Stats s;
  if (v.empty()) return s;
  std::sort(v.begin(), v.end());
  auto at = [&](double f) { return v[std::min(v.size() - 1, size_t(f * double(v.size())))]; };
  s.min = v.front();
  s.max = v.back();
  double sum = 0;
  for (double x : v) sum += x;
  s.mean = sum / double(v.size());
  s.p50 = at(0.5);
  s.p99 = at(0.99);
  s.p999 = at(0.999);
  return s;
}

void printRow(const char* name, const Stats& s) {
  std::printf("  %-34s %9.2f %9.2f %9.2f %9.2f %9.2f\n", name, s.min, s.mean, s.p99, s.p999, s.max);
}

}  // namespace

int runBenchLoop(const LoopOptions& o) {
  if (o.lockstep && !o.robot.in_process)
    throw UsageError("--lockstep applies to the in-process simulator (--robot sim); leave out --lockstep or --robot");
  std::unique_ptr<xmate::sim::Server> server;
  if (o.robot.in_process) server = startSimulator(o);
  const std::string host = o.robot.in_process ? "127.0.0.1" : o.robot.address.host;
  const uint16_t port = o.robot.in_process ? server->port() : o.robot.address.port;
  xmate::Robot robot(host, port, o.type);
  robot.connect();
  robot.setMotorPower(1);
  xmate::client::Connection& session = robot.connection();

  std::printf("rci-cli bench loop: %ld cycles against %s (%s:%u)%s\n", o.cycles,
              o.robot.in_process ? "the in-process simulator" : "a robot", host.c_str(), port,
              o.robot.in_process ? (o.lockstep ? ", lock-step clock" : ", real-time clock") : "");
  std::printf("  client real-time thread: %s\n", session.realtimeStatus().describe().c_str());
  if (server) std::printf("  simulator cycle thread:  %s\n", server->status().realtime.c_str());

  const auto before = server ? server->status().counters : xmate::sim::ServerCounters{};
  Recording rec;
  std::string failure;  // why the loop stopped early, if it did (the statistics so far are printed)
  try {
    runLoop(robot, rec, o.cycles);
  } catch (const xmate::XmateException& e) {
    failure = e.what();
  }
  const auto after = server ? server->status().counters : xmate::sim::ServerCounters{};
  const xmate::client::SessionTiming timing = session.timing();

  std::vector<double> period_us, jitter_us;
  uint64_t missed = 0;
  for (long k = 1; k < rec.cycles; ++k) {
    const double p = double(rec.arrival_ns[size_t(k)] - rec.arrival_ns[size_t(k - 1)]) / 1000.0;
    period_us.push_back(p);
    jitter_us.push_back(std::abs(p - 1000.0));
    missed += rec.message_id[size_t(k)] - rec.message_id[size_t(k - 1)] - 1;
  }
  const Stats period = statsOf(period_us), jitter = statsOf(jitter_us);
  const auto longest = std::max_element(period_us.begin(), period_us.end());
  const long late = long(std::count_if(period_us.begin(), period_us.end(), [](double p) { return p > 1500.0; }));

  std::printf("\n  %-34s %9s %9s %9s %9s %9s   (us)\n", "over the run", "min", "mean", "p99", "p99.9", "max");
  printRow("cycle period (state to state)", period);
  printRow("period jitter |period - 1000 us|", jitter);
  std::printf("\n  late cycles (period > 1.5 ms):    %ld of %ld (%.3f %%)\n", late, long(period_us.size()),
              100.0 * double(late) / double(std::max<size_t>(1, period_us.size())));
  if (longest != period_us.end())
    std::printf("  longest period:                   %.0f us, before cycle %ld\n", *longest,
                long(longest - period_us.begin()) + 1);
  std::printf("  states the client never got:      %llu (message_id gaps)\n", static_cast<unsigned long long>(missed));
  std::printf("  command success rate (last 100):  min %.3f during the run (from cycle 100)\n", rec.min_success_rate);
  if (server) {
    const uint64_t used = after.commands_used - before.commands_used;
    const uint64_t lost = after.commands_lost - before.commands_lost;
    std::printf("  commands on time (simulator):     %llu of %llu (%.3f %%), %llu lost or late\n",
                static_cast<unsigned long long>(used), static_cast<unsigned long long>(used + lost),
                100.0 * double(used) / double(std::max<uint64_t>(1, used + lost)), static_cast<unsigned long long>(lost));
  }

  std::printf("\n  The paper's table (docs/performance.md), over %ld cycles:\n", rec.cycles);
  std::printf("  %-40s %9s %9s %9s\n", "(us)", "min", "max", "mean");
  std::printf("  %-40s %9.2f %9.2f %9.2f\n", "cycle period jitter |period - 1 ms|", jitter.min, jitter.max, jitter.mean);
  std::printf("  %-40s %9.2f %9.2f %9.2f\n", "client response (state in -> command out)", timing.cost.min_us,
              timing.cost.max_us, timing.cost.mean_us);
  if (!failure.empty()) {
    std::fprintf(stderr, "\nrci-cli: the loop stopped after %ld of %ld cycles: %s\n", rec.cycles, o.cycles,
                 failure.c_str());
    return 1;
  }
  return 0;
}

}  // namespace rci_cli
