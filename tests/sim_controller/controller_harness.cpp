// SPDX-License-Identifier: Apache-2.0
// Test harness for sim::Controller (controller_harness.h).
#include "controller_harness.h"

#include <stdexcept>
#include <string>

#include "sim/error_bits.h"

namespace xmate::sim::test {

RawResponse parseResponse(const protocol::Frame& frame) {
  if (frame.size() < protocol::kFrameHeaderSize + 5)
    throw std::runtime_error("response frame of " + std::to_string(frame.size()) + " bytes is too short");
  RawResponse r;
  const uint8_t* p = frame.data();
  const size_t length = (size_t(p[0]) << 8) | p[1];
  if (length != frame.size() - protocol::kFrameHeaderSize)
    throw std::runtime_error("response frame length field " + std::to_string(length) + " does not match its size");
  r.sequence = (uint32_t(p[2]) << 24) | (uint32_t(p[3]) << 16) | (uint32_t(p[4]) << 8) | p[5];
  const uint8_t* q = p + protocol::kFrameHeaderSize;
  r.command = (uint32_t(q[0]) << 24) | (uint32_t(q[1]) << 16) | (uint32_t(q[2]) << 8) | q[3];
  r.value = q[4];
  r.payload_size = length;
  return r;
}

Harness::Harness(const SimConfig& config) : controller_(config) {}

protocol::Frame Harness::sendRaw(const uint8_t* payload, size_t size) {
  const protocol::Frame response = controller_.handleRequest(sequence_, payload, size);
  if (parseResponse(response).sequence != sequence_) throw std::runtime_error("response does not echo the sequence");
  return response;
}

void Harness::powerOnAndSettle(int cycles) {
  if (setMotorPower(1) != 0) throw std::runtime_error("setMotorPower(1) refused: " + controller_.lastRefusal());
  idle(cycles);
}

void Harness::idle(int cycles) {
  for (int i = 0; i < cycles; ++i) controller_.step(nullptr);
}

void Harness::stepCommand(RobotCommand command) {
  command.message_id = state().message_id;
  controller_.step(&command);
}

void Harness::stepJoint(const std::array<double, 7>& q, bool finished) {
  RobotCommand c;
  c.motion.q_c = q;
  c.motion.motion_generation_finished = finished;
  stepCommand(c);
}

void Harness::stepCartesian(const Eigen::Isometry3d& pose, bool finished, bool psi_valid, double psi) {
  RobotCommand c;
  c.motion.toolTobase_pos_c = rowMajor(pose);
  c.motion.psi_valid = psi_valid;
  c.motion.psi_c = psi;
  c.motion.motion_generation_finished = finished;
  stepCommand(c);
}

void Harness::stepTorque(const std::array<double, 7>& tau, bool finished) {
  RobotCommand c;
  c.torque.tau_c = tau;
  c.motion.motion_generation_finished = finished;
  stepCommand(c);
}

bool Harness::anyError() const {
  for (bool b : state().errors)
    if (b) return true;
  return false;
}

std::string Harness::errorList() const {
  std::string s;
  for (int i = 0; i < kErrorBitCount; ++i)
    if (state().errors[size_t(i)]) s += (s.empty() ? "" : ", ") + std::string(errorBitName(i));
  return s.empty() ? "none" : s;
}

Eigen::Isometry3d poseOf(const std::array<double, 16>& m) {
  Eigen::Isometry3d pose;
  pose.matrix() = Eigen::Map<const Eigen::Matrix<double, 4, 4, Eigen::RowMajor>>(m.data());
  return pose;
}

std::array<double, 16> rowMajor(const Eigen::Isometry3d& pose) {
  std::array<double, 16> a{};
  Eigen::Map<Eigen::Matrix<double, 4, 4, Eigen::RowMajor>>(a.data()) = pose.matrix();
  return a;
}

Eigen::Matrix<double, 7, 1> vec7(const std::array<double, 7>& a) { return Eigen::Map<const Eigen::Matrix<double, 7, 1>>(a.data()); }

std::array<double, 7> arr7(const Eigen::Matrix<double, 7, 1>& v) {
  std::array<double, 7> a{};
  for (int i = 0; i < 7; ++i) a[size_t(i)] = v[i];
  return a;
}

}  // namespace xmate::sim::test
