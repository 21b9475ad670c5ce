// SPDX-License-Identifier: Apache-2.0
// Real-time setup of the calling thread (SCHED_FIFO, its stack and the memory its loop touches
// locked in RAM), the process-wide mlockall for headless tools, and facts about the machine's
// real-time fitness. Never fails silently: the result says what was granted and why not.
#pragma once

#include <cstddef>
#include <initializer_list>
#include <string>

namespace xmate::net {

struct RealtimeStatus {
  bool fifo = false;           // SCHED_FIFO granted to this thread
  int priority = 0;            // its priority when granted
  bool memory_locked = false;  // the thread's stack and its regions are locked in RAM
  std::string reason;          // empty when both succeeded; else what was refused and what to do
  std::string describe() const;  // "SCHED_FIFO 80, memory locked" / "normal priority: ..."
};

// A block of memory a real-time loop touches (its state, its buffers).
struct MemoryRegion {
  const void* data;
  size_t size;
};

// Tries SCHED_FIFO at priority (1..99) for the calling thread, and locks in RAM the thread's stack
// (kLockedStackBytes, pre-faulted) and `regions` (mlock) -- not the rest of the process: a window
// keeps its memory pageable; headless tools add lockAllMemory(). Set RCI_NO_REALTIME=1 to skip all
// of it (e.g. on a shared development machine). Call it on the thread itself, before its loop.
inline constexpr size_t kLockedStackBytes = 256 * 1024;
RealtimeStatus enableRealtimeForThisThread(int priority = 80, std::initializer_list<MemoryRegion> regions = {});

// mlockall(MCL_CURRENT | MCL_FUTURE) for the whole process: opt-in for headless real-time
// programs (rci-cli, rci-sim), whose callbacks' plans are then locked too; called once from main. "" on success, else what was refused and what to do.
// Skipped (returns "") with RCI_NO_REALTIME=1.
std::string lockAllMemory();

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
