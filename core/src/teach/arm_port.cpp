// SPDX-License-Identifier: Apache-2.0
// armPort (arm_port.h): each arm family's port, picked by double dispatch on the arm.
#include "teach/arm_port.h"

#include "arm/rci_arm.h"
#include "arm/rsi_arm.h"
#include "teach/rci_port.h"
#include "teach/rsi_port.h"
#include "teach/preflight.h"

namespace xmate::teach {
namespace {

class PortMaker : public arm::ArmVisitor {
 public:
  explicit PortMaker(const Program& program) : program_(program) {}
  void visit(arm::RciArm& arm) override { port = std::make_unique<RciPort>(arm.robot()); }
  void visit(arm::RsiArm& arm) override {
    port = std::make_unique<RsiPort>(arm.stream(), arm.digitalIo(), program_.has_tool ? program_.tool : kIdentityPose);
  }
  std::unique_ptr<RobotPort> port;

 private:
  const Program& program_;
};

}  // namespace

std::unique_ptr<RobotPort> armPort(arm::Arm& arm, const Program& program) {
  PortMaker maker(program);
  arm.accept(maker);
  return std::move(maker.port);
}

}  // namespace xmate::teach
