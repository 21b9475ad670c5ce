// SPDX-License-Identifier: Apache-2.0
// RNEA and CRBA in link coordinates (Featherstone's algorithms written with 3-vectors). Each link's
// mass properties are taken about its frame origin, which lies on its joint axis (arm_model.h).
// Gravity enters as an upward acceleration of the base (a_0 = -g), the usual RNEA trick.
#include "model/dynamics.h"

#include <array>

namespace xmate::model {
namespace {

// Rotation of each link relative to its parent at q (parent <- child).
struct JointRotations {
  std::array<Eigen::Matrix3d, kMaxDof> r;
};

void computeJointRotations(const ArmModel& arm, const JointVector& q, JointRotations& out) {
  for (int i = 0; i < arm.dof; ++i) out.r[i] = jointRotation(arm.joints[i], q[i]);
}

Eigen::Matrix3d skew(const Eigen::Vector3d& v) {
  Eigen::Matrix3d m;
  m << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
  return m;
}

// One RNEA: forward pass for link velocities and accelerations, backward pass for the forces.
JointVector rnea(const ArmModel& arm, const JointRotations& rot, const JointVector& dq, const JointVector& ddq,
                 const Eigen::Vector3d& base_acceleration) {
  std::array<Eigen::Vector3d, kMaxDof> force, moment;  // net inertial wrench of each link, about its origin
  Eigen::Vector3d w = Eigen::Vector3d::Zero();          // angular velocity of the parent, parent frame
  Eigen::Vector3d dw = Eigen::Vector3d::Zero();         // angular acceleration of the parent
  Eigen::Vector3d a = base_acceleration;                // linear acceleration of the parent origin
  for (int i = 0; i < arm.dof; ++i) {
    const JointPlacement& joint = arm.joints[i];
    const LinkInertia& link = arm.links[i];
    const Eigen::Matrix3d rt = rot.r[i].transpose();
    const Eigen::Vector3d& p = joint.translation;
    const Eigen::Vector3d a_origin = a + dw.cross(p) + w.cross(w.cross(p));  // this origin, parent frame
    const Eigen::Vector3d w_parent = rt * w;
    const Eigen::Vector3d w_joint = dq[i] * joint.axis;
    w = w_parent + w_joint;
    dw = rt * dw + ddq[i] * joint.axis + w_parent.cross(w_joint);
    a = rt * a_origin;
    const Eigen::Vector3d& h = link.first_moment;
    force[i] = link.mass * a + dw.cross(h) + w.cross(w.cross(h));
    moment[i] = link.rotational * dw + w.cross(link.rotational * w) + h.cross(a);
  }
  JointVector tau = JointVector::Zero();
  // Wrench the parent exerts on link i (force f, moment n about link i's origin), link i's frame.
  Eigen::Vector3d f = Eigen::Vector3d::Zero();
  Eigen::Vector3d n = Eigen::Vector3d::Zero();
  for (int i = arm.dof - 1; i >= 0; --i) {
    if (i + 1 < arm.dof) {
      const Eigen::Matrix3d& r_child = rot.r[i + 1];
      const Eigen::Vector3d f_child = r_child * f;
      n = r_child * n + arm.joints[i + 1].translation.cross(f_child);
      f = f_child;
    }
    f += force[i];
    n += moment[i];
    tau[i] = arm.joints[i].axis.dot(n);
  }
  return tau;
}

// Composite rigid body of links i..n, about link i's origin in link i's frame.
struct CompositeBodies {
  std::array<double, kMaxDof> mass;
  std::array<Eigen::Vector3d, kMaxDof> first_moment;
  std::array<Eigen::Matrix3d, kMaxDof> rotational;
};

void computeComposites(const ArmModel& arm, const JointRotations& rot, CompositeBodies& c) {
  for (int i = 0; i < arm.dof; ++i) {
    c.mass[i] = arm.links[i].mass;
    c.first_moment[i] = arm.links[i].first_moment;
    c.rotational[i] = arm.links[i].rotational;
  }
  for (int i = arm.dof - 1; i > 0; --i) {
    const Eigen::Matrix3d& r = rot.r[i];
    const Eigen::Vector3d& p = arm.joints[i].translation;
    const Eigen::Vector3d rh = r * c.first_moment[i];
    const Eigen::Matrix3d sp = skew(p), srh = skew(rh);
    c.mass[i - 1] += c.mass[i];
    c.first_moment[i - 1] += rh + c.mass[i] * p;
    c.rotational[i - 1] += r * c.rotational[i] * r.transpose() - c.mass[i] * sp * sp - sp * srh - srh * sp;
  }
}

}  // namespace

JointVector inverseDynamics(const ArmModel& arm, const JointVector& q, const JointVector& dq,
                            const JointVector& ddq, const Eigen::Vector3d& gravity) {
  JointRotations rot;
  computeJointRotations(arm, q, rot);
  return rnea(arm, rot, dq, ddq, -gravity);
}

JointMatrix massMatrix(const ArmModel& arm, const JointVector& q) {
  JointRotations rot;
  computeJointRotations(arm, q, rot);
  CompositeBodies comp;
  computeComposites(arm, rot, comp);
  JointMatrix m = JointMatrix::Zero();
  for (int j = 0; j < arm.dof; ++j) {
    // Wrench that gives the composite body j a unit acceleration of joint j, carried to the base.
    const Eigen::Vector3d& e = arm.joints[j].axis;
    Eigen::Vector3d f = e.cross(comp.first_moment[j]);
    Eigen::Vector3d n = comp.rotational[j] * e;
    m(j, j) = e.dot(n);
    for (int i = j - 1; i >= 0; --i) {
      const Eigen::Matrix3d& r = rot.r[i + 1];
      f = r * f;
      n = r * n + arm.joints[i + 1].translation.cross(f);
      m(i, j) = m(j, i) = arm.joints[i].axis.dot(n);
    }
  }
  return m;
}

JointVector gravityTorques(const ArmModel& arm, const JointVector& q, const Eigen::Vector3d& gravity) {
  JointRotations rot;
  computeJointRotations(arm, q, rot);
  return rnea(arm, rot, JointVector::Zero(), JointVector::Zero(), -gravity);
}

JointVector coriolisTorques(const ArmModel& arm, const JointVector& q, const JointVector& dq) {
  JointRotations rot;
  computeJointRotations(arm, q, rot);
  return rnea(arm, rot, dq, JointVector::Zero(), Eigen::Vector3d::Zero());
}

TorqueTerms torqueTerms(const ArmModel& arm, const JointVector& q, const JointVector& dq, const JointVector& ddq,
                        const Eigen::Vector3d& gravity) {
  JointRotations rot;
  computeJointRotations(arm, q, rot);
  const JointVector zero = JointVector::Zero();
  TorqueTerms t;
  t.full = rnea(arm, rot, dq, ddq, -gravity);
  t.inertial = rnea(arm, rot, zero, ddq, Eigen::Vector3d::Zero());
  t.coriolis = rnea(arm, rot, dq, zero, Eigen::Vector3d::Zero());
  t.gravity = rnea(arm, rot, zero, zero, -gravity);
  return t;
}

}  // namespace xmate::model
