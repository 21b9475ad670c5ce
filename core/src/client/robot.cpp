// SPDX-License-Identifier: Apache-2.0
// xmate::Robot: session calls and the TCP settings of docs/api.md. Each call validates its arguments with
// model/parameter_checks.h (std::invalid_argument, nothing sent), connects if needed, sends the
// request and turns the response into a return value or an exception (robot_responses.h).
// Motion calls (startMove, stopMove, Control) are in robot_control.cpp.
#include <xmate/robot.h>

#include <cmath>
#include <functional>
#include <stdexcept>

#include "client/connection.h"
#include "client/refusal_cause.h"
#include "client/robot_responses.h"
#include "model/parameter_checks.h"
#include "model/robot_spec.h"

namespace xmate {
namespace {

namespace proto = protocol;
using client::requireSetterSuccess;

void require(const std::string& problem) {
  if (!problem.empty()) throw std::invalid_argument(problem);
}

const model::RobotSpec& specOf(const client::Connection& c) { return model::robotSpec(c.type()); }

int responseMs(const client::Connection& c) { return c.options().timeouts.response_ms; }
int motionResponseMs(const client::Connection& c) { return c.options().timeouts.motion_response_ms; }

// A setter's request: the arguments were checked (`problem`: std::invalid_argument, nothing sent),
// then connect if needed, send, and turn a refusal into the call's exception, naming the cause that
// holds (refusal_cause.h; `cause` first, for a cause only this setting has).
template <class Request>
void sendSetting(client::Connection& c, const std::string& problem, const char* call, const Request& request,
                 const std::function<std::string()>& cause = {}) {
  require(problem);
  c.ensureOpen();
  requireSetterSuccess(call, c.request(call, request, responseMs(c)), client::RefusalCause([&c, &cause] {
                         std::string own = cause ? cause() : std::string();
                         return own.empty() ? client::refusalCause(c, client::Request::kSetting) : own;
                       }));
}

// The cause a safety box is refused for that only it has: the TCP outside it (the newest state's).
std::string tcpOutsideBox(client::Connection& c, const std::array<double, 3>& size, const std::array<double, 16>& frame) {
  RCI::robot::RobotState s;
  if (!c.latestState(s)) return "";
  const auto& p = s.toolTobase_pos_m;
  const double d[3] = {p[3] - frame[3], p[7] - frame[7], p[11] - frame[11]};
  for (int axis = 0; axis < 3; ++axis) {
    const double local = frame[size_t(axis)] * d[0] + frame[size_t(4 + axis)] * d[1] + frame[size_t(8 + axis)] * d[2];
    if (std::abs(local) > 0.5 * size[size_t(axis)])
      return "; the TCP is outside the requested box (" + std::string(1, "xyz"[axis]) + " = " + std::to_string(local) +
             " m from its centre, the box reaches " + std::to_string(0.5 * size[size_t(axis)]) +
             " m): move the TCP inside first or enlarge the box";
  }
  return "";
}

}  // namespace

Robot::Robot(const std::string& ip, uint16_t port, XmateType type)
    : connection_(std::make_unique<client::Connection>(ip, port, type)) {}

Robot::~Robot() = default;

void Robot::connect() { connection_->open(); }

bool Robot::reconnect() {
  connection_->close();
  try {
    connection_->open();
    return true;
  } catch (const XmateException&) {
    return false;  // connect() gives the reason
  }
}

RCI::robot::RobotState Robot::receiveRobotState() {
  connection_->ensureOpen();
  return connection_->waitForState();
}

// ---- Settings -----------------------------------------------------------------------------------------

void Robot::setCollisionBehavior(const std::array<double, 7>& thresholds) {
  proto::SetCollisionBehaviorRequest m;
  m.thresholds = thresholds;
  sendSetting(*connection_, model::checkCollisionThresholds(specOf(*connection_), thresholds), "setCollisionBehavior", m);
}

void Robot::setCartesianLimit(const std::array<double, 3>& size, const std::array<double, 16>& frame, bool active) {
  proto::SetCartesianLimitRequest m;
  m.size = size;
  m.frame = frame;
  m.active = active;
  sendSetting(*connection_, model::checkCartesianLimit(size, frame), "setCartesianLimit", m,
              [&] { return active ? tcpOutsideBox(*connection_, size, frame) : std::string(); });
  connection_->updateRemembered([&](client::Connection::Remembered& r) {
    r.limits.box_active = active;
    r.limits.box_size = size;
    r.limits.box_frame = frame;
  });
}

void Robot::setJointImpedance(const std::array<double, 7>& K_theta) {
  proto::SetJointImpedanceRequest m;
  m.stiffness = K_theta;
  sendSetting(*connection_, model::checkJointImpedance(specOf(*connection_), K_theta), "setJointImpedance", m);
}

void Robot::setCartesianImpedance(const std::array<double, 6>& K_x) {
  proto::SetCartesianImpedanceRequest m;
  m.stiffness = K_x;
  sendSetting(*connection_, model::checkCartesianImpedance(K_x), "setCartesianImpedance", m);
}

void Robot::setCoor(const std::array<double, 16>& F_T_EE) {
  proto::SetCoorRequest m;
  m.flange_to_tool = F_T_EE;
  sendSetting(*connection_, model::checkToolFrame(F_T_EE), "setCoor", m);
  connection_->updateRemembered([&](client::Connection::Remembered& r) { r.tool = F_T_EE; });
}

void Robot::setLoad(double mass, const std::array<double, 3>& center, const std::array<double, 9>& inertia) {
  proto::SetLoadRequest m;
  m.mass = mass;
  m.center = center;
  m.inertia = inertia;
  sendSetting(*connection_, model::checkLoad(specOf(*connection_), mass, center, inertia), "setLoad", m);
  connection_->updateRemembered([&](client::Connection::Remembered& r) {
    r.load_mass = mass;
    r.load_center = center;
    r.load_inertia = inertia;
  });
}

void Robot::setFilters(double joint_hz, double cartesian_hz, double torque_hz) {
  proto::SetFiltersRequest m;
  m.joint_hz = joint_hz;
  m.cartesian_hz = cartesian_hz;
  m.torque_hz = torque_hz;
  sendSetting(*connection_, model::checkFilters(joint_hz, cartesian_hz, torque_hz), "setFilters", m);
}

void Robot::setCartImpDesiredTau(const std::array<double, 6>& tau) {
  proto::SetCartImpDesiredTauRequest m;
  m.tau = tau;
  sendSetting(*connection_, model::checkDesiredWrench(tau), "setCartImpDesiredTau", m);
}

bool Robot::setMotorPower(int state) {
  require(model::checkMotorPower(state));
  connection_->ensureOpen();
  proto::SetMotorPowerRequest m;
  m.state = uint8_t(state);
  requireSetterSuccess("setMotorPower", connection_->request("setMotorPower", m, motionResponseMs(*connection_)),
                       client::RefusalCause([this] {
                         return client::refusalCause(*connection_, client::Request::kMotorPower);
                       }));
  return true;
}

int Robot::getMotorState() {
  connection_->ensureOpen();
  const uint8_t value = client::byteValue(
      "getMotorState", connection_->request("getMotorState", proto::EmptyRequest{proto::Command::kGetMotorState},
                                            responseMs(*connection_)));
  if (value > 1)
    throw ProtocolException("getMotorState: the controller answered " + std::to_string(value) + ", not 0 or 1");
  return value;
}

bool Robot::setDO(RCI::robot::DOSIGNAL signal, bool state) {
  proto::SetDORequest m;
  m.signal = uint8_t(signal);
  m.state = state;
  const bool known = uint8_t(signal) <= uint8_t(RCI::robot::DOSIGNAL::DO1_1);
  sendSetting(*connection_,
              known ? "" : "setDO: signal = " + std::to_string(int(signal)) + " is not one of DO0_0..DO1_1", "setDO", m);
  return true;
}

bool Robot::getDI(RCI::robot::DISIGNAL signal) {
  if (uint8_t(signal) > uint8_t(RCI::robot::DISIGNAL::DI1_1))
    throw std::invalid_argument("getDI: signal = " + std::to_string(int(signal)) + " is not one of DI0_0..DI1_1");
  connection_->ensureOpen();
  proto::GetDIStateRequest m;
  m.signal = uint8_t(signal);
  return client::digitalInputLevel(connection_->request("getDI", m, responseMs(*connection_)));
}

void Robot::setJointLimit(const std::array<double, 7>& upper_deg, const std::array<double, 7>& lower_deg,
                          bool auto_limit) {
  proto::SetJointLimitRequest m;
  m.upper = upper_deg;
  m.lower = lower_deg;
  m.auto_limit = auto_limit;
  sendSetting(*connection_, model::checkSoftLimits(specOf(*connection_), upper_deg, lower_deg), "setJointLimit", m);
  connection_->updateRemembered([&](client::Connection::Remembered& r) {
    constexpr double kRad = 3.14159265358979323846 / 180.0;
    r.limits.has_soft_limits = true;
    for (size_t i = 0; i < 7; ++i) {
      r.limits.soft_upper[i] = upper_deg[i] * kRad;
      r.limits.soft_lower[i] = lower_deg[i] * kRad;
    }
  });
}

void Robot::setFcCoor(const std::array<double, 16>& frame, int fc_type) {
  proto::SetFcCoorRequest m;
  m.frame = frame;
  m.type = uint8_t(fc_type - 1);  // API 1 world, 2 tool, 3 path -> wire 0..2
  sendSetting(*connection_, model::checkForceFrame(frame, fc_type), "setFcCoor", m);
}

void Robot::startDrag(int drag_space, int drag_type) {
  require(model::checkDrag(drag_space, drag_type));
  connection_->ensureOpen();
  connection_->awaitStandstill("startDrag");
  proto::StartDragRequest m;
  m.space = uint8_t(drag_space - 1);  // API 1 joint, 2 Cartesian -> wire 0, 1
  m.type = uint8_t(drag_type - 1);    // API 1 translation, 2 rotation, 3 free -> wire 0..2
  requireSetterSuccess("startDrag", connection_->request("startDrag", m, motionResponseMs(*connection_)),
                       client::RefusalCause([this] {
                         return client::refusalCause(*connection_, client::Request::kHandGuiding);
                       }));
}

void Robot::stopDrag() {
  connection_->ensureOpen();
  requireSetterSuccess("stopDrag", connection_->request("stopDrag", proto::EmptyRequest{proto::Command::kStopDrag},
                                                        motionResponseMs(*connection_)));
}

void Robot::automaticErrorRecovery() {
  connection_->ensureOpen();
  client::requireRecoverySuccess(connection_->request(
      "automaticErrorRecovery", proto::EmptyRequest{proto::Command::kAutomaticErrorRecovery},
      motionResponseMs(*connection_)));
}

void Robot::rebootRobot() {
  connection_->ensureOpen();
  requireSetterSuccess("rebootRobot", connection_->request("rebootRobot", proto::EmptyRequest{proto::Command::kRebootRobot},
                                                           motionResponseMs(*connection_)));
  // The controller drops the session and comes back with its defaults: so do we.
  connection_->close();
  connection_->updateRemembered([](client::Connection::Remembered& r) { r = {}; });
}

int Robot::getSafetyStopState() {
  connection_->ensureOpen();
  const uint8_t value = client::byteValue(
      "getSafetyStopState", connection_->request("getSafetyStopState",
                                                 proto::EmptyRequest{proto::Command::kGetSafetyStopState},
                                                 responseMs(*connection_)));
  if (value > 2)
    throw ProtocolException("getSafetyStopState: the controller answered " + std::to_string(value) +
                            ", not 0 (none), 1 (ESTOP) or 2 (GSTOP)");
  return value + 1;  // wire 0 none, 1 ESTOP, 2 GSTOP -> API 1, 2, 3
}

// ---- Extensions ------------------------------------------------------------------------------------------

XmateType Robot::type() const { return connection_->type(); }

std::array<double, 16> Robot::toolFrame() const { return connection_->remembered().tool; }

void Robot::load(double& mass, std::array<double, 3>& center, std::array<double, 9>& inertia) const {
  const auto r = connection_->remembered();
  mass = r.load_mass;
  center = r.load_center;
  inertia = r.load_inertia;
}

client::Connection& Robot::connection() { return *connection_; }

}  // namespace xmate
