// SPDX-License-Identifier: Apache-2.0
// Test support: counts calls of the global operator new (replaced in allocation_counter.cpp), so a
// test can prove that a hot-path function does not allocate.
#pragma once

#include <cstddef>

namespace planning_test {

// Number of global operator new calls since the program started.
std::size_t allocationCount();

}  // namespace planning_test
