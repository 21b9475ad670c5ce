// SPDX-License-Identifier: Apache-2.0
// The inside of sim::Krc (krc.h), shared by its set-up (krc.cpp: reading, checking and ordering the
// signal flow) and its cycle (krc_cycle.cpp: exchange bookkeeping, objects, motion). Not a public header.
#pragma once

#include <array>
#include <atomic>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "model/arm_model.h"
#include "rsi/codec.h"
#include "sim/krc.h"

namespace xmate::sim {

// The object types the simulated KRC runs (docs/rsi.md, "The simulated KRC").
enum class ObjKind { kEthernet, kAxisCorr, kPosCorr, kAxisCorrMon, kPosCorrMon, kGearTorque, kStatus, kOvPro,
                     kDigIn, kDigOut, kAxisAct, kPosAct, kSource };

struct ObjType {
  const char* name;  // ObjType as written in contexts
  ObjKind kind;
  int inputs;   // inputs 1..inputs may be wired
  int outputs;  // outputs 1..outputs exist
};

inline constexpr ObjType kObjTypes[] = {
    {"ETHERNET", ObjKind::kEthernet, 64, 64},      {"AXISCORR", ObjKind::kAxisCorr, 12, 12},
    {"POSCORR", ObjKind::kPosCorr, 6, 6},          {"AXISCORRMON", ObjKind::kAxisCorrMon, 12, 1},
    {"POSCORRMON", ObjKind::kPosCorrMon, 6, 1},    {"GEARTORQUE", ObjKind::kGearTorque, 0, 6},
    {"STATUS", ObjKind::kStatus, 0, 2},            {"OV_PRO", ObjKind::kOvPro, 0, 1},
    {"DIGIN", ObjKind::kDigIn, 0, 16},             {"DIGOUT", ObjKind::kDigOut, 16, 16},
    {"AXISACT", ObjKind::kAxisAct, 0, 6},          {"POSACT", ObjKind::kPosAct, 0, 6},
    {"SOURCE", ObjKind::kSource, 0, 1},
};

// Where POSCORR's corrections act. Base, World and RobRoot are one frame in the simulation.
enum class CorrFrame { kBase, kTool };

// One object of the signal flow, its wiring resolved to pointers (stable: nothing resizes after set-up).
struct Node {
  const rsi::Object* object = nullptr;
  const ObjType* type = nullptr;
  std::vector<const double*> inputs;  // one per input; nullptr when not wired (reads 0)
  std::vector<double> outputs;
  // Parameters, read at set-up (their meaning depends on the kind).
  std::array<double, 12> lower{}, upper{};  // AXISCORR A1..A6, POSCORR X Y Z (A B C: +-max_rot)
  std::array<double, 12> max{};             // AXISCORRMON A1..A6 (NaN: not watched)
  double max_trans = 0, max_rot = 0;         // POSCORR(MON): mm, deg (NaN: not watched)
  CorrFrame frame = CorrFrame::kBase;
  int first_bit = 0;                          // DIGIN/DIGOUT: Index - 1
  int source_type = 0;                        // SOURCE: 0 constant, 1 sine
  double offset = 0, amplitude = 0, period = 1;
  // State of one session.
  std::array<double, 12> total{};  // AXISCORR / POSCORR: the total correction (#RELATIVE sums)
  uint32_t clamp_logged = 0;       // one bit per limit already reported this session
  double input(int k) const { return inputs[size_t(k)] ? *inputs[size_t(k)] : 0.0; }
};

struct Krc::Impl {
  KrcConfig config;
  rsi::Context context;
  rsi::EthernetConfig eth_config;
  const model::RobotSpec* spec = nullptr;
  model::ArmModel arm;
  std::unique_ptr<rsi::RobEncoder> encoder;
  std::unique_ptr<rsi::SenDecoder> decoder;
  int timeout = 100;
  int precision = 4;
  double dt = 0.004;

  std::vector<Node> nodes;  // in file order
  int eth = -1;             // index of the ETHERNET node
  std::vector<int> order;   // the other nodes, in evaluation order

  // What goes into a <Rob>: each SEND slot and where its value comes from.
  struct SendValue {
    int slot;
    const double* source;
    bool text;  // a STRING slot: the number is written as text
  };
  std::vector<SendValue> send_values;
  // What comes out of a <Sen>: each RECEIVE slot and the ETHERNET output it sets.
  struct ReceiveValue {
    int slot;
    int output;  // 0-based
    bool hold_on;
  };
  std::vector<ReceiveValue> receive_values;
  int estr_slot = -1;
  std::array<int, 10> tech_t2_slots{};

  // State of the cycle thread; st is published to other threads after every cycle.
  KrcStatus st;
  net::Seqlock<KrcStatus> published;
  model::JointVector q, dq, ddq, q_set, q_start;
  model::JointVector q_set_before;  // the previous cycle's set-point: its rate is the servo's feedforward
  Eigen::Isometry3d start_flange = Eigen::Isometry3d::Identity();
  std::array<double, 6> last_pos_corr{};  // the Cartesian total the cached IK solved
  model::JointVector q_cartesian;         // start pose moved by last_pos_corr
  bool has_poscorr = false;
  uint32_t joint_limit_logged = 0;
  std::array<double, 10> zeros{};
  double delay_value = 0;
  uint64_t sent_ipoc = 0;
  bool awaiting = false;
  int64_t pause_cycles = 0;     // left before RSI_ON again
  uint64_t session_cycles = 0;  // cycles since this session's RSI_ON
  bool late_this_cycle = false;
  bool axis_clamped = false, cartesian_clamped = false, joint_limited = false;
  std::array<char, rsi::kMaxText> estr{};
  size_t estr_length = 0;
  std::atomic<uint64_t> digin{0};
  std::atomic<double> override_pct{100};
  std::atomic<int> suspend_ms{-1};  // a request from suspendSending, -1 none

  void log(const std::string& line) const {
    if (config.log) config.log(line);
  }
  // Set-up (krc.cpp).
  void build();
  // The cycle (krc_cycle.cpp).
  void rsiOn();
  void rsiStop(KrcStop why, const std::string& message);
  void evaluate();
  void applyCorrections();
  void move();
  void refreshState();
  void torques(const std::array<double, 6>& wrench);
};

}  // namespace xmate::sim
