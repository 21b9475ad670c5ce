// SPDX-License-Identifier: Apache-2.0
// Demonstrated paths without a robot: the spline through the samples, trimming rest, the reduction
// of a 1 kHz recording within 0.1 mrad (and a minute of it well under 1 MB of program file), the
// recorder's lost cycles and sessions, re-timing within the joint limits at any speed (slowed where
// the demonstration is too fast, the geometry kept), the deviation measure, and the PATH fields of
// the program file with every kind of corrupt value named by instruction and field.
#include <QtTest>

#include <cmath>
#include <numbers>

#include "model/arm_kinematics.h"
#include "teach/path.h"
#include "teach/path_timing.h"
#include "teach/program_io.h"

using namespace xmate;
using namespace xmate::teach;

namespace {

const model::RobotSpec& pro7() { return model::robotSpec(XMATE7_PRO); }

// A hand-guided motion: from rest, joints swinging with a few sines (peak speeds ~0.3..0.8 rad/s),
// back to rest; `rest` seconds still at both ends. `scale` multiplies the speed.
std::vector<JointPoint> demonstration(double seconds, double rate, double rest = 0.5, double scale = 1.0) {
  std::vector<JointPoint> q;
  const size_t n = size_t(std::lround((seconds + 2 * rest) * rate)) + 1;
  for (size_t k = 0; k < n; ++k) {
    const double t = std::clamp(double(k) / rate - rest, 0.0, seconds);
    // s(t): 0 -> 1 with zero speed and acceleration at both ends, so the motion starts from rest.
    const double x = t / seconds, s = x * x * x * (10 - 15 * x + 6 * x * x);
    const double w = 2 * std::numbers::pi * s * seconds / 4 * scale;  // ~ one swing per 4 s
    q.push_back({0.3 * std::sin(w), 0.4 + 0.25 * std::sin(0.7 * w), 0.2 * std::cos(1.3 * w) - 0.2,
                 1.2 + 0.3 * std::sin(0.5 * w), 0.1 * std::sin(1.1 * w), 0.9 + 0.2 * std::sin(0.9 * w), 0.15 * s});
  }
  return q;
}

// The largest |finite difference| / rated limit over a timing: velocity, acceleration, jerk.
std::array<double, 3> limitRatios(const PathTiming& timing, const model::RobotSpec& spec) {
  std::array<double, 3> worst{};
  const auto& q = timing.q;
  const double dt = timing.step;
  for (size_t k = 0; k + 3 < q.size(); ++k)
    for (int j = 0; j < spec.dof; ++j) {
      const size_t d = size_t(j);
      const double v = (q[k + 1][d] - q[k][d]) / dt;
      const double a = (q[k + 2][d] - 2 * q[k + 1][d] + q[k][d]) / (dt * dt);
      const double jerk = (q[k + 3][d] - 3 * q[k + 2][d] + 3 * q[k + 1][d] - q[k][d]) / (dt * dt * dt);
      worst[0] = std::max(worst[0], std::abs(v) / spec.dq_max[d]);
      worst[1] = std::max(worst[1], std::abs(a) / spec.ddq_max[d]);
      worst[2] = std::max(worst[2], std::abs(jerk) / spec.jerk_max[d]);
    }
  return worst;
}

Program pathProgram(const JointPath& path) {
  Program p;
  p.robot = &pro7();
  Instruction in;
  in.type = InstructionType::kPath;
  in.name = "wipe";
  in.path = path;
  in.speed = 1.0;
  p.instructions.push_back(in);
  return p;
}

// The program text of a two-sample PATH with `replace` substituted for `what`.
std::string corruptPath(const std::string& what, const std::string& replace, int version = 2) {
  std::string text = R"({"format": "rci-program", "version": )" + std::to_string(version) +
                     R"(, "robot": "xmate7_pro", "instructions": [
    {"type": "MOVEJ", "target": {"q": [0, 0, 0, 0, 0, 0, 0]}, "speed": 0.5},
    {"type": "PATH", "name": "wipe", "rate_hz": 100,
     "q": [[0, 0.1, 0, 1, 0, 1, 0], [0.001, 0.1, 0, 1, 0, 1, 0], [0.002, 0.1, 0, 1, 0, 1, 0]], "speed": 1.0}]})";
  if (!what.empty()) {
    const size_t at = text.find(what);
    if (at == std::string::npos) throw std::logic_error("corruptPath: no " + what);
    text.replace(at, what.size(), replace);
  }
  return text;
}

}  // namespace

class TestPath : public QObject {
  Q_OBJECT
 private slots:
  void splineInterpolatesWithContinuousDerivatives() {
    std::vector<JointPoint> q;
    for (int k = 0; k <= 100; ++k) q.push_back({std::sin(0.05 * k), 0.01 * k, 0, 0, 0, 0, 0});
    const PathSpline spline(q, 100, 7);
    QCOMPARE(spline.duration(), 1.0);
    for (int k = 0; k <= 100; k += 7) QVERIFY(std::abs(spline.at(k / 100.0)[0] - q[size_t(k)][0]) < 1e-12);
    // sin(5 t): the derivatives agree inside (natural ends bend the first and last intervals).
    JointPoint p, d, dd;
    spline.evaluate(0.5, p, &d, &dd);
    QVERIFY2(std::abs(d[0] - 5 * std::cos(2.5)) < 1e-3, qPrintable(QString::number(d[0])));
    QVERIFY(std::abs(dd[0] + 25 * std::sin(2.5)) < 0.05);
    QVERIFY(std::abs(d[1] - 1.0) < 1e-9);
    // Continuity across a knot.
    JointPoint before, after, d0, d1, a0, a1;
    spline.evaluate(0.3 - 1e-9, before, &d0, &a0);
    spline.evaluate(0.3 + 1e-9, after, &d1, &a1);
    QVERIFY(std::abs(d0[0] - d1[0]) < 1e-6 && std::abs(a0[0] - a1[0]) < 1e-5);
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, PathSpline(std::vector<JointPoint>(1), 100, 7));
  }

  void restIsTrimmedAtBothEnds() {
    const std::vector<JointPoint> q = demonstration(3.0, 1000, 1.0);
    const ActiveSpan span = activeSpan(q, 1000, 7);
    QVERIFY(span.moved());
    // 1 s of rest each side; the smooth start only reaches 5 mrad/s a little after it.
    QVERIFY2(span.first > 900 && span.first < 1150, qPrintable(QString::number(span.first)));
    QVERIFY2(span.last > q.size() - 1150 && span.last < q.size() - 900, qPrintable(QString::number(span.last)));
    const std::vector<JointPoint> still(500, JointPoint{0.1, 0.2});
    QVERIFY(!activeSpan(still, 1000, 7).moved());
  }

  void aMinuteAt1kHzIsStoredAt100HzWithin0p1mradAndUnder1MB() {
    const std::vector<JointPoint> q = demonstration(60.0, 1000, 0.0);
    const Reduction r = reducePath(q, 1000, 7);
    QCOMPARE(r.path.rate_hz, 100.0);
    QVERIFY2(r.max_error <= kPathTolerance, qPrintable(QString::number(r.max_error)));
    QVERIFY(std::abs(r.path.duration() - 60.0) < 0.011);
    // Every stored value is a whole number of micro-radians.
    for (const JointPoint& p : r.path.q)
      for (double v : p) QVERIFY(std::abs(v * 1e6 - std::round(v * 1e6)) < 1e-6);
    const std::string text = programText(pathProgram(r.path));
    QVERIFY2(text.size() < 700'000, qPrintable(QString::number(text.size())));
    // And it reads back to the same samples.
    const Program back = parseProgram(text);
    QCOMPARE(back.instructions.front().path.q.size(), r.path.q.size());
    QCOMPARE(back.instructions.front().path.q[123], r.path.q[123]);
  }

  void aFastJerkyRecordingNeedsAHigherRate() {
    std::vector<JointPoint> q;
    for (int k = 0; k <= 2000; ++k) q.push_back({0.02 * std::sin(2 * std::numbers::pi * 20 * k / 1000.0)});
    const Reduction r = reducePath(q, 1000, 7);
    QVERIFY2(r.path.rate_hz > 100, qPrintable(QString::number(r.path.rate_hz)));
    QVERIFY(r.max_error <= kPathTolerance);
  }

  void recorderCountsLostCyclesAndStopsAtANewSession() {
    PathRecorder recorder(pro7(), 1e-3);
    const std::vector<JointPoint> q = demonstration(1.0, 1000, 0.2);
    arm::ArmSample s;
    s.session = 1;
    for (size_t k = 0; k < q.size(); ++k) {
      if (k >= 400 && k < 405) continue;  // five cycles the ring lost
      s.cycle = 1000 + k;
      s.q = q[k];
      recorder.add(s);
    }
    QCOMPARE(recorder.lostCycles(), uint64_t(5));
    QCOMPARE(recorder.samples(), q.size());  // bridged
    QVERIFY(std::abs(recorder.raw()[402][0] - q[402][0]) < 1e-4);
    s.session = 2;
    s.cycle = 5;
    recorder.add(s);
    QVERIFY(recorder.sessionChanged());
    QCOMPARE(recorder.samples(), q.size());
    const PathRecorder::Result r = recorder.finish();
    QCOMPARE(r.lost_cycles, uint64_t(5));
    QVERIFY(r.trimmed_start > 0.1 && r.trimmed_end > 0.1);
    QVERIFY(r.path.duration() > 0.9 && r.path.duration() < 1.2);

    PathRecorder still(pro7(), 1e-3);
    s.session = 1;
    for (int k = 0; k < 300; ++k) {
      s.cycle = uint64_t(k);
      still.add(s);
    }
    try {
      still.finish();
      QFAIL("a recording without motion was accepted");
    } catch (const std::runtime_error& e) {
      QVERIFY2(std::string(e.what()).find("did not move") != std::string::npos, e.what());
    }
  }

  void timingStaysWithinTheLimitsAtEverySpeed() {
    const Reduction r = reducePath(demonstration(4.0, 1000, 0.0), 1000, 7);
    const PathSpline spline(r.path, 7);
    for (double speed : {1.0, 0.5, 0.1}) {
      const PathTiming timing = timePath(spline, pro7(), speed);
      const std::array<double, 3> ratio = limitRatios(timing, pro7());
      QVERIFY2(ratio[0] <= 0.9 && ratio[1] <= 0.9 && ratio[2] <= 0.9,
               qPrintable(QString("speed %1: %2 %3 %4").arg(speed).arg(ratio[0]).arg(ratio[1]).arg(ratio[2])));
      // The demonstrated pace: only the ramps at the ends add time.
      QCOMPARE(timing.slowest, 1.0);
      QVERIFY2(timing.duration >= timing.nominal_duration && timing.duration < timing.nominal_duration * 1.1 + 0.5,
               qPrintable(QString("%1 vs %2").arg(timing.duration).arg(timing.nominal_duration)));
      // From the first sample to the last, at rest at both ends, path time never going back.
      QCOMPARE(timing.path_time.front(), 0.0);
      QCOMPARE(timing.path_time.back(), spline.duration());
      for (size_t k = 1; k < timing.path_time.size(); ++k) QVERIFY(timing.path_time[k] >= timing.path_time[k - 1]);
      QVERIFY(std::abs(timing.q[1][0] - timing.q[0][0]) < 1e-6);
      const size_t n = timing.q.size();
      QVERIFY(std::abs(timing.q[n - 1][0] - timing.q[n - 2][0]) < 1e-6);
    }
  }

  void aDemonstrationTooFastIsSlowedNotClipped() {
    // The same motion three times as fast: joint 1 peaks well above its rated speed.
    const Reduction r = reducePath(demonstration(4.0, 1000, 0.0, 12.0), 1000, 7);
    const PathSpline spline(r.path, 7);
    const PathTiming timing = timePath(spline, pro7(), 1.0);
    QVERIFY2(timing.slowest < 0.9, qPrintable(QString::number(timing.slowest)));
    QVERIFY(timing.slowed_share > 0 && timing.duration > timing.nominal_duration);
    const std::array<double, 3> ratio = limitRatios(timing, pro7());
    QVERIFY2(ratio[0] <= 0.9 && ratio[1] <= 0.9 && ratio[2] <= 0.9,
             qPrintable(QString("%1 %2 %3").arg(ratio[0]).arg(ratio[1]).arg(ratio[2])));
    // The geometry is kept: every replayed sample is the path at its path time.
    for (size_t k = 0; k < timing.q.size(); k += 97) {
      const JointPoint p = spline.at(timing.path_time[k]);
      for (size_t j = 0; j < 7; ++j) QCOMPARE(timing.q[k][j], p[j]);
    }
  }

  void anImpossiblePathIsRefusedNamingWhere() {
    std::vector<JointPoint> q(200, JointPoint{});
    q[100][1] = 0.5;  // a 0.5 rad spike within 10 ms
    const PathSpline spline(q, 100, 7);
    try {
      timePath(spline, pro7(), 1.0);
      QFAIL("an impossible path was timed");
    } catch (const std::runtime_error& e) {
      const std::string what = e.what();
      QVERIFY2(what.find("t = 1.0") != std::string::npos && what.find("joint 2") != std::string::npos, e.what());
    }
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, timePath(spline, pro7(), 0.0));
  }

  void deviationIgnoresLagButNotOffset() {
    const Reduction r = reducePath(demonstration(2.0, 1000, 0.2), 1000, 7);
    const PathSpline spline(r.path, 7);
    model::ArmKinematics model(pro7());
    std::vector<JointPoint> measured;
    std::vector<double> hints;
    for (double t = 0; t <= spline.duration(); t += 1e-3) {
      measured.push_back(spline.at(std::max(0.0, t - 0.004)));  // 4 ms behind
      hints.push_back(t);
    }
    PathDeviation d = pathDeviation(spline, model, measured, hints);
    QVERIFY2(d.joint < 1e-6, qPrintable(QString::number(d.joint)));
    for (JointPoint& q : measured) q[2] += 2e-3;
    d = pathDeviation(spline, model, measured, hints);
    // Nowhere farther than the offset (the nearest point may slide along the path where it runs
    // along joint 3), the full offset where the path rests.
    QVERIFY2(d.joint > 1.99e-3 && d.joint < 2.001e-3, qPrintable(QString::number(d.joint)));
    QVERIFY(d.tcp > 1e-4);
  }

  void pathSummaryAndTrace() {
    const Reduction r = reducePath(demonstration(2.0, 1000, 0.0), 1000, 7);
    const PathSummary s = summarizePath(r.path, pro7(), {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1});
    QCOMPARE(s.samples, r.path.q.size());
    QVERIFY(s.tcp_length > 0.05 && s.duration > 1.9);
    const auto trace = tcpTrace(r.path, pro7(), {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}, 50);
    QCOMPARE(trace.size(), size_t(50));
  }

  void pathFieldsRoundTrip() {
    const Program p = parseProgram(corruptPath("", ""));
    const Instruction& in = p.instructions[1];
    QCOMPARE(in.type, InstructionType::kPath);
    QCOMPARE(in.name, std::string("wipe"));
    QCOMPARE(in.path.rate_hz, 100.0);
    QCOMPARE(in.path.q.size(), size_t(3));
    QCOMPARE(in.path.q[2][0], 0.002);
    const Program again = parseProgram(programText(p));
    QCOMPARE(again.instructions[1].path.q, in.path.q);
  }

  void corruptPathIsRefusedNamingInstructionAndField_data() {
    QTest::addColumn<QString>("what");
    QTest::addColumn<QString>("replace");
    QTest::addColumn<QString>("expected");
    QTest::newRow("rate 0") << "\"rate_hz\": 100" << "\"rate_hz\": 0"
                            << "instruction 2 (PATH), field \"rate_hz\": expected a sample rate from 1 to 1000 Hz";
    QTest::newRow("rate above 1 kHz") << "\"rate_hz\": 100" << "\"rate_hz\": 2000" << "field \"rate_hz\"";
    QTest::newRow("no rate") << "\"rate_hz\": 100," << "" << "field \"rate_hz\": missing";
    QTest::newRow("one sample") << ", [0.001, 0.1, 0, 1, 0, 1, 0], [0.002, 0.1, 0, 1, 0, 1, 0]" << ""
                                << "field \"q\": a path needs at least 2 samples";
    QTest::newRow("short sample") << "[0.001, 0.1, 0, 1, 0, 1, 0]" << "[0.001, 0.1, 0, 1, 0, 1]"
                                  << "field \"q[1]\": expected an array of 7 joint values in rad, got 6 elements";
    QTest::newRow("text value") << "[0.001, 0.1, 0," << "[0.001, 0.1, \"0\","
                                << "field \"q[1][2]\": expected a number, got a string";
    QTest::newRow("beyond joint range") << "[0.002, 0.1, 0, 1" << "[0.002, 0.1, 0, 3"
                                        << "field \"q[2][3]\": joint 4 at 3.0000 rad is outside its range";
    QTest::newRow("not an array") << "\"q\": [[0, 0.1" << "\"q\": 5, \"x\": [[0, 0.1" << "field \"x\": unknown member";
    QTest::newRow("speed") << "\"speed\": 1.0}]" << "\"speed\": 1.5}]" << "field \"speed\": expected a speed ratio";
  }
  void corruptPathIsRefusedNamingInstructionAndField() {
    QFETCH(QString, what);
    QFETCH(QString, replace);
    QFETCH(QString, expected);
    try {
      parseProgram(corruptPath(what.toStdString(), replace.toStdString()));
      QFAIL("a corrupt PATH was accepted");
    } catch (const ProgramError& e) {
      QVERIFY2(QString(e.what()).contains(expected), e.what());
      QVERIFY2(QString(e.what()).startsWith("instruction 2 (PATH"), e.what());
    }
  }

  void aVersion1FileWithAPathIsRefused() {
    try {
      parseProgram(corruptPath("", "", 1));
      QFAIL("a PATH in a version 1 file was accepted");
    } catch (const ProgramError& e) {
      QVERIFY2(QString(e.what()).contains("instruction 2 (PATH), field \"type\": a PATH needs a program of version 2"),
               e.what());
    }
  }
};

QTEST_GUILESS_MAIN(TestPath)
#include "test_path.moc"
