// SPDX-License-Identifier: Apache-2.0
// What the executor needs from a robot apart from its motions, for both robot families: the
// model, the newest joints and TCP, the tool, and the digital IO. The executor's own thread only.
#pragma once

#include <array>

#include "model/robot_spec.h"

namespace xmate::teach {

class RobotPort {
 public:
  struct Reading {
    std::array<double, 7> q{};      // rad (element 6 is 0 on 6-axis models)
    std::array<double, 16> tcp{};   // measured TCP in the base frame, row-major, m
    double psi = 0;                 // arm angle (7-axis), rad
  };
  virtual ~RobotPort() = default;
  virtual const model::RobotSpec& spec() const = 0;
  virtual Reading read() = 0;
  virtual std::array<double, 16> toolFrame() = 0;  // the robot's TCP in the flange frame
  // Throw std::exception (its message says what to do) where the robot cannot.
  virtual void setDO(int signal, bool value) = 0;
  virtual bool getDI(int signal) = 0;
  // The joints (rad) this session can reach at all, when the robot limits them beyond its axis
  // ranges (a KUKA over RSI: the pose at RSI_ON plus the context's correction limits); false when it
  // does not (an xMate) or does not know yet.
  virtual bool reachableBounds(std::array<double, 7>& lower, std::array<double, 7>& upper) {
    (void)lower;
    (void)upper;
    return false;
  }
};

}  // namespace xmate::teach
