// SPDX-License-Identifier: Apache-2.0
// Fixture of tests/layering: a model file that includes the client, which check_layers.cmake must refuse.
#include "model/robot_spec.h"
#include "client/connection.h"
