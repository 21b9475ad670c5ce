// SPDX-License-Identifier: Apache-2.0
// StallInjector (stall_injector.h): SIGUSR2 sent with tgkill to the "rci-rt" thread; the handler
// sleeps for the requested time on that thread.
#include "stall_injector.h"

#include <dirent.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <string>

#include <xmate/robot.h>

#include "client/connection.h"

namespace client_test {
namespace {

std::atomic<int> g_stall_ms{0};
std::atomic<uint64_t> g_completed{0};
struct sigaction g_previous {};

extern "C" void onStallSignal(int) {
  const int ms = g_stall_ms.load();
  timespec left{ms / 1000, long(ms % 1000) * 1'000'000};
  while (nanosleep(&left, &left) != 0) {
  }
  g_completed.fetch_add(1);
}

std::string threadName(const std::string& task_dir) {
  FILE* f = std::fopen((task_dir + "/comm").c_str(), "r");
  if (!f) return {};
  char buffer[32] = {};
  const size_t n = std::fread(buffer, 1, sizeof buffer - 1, f);
  std::fclose(f);
  std::string name(buffer, n);
  while (!name.empty() && (name.back() == '\n' || name.back() == '\0')) name.pop_back();
  return name;
}

}  // namespace

std::vector<int> threadsNamed(const char* name) {
  std::vector<int> tids;
  DIR* dir = opendir("/proc/self/task");
  if (!dir) return tids;
  while (dirent* entry = readdir(dir)) {
    if (entry->d_name[0] == '.') continue;
    if (threadName(std::string("/proc/self/task/") + entry->d_name) == name) tids.push_back(std::atoi(entry->d_name));
  }
  closedir(dir);
  return tids;
}

StallInjector::StallInjector() {
  struct sigaction action {};
  action.sa_handler = onStallSignal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;
  sigaction(SIGUSR2, &action, &g_previous);
}

StallInjector::~StallInjector() { sigaction(SIGUSR2, &g_previous, nullptr); }

bool StallInjector::stallRealtimeThread(int ms) {
  g_stall_ms.store(ms);
  const std::vector<int> tids = threadsNamed("rci-rt");
  for (int tid : tids) syscall(SYS_tgkill, getpid(), tid, SIGUSR2);
  return !tids.empty();
}

uint64_t StallInjector::completed() const { return g_completed.load(); }

namespace {

bool moving(const RCI::robot::RobotState& s) { return s.robot_mode == RCI::robot::RobotMode::kMove; }

}  // namespace

StallDuringMotion::StallDuringMotion(xmate::Robot& robot, StallInjector& injector, int at_cycles, int stall_ms) {
  robot.connect();
  xmate::client::Connection& session = robot.connection();
  thread_ = std::thread([this, &session, &injector, at_cycles, stall_ms] {
    RCI::robot::RobotState s;
    uint64_t first = 0;
    const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(10);
    while (!done_.load() && std::chrono::steady_clock::now() < give_up) {
      if (session.latestState(s) && moving(s)) {
        if (first == 0) first = s.message_id;
        if (s.message_id >= first + uint64_t(at_cycles)) {
          injector.stallRealtimeThread(stall_ms);
          fired_in_motion_.store(true);
          return;
        }
      } else if (first != 0) {
        return;  // the motion ended first
      }
      std::this_thread::sleep_for(std::chrono::microseconds(200));
    }
  });
}

StallDuringMotion::~StallDuringMotion() {
  done_.store(true);
  thread_.join();
}

}  // namespace client_test
