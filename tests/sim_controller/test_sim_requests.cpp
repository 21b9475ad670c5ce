// SPDX-License-Identifier: Apache-2.0
// sim::Controller TCP requests: the response to every command code, the re-check of every value
// (kInvalidArgument), the refusals that depend on the robot's state (kNotPossible and the
// StartMove/StopMove/recovery statuses), malformed and unknown requests, LoadRobotModel's layout,
// IO with loop-back, e-stop, guard stop, motor power and reboot.
#include <QtTest/QtTest>

#include <cmath>

#include <xmate/model.h>

#include "controller_harness.h"
#include "model/chain.h"
#include "model/robot_spec.h"

using namespace xmate;
using namespace xmate::sim;
using namespace xmate::sim::test;
using protocol::Command;
using RCI::robot::RobotMode;

namespace {

constexpr uint8_t kOk = 0, kNotPossible = 1, kInvalid = 2;
// StartMoveStatus values.
constexpr uint8_t kMoveNotPossible = 3, kMoveSingular = 4, kMoveInvalid = 5, kMoveReflex = 6, kMoveEmergency = 7;

const Eigen::Isometry3d kIdentity = Eigen::Isometry3d::Identity();

// Starts a joint-position motion and streams one command (so the motion is really running).
void startJointMotion(Harness& h) {
  QCOMPARE(h.startMove(CM::kJointPosition, MG::kJointPosition), kOk);
  h.stepJoint(h.state().q);
}

}  // namespace

class TestSimRequests : public QObject {
  Q_OBJECT

 private slots:
  void connectAnswers();
  void motorPower();
  void startMoveAcceptsOnlyTheDocumentedPairs();
  void startMoveRefusals();
  void startMoveAtSingularPose();
  void stopMove();
  void settingsRejectValuesOutOfRange();
  void settingsThatMustNotChangeDuringMotion();
  void settingsAllowedDuringMotion();
  void toolChangesTheReportedTcp();
  void loadChangesTheModel();
  void safetyBoxRefusedWhenTcpOutside();
  void softLimitsLeavingJointOutsideReportBitZero();
  void loadRobotModelLayout();
  void digitalIoAndLoopback();
  void dragRequests();
  void emergencyStop();
  void guardStop();
  void errorRecovery();
  void rebootRequest();
  void unknownAndMalformedRequests();
};

void TestSimRequests::connectAnswers() {
  Harness h;
  RawResponse r = parseResponse(h.send(protocol::ConnectRequest{40000}));
  QCOMPARE(r.command, uint32_t(Command::kConnect));
  QCOMPARE(r.value, kOk);
  SimConfig config;
  config.reject_connect_as_incompatible = true;
  Harness old(config);
  QCOMPARE(old.status(protocol::ConnectRequest{40000}), uint8_t(1));  // kIncompatibleLibraryVersion
  // A Connect of the wrong size: another library version.
  const uint8_t short_connect[5] = {0, 0, 0, 0, 7};
  QCOMPARE(parseResponse(h.sendRaw(short_connect, sizeof short_connect)).value, uint8_t(1));
}

void TestSimRequests::motorPower() {
  Harness h;
  QCOMPARE(h.empty(Command::kGetMotorState), uint8_t(0));
  QCOMPARE(h.setMotorPower(1), kOk);
  QCOMPARE(h.empty(Command::kGetMotorState), uint8_t(1));
  QVERIFY(h.status().motors_on);
  QCOMPARE(h.setMotorPower(2), kInvalid);
  QVERIFY(h.controller().lastRefusal().find("setMotorPower") != std::string::npos);
  QCOMPARE(h.setMotorPower(0), kOk);
  QCOMPARE(h.empty(Command::kGetMotorState), uint8_t(0));
  h.controller().setEmergencyStop(true);
  QCOMPARE(h.setMotorPower(1), kNotPossible);
  h.controller().setEmergencyStop(false);
  QCOMPARE(h.setMotorPower(1), kOk);
  SimConfig config;
  config.motors_on_at_start = true;
  Harness on(config);
  QCOMPARE(on.empty(Command::kGetMotorState), uint8_t(1));
}

void TestSimRequests::startMoveAcceptsOnlyTheDocumentedPairs() {
  Harness h;
  h.powerOnAndSettle();
  for (uint8_t controller = 0; controller <= 5; ++controller) {
    for (uint8_t generator = 0; generator <= 3; ++generator) {
      const bool valid = ((controller == 0 || controller == 2) && generator == 1) ||
                         ((controller == 1 || controller == 3) && generator == 2) || (controller == 4 && generator == 0);
      const uint8_t s = h.status(protocol::StartMoveRequestMsg{controller, generator});
      QVERIFY2(s == (valid ? kOk : kMoveInvalid), qPrintable(QString("pair %1/%2 -> %3").arg(controller).arg(generator).arg(s)));
      if (valid) {
        QVERIFY(h.status().motion_active);
        QCOMPARE(h.stopMove(), kOk);
        h.idle(5);
        QVERIFY(!h.status().motion_active);
      }
    }
  }
  QVERIFY2(!h.anyError(), h.errorList().c_str());
}

void TestSimRequests::startMoveRefusals() {
  Harness h;
  QCOMPARE(h.startMove(CM::kJointPosition, MG::kJointPosition), kMoveNotPossible);  // motors off
  QVERIFY(h.controller().lastRefusal().find("motors are off") != std::string::npos);
  h.powerOnAndSettle();
  startJointMotion(h);
  QCOMPARE(h.startMove(CM::kJointPosition, MG::kJointPosition), kMoveNotPossible);  // already moving
  QCOMPARE(h.stopMove(), kOk);
  h.idle(5);
  QCOMPARE(h.startDrag(0, 2), kOk);
  QCOMPARE(h.startMove(CM::kJointPosition, MG::kJointPosition), kMoveNotPossible);  // dragging
  QCOMPARE(h.empty(Command::kStopDrag), kOk);
  h.idle(5);
  h.controller().setGuardStop(true);
  QCOMPARE(h.startMove(CM::kJointPosition, MG::kJointPosition), kMoveNotPossible);
  h.controller().setGuardStop(false);
  h.controller().setEmergencyStop(true);
  QCOMPARE(h.startMove(CM::kJointPosition, MG::kJointPosition), kMoveEmergency);
  h.controller().setEmergencyStop(false);
  QCOMPARE(h.setMotorPower(1), kOk);
  // Error bits set: reflex.
  startJointMotion(h);
  std::array<double, 7> jump = h.state().q;
  jump[0] += 0.1;
  h.stepJoint(jump);
  QVERIFY(h.anyError());
  QCOMPARE(h.startMove(CM::kJointPosition, MG::kJointPosition), kMoveReflex);
  QCOMPARE(h.recover(), kOk);
  h.idle(5);
  QCOMPARE(h.startMove(CM::kJointPosition, MG::kJointPosition), kOk);
}

void TestSimRequests::startMoveAtSingularPose() {
  SimConfig config;
  config.initial_q = {0, 0.5236, 0, 1.0472, 0, 0, 0};  // q6 = 0: the wrist axes J5 and J7 line up
  Harness h(config);
  h.powerOnAndSettle();
  QCOMPARE(h.startMove(CM::kCartesianPosition, MG::kCartesianPosition), kMoveSingular);
  QCOMPARE(h.startMove(CM::kCartesianImpedance, MG::kCartesianPosition), kMoveSingular);
  QCOMPARE(h.startMove(CM::kJointPosition, MG::kJointPosition), kOk);  // joint space is fine
}

void TestSimRequests::stopMove() {
  Harness h;
  QCOMPARE(h.stopMove(), kOk);  // nothing to stop
  h.powerOnAndSettle();
  startJointMotion(h);
  QCOMPARE(h.stopMove(), kOk);
  h.idle(2);
  QVERIFY(!h.status().motion_active);
  QVERIFY(!h.controller().expectsCommand());
  QCOMPARE(h.state().robot_mode, RobotMode::kIdle);
  startJointMotion(h);
  std::array<double, 7> jump = h.state().q;
  jump[1] += 0.1;
  h.stepJoint(jump);
  QCOMPARE(h.stopMove(), uint8_t(3));  // kReflexAborted
  QCOMPARE(h.recover(), kOk);
  h.controller().setEmergencyStop(true);
  QCOMPARE(h.stopMove(), uint8_t(2));  // kEmergencyAborted
}

void TestSimRequests::settingsRejectValuesOutOfRange() {
  Harness h;
  const auto& spec = model::robotSpec(XMATE7_PRO);
  auto thresholds = spec.collision_threshold_max;
  QCOMPARE(h.status(protocol::SetCollisionBehaviorRequest{thresholds}), kOk);
  thresholds[2] += 1;
  QCOMPARE(h.status(protocol::SetCollisionBehaviorRequest{thresholds}), kInvalid);
  QVERIFY(h.controller().lastRefusal().find("upper_torque_thresholds_nominal[2]") != std::string::npos);
  QCOMPARE(h.status(protocol::SetCollisionBehaviorRequest{{10, 10, 10, 10, 10, 10, 0}}), kInvalid);  // 0 not in (0, max]

  QCOMPARE(h.status(protocol::SetJointImpedanceRequest{{0, 0, 0, 0, 0, 0, 0}}), kOk);
  QCOMPARE(h.status(protocol::SetJointImpedanceRequest{{3000, 3000, 3000, 3000, 300, 300, 301}}), kInvalid);
  QCOMPARE(h.status(protocol::SetCartesianImpedanceRequest{{3000, 3000, 3000, 300, 300, 300}}), kOk);
  QCOMPARE(h.status(protocol::SetCartesianImpedanceRequest{{3000, -1, 3000, 300, 300, 300}}), kInvalid);
  QCOMPARE(h.status(protocol::SetCartImpDesiredTauRequest{{60, -60, 0, 10, -10, 0}}), kOk);
  QCOMPARE(h.status(protocol::SetCartImpDesiredTauRequest{{61, 0, 0, 0, 0, 0}}), kInvalid);
  QCOMPARE(h.status(protocol::SetCartImpDesiredTauRequest{{0, 0, 0, 0, 0, NAN}}), kInvalid);
  QCOMPARE(h.status(protocol::SetFiltersRequest{10, 100, 1000}), kOk);
  QCOMPARE(h.status(protocol::SetFiltersRequest{0.5, 100, 100}), kInvalid);
  QCOMPARE(h.status(protocol::SetFiltersRequest{10, 1001, 100}), kInvalid);
  QCOMPARE(h.status(protocol::SetTorqueFilterCutOffFrequencyRequest{50}), kOk);
  QCOMPARE(h.status(protocol::SetTorqueFilterCutOffFrequencyRequest{0}), kInvalid);
  QCOMPARE(h.status(protocol::SetTorqueFilterCutOffFrequencyRequest{INFINITY}), kInvalid);
  QCOMPARE(h.status(protocol::SetLoadRequest{7.0, {0, 0, 0.1}, {0.01, 0, 0, 0, 0.01, 0, 0, 0, 0.01}}), kOk);
  QCOMPARE(h.status(protocol::SetLoadRequest{7.5, {0, 0, 0.1}, {0.01, 0, 0, 0, 0.01, 0, 0, 0, 0.01}}), kInvalid);
  QCOMPARE(h.status(protocol::SetLoadRequest{1.0, {0, 0, 0.6}, {0.01, 0, 0, 0, 0.01, 0, 0, 0, 0.01}}), kInvalid);
  QCOMPARE(h.status(protocol::SetLoadRequest{1.0, {0, 0, 0.1}, {0.01, 0.001, 0, 0, 0.01, 0, 0, 0, 0.01}}), kInvalid);
  QCOMPARE(h.status(protocol::SetLoadRequest{1.0, {0, 0, 0.1}, {0.01, 0, 0, 0, 0.01, 0, 0, 0, 0.03}}), kInvalid);
  QCOMPARE(h.status(protocol::SetLoadRequest{1.0, {0, 0, 0.1}, {2.5, 0, 0, 0, 2.5, 0, 0, 0, 2.5}}), kInvalid);
  // Asymmetry within the relative tolerance of a large inertia is accepted by the range check and
  // by the dynamics model alike (the fuzzer found the two disagreeing and the controller throwing).
  QCOMPARE(h.status(protocol::SetLoadRequest{1.0, {0, 0, 0.1}, {1.5, 1.4e-9, 0, 0, 1.5, 0, 0, 0, 1.5}}), kOk);
  Eigen::Isometry3d tool = kIdentity;
  tool.translation() = Eigen::Vector3d(0, 0, 0.6);
  QCOMPARE(h.status(protocol::SetCoorRequest{rowMajor(tool)}), kInvalid);
  auto skewed = rowMajor(kIdentity);
  skewed[1] = 0.01;
  QCOMPARE(h.status(protocol::SetCoorRequest{skewed}), kInvalid);
  QCOMPARE(h.status(protocol::SetCartesianLimitRequest{{0, 1, 1}, rowMajor(kIdentity), true}), kInvalid);
  QCOMPARE(h.status(protocol::SetCartesianLimitRequest{{1, 1, 5.1}, rowMajor(kIdentity), true}), kInvalid);
  QCOMPARE(h.status(protocol::SetJointLimitRequest{{170, 120, 170, 120, 170, 120, 361}, {-170, -120, -170, -120, -170, -120, -360}, false}), kInvalid);
  QCOMPARE(h.status(protocol::SetJointLimitRequest{{10, 120, 170, 120, 170, 120, 360}, {20, -120, -170, -120, -170, -120, -360}, false}), kInvalid);
  QCOMPARE(h.status(protocol::SetFcCoorRequest{rowMajor(kIdentity), 3}), kInvalid);  // wire types 0..2
  QCOMPARE(h.status(protocol::SetFcCoorRequest{skewed, 0}), kInvalid);
  QCOMPARE(h.status(protocol::SetFcCoorRequest{rowMajor(kIdentity), 2}), kOk);
  QCOMPARE(h.status(protocol::EnableVirtualGuideRequest{true, {100, 100, 100, 10, 10, 10}}), kOk);
  QCOMPARE(h.status(protocol::EnableVirtualGuideRequest{true, {100, 100, 100, 10, 10, 301}}), kInvalid);
  QCOMPARE(h.status(protocol::SetDORequest{6, true}), kInvalid);
  QCOMPARE(h.startDrag(0, 0), kInvalid);  // joint-space drag is always free
  QCOMPARE(h.startDrag(2, 2), kInvalid);
  QCOMPARE(h.startDrag(1, 3), kInvalid);

  SimConfig six;
  six.type = XMATE3;
  six.initial_q = {0, 0.5, 1.0, 0, 0.8, 0, 0};
  Harness h6(six);
  QCOMPARE(h6.status(protocol::SetCollisionBehaviorRequest{{75, 75, 45, 30, 30, 20, 0}}), kOk);
  QCOMPARE(h6.status(protocol::SetCollisionBehaviorRequest{{75, 75, 45, 30, 30, 20, 1}}), kInvalid);
  QCOMPARE(h6.status(protocol::SetLoadRequest{3.5, {0, 0, 0}, {0, 0, 0, 0, 0, 0, 0, 0, 0}}), kInvalid);  // 3 kg rated
}

void TestSimRequests::settingsThatMustNotChangeDuringMotion() {
  Harness h;
  h.powerOnAndSettle();
  startJointMotion(h);
  QCOMPARE(h.status(protocol::SetCoorRequest{rowMajor(kIdentity)}), kNotPossible);
  QCOMPARE(h.status(protocol::SetLoadRequest{1.0, {0, 0, 0.1}, {0.01, 0, 0, 0, 0.01, 0, 0, 0, 0.01}}), kNotPossible);
  QCOMPARE(h.status(protocol::SetFcCoorRequest{rowMajor(kIdentity), 1}), kNotPossible);
  QCOMPARE(h.status(protocol::SetCartesianLimitRequest{{3, 3, 3}, rowMajor(kIdentity), true}), kNotPossible);
  QCOMPARE(h.status(protocol::SetJointLimitRequest{{170, 120, 170, 120, 170, 120, 360}, {-170, -120, -170, -120, -170, -120, -360}, true}), kNotPossible);
  QCOMPARE(h.startDrag(1, 2), kNotPossible);
  QVERIFY(h.controller().lastRefusal().find("motion is running") != std::string::npos);
  // Invalid values are still reported as invalid during motion.
  QCOMPARE(h.status(protocol::SetLoadRequest{99, {0, 0, 0.1}, {0.01, 0, 0, 0, 0.01, 0, 0, 0, 0.01}}), kInvalid);
  // Same while hand guiding.
  QCOMPARE(h.stopMove(), kOk);
  h.idle(5);
  QCOMPARE(h.startDrag(1, 2), kOk);
  QCOMPARE(h.status(protocol::SetCoorRequest{rowMajor(kIdentity)}), kNotPossible);
  QCOMPARE(h.empty(Command::kStopDrag), kOk);
  h.idle(5);
  QCOMPARE(h.status(protocol::SetCoorRequest{rowMajor(kIdentity)}), kOk);
}

void TestSimRequests::settingsAllowedDuringMotion() {
  Harness h;
  h.powerOnAndSettle();
  startJointMotion(h);
  QCOMPARE(h.status(protocol::SetCollisionBehaviorRequest{{70, 70, 50, 40, 25, 25, 15}}), kOk);
  QCOMPARE(h.status(protocol::SetJointImpedanceRequest{{1000, 1000, 1000, 1000, 100, 100, 100}}), kOk);
  QCOMPARE(h.status(protocol::SetCartesianImpedanceRequest{{1000, 1000, 1000, 100, 100, 100}}), kOk);
  QCOMPARE(h.status(protocol::SetCartImpDesiredTauRequest{{0, 0, 5, 0, 0, 0}}), kOk);
  QCOMPARE(h.status(protocol::SetFiltersRequest{50, 50, 50}), kOk);
  QCOMPARE(h.status(protocol::SetDORequest{0, true}), kOk);
  QVERIFY(h.status().motion_active);
}

void TestSimRequests::toolChangesTheReportedTcp() {
  Harness h;
  Eigen::Isometry3d tool(Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitX()));
  tool.translation() = Eigen::Vector3d(0.02, -0.01, 0.15);
  QCOMPARE(h.status(protocol::SetCoorRequest{rowMajor(tool)}), kOk);
  h.idle(1);
  // Independent reference: the flange from the DH table (model/robot_spec.cpp), then the tool.
  const Eigen::Isometry3d flange = model::dhFlangePose(model::robotSpec(XMATE7_PRO), h.state().q);
  const Eigen::Isometry3d expected = flange * tool;
  const Eigen::Isometry3d tcp = poseOf(h.state().toolTobase_pos_m);
  QVERIFY((tcp.translation() - expected.translation()).norm() < 1e-9);
  QVERIFY((tcp.linear() - expected.linear()).cwiseAbs().maxCoeff() < 1e-9);
}

void TestSimRequests::loadChangesTheModel() {
  // A correctly declared load: the motors carry it, the estimate sees nothing external.
  Harness h;
  QCOMPARE(h.status(protocol::SetLoadRequest{5.0, {0, 0, 0.1}, {0.01, 0, 0, 0, 0.01, 0, 0, 0, 0.01}}), kOk);
  h.powerOnAndSettle(200);
  XmateModel model(XMATE7_PRO);
  model.SetLoad(5.0, {0, 0, 0.1}, {0.01, 0, 0, 0, 0.01, 0, 0, 0, 0.01});
  std::array<double, 7> full, inertial, coriolis, gravity;
  model.GetTauNoFriction(h.state().q, {}, {}, full, inertial, coriolis, gravity);
  for (size_t i = 0; i < 7; ++i) {
    QVERIFY(std::abs(h.state().tau_m[i] - gravity[i]) < 1e-6);
    QVERIFY(std::abs(h.status().external_joint_torque[i]) < 1e-6);
  }
  QCOMPARE(h.status().actual_payload_mass, 5.0);
  QVERIFY(h.status().actual_payload_follows_load);
}

void TestSimRequests::safetyBoxRefusedWhenTcpOutside() {
  Harness h;
  h.powerOnAndSettle();
  const Eigen::Vector3d tcp = poseOf(h.state().toolTobase_pos_m).translation();
  Eigen::Isometry3d far = kIdentity;
  far.translation() = tcp + Eigen::Vector3d(2, 0, 0);
  QCOMPARE(h.status(protocol::SetCartesianLimitRequest{{1, 1, 1}, rowMajor(far), true}), kNotPossible);
  QCOMPARE(h.status(protocol::SetCartesianLimitRequest{{1, 1, 1}, rowMajor(far), false}), kOk);  // inactive: fine
  Eigen::Isometry3d around = kIdentity;
  around.translation() = tcp;
  QCOMPARE(h.status(protocol::SetCartesianLimitRequest{{0.4, 0.4, 0.4}, rowMajor(around), true}), kOk);
  h.idle(100);
  QVERIFY(h.status().motors_on);
  QVERIFY2(!h.anyError(), h.errorList().c_str());
}

void TestSimRequests::softLimitsLeavingJointOutsideReportBitZero() {
  Harness h;  // q2 starts at 30 deg
  h.powerOnAndSettle();
  const double q2 = h.state().q[1];
  // Limits that leave J2 outside are accepted, and J2 is reported beyond its limit at once.
  QCOMPARE(h.status(protocol::SetJointLimitRequest{{170, 20, 170, 120, 170, 120, 360}, {-170, -120, -170, -120, -170, -120, -360}, false}), kOk);
  h.idle(2);
  QCOMPARE(h.errorList(), std::string("kActualJointPositionLimitsViolation"));
  QCOMPARE(h.startMove(CM::kJointPosition, MG::kJointPosition), uint8_t(protocol::StartMoveStatus::kReflexAborted));
  // After recovery, a motion back towards the range is accepted; the arm stays powered.
  QCOMPARE(h.recover(), kOk);
  QVERIFY(h.status().motors_on);
  QCOMPARE(h.startMove(CM::kJointPosition, MG::kJointPosition), kOk);
  std::array<double, 7> q = h.state().q;
  for (int i = 0; i < 200; ++i) {
    q[1] -= 2e-6 * i;  // gently accelerating towards 20 deg
    h.stepJoint(q, i == 199);
  }
  h.idle(50);
  QVERIFY2(!h.anyError(), h.errorList().c_str());
  QVERIFY(h.state().q[1] < q2);
  QCOMPARE(h.status(protocol::SetJointLimitRequest{{170, 40, 170, 120, 170, 120, 360}, {-170, -120, -170, -120, -170, -120, -360}, true}), kOk);
  // The 116-byte form (without auto_limit) is accepted.
  protocol::Frame frame = protocol::encodeFrame(1, protocol::SetJointLimitRequest{{170, 40, 170, 120, 170, 120, 360}, {-170, -120, -170, -120, -170, -120, -360}, true});
  QCOMPARE(frame.size(), size_t(6 + 117));
  QCOMPARE(parseResponse(h.sendRaw(frame.data() + 6, 116)).value, kOk);
}

void TestSimRequests::loadRobotModelLayout() {
  for (XmateType type : model::allRobotTypes()) {
    SimConfig config;
    config.type = type;
    const auto& spec = model::robotSpec(type);
    if (spec.dof == 6) config.initial_q = {0, 0.5, 1.0, 0, 0.8, 0, 0};
    Harness h(config);
    const protocol::Frame frame = h.send(protocol::EmptyRequest{Command::kLoadRobotModel});
    protocol::LoadRobotModelResponse r;
    QCOMPARE(protocol::decodePayload(frame.data() + 6, frame.size() - 6, r), protocol::DecodeStatus::kOk);
    QCOMPARE(r.status, uint8_t(0));
    for (size_t i = 0; i < 7; ++i) {
      const bool used = int(i) < spec.dof;
      QCOMPARE(r.dh[4 * i + 0], used ? spec.dh[i].a : 0.0);
      QCOMPARE(r.dh[4 * i + 1], used ? spec.dh[i].alpha : 0.0);
      QCOMPARE(r.dh[4 * i + 2], used ? spec.dh[i].d : 0.0);
      QCOMPARE(r.dims[3 * i + 0], used ? spec.q_min[i] : 0.0);
      QCOMPARE(r.dims[3 * i + 1], used ? spec.q_max[i] : 0.0);
      QCOMPARE(r.dims[3 * i + 2], used ? spec.dq_max[i] : 0.0);
      QCOMPARE(r.dyn[4 * i], used ? spec.link_mass[i + 1] : 0.0);  // link masses (model/robot_spec.cpp)
      if (used) QVERIFY(r.dyn_friction[9 * i + 0] > 0 && r.dyn_friction[9 * i + 8] > 0);  // Ixx, rotor inertia
    }
    QCOMPARE(r.dyn_friction[65], -9.81);
    QCOMPARE(r.dyn[41], 1.0);  // tool quaternion w of the identity tool
  }
}

void TestSimRequests::digitalIoAndLoopback() {
  Harness h;
  const auto di = [&](uint8_t signal) {
    const protocol::Frame frame = h.send(protocol::GetDIStateRequest{signal});
    protocol::GetDIStateResponse r;
    if (protocol::decodePayload(frame.data() + 6, frame.size() - 6, r) != protocol::DecodeStatus::kOk) return -1;
    return r.status != 0 ? -int(r.status) - 10 : int(r.state);
  };
  QCOMPARE(di(6), -12);  // status kInvalidArgument
  h.controller().setDigitalInput(3, true);
  QCOMPARE(di(3), 1);
  QCOMPARE(di(2), 0);
  QCOMPARE(h.status(protocol::SetDORequest{2, true}), kOk);
  QVERIFY(h.status().digital_out[2]);
  QCOMPARE(di(2), 0);  // not wired
  h.controller().setDoToDiLoopback(true);
  QCOMPARE(di(2), 1);
  QCOMPARE(di(3), 0);  // loop-back: DI3 follows DO3
  QCOMPARE(h.status(protocol::SetDORequest{2, false}), kOk);
  QCOMPARE(h.status(protocol::SetDORequest{5, true}), kOk);
  QCOMPARE(di(2), 0);
  QCOMPARE(di(5), 1);
  h.controller().setDoToDiLoopback(false);
  QCOMPARE(di(3), 1);
  SimConfig config;
  config.do_to_di_loopback = true;
  Harness looped(config);
  QCOMPARE(looped.status(protocol::SetDORequest{0, true}), kOk);
  QVERIFY(looped.status().digital_in[0]);
}

void TestSimRequests::dragRequests() {
  Harness h;
  QCOMPARE(h.startDrag(1, 0), kNotPossible);  // motors off
  h.powerOnAndSettle();
  QCOMPARE(h.startDrag(1, 0), kOk);
  h.idle(1);
  QCOMPARE(h.state().robot_mode, RobotMode::kGuiding);
  QVERIFY(h.status().dragging);
  QVERIFY(!h.controller().expectsCommand());
  QCOMPARE(h.startDrag(0, 2), kOk);  // switching the kind of guiding is fine
  QCOMPARE(h.empty(Command::kStopDrag), kOk);
  h.idle(2);
  QCOMPARE(h.state().robot_mode, RobotMode::kIdle);
  QCOMPARE(h.empty(Command::kStopDrag), kOk);  // not dragging: nothing to do
}

void TestSimRequests::emergencyStop() {
  Harness h;
  h.powerOnAndSettle();
  QCOMPARE(h.empty(Command::kGetSafetyStopState), uint8_t(0));
  h.controller().setEmergencyStop(true);  // while idle: no error bit
  h.idle(1);
  QVERIFY(!h.anyError());
  QVERIFY(!h.status().motors_on);
  QCOMPARE(h.status().safety_stop, 2);
  QCOMPARE(h.empty(Command::kGetSafetyStopState), uint8_t(1));
  QCOMPARE(h.state().robot_mode, RobotMode::kUserStopped);
  h.controller().setEmergencyStop(false);
  h.idle(1);
  QCOMPARE(h.state().robot_mode, RobotMode::kIdle);
  // During a motion: aborted with kInstabilityDetection, manual recovery until released.
  QCOMPARE(h.setMotorPower(1), kOk);
  startJointMotion(h);
  h.controller().setEmergencyStop(true);
  h.idle(1);
  QCOMPARE(h.errorList(), std::string("kInstabilityDetection"));
  QVERIFY(!h.status().motion_active);
  QVERIFY(!h.status().motors_on);
  QCOMPARE(h.state().robot_mode, RobotMode::kUserStopped);
  QCOMPARE(h.recover(), uint8_t(2));  // kManualRecoveryRequired
  QCOMPARE(h.startDrag(1, 2), kNotPossible);
  h.controller().setEmergencyStop(false);
  h.idle(1);
  QCOMPARE(h.state().robot_mode, RobotMode::kReflex);
  QCOMPARE(h.recover(), kOk);
  QCOMPARE(h.setMotorPower(1), kOk);
  QCOMPARE(h.startMove(CM::kJointPosition, MG::kJointPosition), kOk);
}

void TestSimRequests::guardStop() {
  Harness h;
  h.powerOnAndSettle();
  startJointMotion(h);
  h.controller().setGuardStop(true);
  h.idle(1);
  QCOMPARE(h.empty(Command::kGetSafetyStopState), uint8_t(2));
  QCOMPARE(h.status().safety_stop, 3);
  QVERIFY(!h.status().motion_active);
  QVERIFY(h.status().motors_on);  // a controlled stop: motors stay on
  QVERIFY(!h.anyError());
  QCOMPARE(h.state().robot_mode, RobotMode::kUserStopped);
  QCOMPARE(h.startMove(CM::kJointPosition, MG::kJointPosition), kMoveNotPossible);
  h.controller().setGuardStop(false);
  h.idle(5);
  QCOMPARE(h.state().robot_mode, RobotMode::kIdle);
  QCOMPARE(h.startMove(CM::kJointPosition, MG::kJointPosition), kOk);
  // The e-stop wins over the guard stop in getSafetyStopState.
  h.controller().setGuardStop(true);
  h.controller().setEmergencyStop(true);
  QCOMPARE(h.empty(Command::kGetSafetyStopState), uint8_t(1));
}

void TestSimRequests::errorRecovery() {
  Harness h;
  QCOMPARE(h.recover(), kOk);  // nothing to recover
  h.powerOnAndSettle();
  startJointMotion(h);
  std::array<double, 7> jump = h.state().q;
  jump[0] += 0.1;
  h.stepJoint(jump);
  QVERIFY(h.anyError());
  h.idle(3);
  QCOMPARE(h.state().robot_mode, RobotMode::kReflex);
  QVERIFY(h.anyError());  // bits stay
  QCOMPARE(h.recover(), kOk);
  h.idle(1);
  QVERIFY(!h.anyError());
  QCOMPARE(h.state().robot_mode, RobotMode::kAutomaticErrorRecovery);
  h.idle(60);
  QCOMPARE(h.state().robot_mode, RobotMode::kIdle);
}

void TestSimRequests::rebootRequest() {
  Harness h;
  h.powerOnAndSettle();
  QVERIFY(!h.controller().rebootRequested());
  QCOMPARE(h.empty(Command::kRebootRobot), kOk);
  QVERIFY(h.controller().rebootRequested());
  QVERIFY(!h.status().motors_on);
  QCOMPARE(h.setMotorPower(1), kNotPossible);
}

void TestSimRequests::unknownAndMalformedRequests() {
  Harness h;
  h.powerOnAndSettle();
  const uint8_t unknown[4] = {0, 0, 0, 99};
  RawResponse r = parseResponse(h.sendRaw(unknown, 4));
  QCOMPARE(r.command, uint32_t(99));
  QCOMPARE(r.value, kNotPossible);
  const uint8_t tiny[2] = {0, 1};
  r = parseResponse(h.sendRaw(tiny, 2));
  QCOMPARE(r.command, uint32_t(0xFF));
  QCOMPARE(r.value, kInvalid);
  r = parseResponse(h.sendRaw(nullptr, 0));
  QCOMPARE(r.command, uint32_t(0xFF));
  // Every known command with a payload of the wrong length, and with garbage: a response, no crash.
  for (uint32_t code = 0; code <= 24; ++code) {
    for (size_t extra : {size_t(1), size_t(3), size_t(200)}) {
      std::vector<uint8_t> payload(4 + extra, 0xA5);
      payload[0] = 0, payload[1] = 0, payload[2] = 0, payload[3] = uint8_t(code);
      const protocol::Frame frame = h.sendRaw(payload.data(), payload.size());
      r = parseResponse(frame);
      QVERIFY(r.command == code || r.command == 0xFF);
    }
  }
  // A bool that is neither 0 nor 1 is malformed too.
  protocol::Frame frame = protocol::encodeFrame(1, protocol::SetDORequest{1, true});
  frame.back() = 2;
  QCOMPARE(parseResponse(h.sendRaw(frame.data() + 6, frame.size() - 6)).value, kInvalid);
  // Malformed StartMove: kInvalidArgument of StartMove.
  const uint8_t start_move[5] = {0, 0, 0, 3, 0};
  QCOMPARE(parseResponse(h.sendRaw(start_move, 5)).value, kMoveInvalid);
  QVERIFY2(!h.anyError(), h.errorList().c_str());
  QVERIFY(h.status().motors_on);
}

QTEST_APPLESS_MAIN(TestSimRequests)
#include "test_sim_requests.moc"
