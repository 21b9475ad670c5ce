// SPDX-License-Identifier: Apache-2.0
// The robot models RCI Studio knows, as the vendor API names them (docs/api.md, "Types"; docs/robot_models.md).
#pragma once

namespace xmate {

// Unscoped on purpose: vendor programs write both XMATE7_PRO and XmateType::XMATE7_PRO.
enum XmateType { XMATE3_PRO, XMATE7_PRO, XMATE3, XMATE7 };

}  // namespace xmate
