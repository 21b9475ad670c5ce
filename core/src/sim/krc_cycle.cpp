// SPDX-License-Identifier: Apache-2.0
// sim::Krc's cycle (krc.h): the <Rob> out, the <Sen> in (late, HOLDON, Delay, Timeout), the signal
// flow's objects, the corrections and their clamps and monitors, and the arm's position controller.
// Allocation-free except for the log lines of events.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>

#include "model/dynamics.h"
#include "model/euler_zyx.h"
#include "model/inverse_kinematics.h"
#include "model/kinematics.h"
#include "model/robot_spec.h"
#include "sim/krc.h"
#include "sim/krc_impl.h"

namespace xmate::sim {
namespace {

constexpr double kDeg = M_PI / 180;
const char* const kAxisNames[6] = {"A1", "A2", "A3", "A4", "A5", "A6"};
const char* const kCartesianNames[6] = {"X", "Y", "Z", "A", "B", "C"};

// Numbers in log lines: "%.3f".
std::string fmt(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.3f", v);
  return b;
}

void poseOf(const Eigen::Isometry3d& t, std::array<double, 6>& out) {
  const model::AbcAngles abc = model::abcFromRotation(t.linear());
  out = {t.translation().x() * 1000, t.translation().y() * 1000, t.translation().z() * 1000,
         abc.a / kDeg,               abc.b / kDeg,               abc.c / kDeg};
}

}  // namespace

// ---- Sessions -------------------------------------------------------------------------------------

void Krc::Impl::rsiOn() {
  ++st.session;
  st.state = KrcState::kRunning;
  q_start = q;
  q_cartesian = q;
  q_set = q;
  q_set_before = q;
  start_flange = model::flangePose(arm, q);
  last_pos_corr = {};
  for (Node& n : nodes) {
    n.total.fill(0);
    n.clamp_logged = 0;
    std::fill(n.outputs.begin(), n.outputs.end(), 0.0);
  }
  joint_limit_logged = 0;
  st.delay = 0;
  delay_value = 0;
  st.late_in_a_row = 0;
  st.axis_corr_deg = {};
  st.pos_corr = {};
  for (int k = 0; k < 6; ++k) st.start_deg[size_t(k)] = q[k] / kDeg;
  session_cycles = 0;
  awaiting = false;
  std::string axes;
  for (int k = 0; k < 6; ++k) axes += (k ? ", " : "") + fmt(q[k] / kDeg);
  log("RSI_ON(" + std::string(config.mode == rsi::CorrectionMode::kAbsolute ? "#ABSOLUTE" : "#RELATIVE") +
      "): session " + std::to_string(st.session) + ", corrections relative to A1..A6 = " + axes + " deg");
}

void Krc::Impl::rsiStop(KrcStop why, const std::string& message) {
  st.last_stop = why;
  awaiting = false;
  q_set = q;  // the arm holds where it is
  q_set_before = q;
  dq.setZero();
  ddq.setZero();
  if (why == KrcStop::kSuspended) {
    st.state = KrcState::kSuspended;
    log(message);
    return;
  }
  if (config.restart_pause_ms > 0) {
    st.state = KrcState::kPaused;
    pause_cycles = (config.restart_pause_ms + config.cycle_ms - 1) / config.cycle_ms;
    log(message + "; RSI stopped, the arm holds; the program starts RSI again in " +
        std::to_string(config.restart_pause_ms) + " ms");
  } else {
    st.state = KrcState::kStopped;
    log(message + "; RSI stopped, the arm holds (no restart: restart pause 0)");
  }
}

// ---- The exchange -----------------------------------------------------------------------------------

size_t Krc::beginCycle(char* out, size_t capacity) {
  Impl& m = *impl_;
  answered_ = false;
  if (m.st.state != KrcState::kRunning) return 0;
  for (const Impl::SendValue& v : m.send_values) {
    if (v.slot < 0) continue;
    if (v.text) {
      char b[32];
      const auto r = std::to_chars(b, b + sizeof b, *v.source);
      m.encoder->setText(v.slot, {b, size_t(r.ptr - b)});
    } else {
      m.encoder->set(v.slot, *v.source);
    }
  }
  char ipoc[24];
  const auto r = std::to_chars(ipoc, ipoc + sizeof ipoc, m.st.ipoc);
  const size_t n = m.encoder->encode({ipoc, size_t(r.ptr - ipoc)}, out, capacity);
  if (n == 0) return 0;  // the buffer is too small for this config: nothing goes out, the answer will be late
  m.sent_ipoc = m.st.ipoc;
  m.awaiting = true;
  ++m.st.robs_sent;
  return n;
}

bool Krc::takeDuplicate() {
  if (!impl_->awaiting || duplicate_.load(std::memory_order_relaxed) <= 0) return false;
  duplicate_.fetch_sub(1);
  ++impl_->st.robs_duplicated;
  return true;
}

bool Krc::awaitingAnswer() const { return impl_->awaiting && !answered_ && !impl_->eth_config.only_send; }

bool Krc::onAnswer(std::string_view datagram) {
  Impl& m = *impl_;
  if (!awaitingAnswer()) {
    ++m.st.answers_stale;
    return false;
  }
  if (drop_.load(std::memory_order_relaxed) > 0) {
    drop_.fetch_sub(1);
    ++m.st.answers_dropped;
    return false;
  }
  if (!m.decoder->decode(datagram)) {
    ++m.st.answers_rejected;
    last_reason_.store(m.decoder->reason());
    return false;
  }
  if (m.decoder->ipoc() != m.sent_ipoc) {
    ++m.st.answers_stale;
    return false;
  }
  if (delay_.load(std::memory_order_relaxed) > 0) {
    delay_.fetch_sub(1);
    ++m.st.answers_delayed;  // it comes after its cycle: late, and then stale
    return false;
  }
  Node& eth = m.nodes[size_t(m.eth)];
  for (const Impl::ReceiveValue& v : m.receive_values)
    if (v.slot >= 0 && m.decoder->layout()[size_t(v.slot)].type != rsi::ValueType::kString)
      eth.outputs[size_t(v.output)] = m.decoder->value(v.slot);
  for (int k = 0; k < 10; ++k)
    if (m.tech_t2_slots[size_t(k)] >= 0) m.st.tech_t2[size_t(k)] = m.decoder->value(m.tech_t2_slots[size_t(k)]);
  if (m.estr_slot >= 0 && m.decoder->seen(m.estr_slot)) {
    const std::string_view text = m.decoder->text(m.estr_slot);
    if (text != std::string_view(m.estr.data(), m.estr_length)) {
      std::copy(text.begin(), text.end(), m.estr.begin());
      m.estr_length = text.size();
      if (!text.empty()) m.log("smartPAD message from the PC (DEF_EStr): " + std::string(text));
    }
  }
  answered_ = true;
  ++m.st.answers_used;
  return true;
}

void Krc::endCycle() {
  Impl& m = *impl_;
  const bool was_off = m.st.state == KrcState::kPaused || m.st.state == KrcState::kSuspended;
  m.late_this_cycle = false;
  if (m.awaiting && !answered_ && !m.eth_config.only_send) {
    ++m.st.delay;
    ++m.st.late_in_a_row;
    ++m.st.answers_late;
    m.delay_value = double(m.st.delay);
    m.late_this_cycle = true;
    Node& eth = m.nodes[size_t(m.eth)];
    for (const Impl::ReceiveValue& v : m.receive_values)
      if (!v.hold_on) eth.outputs[size_t(v.output)] = 0;
    if (m.st.late_in_a_row > uint64_t(m.timeout)) {
      ++m.st.timeouts;
      m.rsiStop(KrcStop::kTimeout, "Signal flow (running): Object " + eth.object->id + " returns error RSITimeout (" +
                                       std::to_string(m.st.late_in_a_row) + " late answers in a row, Timeout " +
                                       std::to_string(m.timeout) + ")");
    }
  } else if (m.awaiting) {
    m.st.late_in_a_row = 0;
  }
  m.awaiting = false;

  const int suspend = m.suspend_ms.exchange(-1);
  if (suspend >= 0) {
    m.rsiStop(KrcStop::kSuspended, "RSI off for " + std::to_string(suspend) +
                                       " ms (fault injection: the KRC stops sending without a timeout)");
    m.pause_cycles = (suspend + m.config.cycle_ms - 1) / m.config.cycle_ms;
  }

  m.axis_clamped = m.cartesian_clamped = m.joint_limited = false;
  if (m.st.state == KrcState::kRunning) {
    m.evaluate();
    if (m.st.state == KrcState::kRunning) m.applyCorrections();
  }
  m.move();
  std::array<double, 6> wrench{};
  wrench_.load(wrench);
  m.refreshState();
  m.torques(wrench);

  if (was_off && --m.pause_cycles <= 0) m.rsiOn();  // the pause counts from the cycle after the stop
  ++m.st.cycles;
  ++m.session_cycles;
  m.st.ipoc = m.config.ipoc_start + m.st.cycles * uint64_t(m.config.cycle_ms);
  answered_ = false;
  m.published.store(m.st);
}

// ---- The signal flow --------------------------------------------------------------------------------

void Krc::Impl::evaluate() {
  const bool absolute = config.mode == rsi::CorrectionMode::kAbsolute;
  for (int i : order) {
    Node& n = nodes[size_t(i)];
    const std::string& id = n.object->id;
    switch (n.type->kind) {
      case ObjKind::kEthernet:
        break;
      case ObjKind::kAxisCorr:
      case ObjKind::kPosCorr: {
        const bool axis = n.type->kind == ObjKind::kAxisCorr;
        for (int k = 0; k < 6; ++k) {
          const double asked = absolute ? n.input(k) : n.total[size_t(k)] + n.input(k);
          const bool rot = !axis && k >= 3;
          const double lo = rot ? -n.max_rot : n.lower[size_t(k)];
          const double hi = rot ? n.max_rot : n.upper[size_t(k)];
          const double held = std::clamp(asked, lo, hi);
          if (held != asked) {
            (axis ? axis_clamped : cartesian_clamped) = true;
            const uint32_t bit = 1u << (k * 2 + (asked > hi ? 1 : 0));
            if (!(n.clamp_logged & bit)) {
              n.clamp_logged |= bit;
              const std::string name = axis ? kAxisNames[k] : kCartesianNames[k];
              const std::string limit = rot ? "MaxRotAngle" : std::string(asked > hi ? "UpperLim" : "LowerLim") + name;
              log(id + ": the correction of " + name + " (" + fmt(asked) + (axis || rot ? " deg" : " mm") +
                  ") reached " + limit + " = " + fmt(asked > hi ? hi : lo) + "; held at the limit");
            }
          }
          n.total[size_t(k)] = held;
          n.outputs[size_t(k)] = held;
        }
        break;
      }
      case ObjKind::kAxisCorrMon:
        for (int k = 0; k < 6; ++k) {
          const double v = n.input(k);
          if (!std::isnan(n.max[size_t(k)]) && std::abs(v) > n.max[size_t(k)] + 1e-9) {
            n.outputs[0] = 1;
            rsiStop(KrcStop::kAxisMonitor, id + ": the total correction of " + kAxisNames[k] + " is " + fmt(v) +
                                               " deg, beyond Max" + kAxisNames[k] + " = " + fmt(n.max[size_t(k)]) + " deg");
            return;
          }
        }
        n.outputs[0] = 0;
        break;
      case ObjKind::kPosCorrMon: {
        const double trans = std::sqrt(n.input(0) * n.input(0) + n.input(1) * n.input(1) + n.input(2) * n.input(2));
        const double rot = Eigen::AngleAxisd(model::rotationFromAbc({n.input(3) * kDeg, n.input(4) * kDeg, n.input(5) * kDeg}))
                               .angle() / kDeg;
        if (!std::isnan(n.max_trans) && trans > n.max_trans + 1e-9) {
          n.outputs[0] = 1;
          rsiStop(KrcStop::kPosMonitor, id + ": the total translation of the correction is " + fmt(trans) +
                                            " mm, beyond MaxTrans = " + fmt(n.max_trans) + " mm");
          return;
        }
        if (!std::isnan(n.max_rot) && rot > n.max_rot + 1e-9) {
          n.outputs[0] = 1;
          rsiStop(KrcStop::kPosMonitor, id + ": the total rotation of the correction is " + fmt(rot) +
                                            " deg, beyond MaxRotAngle = " + fmt(n.max_rot) + " deg");
          return;
        }
        n.outputs[0] = 0;
        break;
      }
      case ObjKind::kGearTorque:
        std::copy(st.gear_torque.begin(), st.gear_torque.end(), n.outputs.begin());
        break;
      case ObjKind::kStatus:
        n.outputs[0] = st.program_status;
        n.outputs[1] = st.status_bits;
        break;
      case ObjKind::kOvPro:
        n.outputs[0] = override_pct.load(std::memory_order_relaxed);
        break;
      case ObjKind::kDigIn: {
        const uint64_t bits = digin.load(std::memory_order_relaxed);
        for (int k = 0; k < 16; ++k) n.outputs[size_t(k)] = double((bits >> (n.first_bit + k)) & 1u);
        break;
      }
      case ObjKind::kDigOut:
        for (int k = 0; k < 16; ++k) {
          const bool on = n.input(k) != 0;
          n.outputs[size_t(k)] = on ? 1 : 0;
          const uint64_t bit = uint64_t(1) << (n.first_bit + k);
          st.digout = on ? (st.digout | bit) : (st.digout & ~bit);
        }
        break;
      case ObjKind::kAxisAct:
        std::copy(st.q_deg.begin(), st.q_deg.end(), n.outputs.begin());
        break;
      case ObjKind::kPosAct:
        std::copy(st.pose.begin(), st.pose.end(), n.outputs.begin());
        break;
      case ObjKind::kSource:
        n.outputs[0] = n.source_type == 0
                           ? n.offset
                           : n.offset + n.amplitude * std::sin(2 * M_PI * double(session_cycles) * dt / n.period);
        break;
    }
  }
}

void Krc::Impl::applyCorrections() {
  std::array<double, 6> axis{}, cartesian{};
  CorrFrame frame = CorrFrame::kBase;
  for (const Node& n : nodes) {
    if (n.type->kind == ObjKind::kAxisCorr)
      for (size_t k = 0; k < 6; ++k) axis[k] += n.total[k];
    if (n.type->kind == ObjKind::kPosCorr) {
      for (size_t k = 0; k < 6; ++k) cartesian[k] += n.total[k];
      frame = n.frame;
    }
  }
  st.axis_corr_deg = axis;
  st.pos_corr = cartesian;
  if (has_poscorr && cartesian != last_pos_corr) {
    Eigen::Isometry3d c = Eigen::Isometry3d::Identity();
    c.linear() = model::rotationFromAbc({cartesian[3] * kDeg, cartesian[4] * kDeg, cartesian[5] * kDeg});
    c.translation() = Eigen::Vector3d(cartesian[0], cartesian[1], cartesian[2]) / 1000;
    Eigen::Isometry3d target = start_flange * c;  // Tool: in the flange frame at RSI_ON
    if (frame == CorrFrame::kBase) {
      target.linear() = c.linear() * start_flange.linear();
      target.translation() = start_flange.translation() + c.translation();
    }
    model::JointVector solution;
    const model::IkStatus ik = model::inverseKinematics(arm, target.matrix(), 0, q_cartesian, solution);
    if (ik != model::IkStatus::kOk) {
      rsiStop(KrcStop::kUnreachable, "the corrected pose (X " + fmt(cartesian[0]) + " Y " + fmt(cartesian[1]) + " Z " +
                                         fmt(cartesian[2]) + " mm, A " + fmt(cartesian[3]) + " B " + fmt(cartesian[4]) +
                                         " C " + fmt(cartesian[5]) + " deg from the start) cannot be reached: " +
                                         model::ikStatusText(ik));
      return;
    }
    q_cartesian = solution;
    last_pos_corr = cartesian;
  }
  const model::JointVector& base = has_poscorr ? q_cartesian : q_start;
  for (int k = 0; k < 6; ++k) {
    const double want = base[k] + axis[size_t(k)] * kDeg;
    const double lo = spec->q_min[size_t(k)], hi = spec->q_max[size_t(k)];
    q_set[k] = std::clamp(want, lo, hi);
    if (q_set[k] != want) {
      joint_limited = true;
      const uint32_t bit = 1u << k;
      if (!(joint_limit_logged & bit)) {
        joint_limit_logged |= bit;
        log("the set-point of " + std::string(kAxisNames[k]) + " (" + fmt(want / kDeg) + " deg) is beyond its axis limit " +
            fmt((want > hi ? hi : lo) / kDeg) + " deg; held at the limit");
      }
    }
  }
}

// ---- The arm ------------------------------------------------------------------------------------------

// Each axis follows its set-point as a servo does: the set-point's own speed (feedforward) plus a
// correction of the error to the previous set-point, min(sqrt(2 a |e|), |e| / dt) (braking in time), within
// its speed (the model's) and acceleration (acceleration_per_speed times it). Without the feedforward
// an axis would trail a moving set-point by v^2 / 2a -- a lag that differs per axis and so leaves the
// commanded path; with it the arm stays on the path, a cycle behind.
void Krc::Impl::move() {
  if (st.state != KrcState::kRunning) {
    dq.setZero();
    ddq.setZero();
    q_set = q;
    q_set_before = q;
    return;
  }
  for (int k = 0; k < 6; ++k) {
    const double v_max = spec->dq_max[size_t(k)];
    const double a_max = config.acceleration_per_speed * v_max;
    const double feedforward = std::clamp((q_set[k] - q_set_before[k]) / dt, -v_max, v_max);
    const double e = q_set_before[k] - q[k];  // behind where the set-point was: the feedforward covers its step
    const double correction = std::copysign(std::min(std::sqrt(2 * a_max * std::abs(e)), std::abs(e) / dt), e);
    const double wanted = std::clamp(feedforward + correction, -v_max, v_max);
    q_set_before[k] = q_set[k];
    const double v = dq[k] + std::clamp(wanted - dq[k], -a_max * dt, a_max * dt);
    ddq[k] = (v - dq[k]) / dt;
    dq[k] = v;
    q[k] += v * dt;
  }
}

// Gear torques: what the motors hold against gravity, inertia and the external wrench (base frame,
// at the flange): tau = RNEA(q, dq, ddq) - J^T F. Motor currents: tau / torque_per_amp.
void Krc::Impl::torques(const std::array<double, 6>& wrench) {
  const model::Vector6d w = Eigen::Map<const model::Vector6d>(wrench.data());
  const model::JointVector tau = model::inverseDynamics(arm, q, dq, ddq) - model::wrenchToJointTorques(arm, q, w);
  for (int k = 0; k < 6; ++k) {
    st.gear_torque[size_t(k)] = tau[k];
    st.motor_current[size_t(k)] = tau[k] / config.torque_per_amp;
  }
}

void Krc::Impl::refreshState() {
  for (int k = 0; k < 6; ++k) {
    st.q_deg[size_t(k)] = q[k] / kDeg;
    st.q_set_deg[size_t(k)] = q_set[k] / kDeg;
    st.dq_deg_s[size_t(k)] = dq[k] / kDeg;
  }
  poseOf(model::flangePose(arm, q), st.pose);
  poseOf(model::flangePose(arm, q_set), st.pose_set);
  st.override_pct = override_pct.load(std::memory_order_relaxed);
  st.digin = digin.load(std::memory_order_relaxed);
  st.program_status = st.state == KrcState::kRunning ? 1 : st.state == KrcState::kStopped ? 2 : 0;
  st.status_bits = (axis_clamped ? 1 : 0) | (cartesian_clamped ? 2 : 0) | (joint_limited ? 4 : 0) | (late_this_cycle ? 8 : 0);
}

}  // namespace xmate::sim
