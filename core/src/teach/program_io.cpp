// SPDX-License-Identifier: Apache-2.0
// Reading and writing programs (program_io.h). Reading is strict: every field is checked for kind,
// length, finiteness and range, unknown members are refused (a typo must not silently vanish).
#include "teach/program_io.h"

#include <cmath>
#include <cstdio>
#include <initializer_list>
#include <vector>

#include "model/robot_spec.h"
#include "planning/cartesian_pose.h"
#include "teach/atomic_file.h"
#include "teach/json_text.h"

namespace xmate::teach {
namespace {

// Where a problem is: "instruction 3 (MOVEL), field \"target.pose\"" or "field \"robot\"".
struct Where {
  std::string prefix;  // "instruction 3 (MOVEL)" or ""
  [[noreturn]] void fail(const std::string& field, const std::string& problem) const {
    std::string s = prefix.empty() ? "" : prefix + ", ";
    s += "field \"" + field + "\": " + problem;
    throw ProgramError(s);
  }
};

std::string got(const Json& v) { return std::string("got ") + kindName(v); }

// Object member by name, nullptr if absent.
const Json* member(const Json& object, const std::string& key) {
  const auto it = object.find(key);
  return it == object.end() ? nullptr : &*it;
}

const Json& require(const Json& object, const std::string& key, const std::string& field, const Where& w) {
  const Json* v = member(object, key);
  if (!v) w.fail(field, "missing");
  return *v;
}

void refuseUnknown(const Json& object, std::initializer_list<const char*> known, const std::string& field,
                   const Where& w) {
  for (const auto& item : object.items()) {
    const std::string& key = item.key();
    bool ok = false;
    std::string list;
    for (const char* k : known) {
      ok = ok || key == k;
      list += (list.empty() ? "" : ", ") + std::string(k);
    }
    if (!ok) w.fail(field.empty() ? key : field + "." + key, "unknown member (known here: " + list + ")");
  }
}

double finiteNumber(const Json& v, const std::string& field, const Where& w) {
  if (!v.is_number()) w.fail(field, "expected a number, " + got(v));
  const double d = v.get<double>();
  if (!std::isfinite(d)) w.fail(field, "not a finite number");
  return d;
}

template <size_t N>
std::array<double, N> numberArray(const Json& v, const std::string& field, const char* unit, const Where& w) {
  const std::string expected = "expected an array of " + std::to_string(N) + " numbers (" + unit + ")";
  if (!v.is_array()) w.fail(field, expected + ", " + got(v));
  if (v.size() != N) w.fail(field, expected + ", got " + std::to_string(v.size()) + " elements");
  std::array<double, N> out{};
  for (size_t i = 0; i < N; ++i) out[i] = finiteNumber(v[i], field + "[" + std::to_string(i) + "]", w);
  return out;
}

int integerIn(const Json& v, const std::string& field, long lo, long hi, const Where& w) {
  const double d = finiteNumber(v, field, w);
  if (d != std::floor(d) || d < double(lo) || d > double(hi))
    w.fail(field, "expected a whole number in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], got " +
                      std::to_string(d));
  return int(d);
}

bool boolean(const Json& v, const std::string& field, const Where& w) {
  if (!v.is_boolean()) w.fail(field, "expected true or false, " + got(v));
  return v.get<bool>();
}

Target targetFrom(const Json& v, const std::string& field, const model::RobotSpec& spec, const Where& w) {
  if (!v.is_object()) w.fail(field, "expected an object with \"q\" and/or \"pose\" + \"psi\", " + got(v));
  refuseUnknown(v, {"q", "pose", "psi"}, field, w);
  Target t;
  if (const Json* q = member(v, "q")) {
    t.q = numberArray<7>(*q, field + ".q", "joint angles in rad", w);
    t.has_q = true;
    if (spec.dof == 6 && t.q[6] != 0) w.fail(field + ".q[6]", "must be 0 on the 6-axis " + std::string(spec.display_name));
  }
  if (const Json* pose = member(v, "pose")) {
    t.pose = numberArray<16>(*pose, field + ".pose", "4x4 row-major homogeneous transform, m", w);
    t.has_pose = true;
    try {
      planning::poseFromRowMajor(t.pose, "pose");
    } catch (const std::invalid_argument& e) {
      w.fail(field + ".pose", std::string("not a homogeneous transform: ") + e.what());
    }
  }
  if (const Json* psi = member(v, "psi")) {
    if (!t.has_pose) w.fail(field + ".psi", "an arm angle needs a \"pose\" beside it");
    t.psi = finiteNumber(*psi, field + ".psi", w);
    t.has_psi = true;
  }
  if (!t.has_q && !t.has_pose) w.fail(field, "needs \"q\" (7 joint angles) or \"pose\" (16 numbers) + \"psi\"");
  return t;
}

Payload payloadFrom(const Json& v, const Where& w) {
  if (!v.is_object()) w.fail("load", "expected an object with \"mass\", \"center\" and \"inertia\", " + got(v));
  refuseUnknown(v, {"mass", "center", "inertia"}, "load", w);
  Payload p;
  p.mass = finiteNumber(require(v, "mass", "load.mass", w), "load.mass", w);
  if (p.mass < 0) w.fail("load.mass", "expected a mass in kg, 0 or more, got " + std::to_string(p.mass));
  p.center = numberArray<3>(require(v, "center", "load.center", w), "load.center", "centre of mass in the flange frame, m", w);
  p.inertia = numberArray<9>(require(v, "inertia", "load.inertia", w), "load.inertia", "3x3 row-major, kg m^2", w);
  return p;
}

double speedFrom(const Json& in, const Where& w) {
  const double s = finiteNumber(require(in, "speed", "speed", w), "speed", w);
  if (!(s > 0 && s <= 1)) w.fail("speed", "expected a speed ratio in (0, 1], got " + std::to_string(s));
  return s;
}

InstructionType typeFrom(const Json& v, const Where& w) {
  if (!v.is_string()) w.fail("type", "expected a string, " + got(v));
  const std::string& name = v.get_ref<const std::string&>();
  for (InstructionType t : {InstructionType::kMoveJ, InstructionType::kMoveL, InstructionType::kMoveC,
                            InstructionType::kWait, InstructionType::kSetDo, InstructionType::kWaitDi,
                            InstructionType::kPath})
    if (name == typeName(t)) return t;
  w.fail("type", "unknown instruction type \"" + name + "\" (known: MOVEJ, MOVEL, MOVEC, PATH, WAIT, SET_DO, WAIT_DI)");
}

int signalFrom(const Json& in, bool output, const model::RobotSpec& spec, const Where& w) {
  const Json& v = require(in, "signal", "signal", w);
  if (!v.is_string()) w.fail("signal", "expected a string, " + got(v));
  const std::string& name = v.get_ref<const std::string&>();
  const int index = output ? doIndex(spec.family, name) : diIndex(spec.family, name);
  if (index < 0)
    w.fail("signal", "unknown signal \"" + name + "\" for the " + std::string(spec.display_name) +
                         " (known: " + knownSignals(spec.family, output) + ")");
  return index;
}

// A PATH's samples: at least kMinPathSamples arrays of 7 finite joint values within the model's range.
// Checked number by number without building field names until one fails (a minute at 1 kHz is
// 420 000 numbers).
std::vector<JointPoint> pathSamplesFrom(const Json& v, double rate_hz, const model::RobotSpec& spec, const Where& w) {
  if (!v.is_array()) w.fail("q", "expected an array of samples, each 7 joint values in rad, " + got(v));
  if (v.size() < kMinPathSamples)
    w.fail("q", "a path needs at least " + std::to_string(kMinPathSamples) + " samples, got " + std::to_string(v.size()));
  std::vector<JointPoint> q(v.size());
  for (size_t k = 0; k < v.size(); ++k) {
    const Json& sample = v[k];
    const std::string field = "q[" + std::to_string(k) + "]";
    if (!sample.is_array() || sample.size() != 7)
      w.fail(field, "expected an array of 7 joint values in rad, " +
                        (sample.is_array() ? "got " + std::to_string(sample.size()) + " elements" : got(sample)));
    for (size_t j = 0; j < 7; ++j) {
      const Json& x = sample[j];
      const double value = x.is_number() ? x.get<double>() : NAN;
      const bool in_range = int(j) < spec.dof ? value >= spec.q_min[j] && value <= spec.q_max[j] : value == 0;
      if (in_range) {
        q[k][j] = value;
        continue;
      }
      const std::string at = field + "[" + std::to_string(j) + "]";
      finiteNumber(x, at, w);  // names a non-number or a non-finite one
      char where[64];
      std::snprintf(where, sizeof where, " (sample %zu, t = %.3f s of the path)", k, double(k) / rate_hz);
      if (int(j) >= spec.dof) w.fail(at, "must be 0 on the 6-axis " + std::string(spec.display_name) + where);
      char range[160];
      std::snprintf(range, sizeof range, "joint %zu at %.4f rad is outside its range [%.4f, %.4f] rad", j + 1, value,
                    spec.q_min[j], spec.q_max[j]);
      w.fail(at, range + std::string(where) + "; record the path again within the joint range");
    }
  }
  return q;
}

Instruction instructionFrom(const Json& in, size_t index, const model::RobotSpec& spec) {
  Where w{"instruction " + std::to_string(index + 1)};
  if (!in.is_object()) w.fail("", "expected an object, " + got(in));
  Instruction out;
  out.type = typeFrom(require(in, "type", "type", w), w);
  w.prefix += std::string(" (") + typeName(out.type) + ")";
  if (const Json* name = member(in, "name")) {
    if (!name->is_string()) w.fail("name", "expected a string, " + got(*name));
    out.name = name->get<std::string>();
  }
  switch (out.type) {
    case InstructionType::kMoveJ:
    case InstructionType::kMoveL:
      refuseUnknown(in, {"type", "name", "target", "speed"}, "", w);
      out.target = targetFrom(require(in, "target", "target", w), "target", spec, w);
      out.speed = speedFrom(in, w);
      break;
    case InstructionType::kMoveC:
      refuseUnknown(in, {"type", "name", "via", "target", "speed"}, "", w);
      out.via = targetFrom(require(in, "via", "via", w), "via", spec, w);
      out.target = targetFrom(require(in, "target", "target", w), "target", spec, w);
      out.speed = speedFrom(in, w);
      break;
    case InstructionType::kWait:
      refuseUnknown(in, {"type", "name", "ms"}, "", w);
      out.ms = integerIn(require(in, "ms", "ms", w), "ms", 0, 3'600'000, w);
      break;
    case InstructionType::kSetDo:
      refuseUnknown(in, {"type", "name", "signal", "value"}, "", w);
      out.signal = signalFrom(in, true, spec, w);
      out.value = boolean(require(in, "value", "value", w), "value", w);
      break;
    case InstructionType::kWaitDi:
      refuseUnknown(in, {"type", "name", "signal", "value", "timeout_ms"}, "", w);
      out.signal = signalFrom(in, false, spec, w);
      out.value = boolean(require(in, "value", "value", w), "value", w);
      out.timeout_ms = integerIn(require(in, "timeout_ms", "timeout_ms", w), "timeout_ms", 1, 3'600'000, w);
      break;
    case InstructionType::kPath: {
      refuseUnknown(in, {"type", "name", "rate_hz", "q", "speed"}, "", w);
      const double rate = finiteNumber(require(in, "rate_hz", "rate_hz", w), "rate_hz", w);
      if (!(rate >= kMinPathRate && rate <= kMaxPathRate))
        w.fail("rate_hz", "expected a sample rate from 1 to 1000 Hz, got " + std::to_string(rate));
      out.path.rate_hz = rate;
      out.path.q = pathSamplesFrom(require(in, "q", "q", w), rate, spec, w);
      out.speed = speedFrom(in, w);
      break;
    }
  }
  return out;
}

Json targetToJson(const Target& t) {
  Json v = Json::object();
  if (t.has_q) v["q"] = t.q;
  if (t.has_pose) v["pose"] = t.pose;
  if (t.has_pose && t.has_psi) v["psi"] = t.psi;
  return v;
}

Json instructionToJson(const Instruction& in, model::RobotFamily family) {
  Json v = Json::object();
  v["type"] = typeName(in.type);
  if (!in.name.empty()) v["name"] = in.name;
  switch (in.type) {
    case InstructionType::kMoveC:
      v["via"] = targetToJson(in.via);
      [[fallthrough]];
    case InstructionType::kMoveJ:
    case InstructionType::kMoveL:
      v["target"] = targetToJson(in.target);
      v["speed"] = in.speed;
      break;
    case InstructionType::kWait:
      v["ms"] = in.ms;
      break;
    case InstructionType::kSetDo:
      v["signal"] = doName(family, in.signal);
      v["value"] = in.value;
      break;
    case InstructionType::kWaitDi:
      v["signal"] = diName(family, in.signal);
      v["value"] = in.value;
      v["timeout_ms"] = in.timeout_ms;
      break;
    case InstructionType::kPath:
      v["rate_hz"] = in.path.rate_hz;
      v["q"] = in.path.q;
      v["speed"] = in.speed;
      break;
  }
  return v;
}

}  // namespace

Program programFromJson(const Json& doc) {
  const Where w;
  if (!doc.is_object()) throw ProgramError("a program is a JSON object with \"format\": \"rci-program\", " + got(doc));
  const Json& format = require(doc, "format", "format", w);
  if (!format.is_string() || format.get_ref<const std::string&>() != kProgramFormat)
    w.fail("format", std::string("expected \"") + kProgramFormat + "\" (this is not an RCI Studio program)");
  const Json& version = require(doc, "version", "version", w);
  const double v = version.is_number() ? version.get<double>() : 0.0;
  if (v != std::floor(v) || v < kOldestProgramVersion || v > kProgramVersion)
    w.fail("version", "unsupported version " + version.dump() + " (this RCI Studio reads versions " + std::to_string(kOldestProgramVersion) +
                          " to " + std::to_string(kProgramVersion) + "); open it with the RCI Studio that saved it");
  if (v < 2)  // the tool and load came with version 2
    refuseUnknown(doc, {"format", "version", "robot", "instructions"}, "", w);
  else
    refuseUnknown(doc, {"format", "version", "robot", "tool", "load", "instructions"}, "", w);
  const Json& robot = require(doc, "robot", "robot", w);
  if (!robot.is_string()) w.fail("robot", "expected a model name string, " + got(robot));
  const model::RobotSpec* spec = model::findRobotSpec(robot.get_ref<const std::string&>());
  if (!spec) {
    std::string known;
    for (const model::RobotSpec& s : model::allRobotSpecs()) known += (known.empty() ? "" : ", ") + std::string(s.name);
    w.fail("robot", "unknown model \"" + robot.get<std::string>() + "\" (known: " + known + ")");
  }
  const Json& list = require(doc, "instructions", "instructions", w);
  if (!list.is_array()) w.fail("instructions", "expected an array, " + got(list));
  Program p;
  p.robot = spec;
  const Json* tool = member(doc, "tool");
  const Json* load = member(doc, "load");
  if ((tool == nullptr) != (load == nullptr))
    w.fail(tool ? "load" : "tool", "missing (a program records its tool and its load together)");
  if (tool) {
    p.tool = numberArray<16>(*tool, "tool", "the TCP in the flange frame, 4x4 row-major homogeneous transform, m", w);
    try {
      planning::poseFromRowMajor(p.tool, "tool");
    } catch (const std::invalid_argument& e) {
      w.fail("tool", std::string("not a homogeneous transform: ") + e.what());
    }
    p.load = payloadFrom(*load, w);
    p.has_tool = true;
  }
  for (size_t i = 0; i < list.size(); ++i) {
    p.instructions.push_back(instructionFrom(list[i], i, *spec));
    if (v < 2 && p.instructions.back().type == InstructionType::kPath)  // PATH came with version 2
      Where{"instruction " + std::to_string(i + 1) + " (PATH)"}.fail(
          "type", "a PATH needs a program of version 2, but the file says \"version\": 1; change it to 2");
  }
  return p;
}

Json programToJson(const Program& program) {
  Json doc = Json::object();
  doc["format"] = kProgramFormat;
  doc["version"] = kProgramVersion;
  doc["robot"] = std::string(program.robot->name);
  if (program.has_tool) {
    doc["tool"] = program.tool;
    Json load = Json::object();
    load["mass"] = program.load.mass;
    load["center"] = program.load.center;
    load["inertia"] = program.load.inertia;
    doc["load"] = std::move(load);
  }
  Json list = Json::array();
  for (const Instruction& in : program.instructions) list.push_back(instructionToJson(in, program.robot->family));
  doc["instructions"] = std::move(list);
  return doc;
}

Program parseProgram(const std::string& text) {
  Json doc;
  try {
    doc = parseJsonText(text);
  } catch (const JsonSyntaxError& e) {
    throw ProgramError(std::string("not valid JSON: ") + e.what());
  }
  return programFromJson(doc);
}

std::string programText(const Program& program) { return jsonText(programToJson(program)); }

Program loadProgram(const std::string& path) {
  const std::string text = readFile(path);
  try {
    return parseProgram(text);
  } catch (const ProgramError& e) {
    throw ProgramError(path + ": " + e.what());
  }
}

void saveProgram(const std::string& path, const Program& program) { writeFileAtomically(path, programText(program)); }

void validateInstruction(const Instruction& instruction, size_t index, const model::RobotSpec& robot) {
  instructionFrom(instructionToJson(instruction, robot.family), index, robot);
}

void requireRobot(const Program& program, const model::RobotSpec& robot) {
  if (program.robot == &robot) return;
  const auto& want = *program.robot;
  const auto& have = robot;
  throw ProgramError("the program was taught for the " + std::string(want.display_name) + " (" +
                     std::string(want.name) + ") but the robot is the " + std::string(have.display_name) + " (" +
                     std::string(have.name) + "); poses and joint angles do not carry over -- teach it again on "
                     "this robot or connect the right one");
}

}  // namespace xmate::teach
