// SPDX-License-Identifier: Apache-2.0
// Manual section 2.5.2: read the controller's address from xmate.ini ([network] ip=..., port=...),
// report the motor state, power on, MOVEJ to a start pose, then a joint-space S-curve back to zero
// on the 6-axis xMate 7. Linux version of the manual's program; usage: ini_joint_motion [INI_FILE]
// (default ./xmate.ini; without a readable file it uses 127.0.0.1:1337).
#include <cstdint>
#include <iostream>
#include <string>

#include <xmate/ini.h>
#include <xmate/joint_motion.h>
#include <xmate/move.h>
#include <xmate/robot.h>

using namespace xmate;

int main(int argc, char* argv[]) {
  std::string ipaddr = "127.0.0.1";
  uint16_t port = 1337;
  const std::string file = argc > 1 ? argv[1] : "xmate.ini";
  INIParser ini;
  if (ini.ReadINI(file)) {
    ipaddr = ini.GetString("network", "ip");
    port = static_cast<uint16_t>(ini.GetInt("network", "port"));
  } else {
    std::cout << "no usable " << file << " (" << ini.LastError() << "); using " << ipaddr << ":" << port << std::endl;
  }
  try {
    xmate::Robot robot(ipaddr, port, XmateType::XMATE7);
    int res = robot.getMotorState();
    std::cout << "motor power state: " << res << std::endl;
    int power_state = 1;
    robot.setMotorPower(power_state);
    const double PI = 3.14159;
    std::array<double, 7> q_init;
    std::array<double, 7> q_drag = {{0, PI / 6, PI / 3, 0, PI / 2, 0, 0}};
    q_init = robot.receiveRobotState().q;
    MOVEJ(0.2, q_init, q_drag, robot);
    std::array<double, 7> q_end = {{0, 0, 0, 0, 0, 0, 0}};
    JointMotionGenerator joint_s(0.2, q_end, XmateType::XMATE7);

    // Select the control and motion modes before the motion starts.
    robot.startMove(RCI::robot::StartMoveRequest::ControllerMode::kJointPosition,
                    RCI::robot::StartMoveRequest::MotionGeneratorMode::kJointPosition);
    std::array<double, 7> init_position;
    std::array<double, 7> joint_delta;
    JointPositions output{};
    bool init = true;
    double time = 0;

    JointControl joint_position_callback = [&](RCI::robot::RobotState robot_state) -> JointPositions {
      if (init) {
        init_position = robot_state.q;
        init = false;
      }
      // One call per 1 ms cycle, as in the vendor manual: Control() calls the callback also for
      // states lost on the way (their output unused), so this clock stays on the controller's.
      time += 0.001;
      joint_s.calculateSynchronizedValues_joint(init_position);
      const bool finished = joint_s.calculateDesiredValues_joint(time, joint_delta);
      for (unsigned int i = 0; i < 6; i++) output.q[i] = init_position[i] + joint_delta[i];
      if (finished) {
        std::cout << "motion finished" << std::endl;
        return MotionFinished(output);
      }
      return output;
    };
    robot.Control(joint_position_callback);
  } catch (const std::exception& e) {
    std::cerr << "ini_joint_motion: " << e.what() << std::endl;
    return 1;
  }
  return 0;
}
