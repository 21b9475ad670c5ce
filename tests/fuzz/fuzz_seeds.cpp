// SPDX-License-Identifier: Apache-2.0
// Writes the fuzzers' seed corpus: valid encoded messages of every kind, so libFuzzer starts from
// inputs that get past the length checks. Usage: fuzz_seeds OUTPUT_DIR (creates robot_state/,
// robot_command/ and tcp/ in it).
#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include "protocol/realtime_codec.h"
#include "protocol/tcp_codec.h"

namespace {

namespace fs = std::filesystem;
using namespace xmate::protocol;

void writeFile(const fs::path& path, const uint8_t* data, size_t size) {
  std::ofstream out(path, std::ios::binary);
  out.write(reinterpret_cast<const char*>(data), std::streamsize(size));
  if (!out) throw std::runtime_error("cannot write " + path.string());
}

// A TCP seed is the payload of a frame: everything after the 6-byte header.
template <class Message>
void writePayload(const fs::path& dir, const std::string& name, const Message& m) {
  const Frame frame = encodeFrame(7, m);
  writeFile(dir / name, frame.data() + kFrameHeaderSize, frame.size() - kFrameHeaderSize);
}

void writeStates(const fs::path& dir) {
  RCI::robot::RobotState s;
  RobotStateBuffer buf{};
  encodeRobotState(s, buf);
  writeFile(dir / "zero", buf.data(), buf.size());
  s.message_id = 123456;
  s.q = {0.1, 0.5, -0.2, 1.0, 0.0, 1.5, 0.3};
  s.toolTobase_pos_m = {1, 0, 0, 0.4, 0, 1, 0, 0, 0, 0, 1, 0.6, 0, 0, 0, 1};
  s.errors[15] = true;
  s.control_command_success_rate = 0.98;
  s.motion_generator_mode = RCI::robot::MotionGeneratorMode::kJointPosition;
  s.robot_mode = RCI::robot::RobotMode::kMove;
  encodeRobotState(s, buf);
  writeFile(dir / "moving", buf.data(), buf.size());
}

void writeCommands(const fs::path& dir) {
  RCI::robot::RobotCommand c;
  c.message_id = 99;
  c.motion.q_c = {0.1, 0.5, -0.2, 1.0, 0.0, 1.5, 0.3};
  c.motion.psi_valid = true;
  c.motion.psi_c = 0.2;
  c.torque.tau_c = {1, 2, 3, 4, 5, 6, 7};
  RobotCommandBuffer buf{};
  encodeRobotCommand(c, buf);
  writeFile(dir / "current", buf.data(), buf.size());
  // The older form: the same without dynamic_wall (32 bytes at offset 202).
  uint8_t legacy[kRobotCommandLegacySize];
  std::copy(buf.begin(), buf.begin() + 202, legacy);
  std::copy(buf.begin() + 234, buf.end(), legacy + 202);
  writeFile(dir / "legacy", legacy, sizeof legacy);
}

void writeTcp(const fs::path& dir) {
  const std::array<double, 16> identity{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  writePayload(dir, "connect", ConnectRequest{40000});
  writePayload(dir, "motor_power", SetMotorPowerRequest{1});
  writePayload(dir, "start_move", StartMoveRequestMsg{0, 1});
  writePayload(dir, "cartesian_limit", SetCartesianLimitRequest{{1, 1, 1}, identity, true});
  writePayload(dir, "joint_limit", SetJointLimitRequest{{170, 120, 170, 120, 170, 120, 360},
                                                        {-170, -120, -170, -120, -170, -120, -360}, true});
  writePayload(dir, "collision", SetCollisionBehaviorRequest{{50, 50, 40, 30, 20, 20, 10}});
  writePayload(dir, "joint_impedance", SetJointImpedanceRequest{{1000, 1000, 1000, 1000, 100, 100, 100}});
  writePayload(dir, "cartesian_impedance", SetCartesianImpedanceRequest{{1000, 1000, 1000, 100, 100, 100}});
  writePayload(dir, "coor", SetCoorRequest{identity});
  writePayload(dir, "load", SetLoadRequest{1.0, {0, 0, 0.05}, {0.01, 0, 0, 0, 0.01, 0, 0, 0, 0.01}});
  writePayload(dir, "desired_tau", SetCartImpDesiredTauRequest{{0, 0, 10, 0, 0, 0}});
  writePayload(dir, "filters", SetFiltersRequest{50, 50, 50});
  writePayload(dir, "torque_filter", SetTorqueFilterCutOffFrequencyRequest{50});
  writePayload(dir, "fc_coor", SetFcCoorRequest{identity, 1});
  writePayload(dir, "virtual_guide", EnableVirtualGuideRequest{true, {100, 100, 100, 10, 10, 10}});
  writePayload(dir, "set_do", SetDORequest{2, true});
  writePayload(dir, "get_di", GetDIStateRequest{3});
  writePayload(dir, "start_drag", StartDragRequest{1, 2});
  for (Command c : {Command::kGetMotorState, Command::kStopMove, Command::kAutomaticErrorRecovery,
                    Command::kLoadRobotModel, Command::kStopDrag, Command::kGetSafetyStopState,
                    Command::kRebootRobot})
    writePayload(dir, std::string("empty_") + commandName(c), EmptyRequest{c});
  writePayload(dir, "response_byte", ByteResponse{Command::kStartMove, 0});
  writePayload(dir, "response_di", GetDIStateResponse{0, true});
  writePayload(dir, "response_model", LoadRobotModelResponse{});
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: fuzz_seeds OUTPUT_DIR\n");
    return 2;
  }
  try {
    const fs::path root = argv[1];
    for (const char* sub : {"robot_state", "robot_command", "tcp"}) fs::create_directories(root / sub);
    writeStates(root / "robot_state");
    writeCommands(root / "robot_command");
    writeTcp(root / "tcp");
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fuzz_seeds: %s\n", e.what());
    return 1;
  }
  return 0;
}
