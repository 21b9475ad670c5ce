// SPDX-License-Identifier: Apache-2.0
// Joint and safety-box allowances (allowance.h).
#include "sim/allowance.h"

#include <algorithm>
#include <cmath>

namespace xmate::sim {
namespace {

// One limit pair: exactly the limit on the side where x is inside it; beyond a limit, x +- slack,
// but never wider than before (an allowance only ever shrinks back towards its limit).
void narrowTowards(double x, double limit_lower, double limit_upper, double slack, double& lower, double& upper) {
  upper = x <= limit_upper ? limit_upper : std::min(upper, x + slack);
  lower = x >= limit_lower ? limit_lower : std::max(lower, x - slack);
}

}  // namespace

void JointAllowance::reset(const JointVector& q, const JointVector& soft_lower, const JointVector& soft_upper,
                           int dof) {
  lower = soft_lower;
  upper = soft_upper;
  for (int i = 0; i < dof; ++i) {
    lower[i] = -INFINITY;
    upper[i] = INFINITY;
    narrowTowards(q[i], soft_lower[i], soft_upper[i], kJointAllowanceSlack, lower[i], upper[i]);
  }
}

void JointAllowance::ratchet(const JointVector& q, const JointVector& soft_lower, const JointVector& soft_upper,
                             int dof) {
  for (int i = 0; i < dof; ++i) narrowTowards(q[i], soft_lower[i], soft_upper[i], kJointAllowanceSlack, lower[i], upper[i]);
}

void BoxAllowance::reset(const SafetyBox& box, const Eigen::Vector3d& tcp_position) {
  lower = Eigen::Vector3d::Constant(-INFINITY);
  upper = Eigen::Vector3d::Constant(INFINITY);
  ratchet(box, tcp_position);
}

void BoxAllowance::ratchet(const SafetyBox& box, const Eigen::Vector3d& tcp_position) {
  const Eigen::Vector3d local = boxLocal(box, tcp_position);
  for (int a = 0; a < 3; ++a)
    narrowTowards(local[a], -0.5 * box.size[a], 0.5 * box.size[a], kBoxAllowanceSlack, lower[a], upper[a]);
}

bool BoxAllowance::contains(const SafetyBox& box, const Eigen::Vector3d& tcp_position) const {
  const Eigen::Vector3d local = boxLocal(box, tcp_position);
  for (int a = 0; a < 3; ++a)
    if (local[a] < lower[a] || local[a] > upper[a]) return false;
  return true;
}

}  // namespace xmate::sim
