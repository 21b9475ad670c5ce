// SPDX-License-Identifier: Apache-2.0
// Where a KUKA's flange may go within the RSI axis-correction limits of one RSI session: the
// base-frame box around the flange positions the corrections reach from the session's start pose.
#pragma once

#include <QVector3D>

#include <array>

#include "arm_poser.h"

namespace rci::ui {

struct CorrectionEnvelope {
  bool valid = false;
  QVector3D min, max;  // m, base frame (axis-aligned)
  QVector3D start;     // the flange at the start pose, m
};

// The box holding the flange positions at q_on + c for corrections c within [lower_i, upper_i] on
// every axis (the totals relative to q_on, rad, that the RSI context's AXISCORR object lets
// through; each axis also kept within its hardware limits), and the start position. Sampled: each
// axis at both ends of its range and evenly between, at most 30 deg apart (3 to 7 values), all
// combinations; the last axis, which turns the flange about itself, only at q_on. With the usual
// few-degree limits the box is within a millimetre of the true region; with +-90 deg within a few
// centimetres. Any thread (not real-time: up to 7^5 forward kinematics, a few milliseconds).
CorrectionEnvelope correctionEnvelope(const ArmPoser& poser, const std::array<double, 6>& q_on,
                                      const std::array<double, 6>& lower, const std::array<double, 6>& upper);

}  // namespace rci::ui
