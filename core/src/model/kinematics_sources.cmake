# SPDX-License-Identifier: Apache-2.0
# Kinematics, closed-form IK, dynamics and the public XmateModel (docs/kinematics.md).
target_sources(rci_core PRIVATE
  ${CMAKE_CURRENT_LIST_DIR}/arm_model.cpp
  ${CMAKE_CURRENT_LIST_DIR}/kinematics.cpp
  ${CMAKE_CURRENT_LIST_DIR}/dynamics.cpp
  ${CMAKE_CURRENT_LIST_DIR}/ik_branches.cpp
  ${CMAKE_CURRENT_LIST_DIR}/ik_srs.cpp
  ${CMAKE_CURRENT_LIST_DIR}/ik_six_axis.cpp
  ${CMAKE_CURRENT_LIST_DIR}/ik_offset_wrist.cpp
  ${CMAKE_CURRENT_LIST_DIR}/inverse_kinematics.cpp
  ${CMAKE_CURRENT_LIST_DIR}/arm_kinematics.cpp
  ${CMAKE_CURRENT_LIST_DIR}/xmate_model.cpp)
