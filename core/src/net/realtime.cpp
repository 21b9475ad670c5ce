// SPDX-License-Identifier: Apache-2.0
// Linux specifics behind realtime.h: pthread scheduling, mlock/mlockall, /proc and /sys reads.
#include "net/realtime.h"

#include <pthread.h>
#include <sched.h>
#include <sys/mman.h>
#include <sys/resource.h>
#include <sys/utsname.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>

namespace xmate::net {
namespace {

std::string readFirstLine(const char* path) {
  std::ifstream f(path);
  std::string line;
  std::getline(f, line);
  return line;
}

bool realtimeDisabled() {
  const char* off = std::getenv("RCI_NO_REALTIME");
  return off && std::strcmp(off, "1") == 0;
}

// Touches kLockedStackBytes of stack below the caller and locks them: the loop's later calls reuse
// these pages. 0 or the errno of mlock.
[[gnu::noinline]] int lockStack() {
  volatile unsigned char pages[kLockedStackBytes];
  for (size_t i = 0; i < sizeof pages; i += 4096) pages[i] = 0;
  return mlock(const_cast<unsigned char*>(pages), sizeof pages) == 0 ? 0 : errno;
}

}  // namespace

std::string RealtimeStatus::describe() const {
  std::string s = fifo ? "SCHED_FIFO " + std::to_string(priority) : std::string("normal priority");
  s += memory_locked ? ", memory locked" : ", memory not locked";
  if (!reason.empty()) s += " (" + reason + ")";
  return s;
}

RealtimeStatus enableRealtimeForThisThread(int priority, std::initializer_list<MemoryRegion> regions) {
  RealtimeStatus st;
  if (realtimeDisabled()) {
    st.reason = "real-time scheduling disabled by RCI_NO_REALTIME=1";
    return st;
  }
  sched_param sp{};
  sp.sched_priority = priority;
  const int err = pthread_setschedparam(pthread_self(), SCHED_FIFO, &sp);
  if (err == 0) {
    st.fifo = true;
    st.priority = priority;
  } else {
    st.reason = std::string("SCHED_FIFO refused: ") + std::strerror(err) +
                "; run as root or grant rtprio in /etc/security/limits.conf";
  }
  // Only what the loop itself touches: a window or a user's program keeps the rest of its memory
  // pageable. Headless tools lock the whole process from main (lockAllMemory()).
  int error = lockStack();
  for (const MemoryRegion& r : regions)
    if (error == 0 && r.size > 0 && mlock(r.data, r.size) != 0) error = errno;
  if (error == 0) {
    st.memory_locked = true;
  } else {
    const std::string why = std::string("mlock refused: ") + std::strerror(error) + "; raise memlock in limits.conf";
    st.reason = st.reason.empty() ? why : st.reason + "; " + why;
  }
  return st;
}

std::string lockAllMemory() {
  if (realtimeDisabled()) return {};
  if (mlockall(MCL_CURRENT | MCL_FUTURE) == 0) return {};
  return std::string("mlockall refused: ") + std::strerror(errno) +
         "; raise memlock in /etc/security/limits.conf (or run as root)";
}

void nameThisThread(const char* name) { pthread_setname_np(pthread_self(), name); }

bool kernelIsPreemptRt() {
  if (readFirstLine("/sys/kernel/realtime") == "1") return true;
  utsname u{};
  return uname(&u) == 0 && std::strstr(u.version, "PREEMPT_RT") != nullptr;
}

std::string kernelRelease() {
  utsname u{};
  return uname(&u) == 0 ? std::string(u.release) + " " + u.version : "unknown";
}

std::string clockSource() {
  const std::string s = readFirstLine("/sys/devices/system/clocksource/clocksource0/current_clocksource");
  return s.empty() ? "unknown" : s;
}

long rtprioLimit() {
  rlimit r{};
  if (getrlimit(RLIMIT_RTPRIO, &r) != 0) return 0;
  return r.rlim_cur == RLIM_INFINITY ? -1 : long(r.rlim_cur);
}

long memlockLimitBytes() {
  rlimit r{};
  if (getrlimit(RLIMIT_MEMLOCK, &r) != 0) return 0;
  return r.rlim_cur == RLIM_INFINITY ? -1 : long(r.rlim_cur);
}

long sysctlValue(const char* path) {
  const std::string s = readFirstLine(path);
  if (s.empty()) return -1;
  return std::strtol(s.c_str(), nullptr, 10);
}

}  // namespace xmate::net
