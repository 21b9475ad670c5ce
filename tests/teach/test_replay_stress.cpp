// SPDX-License-Identifier: Apache-2.0
// Replays after reconnects, under load: 30 rounds of connect -> replay a saved MOVEJ/MOVEL/MOVEC
// program with the teach Executor (as the window does) -> disconnect, in one process, against the
// in-process simulator on its real-time clock, while two threads burn CPU and the client's
// real-time thread is stopped for 4 ms every 40 ms (what a loaded machine without real-time priority
// does to it, made regular: it is then often late at StartMove, the cause of the aborted replays).
// Every replay must finish (docs/reliability.md, "Aborted replays after a reconnect").
#include <QtTest>

#include <atomic>
#include <chrono>
#include <memory>
#include <thread>

#include <xmate/model.h>
#include <xmate/robot.h>

#include "net/cpu_burners.h"
#include "sim/server.h"
#include "stall_injector.h"
#include "teach/executor.h"
#include "teach/program_io.h"
#include "teach/recording.h"

using namespace xmate;
using namespace xmate::teach;

namespace {

constexpr int kRounds = 30;
constexpr int kRoundsPerSimulator = 10;  // then the window's "switch target": a fresh simulator
constexpr XmateType kType = XMATE7_PRO;
constexpr int kStallMs = 4;         // the real-time thread's injected stall ...
constexpr int kStallEveryMs = 40;  // ... and how often

// Stalls the client's real-time thread (whichever Robot is connected) regularly until destroyed.
class RegularStalls {
 public:
  RegularStalls()
      : thread_([this] {
          while (!stop_.load()) {
            injector_.stallRealtimeThread(kStallMs);
            std::this_thread::sleep_for(std::chrono::milliseconds(kStallEveryMs));
          }
        }) {}
  ~RegularStalls() {
    stop_.store(true);
    thread_.join();
  }
  uint64_t count() const { return injector_.completed(); }

 private:
  client_test::StallInjector injector_;
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

std::unique_ptr<sim::Server> startRealTimeSimulator() {
  auto config = sim::embeddedConfig(kType, sim::ClockMode::kRealTime);
  config.sim.motors_on_at_start = true;
  return sim::startEmbedded(std::move(config));
}

Target targetAt(XmateModel& model, const std::array<double, 7>& q) {
  Target t;
  t.has_q = true;
  t.q = q;
  t.has_pose = true;
  t.pose = model.GetCartPose(q);
  t.has_psi = true;
  t.psi = model.GetPsi(q);
  return t;
}

// The TCP of `from` moved by (dx, dy, dz) m, same orientation and arm angle (a pose target).
Target shifted(const Target& from, double dx, double dy, double dz) {
  Target t = from;
  t.has_q = false;
  t.pose[3] += dx;
  t.pose[7] += dy;
  t.pose[11] += dz;
  return t;
}

// MOVEJ to A (away from the start pose), MOVEL 4 cm sideways and down, MOVEC over a 6 cm arc.
// It ends away from A, so every round moves in all three instructions.
Program smallProgram(const std::array<double, 7>& q_home) {
  XmateModel model(kType);
  std::array<double, 7> qa = q_home;
  const std::array<double, 7> offset{0.15, 0.1, -0.1, 0.15, 0.1, -0.1, 0.1};
  for (int i = 0; i < 7; ++i) qa[i] += offset[i];
  const Target a = targetAt(model, qa);
  const Target b = shifted(a, 0.0, 0.04, -0.04);
  const Target via = shifted(b, 0.03, 0.03, 0.0);
  const Target c = shifted(b, 0.06, 0.0, 0.0);
  Program p;
  p.robot = &xmate::model::robotSpec(kType);
  p.instructions.push_back(moveJ(a, 1.0, "A"));
  p.instructions.push_back(moveL(b, 1.0, "B"));
  p.instructions.push_back(moveC(via, c, 1.0, "C"));
  return p;
}

// Clears error bits after an aborted replay (retried while the arm is still stopping).
void recover(Robot& robot) {
  for (int attempt = 0; attempt < 100; ++attempt) {
    try {
      robot.automaticErrorRecovery();
      return;
    } catch (const std::exception&) {
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
  }
}

}  // namespace

class TestReplayStress : public QObject {
  Q_OBJECT

 private slots:
  void replaysAfterReconnectsUnderLoad();
};

void TestReplayStress::replaysAfterReconnectsUnderLoad() {
  std::unique_ptr<sim::Server> server = startRealTimeSimulator();
  // The program goes through a file, as the window saves and opens it.
  QTemporaryDir dir;
  QVERIFY(dir.isValid());
  const std::string path = dir.filePath("stress.json").toStdString();
  {
    Robot probe("127.0.0.1", server->port(), kType);
    saveProgram(path, smallProgram(probe.receiveRobotState().q));
  }
  const Program program = loadProgram(path);

  net::CpuBurners burners;  // both cores of a small machine busy
  RegularStalls stalls;
  Executor executor;  // one for all rounds, as the window's Program panel keeps one
  std::unique_ptr<Robot> robot;
  QStringList aborts;
  for (int round = 0; round < kRounds; ++round) {
    if (round > 0 && round % kRoundsPerSimulator == 0) {
      robot.reset();
      server = startRealTimeSimulator();
    }
    // Odd rounds reconnect the same Robot (the window's reconnect), even rounds make a new one.
    if (robot && round % 2 == 1) {
      QVERIFY(robot->reconnect());
    } else {
      robot = std::make_unique<Robot>("127.0.0.1", server->port(), kType);
      robot->connect();
    }
    const RunReport report = executor.run(*robot, program);
    if (report.outcome != RunState::kFinished) {
      aborts << QStringLiteral("round %1: %2: %3")
                    .arg(round + 1)
                    .arg(runStateName(report.outcome))
                    .arg(QString::fromStdString(report.message));
      recover(*robot);  // so that one abort does not make the next rounds fail too
    }
    if (round % 2 == 1) robot.reset();  // disconnect: the next round starts with a new Robot
  }
  QVERIFY2(stalls.count() > uint64_t(kRounds), "the real-time thread was not stalled");
  QVERIFY2(aborts.isEmpty(), qPrintable(QString::number(aborts.size()) + " of " + QString::number(kRounds) +
                                        " replays did not finish:\n" + aborts.join('\n')));
}

QTEST_GUILESS_MAIN(TestReplayStress)
#include "test_replay_stress.moc"
