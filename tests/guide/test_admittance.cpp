// SPDX-License-Identifier: Apache-2.0
// Hand guiding a KUKA through the F/T sensor, end to end: the simulated KRC (lock-step) pushed by a
// wrench its simulated sensor reads, ft::NetFtClient, arm::RsiArm and guide::AdmittanceGuide. A push
// moves the flange along it (translation: the orientation stays), a twist turns it (rotation: the
// position stays), a push inside the dead band moves nothing, releasing brings it to rest, at the
// edge of the reach it holds still, the operator's stop ends it, a silent sensor ends it saying so;
// the tool's weight is removed at any pose.
#include <QtTest>

#include <chrono>
#include <cmath>
#include <memory>
#include <thread>

#include "arm/rsi_arm.h"
#include "ft/netft.h"
#include "guide/admittance.h"
#include "guide/ft_source.h"
#include "../rsi/rsi_test_support.h"
#include "model/arm_kinematics.h"
#include "sim/ft_sensor.h"
#include "sim/krc_server.h"

using namespace xmate;
using namespace xmate::guide;
using xmate::rsi::testing::krcFor;
using xmate::rsi::testing::loopbackArm;
using xmate::rsi::testing::waitFor;

namespace {

// A KUKA cell: the PC's arm, a simulated KRC in lock-step with its F/T sensor, and the sensor client.
struct Cell {
  std::unique_ptr<arm::RsiArm> arm;
  std::unique_ptr<sim::SimulatedFtSensor> sensor;
  std::unique_ptr<sim::KrcServer> krc;
  std::unique_ptr<ft::NetFtClient> ft;

  Cell() {
    const arm::RsiArmConfig config = loopbackArm("resources/rsi/rci_replay.rsi.xml", 2000);
    arm = std::make_unique<arm::RsiArm>(config);
    arm->start();
    sensor = std::make_unique<sim::SimulatedFtSensor>(sim::FtSensorConfig{"127.0.0.1", 0});
    sensor->start();
    sim::KrcServerConfig k = krcFor(config, arm->link().port(), true);
    k.ft_sensor = sensor.get();
    krc = std::make_unique<sim::KrcServer>(k);
    krc->start();
    ft::NetFtOptions o;
    o.host = "127.0.0.1";
    o.port = sensor->port();
    ft = std::make_unique<ft::NetFtClient>(o);
    ft->start();
  }
  ~Cell() {
    ft->stop();
    krc->stop();
    sensor->stop();
    arm->stop();
  }
  bool ready() {
    arm::ArmState s;
    ft::Wrench w;
    return waitFor([&] { return arm->latest(s) && ft->latest(w); });
  }
  std::array<double, 16> flange() {
    arm::ArmState s;
    arm->latest(s);
    return model::ArmKinematics(arm->spec()).GetCartPose(s.sample.q);
  }
  void push(const std::array<double, 6>& wrench) { krc->krc().setExternalWrench(wrench); }
};

// Runs a guide on its own thread (runJointMotion blocks) until the test ends it.
struct Guiding {
  AdmittanceGuide guide;
  std::thread thread;
  std::string failure;
  Guiding(Cell& cell, const NetFtSource& source, GuideParameters parameters)
      : guide(model::ArmKinematics(cell.arm->spec()), source, cell.arm->cycleSeconds(), parameters) {
    thread = std::thread([this, &cell] {
      try {
        cell.arm->runJointMotion(guide);
      } catch (const std::exception& e) {
        failure = e.what();
      }
    });
  }
  bool started() { return waitFor([&] { return guide.status().cycles > 0; }); }
  // Waits for runJointMotion to return (the guide ended by itself or was stopped).
  void join() {
    if (thread.joinable()) thread.join();
  }
  ~Guiding() {
    guide.requestStop();
    join();
  }
  bool ended() { return waitFor([&] { return guide.status().end != GuideEnd::kRunning; }); }
};

double distance(const std::array<double, 16>& a, const std::array<double, 16>& b) {
  return std::hypot(a[3] - b[3], a[7] - b[7], a[11] - b[11]);
}

// The angle between two poses' orientations (rad).
double turn(const std::array<double, 16>& a, const std::array<double, 16>& b) {
  double trace = 0;
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) trace += a[size_t(4 * k + i)] * b[size_t(4 * k + i)];
  return std::acos(std::clamp((trace - 1) / 2, -1.0, 1.0));
}

bool atRest(Guiding& g) {
  return waitFor([&] {
    const GuideStatus s = g.guide.status();
    return std::hypot(s.velocity[0], s.velocity[1], s.velocity[2]) < 1e-4 &&
           std::hypot(s.velocity[3], s.velocity[4], s.velocity[5]) < 1e-3;
  });
}

}  // namespace

class TestAdmittance : public QObject {
  Q_OBJECT

 private slots:
  void toolWeightIsRemovedAtAnyPose();
  void pushMovesTheFlangeAlongIt();
  void twistTurnsTheFlangeInPlace();
  void atTheEdgeOfReachItHoldsStill();
  void silentSensorEndsTheGuideSayingSo();
};

void TestAdmittance::toolWeightIsRemovedAtAnyPose() {
  const ToolWeight tool{2.5, {0.01, -0.02, 0.12}};
  const model::ArmKinematics kr6(*model::findRobotSpec("kr6_r900_sixx"));
  // Hanging straight down from the flange (flange z along -z of the base): the full weight along
  // the flange's +z, no torque about its axis.
  const std::array<double, 16> down = kr6.GetCartPose({0, -1.5708, 1.5708, 0, 1.5708, 0, 0});
  const std::array<double, 6> w = toolWeightAtSensor(tool, down);
  QVERIFY2(std::abs(std::hypot(w[0], w[1], w[2]) - 2.5 * 9.80665) < 1e-9, qPrintable(QString::number(w[2])));
  // At any pose: force of the weight's size, torque = centre x force.
  for (const std::array<double, 7>& q : {std::array<double, 7>{0.3, -1.2, 1.1, 0.4, 0.9, -0.5, 0},
                                         std::array<double, 7>{-1.0, -0.6, 0.5, 1.2, -0.7, 2.0, 0}}) {
    const std::array<double, 6> at = toolWeightAtSensor(tool, kr6.GetCartPose(q));
    QVERIFY(std::abs(std::hypot(at[0], at[1], at[2]) - 2.5 * 9.80665) < 1e-9);
    const double tx = tool.center[1] * at[2] - tool.center[2] * at[1];
    QVERIFY(std::abs(tx - at[3]) < 1e-12);
  }
  QCOMPARE(QString(describe(GuideEnd::kSensorSilent)).left(30), QString("the force sensor fell silent: "));
}

void TestAdmittance::pushMovesTheFlangeAlongIt() {
  Cell cell;
  QVERIFY(cell.ready());
  const NetFtSource source(*cell.ft);
  const std::array<double, 16> start = cell.flange();
  Guiding g(cell, source, GuideParameters{});
  QVERIFY(g.started());  // the bias is taken: nobody touches the tool yet
  // Inside the dead band (4 N): nothing moves.
  cell.push({3, 0, 0, 0, 0, 0});
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  QVERIFY2(distance(cell.flange(), start) < 1e-5, qPrintable(QString::number(distance(cell.flange(), start))));
  // 30 N along +x of the base: the flange moves along +x, its orientation stays.
  cell.push({30, 0, 0, 0, 0, 0});
  QVERIFY(waitFor([&] { return cell.flange()[3] - start[3] > 0.03; }));
  cell.push({0, 0, 0, 0, 0, 0});  // released
  QVERIFY(atRest(g));
  const std::array<double, 16> end = cell.flange();
  QVERIFY2(end[3] - start[3] > 0.03, qPrintable(QString::number(end[3] - start[3])));
  QVERIFY2(std::hypot(end[7] - start[7], end[11] - start[11]) < 0.002,
           qPrintable(QString("%1 %2").arg(end[7] - start[7]).arg(end[11] - start[11])));
  QVERIFY2(turn(end, start) < 0.005, qPrintable(QString::number(turn(end, start))));
  // The operator's stop ends it.
  g.guide.requestStop();
  QVERIFY(g.ended());
  QCOMPARE(g.guide.status().end, GuideEnd::kOperator);
  g.join();
  QVERIFY2(g.failure.empty(), g.failure.c_str());
}

void TestAdmittance::twistTurnsTheFlangeInPlace() {
  Cell cell;
  QVERIFY(cell.ready());
  const NetFtSource source(*cell.ft);
  const std::array<double, 16> start = cell.flange();
  GuideParameters rotation;
  rotation.axes = GuideAxes::kRotation;
  Guiding g(cell, source, rotation);
  QVERIFY(g.started());
  cell.push({40, 0, 0, 0, 0, 3});  // a push (ignored: rotation only) and a twist about z of the base
  QVERIFY(waitFor([&] { return turn(cell.flange(), start) > 0.1; }));
  cell.push({0, 0, 0, 0, 0, 0});
  QVERIFY(atRest(g));
  const std::array<double, 16> end = cell.flange();
  QVERIFY2(distance(end, start) < 0.002, qPrintable(QString::number(distance(end, start))));
  QVERIFY(turn(end, start) > 0.1);
}

// Pushed outwards until the arm cannot keep its orientation and go further, it holds still there
// (rather than let the flange drift down) and says so; pushed back, it follows again.
void TestAdmittance::atTheEdgeOfReachItHoldsStill() {
  Cell cell;
  QVERIFY(cell.ready());
  const NetFtSource source(*cell.ft);
  const std::array<double, 16> start = cell.flange();
  Guiding g(cell, source, GuideParameters{});
  QVERIFY(g.started());
  cell.push({30, 0, 0, 0, 0, 0});
  QVERIFY(waitFor([&] { return g.guide.status().cannot_follow; }));
  std::this_thread::sleep_for(std::chrono::milliseconds(100));
  const std::array<double, 16> edge = cell.flange();
  QVERIFY2(edge[3] - start[3] > 0.1, qPrintable(QString::number(edge[3] - start[3])));
  QVERIFY2(std::hypot(edge[7] - start[7], edge[11] - start[11]) < 0.002,
           qPrintable(QString("%1 %2").arg(edge[7] - start[7]).arg(edge[11] - start[11])));
  QVERIFY(turn(edge, start) < 0.005);
  cell.push({-30, 0, 0, 0, 0, 0});
  QVERIFY(waitFor([&] { return edge[3] - cell.flange()[3] > 0.02; }));
  QVERIFY(!g.guide.status().cannot_follow);
}

void TestAdmittance::silentSensorEndsTheGuideSayingSo() {
  Cell cell;
  QVERIFY(cell.ready());
  const NetFtSource source(*cell.ft);
  Guiding g(cell, source, GuideParameters{});
  QVERIFY(g.started());
  cell.push({30, 0, 0, 0, 0, 0});
  const std::array<double, 16> start = cell.flange();
  QVERIFY(waitFor([&] { return distance(cell.flange(), start) > 0.01; }));
  cell.sensor->setSilent(true);  // the cable
  QVERIFY(g.ended());
  QCOMPARE(g.guide.status().end, GuideEnd::kSensorSilent);
  g.join();  // it came to rest and ended by itself
  QVERIFY2(g.failure.empty(), g.failure.c_str());
  const std::array<double, 16> rest = cell.flange();
  std::this_thread::sleep_for(std::chrono::milliseconds(100));
  QVERIFY(distance(cell.flange(), rest) < 1e-4);
}

QTEST_GUILESS_MAIN(TestAdmittance)
#include "test_admittance.moc"
