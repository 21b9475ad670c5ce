// SPDX-License-Identifier: Apache-2.0
// arm::RsiArm: a KUKA over RSI as an arm::Arm -- the link, the joint stream and the digital IO of
// one RSI context and its Ethernet config. docs/architecture.md, "One interface for both robot
// families".
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <string>

#include "arm/arm.h"
#include "arm/joint_stream.h"
#include "rsi/config.h"
#include "rsi/digital_io.h"
#include "rsi/link.h"
#include "rsi/session_monitor.h"

namespace xmate::arm {

struct RsiArmConfig {
  std::string context_path;          // NAME.rsi.xml, as the robot runs it
  std::string ethernet_config_path;  // "": the one the context's ETHERNET object names, beside it
  std::string model;                 // "kr6_r900_sixx", "kr16_2"
  rsi::LinkOptions link;
};

class RsiArm : public Arm {
 public:
  // Set-up: reads both files and builds the link (not yet listening). Throws rsi::ConfigError
  // naming file and line, std::invalid_argument for an unknown or non-KUKA model or a config that
  // does not send DEF_AIPos / receive AK.
  explicit RsiArm(const RsiArmConfig& config);
  ~RsiArm() override;  // stop()

  // Any thread, not real-time. start() binds and starts the link's thread (std::runtime_error
  // saying which address could not be bound and what to do).
  void start();
  void stop();

  void accept(ArmVisitor& visitor) override { visitor.visit(*this); }
  const model::RobotSpec& spec() const override { return *spec_; }
  Capabilities capabilities() const override { return capabilities_; }
  double cycleSeconds() const override { return stream_->cycleSeconds(); }
  bool latest(ArmState& out) const override;
  size_t takeSamples(ArmSample* out, size_t max) override;
  uint64_t samplesDropped() const override { return link_->samples().dropped(); }
  // Streams through the joint stream (AXISCORR corrections). The caller checks the motion first
  // (stream().checkSample): the KRC clamps at the context's limits but does not say why.
  void runJointMotion(JointMotion& motion) override;
  // The axis ranges narrowed to the context's correction limits around q_on, for this RSI session.
  MotionBounds motionBounds() const override;
  std::vector<std::string> outputNames() const override;
  std::vector<std::string> inputNames() const override;
  void setOutput(size_t index, bool level) override;
  bool input(size_t index) override;

  // The parts, for what only RSI has (RSI state, limits, the executor's RSI path).
  const rsi::Context& context() const { return context_; }
  const rsi::EthernetConfig& ethernetConfig() const { return config_; }
  rsi::Link& link() { return *link_; }
  JointStream& stream() { return *stream_; }
  rsi::DigitalIo* digitalIo() { return io_.get(); }  // nullptr: the context wires no IO
  // The session as the samples takeSamples() popped show it (waiting / running / stopped and why,
  // cycle, Delay, answer p99). The thread that calls takeSamples(), after it.
  rsi::SessionStatus sessionStatus() const { return monitor_->status(link_->receiving()); }

 private:
  struct Slots {  // decoder slots of the values an ArmSample carries (-1: not sent)
    std::array<int, 6> q{}, q_set{}, current{}, gear{}, pose{}, pose_set{};
  };
  void fill(const double* values, size_t count, ArmSample& s, std::array<double, 6>* pose_mm_deg) const;

  rsi::Context context_;
  rsi::EthernetConfig config_;
  const model::RobotSpec* spec_ = nullptr;
  std::unique_ptr<rsi::Link> link_;
  std::unique_ptr<JointStream> stream_;
  std::unique_ptr<rsi::DigitalIo> io_;
  std::unique_ptr<rsi::SessionMonitor> monitor_;  // fed by takeSamples
  Slots slots_;
  Capabilities capabilities_ = 0;
  int64_t epoch_ns_ = 0;
  // takeSamples' own count of cycles per session (the consumer's thread).
  uint32_t counted_session_ = 0;
  uint64_t counted_cycles_ = 0;
};

}  // namespace xmate::arm
