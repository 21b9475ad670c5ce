// SPDX-License-Identifier: Apache-2.0
// Real-time setup of the calling thread (SCHED_FIFO + mlockall) and facts about the machine's
// real-time fitness. Never fails silently: the result says what was granted and why not.
#pragma once

#include <string>

namespace xmate::net {

struct RealtimeStatus {
  bool fifo = false;           // SCHED_FIFO granted to this thread
  int priority = 0;            // its priority when granted
  bool memory_locked = false;  // mlockall(MCL_CURRENT | MCL_FUTURE) succeeded
  std::string reason;          // empty when both succeeded; else what was refused and what to do
  std::string describe() const;  // "SCHED_FIFO 80, memory locked" / "normal priority: ..."
};

// Tries SCHED_FIFO at priority (1..99) for the calling thread and locks all memory.
// Set RCI_NO_REALTIME=1 to skip both (e.g. on a shared development machine).
RealtimeStatus enableRealtimeForThisThread(int priority = 80);

// Gives the calling thread a name visible in top/ps (max 15 characters).
void nameThisThread(const char* name);

// Facts for `rci-cli doctor`.
bool kernelIsPreemptRt();           // /sys/kernel/realtime == 1 or "PREEMPT_RT" in the version
std::string kernelRelease();        // uname -r
std::string clockSource();          // /sys/devices/system/clocksource/clocksource0/current_clocksource
long rtprioLimit();                 // RLIMIT_RTPRIO soft limit (-1 = unlimited)
long memlockLimitBytes();           // RLIMIT_MEMLOCK soft limit (-1 = unlimited)
long sysctlValue(const char* path); // a number from /proc/sys/..., -1 if unreadable

}  // namespace xmate::net
