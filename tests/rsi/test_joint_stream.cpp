// SPDX-License-Identifier: Apache-2.0
// arm::JointStream against the fake robot: the AXISCORR limits read from a context, corrections held
// at zero until a motion runs, a motion's joints sent as AK totals relative to the set-point at
// RSI_ON, the robot going silent during a motion reported, and the pre-motion checks naming the axis,
// the limit and the value.
#include <QtTest>

#include <atomic>
#include <thread>

#include "arm/joint_stream.h"
#include "model/robot_spec.h"
#include "rsi_test_support.h"

using namespace xmate;
using namespace xmate::rsi;
using xmate::arm::JointStream;
using xmate::arm::StreamState;
using namespace xmate::rsi::testing;

namespace {

constexpr double kDeg = 180.0 / 3.14159265358979323846;

const model::RobotSpec& sixAxes() { return *model::findRobotSpec("xmate3"); }

AxisCorrectionLimits wideLimits() {
  AxisCorrectionLimits l;
  l.lower.fill(-90 / kDeg);
  l.upper.fill(90 / kDeg);
  for (int i = 0; i < 6; ++i) {
    l.lower_by[size_t(i)] = "AXISCORR1's LowerLimA" + std::to_string(i + 1);
    l.upper_by[size_t(i)] = "AXISCORR1's UpperLimA" + std::to_string(i + 1);
  }
  return l;
}

// Moves A1 by `degrees` over `cycles` cycles from the command it starts at.
class Ramp : public arm::JointMotion {
 public:
  Ramp(double degrees, int cycles) : degrees_(degrees), cycles_(cycles) {}
  bool command(const arm::ArmSample& s, std::array<double, 7>& q) override {
    if (calls_++ == 0) start_ = s.q_command;
    q = start_;
    q[0] += degrees_ / kDeg * std::min(1.0, double(calls_) / cycles_);
    return calls_ >= cycles_;
  }
  int calls() const { return calls_; }

 private:
  double degrees_;
  int cycles_;
  int calls_ = 0;
  std::array<double, 7> start_{};
};

}  // namespace

class TestJointStream : public QObject {
  Q_OBJECT

 private slots:
  void limitsComeFromTheContext();
  void holdsStillThenStreamsAMotion();
  void silenceDuringAMotionIsReported();
  void checksNameTheAxisTheLimitAndTheValue();
};

void TestJointStream::limitsComeFromTheContext() {
  const AxisCorrectionLimits sample = axisCorrectionLimits(readContext(dataPath("resources/rsi/rci_axis_corr.rsi.xml")));
  QCOMPARE(sample.lower[0] * kDeg, -5.0);
  QCOMPARE(sample.upper[5] * kDeg, 5.0);
  QCOMPARE(sample.upper_by[5], std::string("AXISCORR1's UpperLimA6"));
  const std::string no_axiscorr =
      "<RSIObjects><RSIObject ObjType=\"ETHERNET\" ObjID=\"ETHERNET1\"><Parameters><Parameter Name=\"ConfigFile\" "
      "ParamValue=\"x.xml\"/></Parameters></RSIObject></RSIObjects>";
  try {
    axisCorrectionLimits(parseContext(no_axiscorr, "cell.rsi.xml"));
    QFAIL("a context without AXISCORR was accepted");
  } catch (const ConfigError& e) {
    QVERIFY2(QString(e.what()).startsWith("cell.rsi.xml: the context has no AXISCORR object"), e.what());
  }
  // A monitor tighter than the clamp sets the limit (it would stop RSI there).
  const std::string monitored =
      "<RSIObjects><RSIObject ObjType=\"ETHERNET\" ObjID=\"ETHERNET1\"><Parameters><Parameter Name=\"ConfigFile\" "
      "ParamValue=\"x.xml\"/></Parameters></RSIObject><RSIObject ObjType=\"AXISCORR\" ObjID=\"AXISCORR1\"><Parameters>"
      "<Parameter Name=\"UpperLimA2\" ParamValue=\"90\"/><Parameter Name=\"LowerLimA2\" ParamValue=\"-90\"/>"
      "</Parameters></RSIObject><RSIObject ObjType=\"AXISCORRMON\" ObjID=\"MON\"><Parameters>"
      "<Parameter Name=\"MaxA2\" ParamValue=\"30\"/></Parameters></RSIObject></RSIObjects>";
  const AxisCorrectionLimits m = axisCorrectionLimits(parseContext(monitored, "cell.rsi.xml"));
  QCOMPARE(m.upper[1] * kDeg, 30.0);
  QCOMPARE(m.lower[1] * kDeg, -30.0);
  QCOMPARE(m.upper_by[1], std::string("MON's MaxA2"));
  QCOMPARE(m.upper[0] * kDeg, 5.0);  // not monitored: AXISCORR's default
  const std::string bad =
      "<RSIObjects><RSIObject ObjType=\"ETHERNET\" ObjID=\"ETHERNET1\"><Parameters><Parameter Name=\"ConfigFile\" "
      "ParamValue=\"x.xml\"/></Parameters></RSIObject>\n<RSIObject ObjType=\"AXISCORR\" ObjID=\"AXISCORR1\"><Parameters>"
      "<Parameter Name=\"UpperLimA3\" ParamValue=\"ninety\"/></Parameters></RSIObject></RSIObjects>";
  try {
    axisCorrectionLimits(parseContext(bad, "cell.rsi.xml"));
    QFAIL("a limit that is not a number was accepted");
  } catch (const ConfigError& e) {
    QVERIFY2(QString(e.what()).startsWith("cell.rsi.xml:2: AXISCORR1 (AXISCORR): parameter UpperLimA3=\"ninety\" is not a number"), e.what());
  }
}

void TestJointStream::holdsStillThenStreamsAMotion() {
  Link link(sampleConfig(), loopback());
  JointStream stream(link, sixAxes(), wideLimits());
  link.start();
  FakeRobot robot(link.port());
  const std::array<double, 6> set{10, -20, 30, 0, 45, 0}, actual{10.01, -20, 30, 0, 45, 0};
  // Before any motion: zero correction, and RSI_ON's set-point is what corrections are relative to.
  for (uint64_t ipoc = 1; ipoc <= 3; ++ipoc) QCOMPARE(attribute(robot.exchangeAxes(ipoc, actual, set), "A1"), 0.0);
  StreamState s;
  QVERIFY(stream.state(s));
  QCOMPARE(s.q_on[0] * kDeg, 10.0);
  QCOMPARE(s.q[0] * kDeg, 10.01);
  QCOMPARE(s.cycles, uint64_t(3));

  // The robot keeps sending from another thread while the motion runs on this one.
  std::atomic<bool> quit{false};
  std::atomic<double> last_a1{0}, last_a2{0};
  std::thread krc([&] {
    for (uint64_t ipoc = 4; !quit; ++ipoc) {
      const std::string sen = robot.exchangeAxes(ipoc, actual, set);
      last_a1 = attribute(sen, "A1");
      last_a2 = attribute(sen, "A2");
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
  });
  Ramp ramp(2.0, 25);
  stream.run(ramp);
  QCOMPARE(ramp.calls(), 25);
  // After the motion the correction holds where it ended.
  QTRY_COMPARE_WITH_TIMEOUT(last_a1.load(), 2.0, 2000);
  QCOMPARE(last_a2.load(), 0.0);
  QVERIFY(stream.state(s));
  QCOMPARE(s.q_command[0] * kDeg, 12.0);
  // A motion planned in another RSI session is never streamed.
  Ramp stale(1.0, 10);
  try {
    stream.run(stale, std::chrono::seconds(1), s.session + 1);
    QFAIL("a motion of another session was streamed");
  } catch (const std::runtime_error& e) {
    QVERIFY2(QString(e.what()).startsWith("RSI was switched on again after the motion was planned"), e.what());
  }
  QCOMPARE(stale.calls(), 0);
  quit = true;
  krc.join();
}

void TestJointStream::silenceDuringAMotionIsReported() {
  LinkOptions options = loopback();
  options.silence_ms = 100;
  Link link(sampleConfig(), options);
  JointStream stream(link, sixAxes(), wideLimits());
  link.start();
  FakeRobot robot(link.port());
  const std::array<double, 6> axes{0, 0, 0, 0, 0, 0};
  robot.exchangeAxes(1, axes, axes);
  std::thread krc([&] {
    for (uint64_t ipoc = 2; ipoc < 20; ++ipoc) robot.exchangeAxes(ipoc, axes, axes);  // then RSI stops
  });
  Ramp endless(1.0, 1 << 30);
  try {
    stream.run(endless);
    QFAIL("the motion ended although the robot stopped sending");
  } catch (const std::runtime_error& e) {
    QVERIFY2(QString(e.what()).startsWith("RSI stopped during the motion"), e.what());
  }
  krc.join();
  try {
    stream.run(endless, std::chrono::milliseconds(50));
    QFAIL("a motion started while RSI was off");
  } catch (const std::runtime_error& e) {
    QVERIFY2(QString(e.what()).startsWith("RSI is not running"), e.what());
  }
}

void TestJointStream::checksNameTheAxisTheLimitAndTheValue() {
  Link link(sampleConfig(), loopback());
  AxisCorrectionLimits limits = wideLimits();
  limits.upper[1] = 5 / kDeg;
  JointStream stream(link, sixAxes(), limits);
  const double dt = stream.cycleSeconds();
  const std::array<double, 6> on{}, zero{};
  std::array<double, 6> q{};
  QCOMPARE(stream.checkSample(q.data(), zero.data(), dt, on), std::string());
  q[1] = 6 / kDeg;  // A2 6 deg in one cycle: too fast, and beyond UpperLimA2
  const QString fast = QString::fromStdString(stream.checkSample(q.data(), zero.data(), dt, on));
  QVERIFY2(fast.startsWith("A2 would move at 1500.0 deg/s, above its rated"), qPrintable(fast));
  const QString beyond = QString::fromStdString(stream.checkSample(q.data(), nullptr, dt, on));
  QVERIFY2(beyond.startsWith("A2 would need a correction of 6.00 deg") && beyond.contains("UpperLimA2 = 5.0 deg"),
           qPrintable(beyond));
  std::array<double, 6> out{};
  out[2] = sixAxes().q_max[2] + 0.01;
  const QString range = QString::fromStdString(stream.checkSample(out.data(), nullptr, dt, on));
  QVERIFY2(range.startsWith("A3 would reach") && range.contains("outside its range"), qPrintable(range));
}

QTEST_MAIN(TestJointStream)
#include "test_joint_stream.moc"
