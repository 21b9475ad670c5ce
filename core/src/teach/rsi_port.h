// SPDX-License-Identifier: Apache-2.0
// The executor's port to a KUKA over RSI (robot_port.h): every motion becomes joints every 1 ms of
// plan time, checked at the RSI cycle against the axis ranges, speeds and the context's correction
// limits before it starts, then streamed as axis corrections, one per RSI cycle (arm::JointStream).
// Its TCP is the model's at the measured joints with the program's tool (RSI does not tell the PC
// which tool the controller has active); its digital IO is what the context wires to the PC.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "model/arm_kinematics.h"
#include "teach/robot_port.h"

namespace xmate::arm {
class JointStream;
}
namespace xmate::rsi {
class DigitalIo;
}

namespace xmate::teach {

class RsiPort : public RobotPort {
 public:
  // `stream` (whose link runs) and `io` (nullptr: none wired) must outlive the port; `tool` is the
  // program's TCP in the flange frame. The executor's thread.
  RsiPort(arm::JointStream& stream, rsi::DigitalIo* io, const std::array<double, 16>& tool);

  const model::RobotSpec& spec() const override;
  Reading read() override;
  std::array<double, 16> toolFrame() override { return tool_; }
  void setDO(int signal, bool value) override;
  bool getDI(int signal) override;
  bool reachableBounds(std::array<double, 7>& lower, std::array<double, 7>& upper) override;
  void move(const Program& program, const Instruction& in, const model::ArmKinematics& model, MotionControl& control,
            InstructionReport& report) override;
  void checkPath(const PathTiming& timing, double rate_hz) override;
  void streamPath(const JointPath& path, const PathTiming& timing, const model::ArmKinematics& model,
                  MotionControl& control, PathRecording& recording, InstructionReport& report) override;

 private:
  rsi::DigitalIo& io();
  // Streams `grid` (joints every 1 ms of plan time) one command per RSI cycle at the scaled plan
  // time, in RSI session `session`; fills the report's motion fields, then waits to settle.
  void streamGrid(const std::vector<std::array<double, 7>>& grid, double share, bool joint_motion,
                  const model::ArmKinematics& model, uint32_t session, MotionControl& control,
                  InstructionReport& report, PathRecording* recording);

  arm::JointStream& stream_;
  rsi::DigitalIo* io_;
  model::ArmKinematics model_;  // with the program's tool: the TCP of read()
  std::array<double, 16> tool_{};
};

}  // namespace xmate::teach
