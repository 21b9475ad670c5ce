// SPDX-License-Identifier: Apache-2.0
// sim::Controller: construction, the public calls forwarded to Impl, the scene (external wrench,
// e-stop, guard stop, digital inputs, actual payload) and the status snapshot.
#include "sim/controller.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "model/dynamics.h"
#include "model/inverse_kinematics.h"
#include "model/kinematics.h"
#include "model/urdf_loader.h"
#include "sim/controller_impl.h"
#include "sim/low_pass.h"
#include "sim/pose_math.h"

namespace xmate::sim {
namespace {

JointVector initialJoints(const SimConfig& config, const model::RobotSpec& spec) {
  const JointVector q = toJointVector(config.initial_q, spec.dof);
  for (int i = 0; i < spec.dof; ++i) {
    const auto k = static_cast<size_t>(i);
    if (!std::isfinite(q[i]) || q[i] < spec.q_min[k] || q[i] > spec.q_max[k])
      throw std::invalid_argument("sim::SimConfig: initial_q[" + std::to_string(i) + "] = " + std::to_string(q[i]) +
                                  " rad is outside the joint range [" + std::to_string(spec.q_min[k]) + ", " +
                                  std::to_string(spec.q_max[k]) + "] of the " + std::string(spec.display_name));
  }
  return q;
}

}  // namespace

Controller::Impl::Impl(const SimConfig& c)
    : config(c),
      spec(model::robotSpec(c.type)),
      chain(model::loadRobotChain(spec)),
      arm(model::makeArmModel(chain, spec)),
      plant_arm(arm),
      params(plantParams(spec)),
      limits(jointLimitVectors(spec)),
      settings(defaultSettings(spec)) {
  model::setSpeedCheckInterval(arm, 0);  // the controller checks speeds itself, with message_id gaps
  plant.q = initialJoints(config, spec);
  loopback = config.do_to_di_loopback;
  updateDigitalInputs();
  ref.track.resetAt(plant.q, JointVector::Zero(), kCycle);
  ref.joint_filter = ref.hold_target = plant.q;
  motors_on = config.motors_on_at_start;
  // What a controller at rest measures: the joints carry the arm's weight.
  meas.tcp = model::tcpPose(arm, plant.q);
  meas.jacobian = model::tcpJacobian(arm, plant.q);
  meas.psi = model::armAngle(arm, plant.q);
  meas.joint_torque = meas.joint_torque_filtered = model::gravityTorques(arm, plant.q);
  if (motors_on) meas.motor_torque = meas.motor_torque_filtered = meas.joint_torque;
  resetAllowances();
  state.message_id = 1;
  updateCommanded();
  fillState();
}

double Controller::Impl::alpha(double hz) const { return lowPassAlpha(hz, kCycle); }

void Controller::Impl::updateDigitalInputs() {
  for (size_t i = 0; i < digital_in.size(); ++i) digital_in[i] = loopback ? digital_out[i] : scene_digital_in[i];
}

SimStatus Controller::Impl::status() const {
  SimStatus s;
  s.motors_on = motors_on;
  s.safety_stop = safetyStop();
  s.dragging = activity == Activity::kDrag;
  s.motion_active = activity == Activity::kMotion;
  s.digital_out = digital_out;
  s.digital_in = digital_in;
  s.external_wrench = toArray6(scene_wrench);
  s.cycles = cycles;
  s.lost_commands = lost_commands;
  s.consecutive_lost_commands = activity == Activity::kMotion ? static_cast<uint64_t>(motion.consecutive_lost) : 0;
  s.external_joint_torque = toArray7(meas.external_torque);
  s.actual_payload_mass = plant_arm.payload.mass;
  s.actual_payload_follows_load = plant_follows_load;
  return s;
}

// ---- Controller ---------------------------------------------------------------------------------

Controller::Controller(const SimConfig& config) : impl_(std::make_unique<Impl>(config)) {}
Controller::~Controller() = default;

protocol::Frame Controller::handleRequest(uint32_t sequence, const uint8_t* payload, size_t size) {
  return impl_->handleRequest(sequence, payload, size);
}

bool Controller::rebootRequested() const { return impl_->reboot_requested; }
const RCI::robot::RobotState& Controller::state() const { return impl_->state; }
bool Controller::expectsCommand() const { return impl_->activity == Activity::kMotion; }
void Controller::step(const RCI::robot::RobotCommand* command) { impl_->step(command); }
SimStatus Controller::status() const { return impl_->status(); }
const SimConfig& Controller::config() const { return impl_->config; }
const std::string& Controller::lastRefusal() const { return impl_->last_refusal; }

void Controller::setExternalWrench(const std::array<double, 6>& wrench) {
  for (size_t i = 0; i < wrench.size(); ++i)
    if (!std::isfinite(wrench[i]))
      throw std::invalid_argument("sim::Controller::setExternalWrench: wrench[" + std::to_string(i) +
                                  "] is not a finite number");
  impl_->scene_wrench = toVector6(wrench);
}

void Controller::setEmergencyStop(bool pressed) {
  Impl& c = *impl_;
  if (pressed && !c.estop) {
    c.estop = true;
    if (c.activity == Activity::kMotion) {  // the manual: an e-stop during motion reports instability
      ErrorBits bits{};
      raise(bits, kInstabilityDetection);
      c.raiseErrors(bits);
    }
    c.powerOff();
  } else if (!pressed) {
    c.estop = false;  // the motors stay off until setMotorPower(1)
  }
}

void Controller::setGuardStop(bool active) {
  Impl& c = *impl_;
  c.guard_stop = active;
  if (active && c.activity != Activity::kHold) c.stopFromMeasured();  // controlled stop, motors stay on
}

void Controller::setDigitalInput(int index, bool level) {
  if (index < 0 || index > 5)
    throw std::invalid_argument("sim::Controller::setDigitalInput: index " + std::to_string(index) +
                                " is outside 0..5 (DI0_0..DI1_1)");
  impl_->scene_digital_in[static_cast<size_t>(index)] = level;
  impl_->updateDigitalInputs();
}

void Controller::setDoToDiLoopback(bool on) {
  impl_->loopback = on;
  impl_->updateDigitalInputs();
}

void Controller::setActualPayload(double mass, const std::array<double, 3>& center,
                                  const std::array<double, 9>& inertia) {
  model::Payload payload;
  payload.mass = mass;
  payload.com = Eigen::Vector3d(center[0], center[1], center[2]);
  payload.inertia = Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(inertia.data());
  model::setPayload(impl_->plant_arm, payload);  // validates, throws std::invalid_argument
  impl_->plant_follows_load = false;
}

void Controller::placeArm(const std::array<double, 7>& q) {
  const model::RobotSpec& spec = impl_->spec;
  for (int i = 0; i < spec.dof; ++i) {
    const auto k = static_cast<size_t>(i);
    const double low = spec.q_min[k] - kPlaceBeyondHardware, high = spec.q_max[k] + kPlaceBeyondHardware;
    if (!std::isfinite(q[k]) || q[k] < low || q[k] > high)
      throw std::invalid_argument("sim::Controller::placeArm: q[" + std::to_string(i) + "] = " + std::to_string(q[k]) +
                                  " rad is outside [" + std::to_string(low) + ", " + std::to_string(high) +
                                  "] (the joint range of the " + std::string(spec.display_name) + " widened by " +
                                  std::to_string(kPlaceBeyondHardware) + " rad)");
  }
  impl_->placeArm(toJointVector(q, spec.dof));
}

void Controller::followConfiguredLoad() {
  model::setPayload(impl_->plant_arm, impl_->settings.load);
  impl_->plant_follows_load = true;
}

}  // namespace xmate::sim
