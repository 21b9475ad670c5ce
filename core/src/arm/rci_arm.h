// SPDX-License-Identifier: Apache-2.0
// arm::RciArm: an xMate over RCI as an arm::Arm, on a vendor-compatible xmate::Robot (which stays
// the API programs written for the xMate use). docs/architecture.md, "One interface for both robot
// families".
#pragma once

#include <xmate/robot.h>

#include "arm/arm.h"
#include "client/state_sample.h"

namespace xmate::arm {

// One cycle of the client's sample ring as an ArmSample (what takeSamples() gives), for a consumer
// that pops the ring itself. Real-time safe.
ArmSample armSample(const client::StateSample& s);

class RciArm : public Arm {
 public:
  // Not owned; it must outlive the arm. The robot connects on its first use (as xmate::Robot does).
  // takeSamples() pops the robot's sample ring: nothing else may consume it.
  explicit RciArm(Robot& robot);

  void accept(ArmVisitor& visitor) override { visitor.visit(*this); }
  const model::RobotSpec& spec() const override { return *spec_; }
  Capabilities capabilities() const override;
  double cycleSeconds() const override { return 0.001; }
  bool latest(ArmState& out) const override;
  size_t takeSamples(ArmSample* out, size_t max) override;
  uint64_t samplesDropped() const override;
  // startMove in joint-position mode and one JointPositions per state until the motion's last;
  // throws what Robot::Control throws (ControlException names the controller's error bits). The
  // first sample's q_command is the measured q: the controller takes the first command against it.
  void runJointMotion(JointMotion& motion) override;
  // startMove in Cartesian-position mode and one CartesianPose per state (the arm angle kept).
  void runCartesianMotion(CartesianMotion& motion) override;
  std::vector<std::string> outputNames() const override;  // DO0_0 .. DO1_1
  std::vector<std::string> inputNames() const override;   // DI0_0 .. DI1_1
  void setOutput(size_t index, bool level) override;
  bool input(size_t index) override;

  Robot& robot() { return robot_; }

 private:
  Robot& robot_;
  const model::RobotSpec* spec_;
};

}  // namespace xmate::arm
