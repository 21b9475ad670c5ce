# SPDX-License-Identifier: Apache-2.0
# Robot description loading (URDF via urdfdom); included from core/src/model/CMakeLists.txt.
target_sources(rci_core PRIVATE ${CMAKE_CURRENT_LIST_DIR}/urdf_loader.cpp)
