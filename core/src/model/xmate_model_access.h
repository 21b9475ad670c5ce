// SPDX-License-Identifier: Apache-2.0
// The model::ArmKinematics inside a user's XmateModel, for the library's own code (the client's
// MOVEL/MOVEC plan with the user's model, tool and soft limits included). Not part of the public API.
#pragma once

#include <xmate/model.h>

#include "model/arm_kinematics.h"

namespace xmate {

struct XmateModelAccess {
  // Any thread that owns `model`. The reference lives as long as `model`.
  static model::ArmKinematics& kinematics(XmateModel& model);
};

}  // namespace xmate
