// SPDX-License-Identifier: Apache-2.0
// The LoadRobotModel response: what the simulated controller tells a client about its arm (DH
// table, joint ranges, link inertias, friction, the configured load and tool). The vendor's layout
// of these arrays is not public; ours is in docs/simulator_controller.md, "LoadRobotModel".
#pragma once

#include "model/chain.h"
#include "model/robot_spec.h"
#include "protocol/tcp_codec.h"
#include "sim/controller_settings.h"
#include "sim/plant.h"

namespace xmate::sim {

protocol::LoadRobotModelResponse robotModelResponse(const model::RobotSpec& spec, const model::Chain& chain,
                                                    const PlantParams& params, const ControllerSettings& settings);

}  // namespace xmate::sim
