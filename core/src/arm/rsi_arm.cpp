// SPDX-License-Identifier: Apache-2.0
// arm::RsiArm (rsi_arm.h): the RSI link's values as ArmSamples (degrees and millimetres to SI), its
// joint stream as runJointMotion, and the context's wired signals as digital IO.
#include "arm/rsi_arm.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "model/euler_zyx.h"
#include "model/signal_names.h"
#include "net/clock.h"

namespace xmate::arm {
namespace {

constexpr double kDeg = 3.14159265358979323846 / 180.0;

// The SEND channel the ETHERNET object's input is wired from output `k` of a GEARTORQUE object:
// its decoder slot, or -1.
int gearTorqueSlot(const rsi::Context& context, const rsi::EthernetConfig& config, const rsi::Link& link, int k) {
  const rsi::Object* ethernet = context.ethernet();
  if (!ethernet) return -1;
  for (const rsi::Input& wire : ethernet->inputs) {
    const rsi::Object* from = context.find(wire.out_object);
    if (!from || from->type != "GEARTORQUE" || wire.out_index != k) continue;
    for (const rsi::Channel& c : config.send)
      if (!c.internal() && c.index == wire.in_index) return link.slot(c.element, c.attribute);
  }
  return -1;
}

double valueAt(const double* values, size_t count, int slot) {
  return slot >= 0 && size_t(slot) < count ? values[slot] : 0.0;
}

}  // namespace

RsiArm::RsiArm(const RsiArmConfig& config) : context_(rsi::readContext(config.context_path)) {
  config_ = rsi::readEthernetConfig(config.ethernet_config_path.empty() ? context_.ethernetConfigPath()
                                                                        : config.ethernet_config_path);
  spec_ = model::findRobotSpec(config.model);
  if (!spec_ || spec_->family != model::RobotFamily::kKuka)
    throw std::invalid_argument("arm::RsiArm: \"" + config.model + "\" is not a KUKA model (kr6_r900_sixx, kr16_2)");
  link_ = std::make_unique<rsi::Link>(config_, config.link);
  stream_ = std::make_unique<JointStream>(*link_, *spec_, rsi::axisCorrectionLimits(context_));
  rsi::DigitalIoMap map = rsi::digitalIoMap(context_, config_);
  if (!map.inputs.empty() || !map.outputs.empty()) io_ = std::make_unique<rsi::DigitalIo>(*link_, std::move(map));
  monitor_ = std::make_unique<rsi::SessionMonitor>(*link_, context_);

  static const char* const kAxes[6] = {"A1", "A2", "A3", "A4", "A5", "A6"};
  static const char* const kPose[6] = {"X", "Y", "Z", "A", "B", "C"};
  bool currents = true, gears = true, set_points = true;
  for (int i = 0; i < 6; ++i) {
    slots_.q[size_t(i)] = link_->slot("AIPos", kAxes[i]);
    slots_.q_set[size_t(i)] = link_->slot("ASPos", kAxes[i]);
    if (slots_.q_set[size_t(i)] < 0) slots_.q_set[size_t(i)] = slots_.q[size_t(i)];
    slots_.current[size_t(i)] = link_->slot("MACur", kAxes[i]);
    slots_.gear[size_t(i)] = gearTorqueSlot(context_, config_, *link_, i + 1);
    slots_.pose[size_t(i)] = link_->slot("RIst", kPose[i]);
    slots_.pose_set[size_t(i)] = link_->slot("RSol", kPose[i]);
    set_points = set_points && slots_.pose_set[size_t(i)] >= 0;
    currents = currents && slots_.current[size_t(i)] >= 0;
    gears = gears && slots_.gear[size_t(i)] >= 0;
  }
  capabilities_ = uint32_t(Capability::kCorrectionLimits);
  if (currents) capabilities_ = capabilities_ | Capability::kMotorCurrents;
  if (gears) capabilities_ = capabilities_ | Capability::kGearTorques;
  if (io_) capabilities_ = capabilities_ | Capability::kDigitalIo;
  if (set_points) capabilities_ = capabilities_ | Capability::kTcpSetPoint;
  epoch_ns_ = net::monotonicNs();
}

RsiArm::~RsiArm() { stop(); }

void RsiArm::start() { link_->start(); }
void RsiArm::stop() { link_->stop(); }

void RsiArm::fill(const double* values, size_t count, ArmSample& s, std::array<double, 6>* pose_mm_deg) const {
  for (size_t i = 0; i < 6; ++i) {
    s.q[i] = valueAt(values, count, slots_.q[i]) * kDeg;
    s.q_command[i] = valueAt(values, count, slots_.q_set[i]) * kDeg;
    s.motor_current[i] = valueAt(values, count, slots_.current[i]);
    s.gear_torque[i] = valueAt(values, count, slots_.gear[i]);
  }
  for (size_t i = 0; i < 3; ++i) {
    s.tcp_position[i] = valueAt(values, count, slots_.pose[i]) * 1e-3;
    s.tcp_position_command[i] = valueAt(values, count, slots_.pose_set[i]) * 1e-3;
  }
  if (pose_mm_deg)
    for (size_t i = 0; i < 6; ++i) (*pose_mm_deg)[i] = valueAt(values, count, slots_.pose[i]);
}

bool RsiArm::latest(ArmState& out) const {
  rsi::RobSample rob;
  StreamState stream;
  if (!link_->latest(rob) || !stream_->state(stream)) return false;
  std::array<double, 6> pose{};
  out.sample = ArmSample{};
  fill(rob.values.data(), rob.count, out.sample, &pose);
  out.sample.cycle = stream.cycles;
  out.sample.session = rob.session;
  const Eigen::Matrix3d r = model::rotationFromAbc({pose[3] * kDeg, pose[4] * kDeg, pose[5] * kDeg});
  out.tcp = {r(0, 0), r(0, 1), r(0, 2), pose[0] * 1e-3, r(1, 0), r(1, 1), r(1, 2), pose[1] * 1e-3,
             r(2, 0), r(2, 1), r(2, 2), pose[2] * 1e-3, 0,       0,       0,       1};
  return true;
}

size_t RsiArm::takeSamples(ArmSample* out, size_t max) {
  size_t n = 0;
  rsi::LinkSample brief;
  while (n < max && link_->samples().pop(brief)) {
    monitor_->add(brief);
    if (brief.session != counted_session_) {
      counted_session_ = brief.session;
      counted_cycles_ = 0;
    }
    ArmSample& s = out[n++];
    s = ArmSample{};
    fill(brief.values.data(), brief.count, s, nullptr);
    s.cycle = ++counted_cycles_;
    s.session = brief.session;
    s.time = double(brief.received_ns - epoch_ns_) * 1e-9;
  }
  return n;
}

void RsiArm::runJointMotion(JointMotion& motion) {
  stream_->run(motion);
}

MotionBounds RsiArm::motionBounds() const {
  StreamState s;
  if (!stream_->state(s))
    throw std::runtime_error("RSI is not running: no <Rob> datagram has arrived; start the KRL program (RSI_ON, "
                             "RSI_MOVECORR) on the robot");
  MotionBounds bounds;
  const rsi::AxisCorrectionLimits& limits = stream_->limits();
  for (size_t i = 0; i < 6; ++i) {
    bounds.lower[i] = std::max(s.q_on[i] + limits.lower[i], spec_->q_min[i]);
    bounds.upper[i] = std::min(s.q_on[i] + limits.upper[i], spec_->q_max[i]);
  }
  bounds.session = s.session;
  return bounds;
}

std::vector<std::string> RsiArm::outputNames() const {
  std::vector<std::string> names;
  if (io_)
    for (const rsi::DigitalSignal& s : io_->map().outputs)
      names.push_back(model::doName(model::RobotFamily::kKuka, s.signal));
  return names;
}

std::vector<std::string> RsiArm::inputNames() const {
  std::vector<std::string> names;
  if (io_)
    for (const rsi::DigitalSignal& s : io_->map().inputs)
      names.push_back(model::diName(model::RobotFamily::kKuka, s.signal));
  return names;
}

void RsiArm::setOutput(size_t index, bool level) {
  if (!io_ || index >= io_->map().outputs.size())
    throw std::runtime_error("output " + std::to_string(index) + " is not one of the " +
                             std::to_string(io_ ? io_->map().outputs.size() : 0) +
                             " outputs the RSI context wires to the PC");
  io_->setOutput(io_->map().outputs[index].signal, level);
}

bool RsiArm::input(size_t index) {
  if (!io_ || index >= io_->map().inputs.size())
    throw std::runtime_error("input " + std::to_string(index) + " is not one of the " +
                             std::to_string(io_ ? io_->map().inputs.size() : 0) +
                             " inputs the RSI context wires to the PC");
  return io_->input(io_->map().inputs[index].signal);
}

}  // namespace xmate::arm
