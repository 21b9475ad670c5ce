// SPDX-License-Identifier: Apache-2.0
// Manual section 2.3.3: read the robot's state, MOVEJ to a start pose, then a joint-space S-curve
// inside a JointControl callback that ends with MotionFinished. Linux version of the manual's
// program; usage: joint_motion [HOST:PORT] (default 127.0.0.1:1337, e.g. a running rci-sim).
#include <cmath>
#include <cstdint>
#include <iostream>
#include <string>

#include <xmate/joint_motion.h>
#include <xmate/move.h>
#include <xmate/robot.h>

using namespace xmate;

int main(int argc, char* argv[]) {
  std::string ipaddr = "127.0.0.1";
  uint16_t port = 1337;
  if (argc > 1) {
    const std::string address = argv[1];
    const auto colon = address.rfind(':');
    ipaddr = address.substr(0, colon);
    if (colon != std::string::npos) port = static_cast<uint16_t>(std::stoi(address.substr(colon + 1)));
  }
  const double PI = M_PI;
  try {
    xmate::Robot robot(ipaddr, port);  // connects on the first call

    // RCI needs the robot in automatic mode with the motors powered on.
    int power_state = 1;
    robot.setMotorPower(power_state);
    std::array<double, 7> q_init;
    std::array<double, 7> q_drag = {{0, PI / 6, 0, PI / 3, 0, PI / 2, 0}};

    // Read one state, then MOVEJ (blocking) to the start pose.
    q_init = robot.receiveRobotState().q;
    MOVEJ(0.2, q_init, q_drag, robot);

    // The user's own plan: an S-curve to q_end, 0.2 of the rated speed.
    std::array<double, 7> q_end = {{0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9}};
    JointMotionGenerator joint_s(0.2, q_end);

    // Select the control and motion modes before the callback runs.
    robot.startMove(RCI::robot::StartMoveRequest::ControllerMode::kJointPosition,
                    RCI::robot::StartMoveRequest::MotionGeneratorMode::kJointPosition);
    std::array<double, 7> init_position;
    std::array<double, 7> joint_delta;
    JointPositions output{};
    bool init = true;
    double time = 0;

    JointControl joint_position_callback = [&](RCI::robot::RobotState robot_state) -> JointPositions {
      if (init) {
        init_position = robot_state.q;  // the joints at the start of the motion
        init = false;
      }
      // One call per 1 ms cycle, as in the vendor manual: Control() calls the callback also for
      // states lost on the way (their output unused), so this clock stays on the controller's.
      time += 0.001;
      // All joints arrive together; true once the plan is finished.
      joint_s.calculateSynchronizedValues_joint(init_position);
      if (!joint_s.calculateDesiredValues_joint(time, joint_delta)) {
        for (int i = 0; i < 7; ++i) output.q[i] = init_position[i] + joint_delta[i];
      } else {
        std::cout << "motion finished" << std::endl;
        for (int i = 0; i < 7; ++i) output.q[i] = init_position[i] + joint_delta[i];
        return MotionFinished(output);
      }
      return output;
    };

    // Blocks until the callback returns MotionFinished; one callback per 1 ms cycle.
    robot.Control(joint_position_callback);
  } catch (const std::exception& e) {
    std::cerr << "joint_motion: " << e.what() << std::endl;
    return 1;
  }
  return 0;
}
