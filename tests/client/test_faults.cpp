// SPDX-License-Identifier: Apache-2.0
// How Control() ends when things go wrong, against the lock-step simulator: each error bit the
// controller raises ends it with a ControlException naming the bit (and carrying the log); collision
// -> power off -> recovery -> moving again; e-stop; packet loss -> instability; reordered and
// malformed datagrams (counted, no crash); controller death mid-motion; a wrong-size RobotState.
#include <QtTest>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <thread>
#include <vector>

#include <xmate/robot.h>

#include "client/connection.h"
#include "client/tcp_session.h"
#include "net/tcp_socket.h"
#include "net/udp_socket.h"
#include "client/error_bits.h"
#include "client_test_support.h"

using namespace xmate;
using namespace client_test;
using CM = RCI::robot::StartMoveRequest::ControllerMode;
using MM = RCI::robot::StartMoveRequest::MotionGeneratorMode;
using RCI::robot::RobotState;

namespace {

constexpr std::array<double, 16> kIdentity{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};

// Simulator options for tests that lose answers on purpose (see SimOptions::lockstep_timeout_ms).
SimOptions lossyOptions() {
  SimOptions o;
  o.lockstep_timeout_ms = 30;
  return o;
}

// A joint callback whose command is start + offset(t) for t = seconds since the first cycle.
JointControl jointProfile(std::function<std::array<double, 7>(double)> offset, int max_cycles = 5000) {
  auto start = std::make_shared<std::array<double, 7>>();
  auto id0 = std::make_shared<uint64_t>(0);
  return [=](RobotState s) -> JointPositions {
    if (*id0 == 0) {
      *start = s.q;
      *id0 = s.message_id - 1;
    }
    const double t = double(s.message_id - *id0) * 1e-3;
    JointPositions out{*start, false};
    const auto d = offset(t);
    for (int i = 0; i < 7; ++i) out.q[i] += d[i];
    return t * 1000 >= max_cycles ? MotionFinished(out) : out;
  };
}

// Runs Control(callback) after startMove(cm, mm) and returns the ControlException it must throw.
template <class Callback>
ControlException expectControlException(Robot& robot, CM cm, MM mm, Callback callback) {
  robot.startMove(cm, mm);
  try {
    robot.Control(callback);
  } catch (const ControlException& e) {
    return e;
  }
  throw std::runtime_error("Control() ended without a ControlException");
}

QString bitList(const std::array<bool, 20>& errors) {
  QStringList names;
  for (int i = 0; i < 20; ++i)
    if (errors[i]) names << QString::number(i) + " " + client::errorBitName(i);
  return names.join(", ");
}

// The exception names the bit in its message, sets it in errors and carries the last cycles.
void verifyNamesBit(const ControlException& e, int bit) {
  QVERIFY2(e.errors[bit], qPrintable("bit " + QString::number(bit) + " not set; set: " + bitList(e.errors)));
  QVERIFY2(QString(e.what()).contains(client::errorBitName(bit)), e.what());
  QVERIFY2(!e.log.empty() && e.log.size() <= 50, qPrintable(QString::number(e.log.size())));
  QVERIFY(e.log.back().state.errors[bit]);
  for (size_t i = 1; i < e.log.size(); ++i) QVERIFY(e.log[i].state.message_id > e.log[i - 1].state.message_id);
}

}  // namespace

class TestFaults : public QObject {
  Q_OBJECT

 private slots:
  void commandedVelocityJump();
  void commandedAccelerationDiscontinuity();
  void commandedAccelerationLimit();
  void commandedPositionBeyondSoftLimit();
  void commandedCartesianVelocity();
  void torqueRangeAndRate();
  void collisionPowersOffThenRecoveryAndMoveAgain();
  void leavingTheSafetyBoxPowersOff();
  void emergencyStopEndsTheMotion();
  void packetLossLeadsToInstability();
  void reorderedStatesAreDropped();
  void corruptedStatesAreCountedAndSkipped();
  void wrongSizeStateIsVersionMismatch();
  void controllerDeathMidMotion();
  void tcpTimeoutBeforeTheAnswerKeepsTheSession();
  void tcpTimeoutMidFrameClosesTheSession();
};

void TestFaults::commandedVelocityJump() {
  auto server = startSim();
  auto robot = robotFor(*server);
  const auto e = expectControlException(*robot, CM::kJointPosition, MM::kJointPosition,
                                        jointProfile([](double t) {
                                          std::array<double, 7> d{};
                                          if (t > 0.02) d[0] = 0.05;  // 50 rad/s for one cycle
                                          return d;
                                        }));
  verifyNamesBit(e, 10);
  QVERIFY(QString(e.what()).contains("automaticErrorRecovery"));
  robot->automaticErrorRecovery();
  QVERIFY(eventually([&] { return !client::anyError(robot->receiveRobotState().errors); }));
}

void TestFaults::commandedAccelerationDiscontinuity() {
  auto server = startSim();
  auto robot = robotFor(*server);
  // Acceleration steps from 0 to 12 rad/s^2 on J1 (its limit is 15): sampled at 1 ms the step is a
  // jerk of 12 / 2 ms = 6000 rad/s^3, above the 5000 limit.
  const auto e = expectControlException(*robot, CM::kJointPosition, MM::kJointPosition,
                                        jointProfile([](double t) {
                                          std::array<double, 7> d{};
                                          const double u = std::max(0.0, t - 0.02);
                                          d[0] = 0.5 * 12.0 * u * u;
                                          return d;
                                        }));
  verifyNamesBit(e, 14);
}

void TestFaults::commandedAccelerationLimit() {
  auto server = startSim();
  auto robot = robotFor(*server);
  // Jerk 2000 rad/s^3 on J1 (limit 5000): the acceleration passes its 15 rad/s^2 limit after 7.5 ms.
  const auto e = expectControlException(*robot, CM::kJointPosition, MM::kJointPosition,
                                        jointProfile([](double t) {
                                          std::array<double, 7> d{};
                                          const double u = std::max(0.0, t - 0.02);
                                          d[0] = 2000.0 * u * u * u / 6.0;
                                          return d;
                                        }));
  verifyNamesBit(e, 12);
}

void TestFaults::commandedPositionBeyondSoftLimit() {
  auto server = startSim();
  auto robot = robotFor(*server);
  const RobotState s = robot->receiveRobotState();
  const double q0_deg = s.q[0] * 180 / M_PI;
  robot->setJointLimit({q0_deg + 2, 120, 170, 120, 170, 120, 360}, {-170, -120, -170, -120, -170, -120, -360}, false);
  try {
    smoothJointMove(*robot, 0, 0.2, 1.0);  // 11.5 deg: crosses the soft limit half way
    QFAIL("the move crossed the soft limit");
  } catch (const ControlException& e) {
    verifyNamesBit(e, 7);
  }
}

void TestFaults::commandedCartesianVelocity() {
  auto server = startSim();
  auto robot = robotFor(*server);
  auto start = std::make_shared<std::array<double, 16>>();
  auto calls = std::make_shared<int>(0);
  const auto e = expectControlException(*robot, CM::kCartesianPosition, MM::kCartesianPosition,
                                        CartesianControl([=](RobotState s) -> CartesianPose {
                                          if ((*calls)++ == 0) *start = s.toolTobase_pos_m;
                                          CartesianPose out{*start, false, 0, false};
                                          if (*calls > 20) out.toolTobase_pos_c[3] += 0.005;  // 5 m/s
                                          return *calls > 3000 ? MotionFinished(out) : out;
                                        }));
  verifyNamesBit(e, 11);
}

void TestFaults::torqueRangeAndRate() {
  auto server = startSim();
  auto robot = robotFor(*server);
  // A 20 Nm step in one cycle: 20000 Nm/s, far above the 1500 Nm/s rate limit.
  auto calls = std::make_shared<int>(0);
  auto e = expectControlException(*robot, CM::kTorque, MM::kIdle, TorqueControl([=](RobotState) -> Torques {
                                    Torques out;
                                    if (++*calls > 20) out.tau[0] = 20;
                                    return *calls > 3000 ? MotionFinished(out) : out;
                                  }));
  verifyNamesBit(e, 17);
  robot->automaticErrorRecovery();
  // A step to 100 Nm, beyond the 85 Nm range. (A ramp within the rate limit would accelerate the
  // free arm past its acceleration limit before reaching the range.)
  *calls = 0;
  QVERIFY(eventually([&] { return !client::anyError(robot->receiveRobotState().errors); }));
  e = expectControlException(*robot, CM::kTorque, MM::kIdle, TorqueControl([=](RobotState) -> Torques {
                               Torques out;
                               if (++*calls > 20) out.tau[1] = 100;
                               return *calls > 3000 ? MotionFinished(out) : out;
                             }));
  verifyNamesBit(e, 18);
}

void TestFaults::collisionPowersOffThenRecoveryAndMoveAgain() {
  auto server = startSim(lossyOptions());
  auto robot = robotFor(*server);
  // Low thresholds and a moderate push: the stiff joint servo holds the arm, the estimated external
  // torques cross the thresholds.
  robot->setCollisionBehavior({10, 10, 10, 10, 5, 5, 5});
  {
    DuringMotion push(*server, [&] { server->setExternalWrench({60, 0, 0, 0, 0, 0}); }, 50);
    const auto e = expectControlException(*robot, CM::kJointPosition, MM::kJointPosition, holdStill(20000));
    verifyNamesBit(e, 15);
    QVERIFY(QString(e.what()).contains("setCollisionBehavior"));
  }
  server->setExternalWrench({0, 0, 0, 0, 0, 0});
  QCOMPARE(robot->getMotorState(), 0);
  robot->automaticErrorRecovery();
  QVERIFY(eventually([&] { return !client::anyError(robot->receiveRobotState().errors); }));
  QVERIFY(robot->setMotorPower(1));
  int calls = 0;
  robot->startMove(CM::kJointPosition, MM::kJointPosition);
  robot->Control(holdStill(200, &calls));
  QCOMPARE(calls, 200);
  smoothJointMove(*robot, 0, 0.05, 0.5);
}

void TestFaults::leavingTheSafetyBoxPowersOff() {
  auto server = startSim();
  auto robot = robotFor(*server);
  std::array<double, 16> frame = robot->receiveRobotState().toolTobase_pos_m;
  robot->setCartesianLimit({0.1, 0.1, 0.1}, frame, true);  // 5 cm each way around the TCP
  try {
    smoothJointMove(*robot, 0, 0.4, 2.0);  // swings the TCP tens of cm sideways
    QFAIL("the TCP left the safety box without an error");
  } catch (const ControlException& e) {
    verifyNamesBit(e, 1);
  }
  QCOMPARE(robot->getMotorState(), 0);
}

void TestFaults::emergencyStopEndsTheMotion() {
  auto server = startSim(lossyOptions());
  auto robot = robotFor(*server);
  {
    DuringMotion press(*server, [&] { server->setEmergencyStop(true); }, 50);
    const auto e = expectControlException(*robot, CM::kJointPosition, MM::kJointPosition, holdStill(20000));
    verifyNamesBit(e, 19);
  }
  QCOMPARE(robot->getSafetyStopState(), 2);
  QCOMPARE(robot->getMotorState(), 0);
  QVERIFY_THROWS_EXCEPTION(CommandException, robot->automaticErrorRecovery());
  server->setEmergencyStop(false);
  robot->automaticErrorRecovery();
  QCOMPARE(robot->getSafetyStopState(), 1);
}

void TestFaults::packetLossLeadsToInstability() {
  auto server = startSim(lossyOptions());
  auto robot = robotFor(*server);
  DuringMotion drop(*server, [&] { server->dropCommands(40); }, 50);
  const auto e = expectControlException(*robot, CM::kJointPosition, MM::kJointPosition, holdStill(20000));
  verifyNamesBit(e, 19);
  QVERIFY2(QString(e.what()).contains("rci-cli doctor"), e.what());
  double lowest_rate = 1.0;
  for (const ControlRecord& r : e.log) lowest_rate = std::min(lowest_rate, r.state.control_command_success_rate);
  QVERIFY2(lowest_rate < 0.9, qPrintable(QString::number(lowest_rate)));
  // The message quotes that lowest rate, not the 1.00 the controller reports once out of kMove.
  QVERIFY2(QString(e.what()).contains(QStringLiteral("lowest command success rate 0.")), e.what());
}

void TestFaults::reorderedStatesAreDropped() {
  auto server = startSim(lossyOptions());
  auto robot = robotFor(*server);
  robot->connect();
  const auto before = robot->connection().timing().counters;
  int calls = 0;
  {
    DuringMotion reorder(*server, [&] { server->reorderStates(20); }, 30);
    robot->startMove(CM::kJointPosition, MM::kJointPosition);
    robot->Control(holdStill(1500, &calls));
  }
  QCOMPARE(calls, 1500);
  QVERIFY(eventually([&] {
    return robot->connection().timing().counters.states_stale >= before.states_stale + 10;
  }, 2000));
  QCOMPARE(server->status().counters.states_reordered >= 20, true);
}

void TestFaults::corruptedStatesAreCountedAndSkipped() {
  auto server = startSim(lossyOptions());
  auto robot = robotFor(*server);
  robot->connect();
  const auto before = robot->connection().timing().counters;
  int calls = 0;
  {
    // Two in a row: in lock-step each undecodable state costs one 30 ms answer timeout, and three
    // would exceed the client's 100 ms limit for a controller without usable states.
    DuringMotion corrupt(*server, [&] { server->corruptStates(2); }, 30);
    robot->startMove(CM::kJointPosition, MM::kJointPosition);
    robot->Control(holdStill(1000, &calls));
  }
  QCOMPARE(calls, 1000);
  QVERIFY(eventually([&] {
    return robot->connection().timing().counters.states_bad_value == before.states_bad_value + 2;
  }, 2000));
}

void TestFaults::wrongSizeStateIsVersionMismatch() {
  auto server = startSim(lossyOptions());
  auto robot = robotFor(*server);
  robot->connect();
  server->sendWrongLengthStates(3000);
  try {
    robot->receiveRobotState();
    QFAIL("a wrong-size state was accepted");
  } catch (const UdpException& e) {
    QVERIFY2(QString(e.what()).contains("another RCI protocol version"), e.what());
    QVERIFY2(QString(e.what()).contains(QString::number(1247 - 8)), e.what());
  }
  // During Control() the same ends the motion.
  QVERIFY(eventually([&] { return server->status().pending.wrong_length_states == 0; }, 10000));
  {
    DuringMotion shorten(*server, [&] { server->sendWrongLengthStates(10); }, 30);
    robot->startMove(CM::kJointPosition, MM::kJointPosition);
    try {
      robot->Control(holdStill(20000));
      QFAIL("Control() ignored a wrong-size state");
    } catch (const UdpException& e) {
      QVERIFY2(QString(e.what()).contains("another RCI protocol version"), e.what());
    }
  }
}

void TestFaults::controllerDeathMidMotion() {
  auto server = startSim();
  auto robot = robotFor(*server);
  {
    DuringMotion die(*server, [&] { server->kill(); }, 50);
    robot->startMove(CM::kJointPosition, MM::kJointPosition);
    try {
      robot->Control(holdStill(20000));
      QFAIL("Control() survived the controller's death");
    } catch (const UdpException& e) {
      QVERIFY2(QString(e.what()).contains("no state from the controller for 100 ms"), e.what());
    }
  }
  QVERIFY(!robot->reconnect());  // nobody listens any more
  server->stop();
  server->start();
  QVERIFY(eventually([&] { return robot->reconnect(); }));
  QCOMPARE(robot->getMotorState(), 1);
}

// A controller that answers the request only with the first `bytes` bytes of the frame (0: nothing),
// then stays silent; the TcpSession under test asks it for the motor state with a 150 ms timeout.
namespace {
struct HalfAnswer {
  xmate::net::TcpListener listener;
  std::thread thread;
  std::atomic<bool> done{false};
  explicit HalfAnswer(size_t bytes) {
    listener.listen("127.0.0.1", 0);
    thread = std::thread([this, bytes] {
      auto peer = listener.accept(5000);
      if (!peer) return;
      uint8_t header[xmate::protocol::kFrameHeaderSize];
      if (peer->readExact(header, sizeof header, 2000) != xmate::net::IoResult::kOk) return;
      const xmate::protocol::FrameHeader request = xmate::protocol::decodeFrameHeader(header);
      std::vector<uint8_t> payload(request.length);
      peer->readExact(payload.data(), payload.size(), 2000);
      const uint32_t sequence = request.sequence;
      const xmate::protocol::Frame answer =
          xmate::protocol::encodeFrame(sequence, xmate::protocol::EmptyRequest{xmate::protocol::Command::kGetMotorState});
      if (bytes > 0) peer->sendAll(answer.data(), std::min(bytes, answer.size()), 1000);
      while (!done.load()) std::this_thread::sleep_for(std::chrono::milliseconds(5));
    });
  }
  ~HalfAnswer() {
    done.store(true);
    thread.join();
  }
};

std::vector<uint8_t> askMotorState(xmate::client::TcpSession& session) {
  return session.exchange(
      "getMotorState",
      [](uint32_t sequence) {
        return xmate::protocol::encodeFrame(sequence,
                                            xmate::protocol::EmptyRequest{xmate::protocol::Command::kGetMotorState});
      },
      xmate::protocol::Command::kGetMotorState, 150);
}
}  // namespace

void TestFaults::tcpTimeoutBeforeTheAnswerKeepsTheSession() {
  HalfAnswer controller(0);
  xmate::client::TcpSession session;
  session.open(xmate::net::makeEndpoint("127.0.0.1", controller.listener.localPort()), 2000);
  try {
    askMotorState(session);
    QFAIL("no answer, yet no timeout");
  } catch (const xmate::TcpException& e) {
    QVERIFY2(QString(e.what()).contains("no response within 150 ms"), e.what());
  }
  QVERIFY(session.isOpen());  // no byte of the answer was read: the stream is still aligned
}

void TestFaults::tcpTimeoutMidFrameClosesTheSession() {
  HalfAnswer controller(3);  // half of the 6-byte header
  xmate::client::TcpSession session;
  session.open(xmate::net::makeEndpoint("127.0.0.1", controller.listener.localPort()), 2000);
  try {
    askMotorState(session);
    QFAIL("half a frame, yet no error");
  } catch (const xmate::TcpException& e) {
    QVERIFY2(QString(e.what()).contains("stopped in the middle of a frame"), e.what());
    QVERIFY2(QString(e.what()).contains("reconnect()"), e.what());
  }
  QVERIFY(!session.isOpen());  // every later answer would have been read misaligned
}

QTEST_APPLESS_MAIN(TestFaults)
#include "test_faults.moc"
