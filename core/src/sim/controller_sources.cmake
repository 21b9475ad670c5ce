# SPDX-License-Identifier: Apache-2.0
# The simulated controller's logic and physics (no I/O); included from core/src/sim/CMakeLists.txt.
# Overview: docs/simulator_controller.md.
target_sources(rci_core PRIVATE
  ${CMAKE_CURRENT_LIST_DIR}/allowance.cpp
  ${CMAKE_CURRENT_LIST_DIR}/controller.cpp
  ${CMAKE_CURRENT_LIST_DIR}/controller_requests.cpp
  ${CMAKE_CURRENT_LIST_DIR}/controller_motion.cpp
  ${CMAKE_CURRENT_LIST_DIR}/controller_cycle.cpp
  ${CMAKE_CURRENT_LIST_DIR}/controller_limits.cpp
  ${CMAKE_CURRENT_LIST_DIR}/controller_state.cpp
  ${CMAKE_CURRENT_LIST_DIR}/controller_settings.cpp
  ${CMAKE_CURRENT_LIST_DIR}/command_checks.cpp
  ${CMAKE_CURRENT_LIST_DIR}/drag_walls.cpp
  ${CMAKE_CURRENT_LIST_DIR}/error_bits.cpp
  ${CMAKE_CURRENT_LIST_DIR}/plant.cpp
  ${CMAKE_CURRENT_LIST_DIR}/reference.cpp
  ${CMAKE_CURRENT_LIST_DIR}/robot_model_dump.cpp
  ${CMAKE_CURRENT_LIST_DIR}/safety.cpp
  ${CMAKE_CURRENT_LIST_DIR}/servo.cpp)
# The simulated KUKA controller's RSI logic (no I/O): docs/rsi.md, "The simulated KRC".
target_sources(rci_core PRIVATE
  ${CMAKE_CURRENT_LIST_DIR}/krc.cpp
  ${CMAKE_CURRENT_LIST_DIR}/krc_cycle.cpp)
