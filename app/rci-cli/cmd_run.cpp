// SPDX-License-Identifier: Apache-2.0
// rci-cli run: loads a program, connects to a robot (or starts an in-process simulator for the
// program's model: real-time clock, or lock-step with --fast) -- an xMate over RCI, or a KUKA over
// RSI (rsi:ETHERNET.xml, or rsi-sim: an in-process simulated KRC) -- runs the pre-flight and the
// executor (core/src/teach), prints what the pre-flight announces and a line per instruction (a
// PATH also how closely it followed the demonstration and how much it was slowed), and writes the
// run report. Ctrl-C stops the robot smoothly on its path.
#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <thread>
#include <vector>

#include <xmate/robot.h>

#include "cli.h"
#include "model/resource_locator.h"
#include "model/robot_spec.h"
#include "arm/rsi_arm.h"
#include "arm/joint_stream.h"
#include "rsi/link.h"
#include "sim/krc_server.h"
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

// A PATH's own line: how long against the demonstration, how closely followed, how much slowed.
void printPath(const InstructionReport& r) {
  std::printf("        path %.3f s (demonstrated pace: %.3f s", r.duration, r.nominal_duration);
  if (r.lead_in > 0) std::printf("; lead-in move %.3f s", r.lead_in);
  std::printf("), deviation from the path %.3f mrad / %.3f mm, ", r.path_joint_deviation * 1000,
              r.path_tcp_deviation * 1000);
  if (r.slowest_pace < 1)
    std::printf("slowed to %.0f %% of the asked pace at t = %.2f s of the path (%.0f %% of its time slowed)\n",
                r.slowest_pace * 100, r.slowest_at, r.slowed_share * 100);
  else
    std::printf("never slowed\n");
}

// What the pre-flight announces (a PATH's lead-in move), before anything moves.
void printNotices(const std::vector<Problem>& notices) {
  for (const Problem& n : notices) std::printf("note: %s\n", n.message.c_str());
  std::fflush(stdout);
}

void printDone(const Program& program, size_t i, const InstructionReport& r) {
  const Instruction& in = program.instructions[i];
  std::printf("[%zu/%zu] %-7s %-10s %-8s %7.3f s", i + 1, program.instructions.size(), typeName(in.type),
              in.name.c_str(), statusName(r.status), r.duration);
  if (isMotion(in.type))
    std::printf("  TCP (%.4f, %.4f, %.4f) m  max tracking error %.2e rad / %.3f mm", r.pose[3], r.pose[7],
                r.pose[11], r.max_joint_error, r.max_tcp_error * 1000);
  std::printf("\n");
  if (in.type == InstructionType::kPath && r.status != InstructionStatus::kNotRun) printPath(r);
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

// Runs the program through `run_on_robot` with Ctrl-C turned into a smooth stop, a line per
// instruction and the report; the exit status.
int replay(const RunOptions& o, const Program& program,
           const std::function<RunReport(Executor&, const ExecutorOptions&)>& run_on_robot) {
  Executor executor;
  ExecutorOptions options;
  options.speed_override = o.speed;
  options.on_notices = printNotices;
  options.on_done = [&](size_t i, const InstructionReport& r) { printDone(program, i, r); };
  std::signal(SIGINT, onInterrupt);
  std::atomic<bool> done{false};
  std::thread watcher = interruptWatcher(executor, done);
  const RunReport report = run_on_robot(executor, options);
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

// A KUKA over RSI: the link and joint stream on this PC, and for rsi-sim a simulated KRC.
int runOverRsi(const RunOptions& o, const Program& program, const xmate::model::RobotSpec& spec) {
  using namespace xmate;
  if (spec.family != model::RobotFamily::kKuka)
    throw std::runtime_error(o.program_path + " was taught for the " + std::string(spec.display_name) +
                             ", an xMate: run it with --robot sim or --robot HOST:PORT");
  const bool simulated = o.robot.rsi_config.empty();
  std::string context_path = o.context_path;
  if (context_path.empty())
    context_path = simulated ? (model::dataDirectory() / "resources/rsi/rci_replay.rsi.xml").string()
                             : contextNaming(o.robot.rsi_config);
  arm::RsiArmConfig arm_config;
  arm_config.context_path = context_path;
  arm_config.ethernet_config_path = simulated ? "" : o.robot.rsi_config;
  arm_config.model = std::string(spec.name);
  arm_config.link.bind_ip = simulated ? "127.0.0.1" : o.listen.bind_ip;
  arm_config.link.port = simulated ? 0 : int(o.listen.port);
  arm_config.link.cycle_ms = o.cycle_ms;
  arm::RsiArm arm(arm_config);
  rsi::Link& link = arm.link();
  arm::JointStream& stream = arm.stream();
  const rsi::EthernetConfig& config = arm.ethernetConfig();
  arm.start();
  std::unique_ptr<sim::KrcServer> krc;
  if (simulated) {
    sim::KrcServerConfig k;
    k.krc.context_path = context_path;
    k.krc.model = std::string(spec.name);
    k.krc.cycle_ms = o.cycle_ms;
    k.target_ip = "127.0.0.1";
    k.target_port = link.port();
    krc = std::make_unique<sim::KrcServer>(k);
    krc->start();
  }
  const std::string where = (arm_config.link.bind_ip.empty() ? config.ip : arm_config.link.bind_ip) + ":" +
                            std::to_string(link.port());
  waitForRsi(link, stream, where, g_interrupted);
  std::printf("running %s (%zu instructions, %s) over RSI on %s%s, %d ms cycle, context %s, at %.0f %% speed\n",
              o.program_path.c_str(), program.instructions.size(), std::string(spec.display_name).c_str(),
              where.c_str(), simulated ? " (in-process simulated KRC)" : "", o.cycle_ms,
              std::filesystem::path(context_path).filename().c_str(), o.speed * 100);
  std::fflush(stdout);
  const int status = replay(o, program, [&](Executor& executor, const ExecutorOptions& options) {
    return executor.run(arm, program, options);
  });
  if (krc) krc->stop();
  arm.stop();
  return status;
}

}  // namespace

int runRun(const RunOptions& o) {
  if (o.fast && !o.robot.in_process)
    throw UsageError("--fast applies to the in-process simulator (--robot sim); a controller keeps its own clock: "
                     "leave out --fast");
  if (o.rsi_options_given && !o.robot.rsi)
    throw UsageError("--bind, --port, --context and --cycle-ms apply to a KUKA over RSI (--robot rsi:ETHERNET.xml or "
                     "rsi-sim); leave them out for an xMate");
  const Program program = loadProgram(o.program_path);
  const xmate::model::RobotSpec& spec = o.model_name.empty() ? *program.robot : *xmate::model::findRobotSpec(o.model_name);
  requireRobot(program, spec);
  if (o.robot.rsi) return runOverRsi(o, program, spec);
  const std::optional<xmate::XmateType> xmate_type = xmate::model::xmateType(spec);
  if (!xmate_type)
    throw std::runtime_error(o.program_path + " was taught for the " + std::string(spec.display_name) +
                             ", a KUKA arm: run it over RSI with --robot rsi:ETHERNET.xml (or rsi-sim for a simulated "
                             "KRC)");
  const xmate::XmateType type = *xmate_type;

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
              program.instructions.size(), std::string(spec.display_name).c_str(), address.host.c_str(),
              address.port, where.c_str(), o.speed * 100);
  std::fflush(stdout);
  return replay(o, program, [&](Executor& executor, const ExecutorOptions& options) {
    return executor.run(robot, program, options);
  });
}

}  // namespace rci_cli
