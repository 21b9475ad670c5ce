// SPDX-License-Identifier: Apache-2.0
// Fills the LoadRobotModel arrays (layout: docs/simulator_controller.md, "LoadRobotModel").
#include "sim/robot_model_dump.h"

#include "model/arm_model.h"

namespace xmate::sim {

protocol::LoadRobotModelResponse robotModelResponse(const model::RobotSpec& spec, const model::Chain& chain,
                                                    const PlantParams& params, const ControllerSettings& settings) {
  protocol::LoadRobotModelResponse r;
  r.status = 0;
  for (size_t i = 0; i < static_cast<size_t>(spec.dof); ++i) {
    const model::DhRow& row = spec.dh[i];
    const model::ChainLink& link = chain.links[i];
    const int j = static_cast<int>(i);
    // dh: [a, alpha, d, theta] per joint (m, rad).
    r.dh[4 * i + 0] = row.a;
    r.dh[4 * i + 1] = row.alpha;
    r.dh[4 * i + 2] = row.d;
    r.dh[4 * i + 3] = row.theta;
    // dims: [q_min, q_max, dq_max] per joint (rad, rad/s).
    r.dims[3 * i + 0] = spec.q_min[i];
    r.dims[3 * i + 1] = spec.q_max[i];
    r.dims[3 * i + 2] = spec.dq_max[i];
    // dyn_friction: [Ixx, Iyy, Izz, Ixy, Ixz, Iyz (kg m^2, about the centre of mass, link axes),
    //                viscous (Nm s/rad), Coulomb (Nm), rotor inertia (kg m^2)] per link.
    const Eigen::Matrix3d& in = link.inertia;
    const double per_link[9] = {in(0, 0), in(1, 1), in(2, 2), in(0, 1), in(0, 2), in(1, 2),
                                params.viscous[j], params.coulomb[j], params.armature[j]};
    for (size_t k = 0; k < 9; ++k) r.dyn_friction[9 * i + k] = per_link[k];
    // dyn: [mass (kg), centre of mass x, y, z (m, link frame)] per link.
    r.dyn[4 * i + 0] = link.mass;
    for (size_t k = 0; k < 3; ++k) r.dyn[4 * i + 1 + k] = link.com[static_cast<int>(k)];
  }
  // dyn_friction[63..65]: gravity in the base frame.
  const Eigen::Vector3d g = model::standardGravity();
  for (size_t k = 0; k < 3; ++k) r.dyn_friction[63 + k] = g[static_cast<int>(k)];
  // dyn[28..37]: the load of setLoad: mass, centre x y z, Ixx Iyy Izz Ixy Ixz Iyz (flange frame).
  const model::Payload& load = settings.load;
  const double payload[10] = {load.mass,         load.com.x(),      load.com.y(),      load.com.z(),
                              load.inertia(0, 0), load.inertia(1, 1), load.inertia(2, 2), load.inertia(0, 1),
                              load.inertia(0, 2), load.inertia(1, 2)};
  for (size_t k = 0; k < 10; ++k) r.dyn[28 + k] = payload[k];
  // dyn[38..44]: the tool of setCoor: translation x y z (m), rotation as quaternion w x y z.
  const Eigen::Vector3d t = settings.tool.translation();
  const Eigen::Quaterniond q(settings.tool.linear());
  const double tool[7] = {t.x(), t.y(), t.z(), q.w(), q.x(), q.y(), q.z()};
  for (size_t k = 0; k < 7; ++k) r.dyn[38 + k] = tool[k];
  return r;
}

}  // namespace xmate::sim
