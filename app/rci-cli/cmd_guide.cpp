// SPDX-License-Identifier: Apache-2.0
// rci-cli guide: hand-guides a KUKA over RSI through the F/T sensor on its flange
// (guide::AdmittanceGuide) until Ctrl-C or --seconds, printing the flange's position, speed and the
// force acted on ten times a second.
#include <atomic>
#include <chrono>
#include <csignal>
#include <cmath>
#include <cstdio>
#include <string>
#include <thread>

#include "arm/rsi_arm.h"
#include "cli.h"
#include "ft/netft.h"
#include "guide/admittance.h"
#include "guide/ft_source.h"
#include "model/arm_kinematics.h"

namespace rci_cli {
namespace {

std::atomic<bool> g_stop{false};
extern "C" void onStop(int) { g_stop.store(true); }

xmate::guide::GuideAxes axesNamed(const std::string& name) {
  if (name == "rotation") return xmate::guide::GuideAxes::kRotation;
  if (name == "free") return xmate::guide::GuideAxes::kFree;
  return xmate::guide::GuideAxes::kTranslation;
}

}  // namespace

int runGuide(const GuideOptions& o) {
  using namespace xmate;
  const model::RobotSpec* spec = model::findRobotSpec(o.model_name);
  if (!spec || spec->family != model::RobotFamily::kKuka)
    throw UsageError("--model: guide drives a KUKA arm over RSI (kr6_r900_sixx, kr16_2), not '" + o.model_name +
                     "'; an xMate guides itself: rci-studio's Drag panel");
  arm::RsiArmConfig config;
  config.context_path = o.context_path.empty() ? contextNaming(o.robot.rsi_config) : o.context_path;
  config.ethernet_config_path = o.robot.rsi_config;
  config.model = o.model_name;
  config.link.bind_ip = o.listen.bind_ip;
  config.link.port = int(o.listen.port);
  config.link.cycle_ms = o.cycle_ms;
  arm::RsiArm arm(config);

  ft::NetFtOptions sensor_options;
  sensor_options.host = o.sensor.host;
  sensor_options.port = o.sensor.port;
  sensor_options.counts_per_force = sensor_options.counts_per_torque = o.sensor.counts_per_unit;
  ft::NetFtClient sensor(sensor_options);

  g_stop.store(false);
  std::signal(SIGINT, onStop);
  std::signal(SIGTERM, onStop);
  arm.start();
  sensor.start();
  const std::string where = (o.listen.bind_ip.empty() ? arm.ethernetConfig().ip : o.listen.bind_ip) + ":" +
                            std::to_string(arm.link().port());
  waitForRsi(arm.link(), arm.stream(), where, g_stop);
  ft::Wrench reading;
  const auto sensor_deadline = std::chrono::steady_clock::now() + std::chrono::seconds(2);
  while (!sensor.latest(reading)) {
    if (std::chrono::steady_clock::now() > sensor_deadline)
      throw std::runtime_error("no data from the F/T sensor at " + o.sensor.host + ":" + std::to_string(o.sensor.port) +
                               " within 2 s; check its address and port, that it is switched on and that RDT output "
                               "is enabled in its web page");
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }

  guide::GuideParameters parameters;
  parameters.axes = axesNamed(o.axes);
  parameters.max_speed = o.max_speed;
  guide::ToolWeight tool{o.tool_mass, {o.tool_center[0], o.tool_center[1], o.tool_center[2]}};
  const guide::NetFtSource source(sensor);
  guide::AdmittanceGuide guide(model::ArmKinematics(*spec), source, arm.cycleSeconds(), parameters, tool);
  // Within the context's correction limits around where RSI started.
  std::array<double, 7> lower{}, upper{};
  arm.stream().reachableBounds(lower, upper);
  guide.setJointBounds(lower, upper);

  const std::string how_long = o.seconds > 0 ? "for " + std::to_string(o.seconds) + " s" : "until Ctrl-C";
  std::printf("guiding the %s by its force sensor (%s, %s); start with nobody touching the tool\n",
              std::string(spec->display_name).c_str(), o.axes.c_str(), how_long.c_str());
  std::printf("# t[s]  X Y Z [mm]  speed [mm/s]  |F| [N]  |T| [Nm]  held axis\n");
  std::fflush(stdout);
  std::string failure;  // the motion thread's, read after it ended
  std::atomic<bool> finished{false};
  std::thread motion([&] {
    try {
      arm.runJointMotion(guide);
    } catch (const std::exception& e) {
      failure = e.what();
    }
    finished.store(true);
  });
  const auto start = std::chrono::steady_clock::now();
  const model::ArmKinematics model(*spec);
  while (!finished.load()) {
    const double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (g_stop.load() || (o.seconds > 0 && t >= double(o.seconds))) guide.requestStop();
    const guide::GuideStatus st = guide.status();
    arm::ArmState state;
    if (arm.latest(state)) {
      const std::array<double, 16> flange = model.GetCartPose(state.sample.q);
      const std::string held = st.cannot_follow        ? "edge of reach"
                               : st.limited_axis >= 0 ? "A" + std::to_string(st.limited_axis + 1)
                                                      : "-";
      std::printf("%7.2f  %8.1f %8.1f %8.1f  %7.1f  %6.1f  %5.2f  %s\n", t, flange[3] * 1e3, flange[7] * 1e3,
                  flange[11] * 1e3, 1e3 * std::hypot(st.velocity[0], st.velocity[1], st.velocity[2]),
                  std::hypot(st.wrench[0], st.wrench[1], st.wrench[2]),
                  std::hypot(st.wrench[3], st.wrench[4], st.wrench[5]), held.c_str());
      std::fflush(stdout);
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  motion.join();
  sensor.stop();
  arm.stop();
  const guide::GuideEnd end = guide.status().end;
  if (!failure.empty()) {
    std::fprintf(stderr, "rci-cli: guiding ended: %s\n", failure.c_str());
    return 1;
  }
  std::printf("guiding ended: %s\n", guide::describe(end));
  return end == guide::GuideEnd::kOperator ? 0 : 1;
}

}  // namespace rci_cli
