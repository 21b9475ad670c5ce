// SPDX-License-Identifier: Apache-2.0
// sim::Krc's set-up (krc.h): reads the context and its Ethernet config, checks each object and its
// wiring, orders the signal flow, binds the datagram slots to the objects and loads the model.
#include "sim/krc.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

#include "model/euler_zyx.h"
#include "model/kinematics.h"
#include "model/robot_spec.h"
#include "model/urdf_loader.h"
#include "sim/krc_impl.h"

namespace xmate::sim {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::string supportedList() {
  std::string list;
  for (const ObjType& t : kObjTypes) list += (list.empty() ? "" : ", ") + std::string(t.name);
  return list;
}

[[noreturn]] void fail(const rsi::Context& c, const rsi::Object& o, const std::string& what) {
  throw KrcError(c.path + ":" + std::to_string(o.line) + ": " + o.id + " (" + o.type + "): " + what);
}

std::string lower(std::string s) {
  for (char& ch : s) ch = char(std::tolower(static_cast<unsigned char>(ch)));
  return s;
}

const char* const kAxes[6] = {"A1", "A2", "A3", "A4", "A5", "A6"};
const char* const kCartesian[3] = {"X", "Y", "Z"};

void readParameters(const rsi::Context& c, Node& n) {
  const rsi::Object& o = *n.object;
  switch (n.type->kind) {
    case ObjKind::kEthernet:
    case ObjKind::kGearTorque:
    case ObjKind::kStatus:
    case ObjKind::kOvPro:
    case ObjKind::kAxisAct:
    case ObjKind::kPosAct:
      break;
    case ObjKind::kAxisCorr:
      for (int k = 0; k < 6; ++k) {
        n.lower[size_t(k)] = rsi::numberParameter(c, o, std::string("LowerLim") + kAxes[k], -5);
        n.upper[size_t(k)] = rsi::numberParameter(c, o, std::string("UpperLim") + kAxes[k], 5);
        if (n.lower[size_t(k)] > n.upper[size_t(k)])
          fail(c, o, std::string("LowerLim") + kAxes[k] + " is above UpperLim" + kAxes[k] + "; swap them");
      }
      break;
    case ObjKind::kPosCorr: {
      for (int k = 0; k < 3; ++k) {
        n.lower[size_t(k)] = rsi::numberParameter(c, o, std::string("LowerLim") + kCartesian[k], -5);
        n.upper[size_t(k)] = rsi::numberParameter(c, o, std::string("UpperLim") + kCartesian[k], 5);
        if (n.lower[size_t(k)] > n.upper[size_t(k)])
          fail(c, o, std::string("LowerLim") + kCartesian[k] + " is above UpperLim" + kCartesian[k] + "; swap them");
      }
      n.max_rot = rsi::numberParameter(c, o, "MaxRotAngle", 5);
      if (n.max_rot < 0) fail(c, o, "MaxRotAngle is negative; give the largest rotation in degrees");
      const std::string* frame = o.parameter("RefCorrSys");
      const std::string f = frame ? lower(*frame) : "base";
      if (f == "tool")
        n.frame = CorrFrame::kTool;
      else if (f == "base" || f == "world" || f == "robroot")
        n.frame = CorrFrame::kBase;
      else
        fail(c, o, "RefCorrSys \"" + *frame + "\" is not supported; give World, Base, RobRoot or Tool");
      break;
    }
    case ObjKind::kAxisCorrMon:
      for (int k = 0; k < 6; ++k) n.max[size_t(k)] = rsi::numberParameter(c, o, std::string("Max") + kAxes[k], kNaN);
      break;
    case ObjKind::kPosCorrMon:
      n.max_trans = rsi::numberParameter(c, o, "MaxTrans", kNaN);
      n.max_rot = rsi::numberParameter(c, o, "MaxRotAngle", kNaN);
      break;
    case ObjKind::kDigIn:
    case ObjKind::kDigOut: {
      const double index = rsi::numberParameter(c, o, "Index", 1);
      if (index < 1 || index > 64 - 16 + 1 || index != std::floor(index))
        fail(c, o, "Index " + std::to_string(index) + " is not a first input/output 1 to 49 (16 bits from it)");
      n.first_bit = int(index) - 1;
      break;
    }
    case ObjKind::kSource:
      n.source_type = int(rsi::numberParameter(c, o, "Type", 0));
      if (n.source_type != 0 && n.source_type != 1) fail(c, o, "Type must be 0 (constant) or 1 (sine)");
      n.offset = rsi::numberParameter(c, o, "Offset", 0);
      n.amplitude = rsi::numberParameter(c, o, "Amplitude", 0);
      n.period = rsi::numberParameter(c, o, "Period", 1);
      if (!(n.period > 0)) fail(c, o, "Period must be positive (seconds)");
      break;
  }
}

}  // namespace

const char* toString(KrcState state) {
  switch (state) {
    case KrcState::kRunning: return "running";
    case KrcState::kPaused: return "paused";
    case KrcState::kStopped: return "stopped";
    case KrcState::kSuspended: return "suspended";
  }
  return "?";
}

const char* toString(KrcStop stop) {
  switch (stop) {
    case KrcStop::kNone: return "none";
    case KrcStop::kTimeout: return "RSITimeout";
    case KrcStop::kAxisMonitor: return "axis correction monitor";
    case KrcStop::kPosMonitor: return "Cartesian correction monitor";
    case KrcStop::kUnreachable: return "unreachable pose";
    case KrcStop::kSuspended: return "sending suspended";
  }
  return "?";
}

void Krc::Impl::build() {
  if (config.cycle_ms != 4 && config.cycle_ms != 12)
    throw KrcError("cycle " + std::to_string(config.cycle_ms) + " ms: RSI runs every 4 ms (#IPO_FAST) or 12 ms");
  dt = config.cycle_ms / 1000.0;
  spec = model::findRobotSpec(config.model);
  if (!spec) throw KrcError("unknown model '" + config.model + "'; give a 6-axis model such as kr6_r900_sixx");
  if (spec->dof != 6)
    throw KrcError("model '" + config.model + "' has " + std::to_string(spec->dof) +
                   " axes; the simulated KRC drives 6-axis arms (A1..A6), e.g. kr6_r900_sixx or kr16_2");
  arm = model::makeArmModel(model::loadRobotChain(*spec), *spec);
  model::setSpeedCheckInterval(arm, 0);  // the position controller below keeps the axis speeds

  for (int k = 0; k < 6; ++k) {
    const double rad = config.start_deg[size_t(k)] * M_PI / 180;
    if (!(rad >= spec->q_min[size_t(k)] - 1e-9 && rad <= spec->q_max[size_t(k)] + 1e-9))
      throw KrcError("start pose: " + std::string(kAxes[k]) + " = " + std::to_string(config.start_deg[size_t(k)]) +
                     " deg is outside its range " + std::to_string(spec->q_min[size_t(k)] * 180 / M_PI) + " .. " +
                     std::to_string(spec->q_max[size_t(k)] * 180 / M_PI) + " deg of " + config.model +
                     "; give a start pose within the axis limits");
  }

  context = rsi::readContext(config.context_path);
  eth_config = rsi::readEthernetConfig(context.ethernetConfigPath());

  // The nodes, in file order; each type known.
  nodes.resize(context.objects.size());
  for (size_t i = 0; i < context.objects.size(); ++i) {
    Node& n = nodes[i];
    n.object = &context.objects[i];
    for (const ObjType& t : kObjTypes)
      if (n.object->type == t.name) n.type = &t;
    if (!n.type)
      fail(context, *n.object, "this object type is not supported by the simulated KRC; it runs " + supportedList() +
                                   " -- take the object out of the context or run it on a real controller");
    if (n.type->kind == ObjKind::kEthernet) {
      if (eth >= 0)
        fail(context, *n.object, "a second ETHERNET object; the simulated KRC exchanges with one PC, keep one");
      eth = int(i);
    }
    n.outputs.assign(size_t(n.type->outputs), 0.0);
    n.inputs.assign(size_t(n.type->inputs), nullptr);
    readParameters(context, n);
  }
  const rsi::Object& eth_object = *nodes[size_t(eth)].object;
  timeout = int(rsi::numberParameter(context, eth_object, "Timeout", 100));
  precision = int(rsi::numberParameter(context, eth_object, "Precision", 4));
  if (timeout < 0) fail(context, eth_object, "Timeout is negative; give the number of late answers tolerated, e.g. 100");
  if (precision < 0 || precision > 9) fail(context, eth_object, "Precision must be 0 to 9 decimals");

  // The wiring: input k of a node reads output m of another (checked against both types).
  for (Node& n : nodes) {
    for (const rsi::Input& in : n.object->inputs) {
      if (in.in_index > n.type->inputs)
        fail(context, *n.object, "input " + std::to_string(in.in_index) + " is wired, but " + n.type->name +
                                     (n.type->inputs ? " has inputs 1 to " + std::to_string(n.type->inputs)
                                                     : std::string(" has no inputs")));
      if (n.inputs[size_t(in.in_index - 1)])
        fail(context, *n.object, "input " + std::to_string(in.in_index) + " is wired twice; keep one wire");
      auto source = std::find_if(nodes.begin(), nodes.end(), [&](const Node& s) { return s.object->id == in.out_object; });
      if (in.out_index > source->type->outputs)
        fail(context, *n.object, "input " + std::to_string(in.in_index) + " takes output " + std::to_string(in.out_index) +
                                     " of " + in.out_object + ", but " + source->type->name + " has outputs 1 to " +
                                     std::to_string(source->type->outputs));
      n.inputs[size_t(in.in_index - 1)] = &source->outputs[size_t(in.out_index - 1)];
    }
  }

  // Evaluation order: depth-first over "takes an output of", ETHERNET excluded (its outputs are what
  // the PC sent this cycle, its inputs are sent in the next <Rob>: it may close a loop, nothing else).
  std::vector<int> mark(nodes.size(), 0);  // 0 new, 1 on the path, 2 done
  std::vector<int> path;
  std::function<void(int)> visit = [&](int i) {
    if (mark[size_t(i)] == 2) return;
    if (mark[size_t(i)] == 1) {
      std::string loop;
      const auto from = std::find(path.begin(), path.end(), i);
      for (auto it = from; it != path.end(); ++it) loop += nodes[size_t(*it)].object->id + " -> ";
      loop += nodes[size_t(i)].object->id;
      fail(context, *nodes[size_t(i)].object,
           "its inputs form a wiring cycle (" + loop +
               "); every object must take its inputs from objects evaluated before it -- only the ETHERNET object "
               "may close a loop: break the cycle");
    }
    mark[size_t(i)] = 1;
    path.push_back(i);
    for (const rsi::Input& in : nodes[size_t(i)].object->inputs) {
      const int s = int(std::find_if(nodes.begin(), nodes.end(), [&](const Node& x) { return x.object->id == in.out_object; }) -
                        nodes.begin());
      if (s != eth) visit(s);
    }
    path.pop_back();
    mark[size_t(i)] = 2;
    order.push_back(i);
  };
  for (int i = 0; i < int(nodes.size()); ++i)
    if (i != eth) visit(i);
  for (const Node& n : nodes) has_poscorr = has_poscorr || n.type->kind == ObjKind::kPosCorr;

  // The datagrams.
  encoder = std::make_unique<rsi::RobEncoder>(eth_config, precision);
  decoder = std::make_unique<rsi::SenDecoder>(eth_config);
  Node& eth_node = nodes[size_t(eth)];
  for (const rsi::Channel& ch : eth_config.send) {
    if (!ch.internal()) {
      const int slot = encoder->slot(ch.element, ch.attribute);
      if (!eth_node.inputs[size_t(ch.index - 1)])
        eth_node.inputs[size_t(ch.index - 1)] = &zeros[0];  // an input nobody wired is sent as 0
      send_values.push_back({slot, eth_node.inputs[size_t(ch.index - 1)], ch.type == rsi::ValueType::kString});
      continue;
    }
    for (const std::string& attribute : rsi::builtInAttributes(ch)) {
      const int slot = encoder->slot(ch.element, attribute);
      const double* source = &zeros[0];
      const auto axis = [&](const std::array<double, 6>& values) {
        const int k = attribute.size() == 2 ? attribute[1] - '1' : -1;  // A1..A6
        return k >= 0 && k < 6 ? &values[size_t(k)] : &zeros[0];
      };
      const auto cartesian = [&](const std::array<double, 6>& values) {
        static const std::string names = "XYZABC";
        const size_t k = names.find(attribute);
        return attribute.size() == 1 && k != std::string::npos ? &values[k] : &zeros[0];
      };
      if (ch.element == "RIst") source = cartesian(st.pose);
      else if (ch.element == "RSol") source = cartesian(st.pose_set);
      else if (ch.element == "AIPos") source = axis(st.q_deg);
      else if (ch.element == "ASPos") source = axis(st.q_set_deg);
      else if (ch.element == "MACur") source = axis(st.motor_current);
      else if (ch.element == "Delay") source = &delay_value;
      // EIPos, ESPos, MECur (no external axes) and Tech (C1x, T1x: no technology values) are 0.
      send_values.push_back({slot, source, ch.type == rsi::ValueType::kString});
    }
  }
  tech_t2_slots.fill(-1);
  for (const rsi::Channel& ch : eth_config.receive) {
    if (!ch.internal()) {
      receive_values.push_back({decoder->slot(ch.element, ch.attribute), ch.index - 1, ch.hold_on});
      continue;
    }
    if (ch.element == "EStr") estr_slot = decoder->slot("EStr", "");
    if (ch.element == "Tech" && ch.attribute == "T2")
      for (int k = 0; k < 10; ++k) tech_t2_slots[size_t(k)] = decoder->slot("Tech", "T2" + std::to_string(k + 1));
  }

  for (int k = 0; k < 6; ++k) q[k] = config.start_deg[size_t(k)] * M_PI / 180;
  dq.setZero();
  ddq.setZero();
  q_set = q;
  q_set_before = q;
  st.ipoc = config.ipoc_start;
}

Krc::Krc(KrcConfig config) : impl_(std::make_unique<Impl>()) {
  wrench_.store(std::array<double, 6>{});
  impl_->config = std::move(config);
  impl_->build();
  impl_->refreshState();
  impl_->torques({});
  impl_->rsiOn();
  impl_->published.store(impl_->st);
}

Krc::~Krc() = default;

void Krc::setDigitalInput(int index, bool level) {
  if (index < 1 || index > 64) throw std::out_of_range("digital input " + std::to_string(index) + ": give 1 to 64");
  const uint64_t bit = uint64_t(1) << (index - 1);
  if (level)
    impl_->digin.fetch_or(bit);
  else
    impl_->digin.fetch_and(~bit);
}

void Krc::setOverride(double percent) {
  if (!(percent >= 0 && percent <= 100))
    throw std::out_of_range("override " + std::to_string(percent) + " %: give 0 to 100");
  impl_->override_pct.store(percent);
}

void Krc::suspendSending(int ms) {
  if (ms < 0) throw std::out_of_range("suspendSending: give a time of 0 ms or more");
  impl_->suspend_ms.store(ms);
}

KrcStatus Krc::status() const {
  KrcStatus s;
  impl_->published.load(s);
  return s;
}

std::array<double, 6> Krc::flangeWrench() const {
  std::array<double, 6> w{};
  wrench_.load(w);
  KrcStatus s;
  impl_->published.load(s);
  const model::AbcAngles abc{s.pose[3] * M_PI / 180, s.pose[4] * M_PI / 180, s.pose[5] * M_PI / 180};
  const Eigen::Matrix3d r = model::rotationFromAbc(abc);
  const Eigen::Vector3d f = r.transpose() * Eigen::Vector3d(w[0], w[1], w[2]);
  const Eigen::Vector3d m = r.transpose() * Eigen::Vector3d(w[3], w[4], w[5]);
  return {f.x(), f.y(), f.z(), m.x(), m.y(), m.z()};
}

const rsi::Context& Krc::context() const { return impl_->context; }
const rsi::EthernetConfig& Krc::ethernetConfig() const { return impl_->eth_config; }
int Krc::timeoutLimit() const { return impl_->timeout; }
int Krc::cycleMs() const { return impl_->config.cycle_ms; }

std::string Krc::evaluationOrder() const {
  std::string s = impl_->nodes[size_t(impl_->eth)].object->id;
  for (int i : impl_->order) s += " " + impl_->nodes[size_t(i)].object->id;
  return s;
}

double Krc::output(std::string_view object_id, int index) const {
  for (const Node& n : impl_->nodes)
    if (n.object->id == object_id && index >= 1 && index <= int(n.outputs.size())) return n.outputs[size_t(index - 1)];
  return kNaN;
}

}  // namespace xmate::sim
