# SPDX-License-Identifier: Apache-2.0
# The simulator server (server*): sockets, clocks, reboot, fault injection and the control port
# around the controller, the simulated F/T sensor, and the simulated KRC's socket and clock (krc_server). Included from CMakeLists.txt next to this file.
target_sources(rci_core PRIVATE
  ${CMAKE_CURRENT_LIST_DIR}/server.cpp
  ${CMAKE_CURRENT_LIST_DIR}/server_control.cpp
  ${CMAKE_CURRENT_LIST_DIR}/server_cycle.cpp
  ${CMAKE_CURRENT_LIST_DIR}/server_faults.cpp
  ${CMAKE_CURRENT_LIST_DIR}/server_session.cpp
  ${CMAKE_CURRENT_LIST_DIR}/ft_sensor.cpp
  ${CMAKE_CURRENT_LIST_DIR}/krc_server.cpp
  ${CMAKE_CURRENT_LIST_DIR}/krc_control.cpp
  ${CMAKE_CURRENT_LIST_DIR}/control_lines.cpp)
