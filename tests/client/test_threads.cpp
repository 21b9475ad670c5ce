// SPDX-License-Identifier: Apache-2.0
// One xmate::Robot used from four threads at once -- states, TCP commands, motions, and reconnects
// with the controller killed and restarted -- for a few seconds: no crash, no hang, every failure a
// documented exception, and the robot works normally afterwards. Run under ThreadSanitizer (label tsan).
#include <QtTest>

#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <thread>
#include <vector>

#include <xmate/move.h>
#include <xmate/robot.h>

#include "client/connection.h"
#include "client_test_support.h"

using namespace xmate;
using namespace client_test;
using CM = RCI::robot::StartMoveRequest::ControllerMode;
using MM = RCI::robot::StartMoveRequest::MotionGeneratorMode;
using RCI::robot::RobotState;
using Clock = std::chrono::steady_clock;

namespace {

constexpr std::array<double, 16> kIdentity{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
constexpr auto kRunFor = std::chrono::seconds(4);
// Every thread must have returned this long after it was asked to stop (the longest single call is
// a motion's timeout, 5 s, plus a reconnect's 2 s; ThreadSanitizer slows everything down).
constexpr auto kJoinWithin = std::chrono::seconds(40);

// What one worker did: calls that returned, calls that threw a std::exception, and whether it ended.
struct Worker {
  explicit Worker(const char* worker_name) : name(worker_name) {}
  const char* name;
  std::atomic<uint64_t> ok{0};
  std::atomic<uint64_t> threw{0};
  std::atomic<bool> done{false};
  std::string first_error;  // written by the worker only, read after it is done
};

void sleepMs(int ms) { std::this_thread::sleep_for(std::chrono::milliseconds(ms)); }

// Runs step until stop is set, counting what it did; any exception but std::exception escapes and
// ends the process (that is a failure too).
void work(Worker& w, const std::atomic<bool>& stop, const std::function<void()>& step) {
  while (!stop.load()) {
    try {
      step();
      ++w.ok;
    } catch (const std::exception& e) {
      if (w.threw++ == 0) w.first_error = e.what();
      sleepMs(2);  // a lost session fails fast: do not spin
    }
  }
  w.done.store(true);
}

// A short joint motion: out by `delta` on joint 0 and back, `cycles` cycles in all (smooth, small).
JointControl outAndBack(double delta, int cycles) {
  auto start = std::make_shared<std::array<double, 7>>();
  auto count = std::make_shared<int>(0);
  return [=](RobotState s) -> JointPositions {
    if ((*count)++ == 0) *start = s.q;
    const double x = double(*count) / cycles;
    const double bump = std::sin(M_PI * x);
    JointPositions out{*start, false};
    out.q[0] += delta * bump * bump;  // zero velocity and acceleration at both ends
    return *count >= cycles ? MotionFinished(out) : out;
  };
}

}  // namespace

class TestThreads : public QObject {
  Q_OBJECT

 private slots:
  void oneRobotFromFourThreadsThroughReconnectsAndControllerDeath();
};

void TestThreads::oneRobotFromFourThreadsThroughReconnectsAndControllerDeath() {
  auto server = startSim();
  auto robot = robotFor(*server);
  robot->connect();
  robot->receiveRobotState();

  std::atomic<bool> stop{false};
  Worker reader("states"), commands("commands"), motions("motions"), chaos("reconnects");
  std::atomic<uint64_t> kills{0}, reconnects{0}, closes{0};
  std::array<client::StateSample, 64> samples{};

  std::vector<std::thread> threads;
  // The newest state, the timing, the real-time status, the GUI's sample ring (this thread is its
  // only consumer) and the remembered tool and load.
  threads.emplace_back([&] {
    work(reader, stop, [&] {
      const RobotState s = robot->receiveRobotState();
      if (s.message_id == 0) throw std::runtime_error("a state without message_id");
      RobotState latest;
      robot->connection().latestState(latest);
      (void)robot->connection().timing();
      (void)robot->connection().realtimeStatus();
      (void)robot->connection().udpPort();
      (void)robot->connection().isOpen();
      robot->connection().samples().popBatch(samples.data(), samples.size());
      (void)robot->toolFrame();
      double mass;
      std::array<double, 3> center;
      std::array<double, 9> inertia;
      robot->load(mass, center, inertia);
    });
  });
  // TCP commands, getters and setters (setters the controller refuses during a motion throw; the
  // tool and load it sets are the ones the other threads read).
  threads.emplace_back([&] {
    int i = 0;
    work(commands, stop, [&] {
      switch (i++ % 7) {
        case 0: (void)robot->getMotorState(); break;
        case 1: robot->setCollisionBehavior({60, 60, 50, 40, 25, 25, 15}); break;
        case 2: robot->setDO(RCI::robot::DOSIGNAL::DO0_1, i % 4 == 0); break;
        case 3: (void)robot->getDI(RCI::robot::DISIGNAL::DI0_1); break;
        case 4: robot->setLoad(0.5, {0, 0, 0.02}, {0.001, 0, 0, 0, 0.001, 0, 0, 0, 0.001}); break;
        case 5: robot->setCoor(kIdentity); break;
        case 6: (void)robot->getSafetyStopState(); break;
      }
    });
  });
  // Motions: a raw Control() run and a MOVEJ, alternately; recovery after a controller error.
  threads.emplace_back([&] {
    int i = 0;
    work(motions, stop, [&] {
      try {
        if (i++ % 2 == 0) {
          robot->startMove(CM::kJointPosition, MM::kJointPosition);
          robot->Control(outAndBack(0.002, 150));
        } else {
          const RobotState s = robot->receiveRobotState();
          std::array<double, 7> target = s.q;
          target[1] += (i % 4 == 1) ? 0.01 : -0.01;
          MOVEJ(0.5, s.q, target, *robot);
        }
      } catch (const ControlException&) {
        robot->automaticErrorRecovery();
        throw;
      }
    });
  });
  // The session's owner: reconnects, closes, and kills and restarts the controller.
  threads.emplace_back([&] {
    int i = 0;
    work(chaos, stop, [&] {
      sleepMs(150 + 50 * (i % 3));
      switch (i++ % 3) {
        case 0:
          ++reconnects;
          if (!robot->reconnect()) throw std::runtime_error("reconnect() to a running controller failed");
          break;
        case 1:
          ++closes;
          robot->connection().close();
          sleepMs(30);
          robot->connect();
          break;
        case 2: {
          ++kills;
          server->kill();
          sleepMs(50);
          server->stop();
          server->start();
          if (!eventually([&] { return robot->reconnect(); }, 5000))
            throw std::runtime_error("no reconnect after the controller's restart");
          break;
        }
      }
    });
  });

  std::this_thread::sleep_for(kRunFor);
  stop.store(true);
  // Watchdog: a thread that does not return in time is a hang. The process ends with the names of
  // the threads still running (a joinable std::thread cannot be abandoned, and a hung one would
  // keep using the robot and the simulator after the test).
  const auto deadline = Clock::now() + kJoinWithin;
  const std::array<Worker*, 4> workers{&reader, &commands, &motions, &chaos};
  auto allDone = [&] {
    for (const Worker* w : workers)
      if (!w->done.load()) return false;
    return true;
  };
  while (!allDone() && Clock::now() < deadline) sleepMs(10);
  if (!allDone()) {
    std::string stuck;
    for (const Worker* w : workers)
      if (!w->done.load()) stuck += std::string(" ") + w->name;
    qFatal("hang: these threads did not return within %lld s of being asked to stop:%s",
           static_cast<long long>(std::chrono::duration_cast<std::chrono::seconds>(kJoinWithin).count()),
           stuck.c_str());
  }
  for (auto& t : threads) t.join();

  for (const Worker* w : workers)
    qInfo("%-10s %6llu returned, %5llu threw%s%s", w->name, static_cast<unsigned long long>(w->ok.load()),
          static_cast<unsigned long long>(w->threw.load()), w->first_error.empty() ? "" : "; first: ",
          w->first_error.c_str());
  qInfo("reconnects %llu, closes %llu, controller kills %llu", static_cast<unsigned long long>(reconnects.load()),
        static_cast<unsigned long long>(closes.load()), static_cast<unsigned long long>(kills.load()));
  // Every thread got through: the run was not one long failure.
  QVERIFY(reader.ok > 0);
  QVERIFY(commands.ok > 0);
  QVERIFY(motions.ok + motions.threw > 0);
  QVERIFY(kills > 0);

  // Afterwards the robot works normally: a reconnect, then a motion that reaches its target.
  QVERIFY(server->running());
  QVERIFY(eventually([&] { return robot->reconnect(); }));
  whenReady([&] { robot->automaticErrorRecovery(); });
  QCOMPARE(robot->getMotorState(), 1);
  const RobotState before = robot->receiveRobotState();
  QVERIFY(before.message_id > 0);
  smoothJointMove(*robot, 0, 0.05, 0.3);
  const RobotState after = robot->receiveRobotState();
  QVERIFY2(std::abs(after.q[0] - before.q[0] - 0.05) < 1e-3,
           qPrintable(QString("joint 0 moved by %1 rad, not 0.05").arg(after.q[0] - before.q[0])));
}

// QTEST_APPLESS_MAIN, plus a pause before the process exits: QtTest's watchdog thread (a QThread)
// reports "finished" before its OS thread has released its QThreadData, and LeakSanitizer (the
// AddressSanitizer stage) checks at exit -- without the pause it reported that 152-byte block as
// leaked in about half of the runs of this test.
int main(int argc, char** argv) {
  TestThreads test;
  QTEST_SET_MAIN_SOURCE_PATH
  const int result = QTest::qExec(&test, argc, argv);
  std::this_thread::sleep_for(std::chrono::milliseconds(100));
  return result;
}
#include "test_threads.moc"
