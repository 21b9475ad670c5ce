// SPDX-License-Identifier: Apache-2.0
// Manual section 2.5.1: connect (with a bounded reconnect loop), MOVEJ to a start pose, MOVEL 10 cm
// down with the kinematic model, then a Cartesian callback that moves the TCP along an arc in the
// x-z plane and returns to the start after one period (10 s), ending with MotionFinished.
// Linux version of the manual's program; usage: cartesian_motion [HOST:PORT] (default 127.0.0.1:1337).
#include <chrono>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <string>
#include <thread>

#include <xmate/model.h>
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
  xmate::Robot robot(ipaddr, port, XmateType::XMATE7_PRO);
  try {
    robot.connect();
  } catch (const xmate::XmateException& e) {
    std::cout << "connect failed (" << e.what() << "), retrying" << std::endl;
    int attempts = 0;
    while (!robot.reconnect()) {
      if (++attempts == 10) {
        std::cerr << "cartesian_motion: no controller at " << ipaddr << ":" << port << std::endl;
        return 1;
      }
      std::cout << "reconnect" << std::endl;
      std::this_thread::sleep_for(std::chrono::seconds(1));
    }
  }
  try {
    robot.setMotorPower(1);
  } catch (const xmate::TcpException& e) {
    std::cout << "exception: " << e.what() << std::endl;
  }

  try {
    const double PI = 3.14159;
    std::array<double, 7> q_init;
    std::array<double, 7> q_drag = {{0, PI / 6, 0, PI / 3, 0, PI / 2, 0}};
    q_init = robot.receiveRobotState().q;
    MOVEJ(0.2, q_init, q_drag, robot);
    robot.setCoor({{1.0, 0.0, 0.0, 0.0,  //
                    0.0, 1.0, 0.0, 0.0,  //
                    0.0, 0.0, 1.0, 0.0,  //
                    0.0, 0.0, 0.0, 1.0}});
    cart_pos pos_start, pos_end;
    pos_start.pos = robot.receiveRobotState().toolTobase_pos_m;
    pos_end = pos_start;
    pos_end.pos[11] -= 0.1;

    xmate::XmateModel model(&robot, XmateType::XMATE7_PRO);
    std::array<double, 7> q_out;
    int res = model.GetJointPos(pos_start.pos, robot.receiveRobotState().psi_m, q_drag, q_out);
    std::cout << "inverse kinematics of the start pose: " << res << std::endl;
    try {
      MOVEL(0.1, pos_start, pos_end, robot, model);
    } catch (const xmate::ControlException& e) {
      std::cout << "exception: " << e.what() << std::endl;
    }

    robot.startMove(RCI::robot::StartMoveRequest::ControllerMode::kCartesianPosition,
                    RCI::robot::StartMoveRequest::MotionGeneratorMode::kCartesianPosition);
    std::array<double, 16> init_position;
    bool init = true;
    double init_psi = 0;
    double time = 0;
    constexpr double kPeriod = 10.0;  // s: the arc angle returns to 0 after one period of cos(pi/5 t)

    CartesianControl cartesian_position_callback = [&](RCI::robot::RobotState robot_state) -> CartesianPose {
      if (init) {
        init_position = robot_state.toolTobase_pos_m;
        init_psi = robot_state.psi_m;
        init = false;
      }
      // One call per 1 ms cycle, as in the vendor manual: Control() calls the callback also for
      // states lost on the way (their output unused), so this clock stays on the controller's.
      time += 0.001;
      constexpr double kRadius = 0.2;
      const double angle = M_PI / 4 * (1 - std::cos(M_PI / 5 * time));
      const double delta_x = kRadius * std::sin(angle);
      const double delta_z = kRadius * (std::cos(angle) - 1);

      CartesianPose output{};
      output.toolTobase_pos_c = init_position;
      output.toolTobase_pos_c[3] += delta_x;
      output.toolTobase_pos_c[11] += delta_z;
      output.psi_c = init_psi;  // psi_valid stays false: the arm angle is kept
      if (time >= kPeriod - 1e-9) {
        std::cout << "motion finished" << std::endl;
        return MotionFinished(output);
      }
      return output;
    };

    robot.Control(cartesian_position_callback);
  } catch (const std::exception& e) {
    std::cerr << "cartesian_motion: " << e.what() << std::endl;
    return 1;
  }
  return 0;
}
