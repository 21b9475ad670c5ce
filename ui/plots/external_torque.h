// SPDX-License-Identifier: Apache-2.0
// ExternalTorqueMap: external joint torques tau = J(q)^T F from the TCP wrench in the base frame that
// RobotState carries (tau_ext_in_base). Allocation-free, cheap enough for 1 kHz on the GUI thread.
#pragma once

#include <array>

#include <xmate/types.h>

#include "model/arm_model.h"

namespace rci::ui::plots {

class ExternalTorqueMap {
 public:
  // Loads the model's description (URDF); throws std::runtime_error if it cannot be found or read.
  explicit ExternalTorqueMap(xmate::XmateType type);

  // The tool (flange -> TCP, row-major 4x4) the wrench refers to; identity = the flange.
  // Throws std::invalid_argument unless it is a rigid transform.
  void setTool(const std::array<double, 16>& flange_to_tcp);
  int dof() const { return arm_.dof; }

  // wrench = [force (N); moment (Nm)] at the TCP, base frame. Joints >= dof() get 0.
  std::array<double, 7> jointTorques(const std::array<double, 7>& q, const std::array<double, 6>& wrench) const;

 private:
  xmate::model::ArmModel arm_;
};

}  // namespace rci::ui::plots
