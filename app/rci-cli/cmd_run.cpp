// SPDX-License-Identifier: Apache-2.0
// rci-cli run: loads a program, connects to a robot (or starts an in-process simulator for the
// program's model: real-time clock, or lock-step with --fast), runs the pre-flight and the executor
// (core/src/teach), prints a line per instruction, and writes the run report. Ctrl-C stops the
// robot smoothly on its path.
#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <thread>

#include <xmate/robot.h>

#include "cli.h"
#include "model/robot_spec.h"
#include "sim/server.h"
#include "teach/executor.h"
#include "teach/program_io.h"
#include "teach/report.h"

namespace rci_cli {
namespace {

using namespace xmate::teach;

std::atomic<bool> g_interrupted{false};
extern "C" void onInterrupt(int) { g_interrupted.store(true); }

// Real-time clock by default: the motions take their real durations, as on a robot. --fast: the
// lock-step clock, which waits for each answer and otherwise runs as fast as the client answers.
xmate::sim::ClockMode simulatorClock(const RunOptions& o) {
  return o.fast ? xmate::sim::ClockMode::kLockStep : xmate::sim::ClockMode::kRealTime;
}

const char* clockText(xmate::sim::ClockMode clock) {
  return clock == xmate::sim::ClockMode::kLockStep ? "lock-step clock, faster than real time" : "real-time clock";
}

std::unique_ptr<xmate::sim::Server> startSimulator(xmate::XmateType type, xmate::sim::ClockMode clock) {
  auto config = xmate::sim::embeddedConfig(type, clock);
  config.sim.motors_on_at_start = true;
  config.sim.do_to_di_loopback = true;  // DO k drives DI k, so SET_DO / WAIT_DI pairs work without wiring
  return xmate::sim::startEmbedded(std::move(config));
}

void printDone(const Program& program, size_t i, const InstructionReport& r) {
  const Instruction& in = program.instructions[i];
  std::printf("[%zu/%zu] %-7s %-10s %-8s %7.3f s", i + 1, program.instructions.size(), typeName(in.type),
              in.name.c_str(), statusName(r.status), r.duration);
  if (isMotion(in.type))
    std::printf("  TCP (%.4f, %.4f, %.4f) m  max tracking error %.2e rad / %.3f mm", r.pose[3], r.pose[7],
                r.pose[11], r.max_joint_error, r.max_tcp_error * 1000);
  std::printf("\n");
  if (isMotion(in.type) && !r.settled)
    std::printf("        not at rest 1 s after the motion (joint error %.2e rad): check the payload and the "
                "joint impedance\n",
                r.settle_error);
  if (!r.message.empty() && r.status != InstructionStatus::kDone) std::printf("        %s\n", r.message.c_str());
  std::fflush(stdout);
}

// Polls for Ctrl-C and turns it into a smooth stop; ends when `done` is set.
std::thread interruptWatcher(Executor& executor, const std::atomic<bool>& done) {
  return std::thread([&executor, &done] {
    while (!done.load()) {
      if (g_interrupted.exchange(false)) {
        std::fprintf(stderr, "rci-cli: interrupted -- stopping the robot smoothly on its path\n");
        executor.stop();
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
  });
}

// The controller time of the motions plus the wall time of the other instructions.
double instructionSeconds(const RunReport& report) {
  double total = 0;
  for (const InstructionReport& r : report.instructions)
    if (r.status != InstructionStatus::kNotRun) total += r.duration;
  return total;
}

void printFinished(const RunOptions& o, const Program& program, const RunReport& report) {
  std::printf("finished: %zu instructions in %.2f s", program.instructions.size(), report.duration);
  if (o.robot.in_process && o.fast)
    std::printf(" (in-process simulator, %s; the instructions' own durations add up to %.2f s)",
                clockText(simulatorClock(o)), instructionSeconds(report));
  else if (o.robot.in_process)
    std::printf(" (in-process simulator, %s)", clockText(simulatorClock(o)));
  std::printf("\n");
}

}  // namespace

int runRun(const RunOptions& o) {
  if (o.fast && !o.robot.in_process)
    throw UsageError("--fast applies to the in-process simulator (--robot sim); a controller keeps its own clock: "
                     "leave out --fast");
  const Program program = loadProgram(o.program_path);
  const xmate::XmateType type = o.have_model ? o.model : program.robot;
  requireRobot(program, type);

  std::unique_ptr<xmate::sim::Server> server;
  HostPort address = o.robot.address;
  if (o.robot.in_process) {
    server = startSimulator(type, simulatorClock(o));
    address = {"127.0.0.1", server->port()};
  }
  xmate::Robot robot(address.host, address.port, type);
  robot.connect();
  const std::string where = o.robot.in_process ? std::string(" (in-process simulator, ") + clockText(simulatorClock(o)) + ")" : "";
  std::printf("running %s (%zu instructions, %s) on %s:%u%s at %.0f %% speed\n", o.program_path.c_str(),
              program.instructions.size(), std::string(xmate::model::robotSpec(type).display_name).c_str(),
              address.host.c_str(), address.port, where.c_str(), o.speed * 100);
  std::fflush(stdout);

  Executor executor;
  ExecutorOptions options;
  options.speed_override = o.speed;
  options.on_done = [&](size_t i, const InstructionReport& r) { printDone(program, i, r); };
  std::signal(SIGINT, onInterrupt);
  std::atomic<bool> done{false};
  std::thread watcher = interruptWatcher(executor, done);
  const RunReport report = executor.run(robot, program, options);
  done.store(true);
  watcher.join();
  std::signal(SIGINT, SIG_DFL);

  if (!o.report_path.empty()) {
    saveReport(o.report_path, program, report);
    std::printf("report written to %s\n", o.report_path.c_str());
  }
  switch (report.outcome) {
    case RunState::kFinished:
      printFinished(o, program, report);
      return 0;
    case RunState::kRefused:
      std::fprintf(stderr, "rci-cli: %s", report.message.c_str());
      return 1;
    default:
      std::fprintf(stderr, "rci-cli: %s: %s\n", runStateName(report.outcome), report.message.c_str());
      return 1;
  }
}

}  // namespace rci_cli
