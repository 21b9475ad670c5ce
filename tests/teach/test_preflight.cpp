// SPDX-License-Identifier: Apache-2.0
// Pre-flight and preview without a robot: every problem of a program is reported by instruction
// (unreachable pose, joint and soft limits, safety box for targets and paths, degenerate arcs,
// invalid fields); a clean program gives a TCP polyline per motion; and the executor's time
// scaling ramps with bounded rate and rate change, without overshoot. A PATH is checked sample by
// sample, naming the first offending one by its time, and its lead-in move is announced.
#include <QtTest>

#include <cmath>

#include <xmate/model.h>

#include "demonstration.h"
#include "model/arm_kinematics.h"
#include "model/robot_spec.h"
#include "teach/path.h"
#include "teach/preflight.h"
#include "teach/recording.h"
#include "teach/time_scaling.h"

using namespace xmate;
using namespace xmate::teach;
using teach_test::demonstration;
using teach_test::pathInstruction;

namespace {

const std::array<double, 7> kStart{0.0, 0.5236, 0.0, 1.0472, 0.0, 1.5708, 0.0};  // the simulator's start

// A target holding q and the pose and arm angle it gives.
Target targetAt(const std::array<double, 7>& q) {
  XmateModel model(XMATE7_PRO);
  Target t;
  t.has_q = true;
  t.q = q;
  t.has_pose = true;
  t.pose = model.GetCartPose(q);
  t.has_psi = true;
  t.psi = model.GetPsi(q);
  return t;
}

Target poseOnly(const Target& t) {
  Target p = t;
  p.has_q = false;
  return p;
}

Target shifted(const Target& t, double dx, double dy, double dz) {
  Target p = poseOnly(t);
  p.pose[3] += dx;
  p.pose[7] += dy;
  p.pose[11] += dz;
  return p;
}

TraceOptions fromStart() {
  TraceOptions o;
  o.q_start = kStart;
  return o;
}

QString allMessages(const std::vector<Problem>& problems) { return QString::fromStdString(problemsText(problems)); }

// 2 s from kStart: joint 2 out by 0.6 rad and back, joint 1 across by 0.2 rad.
JointPath raisingPath() { return demonstration(kStart, {0, 0.6, 0, 0, 0, 0, 0}, {0.2, 0, 0, 0, 0, 0, 0}, 2.0); }

Program pathProgram(const JointPath& path, const std::string& name = "wipe") {
  Program p;
  p.instructions.push_back(pathInstruction(path, 1.0, name));
  return p;
}

// The first sample whose joint 2 is above `limit`.
size_t firstAbove(const JointPath& path, double limit) {
  size_t k = 0;
  while (k < path.q.size() && path.q[k][1] <= limit) ++k;
  return k;
}

// "at t = 0.420 s of the path (sample 42): ": how the pre-flight names a sample of a 100 Hz path.
QString atSample(size_t k) {
  return QString("at t = %1 s of the path (sample %2): ").arg(double(k) / 100, 0, 'f', 3).arg(k);
}

}  // namespace

class TestPreflight : public QObject {
  Q_OBJECT

 private slots:
  void cleanProgramPassesWithAPreview();
  void everyProblemIsReportedByInstruction();
  void safetyBoxTargetsAndPaths();
  void softLimits();
  void invalidFieldsOfAProgramBuiltInMemory();
  void timeScalingRampsWithinItsBounds();
  void toolOfTheProgramMustMatchTheRobot();
  void firstRecordingAdoptsTheRobotsTool();
  void pathIsTracedAndItsLeadInAnnounced();
  void pathSamplesBeyondALimitAreNamedByTime();
  void pathOutsideTheBoxIsNamedByTime();
  void pathTooFastForAnyTimingIsAProblem();
};

void TestPreflight::cleanProgramPassesWithAPreview() {
  const Target home = targetAt(kStart);
  Program p;
  p.instructions.push_back(moveJ(targetAt({0.2, 0.4, 0.1, 1.3, 0.0, 1.3, 0.2}), 0.5, "P1"));
  p.instructions.push_back(moveL(shifted(home, 0.0, 0.05, -0.1), 0.3));
  const Target l = shifted(home, 0.0, 0.05, -0.1);
  p.instructions.push_back(moveC(shifted(l, 0.05, 0.05, 0.0), shifted(l, 0.0, 0.1, 0.0), 0.3));
  const ProgramTrace trace = traceProgram(p, fromStart());
  QVERIFY2(trace.problems.empty(), qPrintable(allMessages(trace.problems)));
  QCOMPARE(trace.instructions.size(), size_t(3));
  for (const InstructionTrace& t : trace.instructions) {
    QVERIFY(t.traced);
    QVERIFY(t.tcp_path.size() >= 3);
  }
  // The arc's polyline ends at its target and passes near the via point.
  const auto& arc = trace.instructions[2].tcp_path;
  const Target target = shifted(l, 0.0, 0.1, 0.0), via = shifted(l, 0.05, 0.05, 0.0);
  QVERIFY(std::abs(arc.back()[1] - target.pose[7]) < 1e-9);
  double closest = 1;
  for (const auto& pt : arc)
    closest = std::min(closest, std::hypot(pt[0] - via.pose[3], pt[1] - via.pose[7], pt[2] - via.pose[11]));
  QVERIFY(closest < 2e-3);
  // The 3D view's shortcut gives the same polylines; a non-motion has none.
  Instruction wait;
  wait.type = InstructionType::kWait;
  p.instructions.push_back(wait);
  const auto paths = plannedPath(p, kStart);
  QCOMPARE(paths.size(), size_t(4));
  QCOMPARE(paths[2], arc);
  QVERIFY(paths[3].empty());
}

void TestPreflight::everyProblemIsReportedByInstruction() {
  const Target home = targetAt(kStart);
  Program p;
  p.instructions.push_back(moveL(shifted(home, 0.0, 0.0, -0.05), 0.3, "ok"));
  p.instructions.push_back(moveL(shifted(home, 2.0, 0.0, 0.0), 0.3, "far"));           // unreachable
  Target beyond = targetAt(kStart);
  beyond.has_pose = false;
  beyond.q[1] = 2.5;                                                                    // J2 beyond 120 deg
  p.instructions.push_back(moveJ(beyond, 0.3, "limit"));
  const Target l = shifted(home, 0.0, 0.0, -0.05);
  p.instructions.push_back(moveC(shifted(l, 0.0, 0.0, -0.02), shifted(l, 0.0, 0.0, -0.04), 0.3, "line"));  // collinear
  p.instructions.push_back(moveJ(shifted(home, 0.0, 0.0, 3.0), 0.3, "high"));          // IK of a pose out of reach
  const std::vector<Problem> problems = preflight(p, fromStart());
  const QString text = allMessages(problems);
  QCOMPARE(problems.size(), size_t(4));
  QCOMPARE(problems[0].instruction, size_t(1));
  QVERIFY2(text.contains("instruction 2 (MOVEL \"far\"): the path cannot be followed"), qPrintable(text));
  QVERIFY2(text.contains("beyond the arm's reach"), qPrintable(text));
  QVERIFY2(text.contains("instruction 3 (MOVEJ \"limit\"): the target: joint 2 at 2.5000 rad"), qPrintable(text));
  QVERIFY2(text.contains("instruction 4 (MOVEC \"line\"): MOVEC: start, via and target are collinear"), qPrintable(text));
  QVERIFY2(text.contains("instruction 5 (MOVEJ \"high\"): the target pose cannot be reached"), qPrintable(text));
}

void TestPreflight::safetyBoxTargetsAndPaths() {
  const Target home = targetAt(kStart);
  TraceOptions o = fromStart();
  o.has_box = true;
  o.box.size = {0.6, 0.6, 0.4};
  o.box.frame = kIdentityPose;
  o.box.frame[3] = home.pose[3];
  o.box.frame[7] = home.pose[7];
  o.box.frame[11] = home.pose[11];  // centred on the start TCP: +-0.3 m in x, y, +-0.2 m in z
  Program p;
  p.instructions.push_back(moveL(shifted(home, 0.0, 0.0, -0.1), 0.3, "inside"));
  p.instructions.push_back(moveL(shifted(home, 0.0, 0.0, -0.25), 0.3, "below"));  // target out of the box
  // An arc from (z - 0.1) through a via far out in y back to a target inside: the path leaves.
  const Target l = shifted(home, 0.0, 0.0, -0.1);
  p.instructions.push_back(moveC(shifted(l, 0.0, 0.2, 0.0), shifted(l, 0.0, 0.0, 0.15), 0.3, "bulge"));
  const std::vector<Problem> problems = preflight(p, o);
  const QString text = allMessages(problems);
  QCOMPARE(problems.size(), size_t(2));
  QVERIFY2(text.contains("instruction 2 (MOVEL \"below\"): the target (") && text.contains("outside the Cartesian safety box"),
           qPrintable(text));
  QVERIFY2(text.contains("instruction 3 (MOVEC \"bulge\"): the path leaves the Cartesian safety box"), qPrintable(text));
}

void TestPreflight::softLimits() {
  TraceOptions o = fromStart();
  o.has_soft_limits = true;
  for (int j = 0; j < 7; ++j) {
    o.soft_lower[j] = -1.0;
    o.soft_upper[j] = 1.6;
  }
  Target t = targetAt(kStart);
  t.q[0] = 1.2;
  Program ok;
  ok.instructions.push_back(moveJ(t, 0.3));
  QVERIFY(preflight(ok, o).empty());
  o.soft_upper[0] = 1.0;
  const std::vector<Problem> problems = preflight(ok, o);
  QCOMPARE(problems.size(), size_t(1));
  QVERIFY2(allMessages(problems).contains("joint 1 at 68.75 deg is outside its soft limits"), qPrintable(allMessages(problems)));
  // Soft limits that make no sense are a problem of their own, not a crash.
  o.soft_lower[0] = 1.2;
  const std::vector<Problem> bad = preflight(ok, o);
  QCOMPARE(bad.size(), size_t(1));
  QVERIFY2(allMessages(bad).contains("the pre-flight cannot start"), qPrintable(allMessages(bad)));
}

void TestPreflight::invalidFieldsOfAProgramBuiltInMemory() {
  Program p;
  Target t = targetAt(kStart);
  t.q[3] = NAN;
  t.has_pose = false;
  p.instructions.push_back(moveJ(t, 0.3));
  p.instructions.push_back(moveJ(targetAt(kStart), 1.7));
  Instruction wait;
  wait.type = InstructionType::kWaitDi;
  wait.signal = 9;
  wait.timeout_ms = 100;
  p.instructions.push_back(wait);
  const std::vector<Problem> problems = preflight(p, fromStart());
  const QString text = allMessages(problems);
  QCOMPARE(problems.size(), size_t(3));
  QVERIFY2(text.contains("instruction 1 (MOVEJ), field \"target.q[3]\": not a finite number"), qPrintable(text));
  QVERIFY2(text.contains("instruction 2 (MOVEJ), field \"speed\""), qPrintable(text));
  QVERIFY2(text.contains("instruction 3 (WAIT_DI), field \"signal\": unknown signal"), qPrintable(text));
}

void TestPreflight::timeScalingRampsWithinItsBounds() {
  const double dt = 1e-3;
  const double rate = safeScalingRate(0.8, 7.5 / 2.175);  // full speed, the xMate Pro's J2
  QVERIFY(rate > 0.7 && rate < 0.8);
  QCOMPARE(safeScalingRate(0.05, 10), TimeScaling::kMaxRate);
  TimeScaling k(1.0, rate);
  k.setTarget(0.0);
  double previous = k.value(), previous_rate = 0;
  int steps = 0;
  while (!k.settled() && steps < 10000) {
    k.step(dt);
    const double slope = (k.value() - previous) / dt;
    QVERIFY(k.value() <= previous);  // monotone, never below the target
    QVERIFY(k.value() >= 0);
    QVERIFY(std::abs(slope) <= rate * (1 + 1e-9));
    // The rate changes by at most kRateChange * dt per step (the final snap to rest at most twice).
    QVERIFY2(std::abs(slope - previous_rate) <= 2 * TimeScaling::kRateChange * dt + 1e-12,
             qPrintable(QString("step %1: rate %2 -> %3").arg(steps).arg(previous_rate).arg(slope)));
    previous = k.value();
    previous_rate = slope;
    ++steps;
  }
  QCOMPARE(k.value(), 0.0);
  const double seconds = steps * dt;
  qInfo("time scaling 1 -> 0 in %.3f s", seconds);
  QVERIFY(seconds > 1.0 / rate && seconds < 1.0 / rate + 2 * rate / TimeScaling::kRateChange);
  // Back up to an override of 0.4, then down to 0.1 on the way: no overshoot.
  k.setTarget(0.4);
  for (int i = 0; i < 400; ++i) k.step(dt);
  k.setTarget(0.1);
  double highest = 0;
  for (int i = 0; i < 5000; ++i) {
    k.step(dt);
    highest = std::max(highest, k.value());
  }
  QVERIFY(highest <= 0.4 + 1e-12);
  QCOMPARE(k.value(), 0.1);
}


namespace {

// A 4x4 row-major tool: `dz` m along the flange's z axis, turned `rz` rad about it.
std::array<double, 16> toolAt(double dz, double rz = 0) {
  const double c = std::cos(rz), s = std::sin(rz);
  return {c, -s, 0, 0, s, c, 0, 0, 0, 0, 1, dz, 0, 0, 0, 1};
}

// The measured TCP at q with `tool` on the flange.
std::array<double, 16> tcpWith(const std::array<double, 16>& tool, const std::array<double, 7>& q) {
  XmateModel model(XMATE7_PRO);
  model.SetCoor(tool);
  return model.GetCartPose(q);
}

}  // namespace

void TestPreflight::toolOfTheProgramMustMatchTheRobot() {
  Program p;
  p.has_tool = true;
  p.tool = toolAt(0.1);
  p.instructions.push_back(moveJ(targetAt({0.2, 0.4, 0.1, 1.3, 0.0, 1.3, 0.2}), 0.5, "by joints"));
  XmateModel with_tool(XMATE7_PRO);
  with_tool.SetCoor(p.tool);
  Target here;
  here.has_pose = true;
  here.pose = with_tool.GetCartPose(kStart);
  p.instructions.push_back(moveL(here, 0.3, "line"));
  p.instructions.push_back(moveL(here, 0.3, "line again"));
  TraceOptions o = fromStart();
  o.has_tcp = true;

  o.tcp = tcpWith(p.tool, kStart);  // the robot carries the program's tool
  QVERIFY2(preflight(p, o).empty(), qPrintable(allMessages(preflight(p, o))));
  o.tcp = tcpWith(toolAt(0.1005, 0.005), kStart);  // within 1 mm and 0.5 deg
  QVERIFY2(preflight(p, o).empty(), qPrintable(allMessages(preflight(p, o))));

  o.tcp = tcpWith(toolAt(0.2), kStart);  // another tool: 100 mm longer
  std::vector<Problem> problems = preflight(p, o);
  QCOMPARE(problems.size(), size_t(1));  // once, at the first instruction that uses the tool
  QCOMPARE(problems[0].instruction, size_t(1));
  QVERIFY2(problems[0].message.find("instruction 2 (MOVEL") == 0, problems[0].message.c_str());
  QVERIFY2(problems[0].message.find("100.0 mm") != std::string::npos, problems[0].message.c_str());
  QVERIFY2(problems[0].message.find("x, y, z = 0.0000, 0.0000, 0.1000 m") != std::string::npos, problems[0].message.c_str());
  o.tcp = tcpWith(toolAt(0.1, 0.02), kStart);  // turned 1.1 deg
  problems = preflight(p, o);
  QCOMPARE(problems.size(), size_t(1));
  QVERIFY2(problems[0].message.find("1.1 deg away") != std::string::npos, problems[0].message.c_str());

  // A program without a recorded tool, or one that moves by joints only, needs no check.
  Program joints_only = p;
  joints_only.instructions.resize(1);
  QVERIFY(preflight(joints_only, o).empty());
  Program untooled = p;
  untooled.has_tool = false;
  untooled.tool = kIdentityPose;
  o.tool = p.tool;  // the pre-flight then takes the robot's tool
  QVERIFY2(preflight(untooled, o).empty(), qPrintable(allMessages(preflight(untooled, o))));
}

void TestPreflight::firstRecordingAdoptsTheRobotsTool() {
  RCI::robot::RobotState state{};
  state.q = kStart;
  const Payload load{0.8, {0, 0, 0.05}, {0.002, 0, 0, 0, 0.002, 0, 0, 0, 0.001}};

  // The first pose of an empty program: the robot's tool and load become the program's.
  Program p;
  state.toolTobase_pos_m = tcpWith(toolAt(0.12), kStart);
  QCOMPARE(adoptTool(p, state, toolAt(0.12), load), std::string());
  QVERIFY(p.has_tool);
  QCOMPARE(p.tool, toolAt(0.12));
  QCOMPARE(p.load.mass, 0.8);
  QCOMPARE(p.load.center, load.center);
  p.instructions.push_back(moveJ(targetFromState(state, XMATE7_PRO), 0.5));

  // Later poses with the same tool are fine; with another one they are refused, the program kept.
  QCOMPARE(adoptTool(p, state, toolAt(0.12), load), std::string());
  state.toolTobase_pos_m = tcpWith(toolAt(0.05), kStart);
  const std::string refused = adoptTool(p, state, toolAt(0.05), Payload{});
  QVERIFY2(refused.find("70.0 mm") != std::string::npos, refused.c_str());
  QCOMPARE(p.tool, toolAt(0.12));
  QCOMPARE(p.load.mass, 0.8);

  // A tool the client did not set (the pendant, another program): taken from the measured TCP.
  Program fresh;
  const std::string none = adoptTool(fresh, state, kIdentityPose, Payload{});
  QVERIFY2(none.empty(), none.c_str());
  QVERIFY(fresh.has_tool);
  for (size_t i = 0; i < 16; ++i) QVERIFY2(std::abs(fresh.tool[i] - toolAt(0.05)[i]) < 1e-9, qPrintable(QString::number(i)));

  // A program taught before tools were recorded stays without one.
  Program old;
  old.instructions.push_back(moveJ(targetFromState(state, XMATE7_PRO), 0.5));
  QCOMPARE(adoptTool(old, state, toolAt(0.05), load), std::string());
  QVERIFY(!old.has_tool);
}

// A clean PATH: traced with the TCP of every sample (the 3D view's trace), ending at its last
// sample; starting elsewhere, the joint move to its start is announced, not a problem.
void TestPreflight::pathIsTracedAndItsLeadInAnnounced() {
  const JointPath path = raisingPath();
  const Program here = pathProgram(path);
  ProgramTrace trace = traceProgram(here, fromStart());
  QVERIFY2(trace.problems.empty(), qPrintable(allMessages(trace.problems)));
  QVERIFY(trace.notices.empty());
  QVERIFY(trace.instructions[0].traced);
  QCOMPARE(trace.instructions[0].q_end, path.q.back());
  QCOMPARE(trace.instructions[0].tcp_path, tcpTrace(path, model::robotSpec(XMATE7_PRO), kIdentityPose));

  TraceOptions elsewhere = fromStart();
  elsewhere.q_start[0] -= 0.3;
  elsewhere.q_start[3] += 0.1;
  trace = traceProgram(here, elsewhere);
  QVERIFY2(trace.problems.empty(), qPrintable(allMessages(trace.problems)));
  QCOMPARE(trace.notices.size(), size_t(1));
  QCOMPARE(trace.notices[0].message, std::string("instruction 1 (PATH \"wipe\"): first moves to the start of the path with "
                                                 "a joint move (largest joint change 17.2 deg)"));
  // A lead-in that would leave the safety box is a problem: the box holds the path, not the way there.
  elsewhere.q_start[0] = kStart[0] - 1.5;
  elsewhere.has_box = true;
  elsewhere.box.size = {0.8, 0.8, 0.8};
  const std::array<double, 16> start_tcp = XmateModel(XMATE7_PRO).GetCartPose(kStart);
  elsewhere.box.frame[3] = start_tcp[3];
  elsewhere.box.frame[7] = start_tcp[7];
  elsewhere.box.frame[11] = start_tcp[11];
  trace = traceProgram(here, elsewhere);
  QCOMPARE(trace.problems.size(), size_t(1));
  QVERIFY2(allMessages(trace.problems)
               .startsWith("instruction 1 (PATH \"wipe\"): the joint move to the start of the path leaves the Cartesian "
                           "safety box at ("),
           qPrintable(allMessages(trace.problems)));
}

// Soft limits and the joints a session can reach (a KUKA's correction limits): the first sample
// beyond each is named by its time in the path; a sample beyond the joint range is refused as the
// program file would refuse it, naming the sample and its time too.
void TestPreflight::pathSamplesBeyondALimitAreNamedByTime() {
  const JointPath path = raisingPath();
  TraceOptions o = fromStart();
  o.has_soft_limits = true;
  for (int j = 0; j < 7; ++j) {
    o.soft_lower[j] = -2.0;
    o.soft_upper[j] = 2.0;
  }
  o.soft_upper[1] = 0.9;
  std::vector<Problem> problems = preflight(pathProgram(path), o);
  QCOMPARE(problems.size(), size_t(1));
  size_t k = firstAbove(path, 0.9);
  QVERIFY(k > 0 && k < path.q.size());
  QString expected = "instruction 1 (PATH \"wipe\"): " + atSample(k) +
                     QString("joint 2 at %1 deg is outside its soft limits [-114.59, 51.57] deg").arg(path.q[k][1] * 180 / M_PI, 0, 'f', 2);
  QVERIFY2(allMessages(problems).startsWith(expected), qPrintable(allMessages(problems) + "\nexpected: " + expected));

  TraceOptions bounds = fromStart();
  bounds.has_joint_bounds = true;
  for (int j = 0; j < 7; ++j) {
    bounds.joint_lower[j] = -2.0;
    bounds.joint_upper[j] = 2.0;
  }
  bounds.joint_upper[1] = 1.0;
  problems = preflight(pathProgram(path), bounds);
  QCOMPARE(problems.size(), size_t(1));
  k = firstAbove(path, 1.0);
  expected = "instruction 1 (PATH \"wipe\"): " + atSample(k) + "joint 2 at ";
  QVERIFY2(allMessages(problems).startsWith(expected) && allMessages(problems).contains("outside what this session can reach"),
           qPrintable(allMessages(problems) + "\nexpected: " + expected));

  // Beyond joint 2's 120 deg: refused as the file format refuses it.
  const JointPath beyond = demonstration(kStart, {0, 1.8, 0, 0, 0, 0, 0}, {}, 2.0);
  problems = preflight(pathProgram(beyond), fromStart());
  QCOMPARE(problems.size(), size_t(1));
  k = firstAbove(beyond, model::robotSpec(XMATE7_PRO).q_max[1]);
  const QString text = allMessages(problems);
  QVERIFY2(text.startsWith("instruction 1 (PATH") &&
               text.contains(QString("(sample %1, t = %2 s of the path)").arg(k).arg(double(k) / 100, 0, 'f', 3)),
           qPrintable(text));
}

// The TCP (by forward kinematics with the program's tool) of the first sample outside the box.
void TestPreflight::pathOutsideTheBoxIsNamedByTime() {
  const JointPath path = raisingPath();
  model::ArmKinematics fk(model::robotSpec(XMATE7_PRO));
  // The box's edge halfway along the path's largest excursion of the TCP from its start (x, y or z).
  const std::array<double, 16> start = fk.GetCartPose(kStart);
  int axis = 0;
  double excursion = 0;
  for (const JointPoint& q : path.q) {
    const std::array<double, 16> p = fk.GetCartPose(q);
    for (int a = 0; a < 3; ++a)
      if (std::abs(p[4 * a + 3] - start[4 * a + 3]) > std::abs(excursion)) {
        axis = a;
        excursion = p[4 * a + 3] - start[4 * a + 3];
      }
  }
  QVERIFY2(std::abs(excursion) > 0.05, "the path's TCP hardly moves");
  const double edge = start[4 * axis + 3] + excursion / 2;
  TraceOptions o = fromStart();
  o.has_box = true;
  o.box.size = {2, 2, 2};
  for (int a = 0; a < 3; ++a) o.box.frame[4 * a + 3] = start[4 * a + 3];
  o.box.frame[4 * axis + 3] = edge - std::copysign(1.0, excursion);
  size_t k = 0;
  while (k < path.q.size() && std::abs(fk.GetCartPose(path.q[k])[4 * axis + 3] - start[4 * axis + 3]) <= std::abs(excursion) / 2)
    ++k;
  const std::vector<Problem> problems = preflight(pathProgram(path), o);
  QCOMPARE(problems.size(), size_t(1));
  const QString expected = "instruction 1 (PATH \"wipe\"): " + atSample(k) + "the TCP at (";
  QVERIFY2(allMessages(problems).startsWith(expected) && allMessages(problems).contains("outside the Cartesian safety box"),
           qPrintable(allMessages(problems) + "\nexpected: " + expected));
}

// Two samples 1 ms apart and 1 rad apart: no timing within the limits exists.
void TestPreflight::pathTooFastForAnyTimingIsAProblem() {
  JointPath jump;
  jump.rate_hz = 1000;
  jump.q = {kStart, kStart};
  jump.q[1][0] += 1.0;
  const std::vector<Problem> problems = preflight(pathProgram(jump, "jump"), fromStart());
  QCOMPARE(problems.size(), size_t(1));
  QVERIFY2(allMessages(problems).startsWith("instruction 1 (PATH \"jump\"): "), qPrintable(allMessages(problems)));
}

int runPreflightTests(int argc, char** argv) {
  TestPreflight t;
  return QTest::qExec(&t, argc, argv);
}

#include "test_preflight.moc"
