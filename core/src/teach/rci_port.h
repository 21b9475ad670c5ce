// SPDX-License-Identifier: Apache-2.0
// The executor's port to an xMate through the vendor API (robot_port.h): MOVEJ and a PATH's timing
// stream joints in joint position mode, MOVEL/MOVEC the timed Cartesian path in Cartesian position
// mode, each on the client's real-time loop, bridging lost states (client/stall_bridge.h).
#pragma once

#include <xmate/robot.h>

#include "teach/robot_port.h"

namespace xmate::teach {

class RciPort : public RobotPort {
 public:
  // `robot` must be connected and outlive the port. The executor's thread.
  explicit RciPort(Robot& robot);

  const model::RobotSpec& spec() const override { return spec_; }
  Reading read() override;
  std::array<double, 16> toolFrame() override;
  void setDO(int signal, bool value) override;
  bool getDI(int signal) override;
  void move(const Program& program, const Instruction& in, const model::ArmKinematics& model, MotionControl& control,
            InstructionReport& report) override;
  void streamPath(const JointPath& path, const PathTiming& timing, const model::ArmKinematics& model,
                  MotionControl& control, PathRecording& recording, InstructionReport& report) override;

 private:
  Robot& robot_;
  const model::RobotSpec& spec_;
};

}  // namespace xmate::teach
