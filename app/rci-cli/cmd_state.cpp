// SPDX-License-Identifier: Apache-2.0
// rci-cli state: a live readout of one robot's state (q, torques, TCP pose, mode, error bits by
// name, command success rate), refreshed in place on a terminal, one block per refresh otherwise.
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <thread>

#include <xmate/robot.h>

#include "cli.h"
#include "client/connection.h"
#include "client/error_bits.h"

namespace rci_cli {
namespace {

constexpr double kDeg = 180.0 / std::numbers::pi;

std::string joints(const std::array<double, 7>& v, int dof, double scale, const char* format) {
  std::string s;
  char buf[32];
  for (int i = 0; i < dof; ++i) {
    std::snprintf(buf, sizeof buf, format, v[i] * scale);
    s += buf;
  }
  return s;
}

// Roll-pitch-yaw (rotations about fixed x, y, z) of a row-major pose, degrees.
std::array<double, 3> rpyDeg(const std::array<double, 16>& m) {
  const double pitch = std::asin(std::clamp(-m[8], -1.0, 1.0));
  const double roll = std::atan2(m[9], m[10]);
  const double yaw = std::atan2(m[4], m[0]);
  return {roll * kDeg, pitch * kDeg, yaw * kDeg};
}

std::string errorNames(const std::array<bool, 20>& errors) {
  std::string s;
  for (int i = 0; i < 20; ++i)
    if (errors[i]) s += (s.empty() ? "" : ", ") + std::to_string(i) + " " + xmate::client::errorBitName(i);
  return s.empty() ? "none" : s;
}

// The block of lines for one state; returns how many lines it printed.
int printState(const HostPort& robot, const RCI::robot::RobotState& s, int dof, const char* clear) {
  const auto rpy = rpyDeg(s.toolTobase_pos_m);
  std::printf("%s%s:%u  message_id %llu  mode %s  command success rate %.3f\n", clear, robot.host.c_str(), robot.port,
              static_cast<unsigned long long>(s.message_id), xmate::client::robotModeName(s.robot_mode),
              s.control_command_success_rate);
  std::printf("%s  q (deg)     %s\n", clear, joints(s.q, dof, kDeg, "%9.3f").c_str());
  std::printf("%s  dq (deg/s)  %s\n", clear, joints(s.dq_m, dof, kDeg, "%9.3f").c_str());
  std::printf("%s  tau (Nm)    %s\n", clear, joints(s.tau_m, dof, 1.0, "%9.3f").c_str());
  std::printf("%s  TCP (m)     x %.4f  y %.4f  z %.4f   rpy (deg) %.2f %.2f %.2f   psi %.2f deg\n", clear, s.toolTobase_pos_m[3], s.toolTobase_pos_m[7], s.toolTobase_pos_m[11], rpy[0], rpy[1], rpy[2],
              s.psi_m * kDeg);
  std::printf("%s  external    F %.2f %.2f %.2f N   M %.2f %.2f %.2f Nm\n", clear, s.tau_ext_in_base[0],
              s.tau_ext_in_base[1], s.tau_ext_in_base[2], s.tau_ext_in_base[3], s.tau_ext_in_base[4],
              s.tau_ext_in_base[5]);
  std::printf("%s  errors      %s\n", clear, errorNames(s.errors).c_str());
  return 7;
}

}  // namespace

int runState(const StateOptions& options) {
  const HostPort& robot_address = options.robot.address;
  const long count = options.count;
  const xmate::XmateType type = options.model;
  xmate::Robot robot(robot_address.host, robot_address.port, type);
  robot.connect();
  const int dof = type == xmate::XMATE3 || type == xmate::XMATE7 ? 6 : 7;
  const bool terminal = isatty(STDOUT_FILENO);
  int lines = 0;
  for (long n = 0; count == 0 || n < count; ++n) {
    if (n > 0) std::this_thread::sleep_for(std::chrono::milliseconds(100));
    const RCI::robot::RobotState s = robot.receiveRobotState();
    if (terminal && lines > 0) std::printf("\x1b[%dA", lines);  // back to the top of the block
    lines = printState(robot_address, s, dof, terminal ? "\x1b[K" : "");  // \x1b[K clears the old line
    if (!terminal) std::printf("\n");
    std::fflush(stdout);
  }
  return 0;
}

}  // namespace rci_cli
