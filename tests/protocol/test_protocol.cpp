// SPDX-License-Identifier: Apache-2.0
// Pins the RCI wire format: sizes, field offsets, byte order, round trips, and rejection of
// datagrams and payloads of the wrong length or with impossible values.
#include <QtTest>

#include <bit>
#include <cstring>

#include "protocol/realtime_codec.h"
#include "protocol/tcp_codec.h"

using namespace xmate::protocol;
using RCI::robot::RobotCommand;
using RCI::robot::RobotState;

namespace {

double readLeDouble(const uint8_t* p) {
  uint64_t bits = 0;
  for (int i = 7; i >= 0; --i) bits = bits << 8 | p[i];
  return std::bit_cast<double>(bits);
}

// A state whose every field holds a distinct value, so a misplaced field shows.
RobotState numberedState() {
  RobotState s;
  double v = 1.0;
  auto fill = [&](auto& arr) { for (auto& x : arr) x = (v += 0.5); };
  s.message_id = 0x0102030405060708ULL;
  fill(s.q); fill(s.q_c); fill(s.dq_m); fill(s.dq_c); fill(s.ddq_c);
  fill(s.toolTobase_pos_m); fill(s.toolTobase_pos_c); fill(s.toolTobase_vel_c); fill(s.toolTobase_acc_c);
  s.psi_m = (v += 0.5); s.psi_c = (v += 0.5); s.psi_vel_c = (v += 0.5); s.psi_acc_c = (v += 0.5);
  fill(s.tau_m); fill(s.tau_m_filtered); fill(s.tau_c); fill(s.tau_vel_c);
  fill(s.tau_ext_in_base); fill(s.tau_ext_in_stiff);
  fill(s.theta_m); fill(s.theta_vel_m); fill(s.motor_tau); fill(s.motor_tau_filtered);
  for (size_t i = 0; i < s.errors.size(); ++i) s.errors[i] = i % 3 == 0;
  s.control_command_success_rate = 0.97;
  s.motion_generator_mode = RCI::robot::MotionGeneratorMode::kCartesianPosition;
  s.controller_mode = RCI::robot::ControllerMode::kTorque;
  s.robot_mode = RCI::robot::RobotMode::kGuiding;
  return s;
}

}  // namespace

class TestProtocol : public QObject {
  Q_OBJECT

 private slots:
  void robotStateSizeAndOffsets() {
    QCOMPARE(kRobotStateSize, size_t(1247));
    RobotStateBuffer buf{};
    const RobotState s = numberedState();
    encodeRobotState(s, buf);
    // message_id is big-endian.
    for (int i = 0; i < 8; ++i) QCOMPARE(int(buf[i]), i + 1);
    // Doubles are little-endian, in declaration order: q at 8, q_c at 64, ...
    QCOMPARE(readLeDouble(&buf[8]), s.q[0]);
    QCOMPARE(readLeDouble(&buf[8 + 7 * 8]), s.q_c[0]);
    QCOMPARE(readLeDouble(&buf[288]), s.toolTobase_pos_m[0]);
    QCOMPARE(readLeDouble(&buf[416]), s.toolTobase_pos_c[0]);
    QCOMPARE(readLeDouble(&buf[544]), s.toolTobase_vel_c[0]);
    QCOMPARE(readLeDouble(&buf[640]), s.psi_m);
    QCOMPARE(readLeDouble(&buf[672]), s.tau_m[0]);
    QCOMPARE(readLeDouble(&buf[896]), s.tau_ext_in_base[0]);
    QCOMPARE(readLeDouble(&buf[992]), s.theta_m[0]);
    QCOMPARE(readLeDouble(&buf[1160]), s.motor_tau_filtered[0]);
    QCOMPARE(kRobotStateErrorsOffset, size_t(1216));
    for (int i = 0; i < 20; ++i) QCOMPARE(int(buf[kRobotStateErrorsOffset + i]), i % 3 == 0 ? 1 : 0);
    QCOMPARE(kRobotStateSuccessRateOffset, size_t(1236));
    QCOMPARE(readLeDouble(&buf[kRobotStateSuccessRateOffset]), 0.97);
    QCOMPARE(kRobotStateModesOffset, size_t(1244));
    QCOMPARE(int(buf[1244]), 3);  // Cartesian position
    QCOMPARE(int(buf[1245]), 4);  // torque
    QCOMPARE(int(buf[1246]), 3);  // guiding
  }

  void robotStateRoundTrip() {
    RobotStateBuffer buf{};
    const RobotState s = numberedState();
    encodeRobotState(s, buf);
    RobotState d;
    QCOMPARE(decodeRobotState(buf.data(), buf.size(), d), DecodeStatus::kOk);
    QCOMPARE(d.message_id, s.message_id);
    QVERIFY(d.q == s.q && d.motor_tau_filtered == s.motor_tau_filtered && d.errors == s.errors);
    QVERIFY(d.toolTobase_pos_c == s.toolTobase_pos_c && d.tau_ext_in_stiff == s.tau_ext_in_stiff);
    QCOMPARE(d.psi_acc_c, s.psi_acc_c);
    QVERIFY(d.robot_mode == s.robot_mode && d.controller_mode == s.controller_mode);
    QVERIFY(d.motion_generator_mode == s.motion_generator_mode);
  }

  void robotStateRejectsBadDatagrams() {
    RobotStateBuffer buf{};
    encodeRobotState(numberedState(), buf);
    RobotState d;
    QCOMPARE(decodeRobotState(buf.data(), 1246, d), DecodeStatus::kWrongLength);
    QCOMPARE(decodeRobotState(buf.data(), 0, d), DecodeStatus::kWrongLength);
    auto bad = buf;
    bad[kRobotStateErrorsOffset + 2] = 7;  // a bool that is neither 0 nor 1
    QCOMPARE(decodeRobotState(bad.data(), bad.size(), d), DecodeStatus::kBadValue);
    bad = buf;
    bad[1246] = 9;  // robot_mode out of range
    QCOMPARE(decodeRobotState(bad.data(), bad.size(), d), DecodeStatus::kBadValue);
  }

  void robotCommandLayout() {
    QCOMPARE(kRobotCommandSize, size_t(290));
    QCOMPARE(kRobotCommandLegacySize, size_t(258));
    RobotCommand c;
    c.message_id = 42;
    for (int i = 0; i < 7; ++i) c.motion.q_c[i] = 0.1 * i;
    for (int i = 0; i < 16; ++i) c.motion.toolTobase_pos_c[i] = 10.0 + i;
    c.motion.psi_valid = true;
    c.motion.psi_c = -0.25;
    c.motion.motion_generation_finished = true;
    c.motion.dynamic_wall = {1, 2, 3, 4};
    for (int i = 0; i < 7; ++i) c.torque.tau_c[i] = -1.0 - i;
    RobotCommandBuffer buf{};
    encodeRobotCommand(c, buf);
    QCOMPARE(int(buf[7]), 42);  // big-endian id
    QCOMPARE(int(buf[0]), 0);
    QCOMPARE(readLeDouble(&buf[8 + 8]), 0.1);
    QCOMPARE(readLeDouble(&buf[64]), 10.0);
    QCOMPARE(int(buf[192]), 1);
    QCOMPARE(readLeDouble(&buf[193]), -0.25);
    QCOMPARE(int(buf[201]), 1);
    QCOMPARE(readLeDouble(&buf[202]), 1.0);
    QCOMPARE(readLeDouble(&buf[234]), -1.0);
    QCOMPARE(readLeDouble(&buf[282]), -7.0);

    RobotCommand d;
    QCOMPARE(decodeRobotCommand(buf.data(), buf.size(), d), DecodeStatus::kOk);
    QVERIFY(d.motion.q_c == c.motion.q_c && d.torque.tau_c == c.torque.tau_c);
    QVERIFY(d.motion.dynamic_wall == c.motion.dynamic_wall && d.motion.psi_valid);

    // The legacy 258-byte form: the same without dynamic_wall.
    std::array<uint8_t, 258> legacy{};
    std::memcpy(legacy.data(), buf.data(), 202);
    std::memcpy(legacy.data() + 202, buf.data() + 234, 56);
    RobotCommand l;
    QCOMPARE(decodeRobotCommand(legacy.data(), legacy.size(), l), DecodeStatus::kOk);
    QVERIFY(l.torque.tau_c == c.torque.tau_c && l.motion.q_c == c.motion.q_c);
    QVERIFY(l.motion.dynamic_wall == (std::array<double, 4>{}));

    QCOMPARE(decodeRobotCommand(buf.data(), 289, d), DecodeStatus::kWrongLength);
    buf[192] = 2;
    QCOMPARE(decodeRobotCommand(buf.data(), buf.size(), d), DecodeStatus::kBadValue);
  }

  void tcpFramingAndByteOrder() {
    const Frame f = encodeFrame(0x01020304, ConnectRequest{0x1234});
    QCOMPARE(f.size(), size_t(6 + 6));
    const uint8_t expected[] = {0x00, 0x06, 0x01, 0x02, 0x03, 0x04, 0, 0, 0, 0, 0x12, 0x34};
    QVERIFY(std::memcmp(f.data(), expected, sizeof expected) == 0);
    uint8_t head[kFrameHeaderSize];
    std::memcpy(head, f.data(), kFrameHeaderSize);
    const FrameHeader h = decodeFrameHeader(head);
    QCOMPARE(h.length, uint16_t(6));
    QCOMPARE(h.sequence, uint32_t(0x01020304));
    QCOMPARE(peekCommand(f.data() + 6, 6), Command::kConnect);
  }

  void tcpPayloadSizes() {
    // The "bytes" column of docs/protocol.md ("Command codes and payloads"): Command code (4) + fields.
    auto payload = [](const Frame& f) { return f.size() - kFrameHeaderSize; };
    QCOMPARE(payload(encodeFrame(1, ConnectRequest{})), size_t(6));
    QCOMPARE(payload(encodeFrame(1, ByteResponse{Command::kConnect, 0})), size_t(5));
    QCOMPARE(payload(encodeFrame(1, SetMotorPowerRequest{})), size_t(5));
    QCOMPARE(payload(encodeFrame(1, StartMoveRequestMsg{})), size_t(6));
    QCOMPARE(payload(encodeFrame(1, SetCartesianLimitRequest{})), size_t(157));
    QCOMPARE(payload(encodeFrame(1, SetJointLimitRequest{})), size_t(117));
    QCOMPARE(payload(encodeFrame(1, SetCollisionBehaviorRequest{})), size_t(60));
    QCOMPARE(payload(encodeFrame(1, SetJointImpedanceRequest{})), size_t(60));
    QCOMPARE(payload(encodeFrame(1, SetCartesianImpedanceRequest{})), size_t(52));
    QCOMPARE(payload(encodeFrame(1, SetCoorRequest{})), size_t(132));
    QCOMPARE(payload(encodeFrame(1, SetLoadRequest{})), size_t(108));
    QCOMPARE(payload(encodeFrame(1, SetCartImpDesiredTauRequest{})), size_t(52));
    QCOMPARE(payload(encodeFrame(1, SetFiltersRequest{})), size_t(28));
    QCOMPARE(payload(encodeFrame(1, SetTorqueFilterCutOffFrequencyRequest{})), size_t(12));
    QCOMPARE(payload(encodeFrame(1, LoadRobotModelResponse{})), size_t(1285));
    QCOMPARE(payload(encodeFrame(1, SetFcCoorRequest{})), size_t(133));
    QCOMPARE(payload(encodeFrame(1, EnableVirtualGuideRequest{})), size_t(53));
    QCOMPARE(payload(encodeFrame(1, SetDORequest{})), size_t(6));
    QCOMPARE(payload(encodeFrame(1, GetDIStateRequest{})), size_t(5));
    QCOMPARE(payload(encodeFrame(1, GetDIStateResponse{})), size_t(6));
    QCOMPARE(payload(encodeFrame(1, StartDragRequest{})), size_t(6));
    QCOMPARE(payload(encodeFrame(1, EmptyRequest{Command::kRebootRobot})), size_t(4));
  }

  void tcpRoundTrips() {
    SetLoadRequest load;
    load.mass = 2.5;
    load.center = {0.01, 0.02, 0.1};
    load.inertia = {1, 0, 0, 0, 2, 0, 0, 0, 3};
    Frame f = encodeFrame(7, load);
    SetLoadRequest back;
    QCOMPARE(decodePayload(f.data() + 6, f.size() - 6, back), DecodeStatus::kOk);
    QCOMPARE(back.mass, 2.5);
    QVERIFY(back.center == load.center && back.inertia == load.inertia);

    SetJointLimitRequest jl;
    jl.upper = {1, 2, 3, 4, 5, 6, 7};
    jl.lower = {-1, -2, -3, -4, -5, -6, -7};
    jl.auto_limit = true;
    f = encodeFrame(8, jl);
    SetJointLimitRequest jb;
    QCOMPARE(decodePayload(f.data() + 6, f.size() - 6, jb), DecodeStatus::kOk);
    QVERIFY(jb.auto_limit && jb.upper == jl.upper && jb.lower == jl.lower);
    // The older 116-byte form (no auto_limit) is accepted and means auto_limit = false.
    QCOMPARE(decodePayload(f.data() + 6, 116, jb), DecodeStatus::kOk);
    QVERIFY(!jb.auto_limit && jb.upper == jl.upper);

    ByteResponse r;
    f = encodeFrame(9, ByteResponse{Command::kStartMove, 3});
    QCOMPARE(decodePayload(f.data() + 6, f.size() - 6, r), DecodeStatus::kOk);
    QCOMPARE(r.command, Command::kStartMove);
    QCOMPARE(int(r.value), 3);

    LoadRobotModelResponse lm;
    lm.dh[27] = 1.25;
    lm.dyn[44] = -3.5;
    f = encodeFrame(10, lm);
    LoadRobotModelResponse lb;
    QCOMPARE(decodePayload(f.data() + 6, f.size() - 6, lb), DecodeStatus::kOk);
    QCOMPARE(lb.dh[27], 1.25);
    QCOMPARE(lb.dyn[44], -3.5);
  }

  void tcpRejectsMismatches() {
    Frame f = encodeFrame(1, SetDORequest{3, true});
    SetMotorPowerRequest wrong;
    // Same size as SetMotorPower? No: SetDO is 6 bytes, SetMotorPower 5 -> wrong length.
    QCOMPARE(decodePayload(f.data() + 6, f.size() - 6, wrong), DecodeStatus::kWrongLength);
    StartDragRequest drag;  // same size (6) but another Command code
    QCOMPARE(decodePayload(f.data() + 6, f.size() - 6, drag), DecodeStatus::kBadValue);
    SetDORequest dor;
    f[6 + 5] = 2;  // bool state = 2
    QCOMPARE(decodePayload(f.data() + 6, f.size() - 6, dor), DecodeStatus::kBadValue);
    ByteResponse r;
    const uint8_t unknown[] = {0, 0, 0, 99, 0};
    QCOMPARE(decodePayload(unknown, sizeof unknown, r), DecodeStatus::kBadValue);
    QCOMPARE(peekCommand(unknown, sizeof unknown), Command::kInvalid);
    QCOMPARE(peekCommand(unknown, 3), Command::kInvalid);
  }
};

QTEST_APPLESS_MAIN(TestProtocol)
#include "test_protocol.moc"
