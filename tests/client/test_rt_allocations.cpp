// SPDX-License-Identifier: Apache-2.0
// The real-time loop allocates nothing: this binary replaces the global operator new/delete with
// versions that count the calls made on the client's real-time thread (named "rci-rt"), and
// checks that 1000 steady-state cycles of a JointControl run (receive, decode, publish, callback,
// encode, send) make none -- also when the callback uses what the public headers call real-time safe
// (the motion generators, the model, the rate limiter) and the jog's generators. A callback that
// allocates proves the counter sees the thread.
#include <QtTest>

#include <sys/prctl.h>

#include <atomic>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <new>
#include <vector>

#include <xmate/cart_motion.h>
#include <xmate/joint_motion.h>
#include <xmate/model.h>
#include <xmate/rate_limiting.h>
#include <xmate/robot.h>

#include "client_test_support.h"
#include "jog/jog.h"
#include "model/robot_spec.h"

namespace {

// Test instrumentation, not product code: counters of heap calls on the real-time thread.
std::atomic<uint64_t> g_rt_news{0};
std::atomic<uint64_t> g_rt_deletes{0};

bool onRealtimeThread() {
  char name[16] = {};
  prctl(PR_GET_NAME, name, 0, 0, 0);
  return std::strcmp(name, "rci-rt") == 0;
}

void* countedAlloc(std::size_t size) {
  if (onRealtimeThread()) ++g_rt_news;
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}

void countedFree(void* p) {
  if (p && onRealtimeThread()) ++g_rt_deletes;
  std::free(p);
}

}  // namespace

void* operator new(std::size_t size) { return countedAlloc(size); }
void* operator new[](std::size_t size) { return countedAlloc(size); }
void operator delete(void* p) noexcept { countedFree(p); }
void operator delete[](void* p) noexcept { countedFree(p); }
void operator delete(void* p, std::size_t) noexcept { countedFree(p); }
void operator delete[](void* p, std::size_t) noexcept { countedFree(p); }

using namespace xmate;
using namespace client_test;
using CM = RCI::robot::StartMoveRequest::ControllerMode;
using MM = RCI::robot::StartMoveRequest::MotionGeneratorMode;

class TestRtAllocations : public QObject {
  Q_OBJECT

 private slots:
  void steadyStateJointControlDoesNotAllocate();
  void counterSeesAnAllocatingCallback();
  void realTimeSafeCallsDoNotAllocate();
};

namespace {

// Runs 1300 cycles of a joint callback (a slow sine on J1, so the commands change every cycle) and
// returns the heap calls of the real-time thread between cycle 200 and cycle 1200.
struct Window {
  uint64_t news = 0, deletes = 0;
};

// `also` runs in every callback (after the first) with the state.
Window measure(Robot& robot, bool allocate_in_callback,
               const std::function<void(const RCI::robot::RobotState&)>& also = nullptr) {
  Window w;
  uint64_t news0 = 0, deletes0 = 0;
  int cycle = 0;
  std::array<double, 7> start{};
  std::vector<int>* sink = nullptr;
  robot.startMove(CM::kJointPosition, MM::kJointPosition);
  robot.Control(JointControl([&](RCI::robot::RobotState s) -> JointPositions {
    ++cycle;
    if (cycle == 1) start = s.q;
    if (cycle == 200) {
      news0 = g_rt_news;
      deletes0 = g_rt_deletes;
    }
    if (cycle == 1200) {
      w.news = g_rt_news - news0;
      w.deletes = g_rt_deletes - deletes0;
    }
    if (allocate_in_callback) {
      delete sink;
      sink = new std::vector<int>(3);
    }
    if (also && cycle > 1) also(s);
    JointPositions out{start, false};
    const double t = cycle * 1e-3;
    out.q[0] += 0.01 * (1 - std::cos(2 * M_PI * t / 1.3));  // one smooth period over the run
    return cycle >= 1300 ? MotionFinished(out) : out;
  }));
  delete sink;
  return w;
}

}  // namespace

void TestRtAllocations::steadyStateJointControlDoesNotAllocate() {
  auto server = startSim();
  auto robot = robotFor(*server);
  robot->connect();
  const Window w = measure(*robot, false);
  QCOMPARE(w.news, uint64_t(0));
  QCOMPARE(w.deletes, uint64_t(0));
}

void TestRtAllocations::counterSeesAnAllocatingCallback() {
  auto server = startSim();
  auto robot = robotFor(*server);
  robot->connect();
  const Window w = measure(*robot, true);
  QVERIFY2(w.news >= 1000, qPrintable(QString::number(w.news)));
  QVERIFY2(w.deletes >= 1000, qPrintable(QString::number(w.deletes)));
}

// What the public headers call real-time safe, called in the callback every cycle as programs do:
// the generators (planned again from the same start, as the manual's programs do each cycle), the
// model (forward and inverse kinematics, Jacobian, dynamics, arm angle), the rate limiter; and the
// jog's generators.
void TestRtAllocations::realTimeSafeCallsDoNotAllocate() {
  auto server = startSim();
  auto robot = robotFor(*server);
  robot->connect();
  const std::array<double, 7> q0 = robot->receiveRobotState().q;
  std::array<double, 7> goal = q0;
  goal[1] += 0.2;
  JointMotionGenerator joint(0.5, goal);
  CartMotionGenerator cart(0.5, 0.1);
  XmateModel model(XMATE7_PRO);
  JointRateLimiter limiter(ratedJointRateLimits(XMATE7_PRO));
  jog::JogFlags flags;
  const auto& spec = model::robotSpec(XMATE7_PRO);
  jog::JointJog joint_jog(spec, 0, +1, 0.5, jog::jogLimits(spec, false, {}, {}), flags);
  jog::CartesianJog cartesian_jog(2, -1, 0.5, 7, jog::jogLimits(spec, false, {}, {}), flags);
  double sink = 0;
  int k = 0;
  const Window w = measure(*robot, false, [&](const RCI::robot::RobotState& s) {
    const double t = ++k * 1e-3;
    std::array<double, 7> dq{}, zero{}, full{}, inertial{}, coriolis{}, gravity{}, q_ik{};
    joint.calculateSynchronizedValues_joint(q0);
    joint.calculateDesiredValues_joint(t, dq);
    double ds = 0;
    cart.calculateSynchronizedValues_cart(0.0);
    cart.calculateDesiredValues_cart(t, &ds);
    const std::array<double, 16> pose = model.GetCartPose(s.q);
    const int ik = model.GetJointPos(pose, model.GetPsi(s.q), s.q, q_ik);
    const std::array<double, 42> jacobian = model.Jacobian(s.q);
    model.GetTauNoFriction(s.q, s.dq_m, zero, full, inertial, coriolis, gravity);
    const std::array<double, 7> limited = limiter.limit(s.q_c, s);
    const JointPositions jog_joint = joint_jog.next(s);
    const CartesianPose jog_cartesian = cartesian_jog.next(s);
    sink += dq[1] + ds + pose[3] + ik + jacobian[0] + full[1] + limited[0] + jog_joint.q[0] +
            jog_cartesian.toolTobase_pos_c[11];
  });
  QVERIFY(std::isfinite(sink));
  QCOMPARE(w.news, uint64_t(0));
  QCOMPARE(w.deletes, uint64_t(0));
}

QTEST_APPLESS_MAIN(TestRtAllocations)
#include "test_rt_allocations.moc"
