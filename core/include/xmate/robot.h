// SPDX-License-Identifier: Apache-2.0
// xmate::Robot: the client side of RCI (docs/api.md, "xmate::Robot"). TCP commands run on the
// caller's thread; the 1 kHz UDP exchange runs on a dedicated real-time thread per robot.
// Threads: every call below may be made from any thread, one Robot shared by several (docs/client.md,
// "Threads"), but never from a Control() callback -- they block on the network. None of them is
// real-time safe; in a callback, use the state it is given.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <string>

#include <xmate/exception.h>
#include <xmate/rci_types.h>
#include <xmate/types.h>

namespace xmate {

namespace client { class Connection; }

class Robot {
 public:
  // Nothing is sent until the first call that needs the controller (lazy connect).
  Robot(const std::string& ip, uint16_t port, XmateType type = XMATE7_PRO);
  ~Robot();
  Robot(const Robot&) = delete;
  Robot& operator=(const Robot&) = delete;

  // Opens the TCP session and the UDP exchange. Throws TcpException / NetworkException with the
  // address and the reason; no-op when connected. Blocking.
  void connect();
  // Drops the session and opens it again (after a reboot, a cable pull). true on success. Blocking.
  bool reconnect();

  // ---- Motion -----------------------------------------------------------------------------
  // While the arm is still coming to rest after a stop, a recovered reflex or the end of hand
  // guiding, startMove (and startDrag) wait for standstill, at most 1 s, then throw
  // MotionException naming the moving joint. A refusal by the controller (CommandException) names
  // the cause that holds: error bits, emergency or guard stop, motors off, hand guiding on, a
  // motion running, or the arm still moving. Caller's thread, blocking.
  void startMove(RCI::robot::StartMoveRequest::ControllerMode controller_mode,
                 RCI::robot::StartMoveRequest::MotionGeneratorMode motion_mode);
  // Ends the running motion with the controller's stop ramp; Control() then throws. Any thread (the
  // one that stops a Control() running on another), blocking on the network.
  void stopMove();
  // Calls the callback once per 1 ms cycle with the newest state and sends what it returns;
  // blocks until the callback returns MotionFinished(...). The caller's thread blocks (one
  // Control() at a time per robot). The callback runs on the robot's real-time thread and must not
  // block, allocate, lock or do I/O: a cycle it misses is a command the controller never gets. What
  // it may call: the generators of joint_motion.h and cart_motion.h, XmateModel's kinematics and
  // dynamics, JointRateLimiter::limit (each says "real-time safe").
  // Lost states: when states never reached this PC (or were left unanswered after a stall of the
  // real-time thread), the callback is first called once for each missed cycle, oldest first --
  // with the newest state, its message_id set to the missed cycle's -- and those outputs are not
  // sent (a MotionFinished among them is: it ends the motion); then it is called for the newest
  // state, whose output is sent. So the callback runs exactly once per controller cycle, and a
  // program that keeps time by counting calls (time += 0.001, as in the vendor manual) stays on the
  // controller's clock. At most 20 missed cycles are replayed (the controller stops a motion after
  // about 15 lost commands in a row).
  // Throws ControlException when the controller reports error bits, InvalidOperationException
  // when startMove() did not select a matching mode.
  void Control(JointControl callback);
  void Control(CartesianControl callback);
  void Control(TorqueControl callback);
  // Waits for the next state from the controller (UdpException after 1 s without one). Blocking.
  RCI::robot::RobotState receiveRobotState();

  // ---- Settings (ranges in docs/api.md; violations throw std::invalid_argument) ------------
  // Each is one request to the controller and waits for its answer: blocking, any thread, not real-time safe.
  void setCollisionBehavior(const std::array<double, 7>& upper_torque_thresholds_nominal);
  void setCartesianLimit(const std::array<double, 3>& size, const std::array<double, 16>& frame,
                         bool active = true);
  void setJointImpedance(const std::array<double, 7>& K_theta);
  void setCartesianImpedance(const std::array<double, 6>& K_x);
  void setCoor(const std::array<double, 16>& F_T_EE);
  void setLoad(double mass, const std::array<double, 3>& center, const std::array<double, 9>& inertia);
  void setFilters(double joint_hz, double cartesian_hz, double torque_hz);
  void setCartImpDesiredTau(const std::array<double, 6>& tau);
  bool setMotorPower(int state);
  int getMotorState();
  bool setDO(RCI::robot::DOSIGNAL signal, bool state);
  bool getDI(RCI::robot::DISIGNAL signal);
  void setJointLimit(const std::array<double, 7>& upper_deg, const std::array<double, 7>& lower_deg,
                     bool auto_limit);
  void setFcCoor(const std::array<double, 16>& frame, int fc_type);  // 1 world, 2 tool, 3 path
  void startDrag(int drag_space, int drag_type);  // space 1 joint, 2 Cartesian; type 1 translation, 2 rotation, 3 free
  void stopDrag();
  void automaticErrorRecovery();
  void rebootRobot();
  int getSafetyStopState();  // 1 none, 2 ESTOP, 3 GSTOP

  // ---- Extensions (RCI Studio) ----------------------------------------------------------------
  // These three never block (any thread).
  XmateType type() const;
  // Tool and payload last set through this robot (identity / zero until set).
  std::array<double, 16> toolFrame() const;
  void load(double& mass, std::array<double, 3>& center, std::array<double, 9>& inertia) const;
  // The session behind this robot, for RCI Studio's own tools (timing statistics, state stream).
  client::Connection& connection();

 private:
  std::unique_ptr<client::Connection> connection_;
};

}  // namespace xmate
