// SPDX-License-Identifier: Apache-2.0
// rci-cli doctor: is this machine fit for a 1 kHz control loop? Each fact comes with a verdict and,
// when it is not good, what to do. SCHED_FIFO and mlockall are actually tried (on a helper thread).
#include <dirent.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <thread>

#include "cli.h"
#include "net/realtime.h"

namespace rci_cli {
namespace {

enum class Verdict { kOk, kWarn, kFail, kInfo };

void report(Verdict v, const std::string& fact, const std::string& advice = "") {
  const char* tag = v == Verdict::kOk ? "[ ok ]" : v == Verdict::kWarn ? "[warn]" : v == Verdict::kFail ? "[FAIL]" : "[info]";
  std::printf("%s %s\n", tag, fact.c_str());
  if (!advice.empty()) std::printf("       -> %s\n", advice.c_str());
}

std::string firstLine(const std::string& path) {
  std::ifstream f(path);
  std::string line;
  std::getline(f, line);
  return line;
}

std::string limitText(long v) { return v < 0 ? "unlimited" : std::to_string(v); }

void checkKernel() {
  const std::string release = xmate::net::kernelRelease();
  if (xmate::net::kernelIsPreemptRt())
    report(Verdict::kOk, "kernel is PREEMPT_RT: " + release);
  else
    report(Verdict::kWarn, "kernel is not PREEMPT_RT: " + release,
           "install a real-time kernel (Debian/Ubuntu: linux-image-rt-amd64) for bounded latencies");
}

void checkScheduling() {
  xmate::net::RealtimeStatus status;
  std::thread([&] { status = xmate::net::enableRealtimeForThisThread(80); }).join();  // really try it
  const std::string limits = " (RLIMIT_RTPRIO " + limitText(xmate::net::rtprioLimit()) + ")";
  if (status.fifo)
    report(Verdict::kOk, "SCHED_FIFO priority 80 granted" + limits);
  else
    report(Verdict::kFail, "SCHED_FIFO refused" + limits,
           "run as root, or add '@realtime - rtprio 99' to /etc/security/limits.conf and join that group");
  const std::string memlock = " (RLIMIT_MEMLOCK " + limitText(xmate::net::memlockLimitBytes()) + " bytes)";
  // Headless tools lock all their memory (mlockall, as rci-cli does at start); the library itself
  // locks only the real-time thread's stack and state.
  const std::string all = xmate::net::lockAllMemory();
  if (status.memory_locked && all.empty())
    report(Verdict::kOk, "memory locking granted (mlock, mlockall): memory will not be paged out" + memlock);
  else
    report(Verdict::kFail, "memory locking refused" + memlock + ": " + (all.empty() ? status.reason : all),
           "add '@realtime - memlock unlimited' to /etc/security/limits.conf, or run as root");
  if (const char* off = std::getenv("RCI_NO_REALTIME"); off && std::string(off) == "1")
    report(Verdict::kWarn, "RCI_NO_REALTIME=1 is set: the client will not even try real-time scheduling",
           "unset RCI_NO_REALTIME when controlling a real robot");
}

void checkClockSource() {
  const std::string source = xmate::net::clockSource();
  if (source == "tsc")
    report(Verdict::kOk, "clock source: tsc");
  else if (source == "unknown")
    report(Verdict::kInfo, "clock source: unreadable (/sys/devices/system/clocksource)");
  else
    report(Verdict::kWarn, "clock source: " + source + " (slower to read than tsc)",
           "if the CPU has a stable TSC, boot with clocksource=tsc");
}

void checkSocketBuffers() {
  struct Sysctl {
    const char* name;
    const char* path;
  };
  constexpr long kNeeded = 64 * 1024;  // what the client asks for on its UDP socket
  for (const Sysctl s : {Sysctl{"net.core.rmem_max", "/proc/sys/net/core/rmem_max"},
                         Sysctl{"net.core.wmem_max", "/proc/sys/net/core/wmem_max"},
                         Sysctl{"net.core.rmem_default", "/proc/sys/net/core/rmem_default"},
                         Sysctl{"net.core.wmem_default", "/proc/sys/net/core/wmem_default"}}) {
    const long v = xmate::net::sysctlValue(s.path);
    if (v < 0)
      report(Verdict::kInfo, std::string(s.name) + ": unreadable");
    else if (v >= kNeeded)
      report(Verdict::kOk, std::string(s.name) + " = " + std::to_string(v) + " bytes");
    else
      report(Verdict::kWarn, std::string(s.name) + " = " + std::to_string(v) + " bytes (the client asks for 65536)",
             std::string("sysctl -w ") + s.name + "=262144");
  }
}

void checkGovernor() {
  int performance = 0, other = 0;
  std::string example;
  if (DIR* d = opendir("/sys/devices/system/cpu")) {
    while (dirent* e = readdir(d)) {
      const std::string name = e->d_name;
      if (name.rfind("cpu", 0) != 0 || name.size() < 4 || !std::isdigit(static_cast<unsigned char>(name[3]))) continue;
      const std::string g = firstLine("/sys/devices/system/cpu/" + name + "/cpufreq/scaling_governor");
      if (g.empty()) continue;
      (g == "performance" ? performance : other)++;
      if (g != "performance") example = g;
    }
    closedir(d);
  }
  if (performance + other == 0)
    report(Verdict::kInfo, "CPU frequency governor: not readable (no cpufreq here, e.g. a VM or container)");
  else if (other == 0)
    report(Verdict::kOk, "CPU frequency governor: performance on all " + std::to_string(performance) + " CPUs");
  else
    report(Verdict::kWarn, "CPU frequency governor: '" + example + "' on " + std::to_string(other) + " CPUs",
           "cpupower frequency-set -g performance (frequency changes add latency)");
}

void checkCpus() {
  const unsigned n = std::thread::hardware_concurrency();
  const std::string cmdline = firstLine("/proc/cmdline");
  const bool isolated = cmdline.find("isolcpus") != std::string::npos;
  report(n >= 2 ? Verdict::kInfo : Verdict::kWarn,
         std::to_string(n) + " CPUs" + (isolated ? ", isolcpus set on the kernel command line" : ", none isolated"),
         n >= 2 && !isolated ? "optional: isolate a CPU for the real-time thread (isolcpus=, nohz_full=)" : "");
}

}  // namespace

int runDoctor() {
  std::printf("rci-cli doctor: real-time fitness of this machine for the 1 kHz RCI loop\n");
  checkKernel();
  checkScheduling();
  checkClockSource();
  checkSocketBuffers();
  checkGovernor();
  checkCpus();
  return 0;
}

}  // namespace rci_cli
