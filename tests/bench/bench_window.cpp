// SPDX-License-Identifier: Apache-2.0
// rci-bench-window: CPU share of one core of the whole rci-studio window (plots, 3D view, panels,
// embedded simulator) with the arm at rest and while it replays a program, against the same program
// replayed headless (simulator + client + executor, no window) afterwards in the same run -- on the
// built-in xMate simulator (RCI, 1 ms) or, with --robot kuka, the built-in KUKA simulator (RSI, 4 ms).
// Run under xvfb-run for the 3D view. Results: docs/performance.md ("The window").
#include <QAbstractButton>
#include <QApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QSettings>
#include <QStyleFactory>
#include <QTemporaryDir>
#include <QTimer>

#include <sys/resource.h>

#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <thread>

#include <xmate/robot.h>

#include "arm/rsi_arm.h"
#include "model/resource_locator.h"
#include "panels/program_panel.h"
#include "session/session.h"
#include "sim/krc_server.h"
#include "sim/server.h"
#include "teach/executor.h"
#include "teach/program_io.h"
#include "window/main_window.h"

namespace {

using xmate::teach::Instruction;
using xmate::teach::InstructionType;
using xmate::teach::Program;

double cpuSeconds() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_utime.tv_sec + usage.ru_stime.tv_sec + 1e-6 * (usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
}

// Runs the event loop (idle between events, as in the application) for `seconds`.
void spin(double seconds) {
  QEventLoop loop;
  QTimer::singleShot(static_cast<int>(seconds * 1000), &loop, &QEventLoop::quit);
  loop.exec();
}

// Percent of one core this process used while `during` ran the event loop (or slept) for `seconds`.
template <typename Body>
double cpuShare(double seconds, Body during) {
  const double cpu0 = cpuSeconds();
  QElapsedTimer wall;
  wall.start();
  during(seconds);
  return 100 * (cpuSeconds() - cpu0) / (wall.nsecsElapsed() * 1e-9);
}

// Back and forth between the start pose and one 0.4-0.6 rad away on joints 1, 2 and 4, at 50 %
// speed: the arm is always moving, for about 1.5 s per instruction.
Program backAndForth(const xmate::model::RobotSpec& robot, const std::array<double, 7>& start, int moves) {
  Program program;
  program.robot = &robot;
  std::array<double, 7> away = start;
  away[0] += 0.6;
  away[1] += 0.4;
  away[3] -= 0.5;
  for (int i = 0; i < moves; ++i) {
    Instruction in;
    in.type = InstructionType::kMoveJ;
    in.target.has_q = true;
    in.target.q = i % 2 == 0 ? away : start;
    in.speed = 0.5;
    program.instructions.push_back(in);
  }
  return program;
}

bool waitFor(const std::function<bool()>& condition, double seconds) {
  QElapsedTimer clock;
  clock.start();
  while (!condition()) {
    if (clock.elapsed() > seconds * 1000) return false;
    spin(0.02);
  }
  return true;
}

// The reference: the built-in simulator (real-time clock, as in the window), a client and the
// executor replaying the program, with no window at all.
double headlessReplay(double seconds) {
  auto server = xmate::sim::startEmbedded(xmate::sim::embeddedConfig(xmate::XMATE7_PRO, xmate::sim::ClockMode::kRealTime));
  xmate::Robot robot("127.0.0.1", server->port(), xmate::XMATE7_PRO);
  robot.connect();
  robot.setMotorPower(1);
  const Program program = backAndForth(xmate::model::robotSpec(xmate::XMATE7_PRO), robot.receiveRobotState().q, 200);
  xmate::teach::Executor executor;
  xmate::teach::RunReport report;
  std::thread run([&] { report = executor.run(robot, program); });
  std::this_thread::sleep_for(std::chrono::seconds(2));  // past the pre-flight and the first ramp-up
  const double share = cpuShare(seconds, [](double s) { std::this_thread::sleep_for(std::chrono::duration<double>(s)); });
  executor.stop();
  run.join();
  if (report.outcome != xmate::teach::RunState::kStopped)
    std::printf("  (the headless run ended before the measurement did: %s)\n", report.message.c_str());
  return share;
}

// The same for a KUKA: the simulated KRC (real time, 4 ms) running the sample RSI context, an RSI
// arm and the executor, no window.
double headlessKukaReplay(double seconds) {
  xmate::arm::RsiArmConfig config;
  config.context_path = (xmate::model::dataDirectory() / "resources/rsi/rci_replay.rsi.xml").string();
  config.model = "kr6_r900_sixx";
  config.link.bind_ip = "127.0.0.1";
  config.link.port = 0;
  config.link.silence_ms = 1000;
  xmate::arm::RsiArm arm(config);
  arm.start();
  xmate::sim::KrcServerConfig krc;
  krc.krc.context_path = config.context_path;
  krc.krc.model = config.model;
  krc.target_ip = "127.0.0.1";
  krc.target_port = arm.link().port();
  xmate::sim::KrcServer server(krc);
  server.start();
  xmate::arm::ArmState state;
  for (int i = 0; i < 2000 && !arm.latest(state); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(5));
  const Program program = backAndForth(arm.spec(), state.sample.q, 200);
  xmate::teach::Executor executor;
  xmate::teach::RunReport report;
  std::thread run([&] { report = executor.run(arm, program); });
  std::this_thread::sleep_for(std::chrono::seconds(2));
  const double share = cpuShare(seconds, [](double s) { std::this_thread::sleep_for(std::chrono::duration<double>(s)); });
  executor.stop();
  run.join();
  server.stop();
  arm.stop();
  if (report.outcome != xmate::teach::RunState::kStopped)
    std::printf("  (the headless run ended before the measurement did: %s)\n", report.message.c_str());
  return share;
}

void fail(const char* what) {
  std::fprintf(stderr, "rci-bench-window: %s\n", what);
  std::exit(1);
}

}  // namespace

int main(int argc, char** argv) {
  double seconds = 10;
  bool kuka = false;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--seconds") == 0 && i + 1 < argc) {
      seconds = std::max(2.0, std::atof(argv[++i]));
    } else if (std::strcmp(argv[i], "--robot") == 0 && i + 1 < argc &&
               (std::strcmp(argv[i + 1], "xmate") == 0 || std::strcmp(argv[i + 1], "kuka") == 0)) {
      kuka = std::strcmp(argv[++i], "kuka") == 0;
    } else {
      std::fprintf(stderr,
                   "usage: rci-bench-window [--seconds S] [--robot xmate|kuka]   (run it under xvfb-run for the 3D view)\n");
      return 2;
    }
  }
  QApplication app(argc, argv);
  QApplication::setStyle(QStyleFactory::create(QStringLiteral("Fusion")));
  QTemporaryDir settings;  // the default layout, not the user's
  QSettings::setPath(QSettings::NativeFormat, QSettings::UserScope, settings.path());
  std::printf("rci-bench-window: platform %s, %.0f s per phase, %s (real-time clock)\n",
              qPrintable(QGuiApplication::platformName()), seconds,
              kuka ? "KR 6 R900 sixx, built-in KUKA simulator (RSI, 4 ms)" : "xMate7 Pro, built-in simulator (RCI, 1 ms)");

  rci::ui::Session session;
  rci::ui::MainWindow window(session);
  window.resize(1600, 1000);
  window.show();
  rci::ui::SessionTarget target;
  if (kuka) target.kind = rci::ui::SessionTarget::Kind::kKukaSimulator;
  window.connectTo(target);
  if (!waitFor([&] { return session.live().has_arm_state; }, 20)) fail("the built-in simulator did not start streaming");
  if (!kuka) {  // a KUKA's motors are on while its KRL program runs RSI
    auto* power_on = window.findChild<QAbstractButton*>(QStringLiteral("power.on"));
    if (power_on == nullptr) fail("no power.on button");
    power_on->click();
    if (!waitFor([&] { return session.live().motor_state == 1; }, 10)) fail("the motors did not come on");
  }
  spin(3);  // warm-up: first 3D frames, plots filling

  const double rest = cpuShare(seconds, spin);
  std::printf("  rci-studio, arm at rest:                                    %5.1f %% of one core\n", rest);
  std::fflush(stdout);

  QTemporaryDir dir;
  const QString path = dir.filePath(QStringLiteral("back_and_forth.json"));
  xmate::teach::saveProgram(path.toStdString(), backAndForth(session.spec(), session.live().arm.sample.q, 200));
  auto* panel = window.findChild<rci::ui::ProgramPanel*>(QStringLiteral("panel.program"));
  if (panel == nullptr || !panel->openFile(path)) fail("the Program panel could not open the program");
  auto* run = window.findChild<QAbstractButton*>(QStringLiteral("program.run"));
  if (run == nullptr || !run->isEnabled()) fail("program.run is missing or disabled");
  run->click();
  if (!waitFor([&] { return session.live().motion_running; }, 10)) fail("the program did not start");
  spin(2);
  const double moving = cpuShare(seconds, spin);
  const bool still_running = panel->isRunning();
  if (!still_running)
    std::printf("  the run ended: %s after %zu instructions\n", panel->lastReport().message.c_str(),
                panel->lastReport().instructions.size());
  std::printf("  rci-studio, arm replaying the program:                      %5.1f %% of one core%s\n", moving,
              still_running ? "" : "  (the run ended early: the figure is not valid)");
  auto* stop = window.findChild<QAbstractButton*>(QStringLiteral("program.stop"));
  if (stop != nullptr && stop->isEnabled()) stop->click();
  waitFor([&] { return !panel->isRunning(); }, 10);
  session.close();
  waitFor([&] { return !session.isOpen(); }, 10);

  // The reference last, so that nothing of it is in the process while the window is measured.
  const double reference = kuka ? headlessKukaReplay(seconds) : headlessReplay(seconds);
  std::printf("  reference, headless replay (simulator + %s + executor): %5.1f %% of one core\n",
              kuka ? "RSI arm" : "client", reference);
  std::printf("  window / reference while moving: %.2fx; target < 30 %% of one core: at rest %s, moving %s\n",
              moving / reference, rest < 30 ? "met" : "NOT met", moving < 30 ? "met" : "NOT met");
  return still_running ? 0 : 1;
}
