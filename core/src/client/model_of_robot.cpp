// SPDX-License-Identifier: Apache-2.0
// XmateModel(Robot*, XmateType) (xmate/model.h): a model that starts with the tool and payload last
// set through the robot. Here, not in model/, because it reads the client.
#include <xmate/model.h>
#include <xmate/robot.h>

namespace xmate {

XmateModel::XmateModel(Robot* robot, XmateType type) : XmateModel(type) {
  if (robot == nullptr) return;
  SetCoor(robot->toolFrame());
  double mass = 0;
  std::array<double, 3> center{};
  std::array<double, 9> inertia{};
  robot->load(mass, center, inertia);
  SetLoad(mass, center, inertia);
}

}  // namespace xmate
