// SPDX-License-Identifier: Apache-2.0
// The 3D view without a display: the factory's placeholder (no hang under the offscreen platform),
// link meshes of every model (xMate and KUKA) through assimp, link poses against the core's FK, tints,
// camera maths, recognising software OpenGL renderers, a KUKA's RSI correction envelope.
#include <QLabel>
#include <QSignalSpy>
#include <QtTest>

#include <Qt3DCore/QEntity>

#include <cmath>
#include <random>

#include "model/kinematics.h"
#include "model/urdf_loader.h"
#include "session/session.h"
#include "sim/krc.h"
#include "view3d/arm_poser.h"
#include "view3d/correction_envelope.h"
#include "view3d/gl_probe.h"
#include "view3d/link_tints.h"
#include "view3d/mesh_data.h"
#include "view3d/orbit_camera.h"
#include "view3d/robot_scene.h"
#include "view3d/robot_view.h"
#include "window/parts.h"

using namespace rci::ui;
namespace model = xmate::model;

namespace {

std::array<double, 7> randomPose(const model::RobotSpec& spec, std::mt19937& rng) {
  std::array<double, 7> q{};
  for (int i = 0; i < spec.dof; ++i) {
    std::uniform_real_distribution<double> d(spec.q_min[size_t(i)], spec.q_max[size_t(i)]);
    q[size_t(i)] = d(rng);
  }
  return q;
}

double maxDifference(const QMatrix4x4& a, const QMatrix4x4& b) {
  double worst = 0;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) worst = std::max(worst, double(std::abs(a(r, c) - b(r, c))));
  return worst;
}

}  // namespace

class TestView3dOffscreen : public QObject {
  Q_OBJECT
 private slots:
  void factoryReturnsPlaceholder();
  void placeholderIgnoresSetters();
  void meshesOfEveryModelLoad();
  void meshCacheReadsEachFileOnce();
  void linkPosesEqualForwardKinematics();
  void tcpFrameFollowsFlangeUntilSet();
  void tintsMarkLimitsAndOverload();
  void sceneShowsBoxWaypointsPath();
  void springForceIsClamped();
  void cameraRayHitsProjectedPoint();
  void softwareRenderersAreRecognised();
  void kukaModelsLoadAndPose();
  void placeholderKeepsAKukaModel();
  void correctionEnvelopeSpansTheLimits();
  void sceneShowsCorrectionEnvelope();
};

void TestView3dOffscreen::factoryReturnsPlaceholder() {
  Session session;
  std::unique_ptr<QWidget> widget(createRobotView(session, nullptr));
  auto* view = qobject_cast<RobotView*>(widget.get());
  QVERIFY(view);
  QVERIFY(!view->is3D());
  QVERIFY2(view->unavailableReason().contains(QLatin1String("offscreen")), qPrintable(view->unavailableReason()));
  auto* label = view->findChild<QLabel*>(QStringLiteral("robotViewPlaceholder"));
  QVERIFY(label);
  QVERIFY(label->text().contains(QLatin1String("3D view unavailable")));
  QVERIFY(label->text().contains(QLatin1String("What to do")));
  widget->show();  // must not hang either
  QCoreApplication::processEvents();
  bool called = false;
  captureRobotView(widget.get(), [&](const QImage& image) {
    called = true;
    QVERIFY(image.isNull());
  });
  QVERIFY(called);
}

void TestView3dOffscreen::placeholderIgnoresSetters() {
  RobotView view;
  QVERIFY(!view.is3D());
  QVERIFY(!view.scene());
  view.setModel(xmate::XMATE3);
  QCOMPARE(view.model(), xmate::XMATE3);
  view.setJointPositions({0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0});
  view.setWaypoints(std::vector<QVector3D>{{0.5f, 0, 0.5f}});
  view.setPlannedPath({{0.5f, 0, 0.5f}, {0.5f, 0.2f, 0.5f}});
  view.setPullEnabled(true);
  QVERIFY(!view.beginPull(QPointF(10, 10)));
}

void TestView3dOffscreen::meshesOfEveryModelLoad() {
  for (xmate::XmateType type : model::allRobotTypes()) {
    const ArmPoser poser(type);
    const model::RobotSpec& spec = model::robotSpec(type);
    QCOMPARE(int(poser.links().size()), spec.dof + 1);
    for (const LinkVisual& link : poser.links()) {
      const QString what = QString::fromLatin1(spec.name.data(), qsizetype(spec.name.size())) + '/' + link.name;
      QVERIFY2(!link.mesh.isEmpty(), qPrintable(what));
      const MeshData mesh = loadMeshData(link.mesh, link.scale);
      QVERIFY2(mesh.triangleCount() > 100, qPrintable(what));
      QCOMPARE(mesh.vertices.size() % 6, size_t(0));
      for (quint32 index : mesh.indices) QVERIFY(index < quint32(mesh.vertexCount()));
      const QVector3D extent = mesh.max - mesh.min;
      for (int axis = 0; axis < 3; ++axis) {
        QVERIFY2(extent[axis] > 0.02f && extent[axis] < 1.0f, qPrintable(what));
      }
      for (int v = 0; v < mesh.vertexCount(); ++v) {
        const QVector3D n(mesh.vertices[size_t(6 * v + 3)], mesh.vertices[size_t(6 * v + 4)],
                          mesh.vertices[size_t(6 * v + 5)]);
        QVERIFY2(std::abs(n.length() - 1.0f) < 1e-3f, qPrintable(what));
      }
    }
    // Light housings, darker flange part (URDF materials).
    QVERIFY(poser.links().front().color.lightnessF() > 0.8);
    QVERIFY(poser.links().back().color.lightnessF() < 0.5);
  }
}

void TestView3dOffscreen::meshCacheReadsEachFileOnce() {
  MeshCache cache;
  const ArmPoser poser(xmate::XMATE7_PRO);
  const LinkVisual& link = poser.links()[1];
  auto a = cache.get(link.mesh, link.scale);
  auto b = cache.get(link.mesh, link.scale);
  QCOMPARE(a.get(), b.get());
  QCOMPARE(cache.size(), 1);
  auto scaled = cache.get(link.mesh, QVector3D(2, 2, 2));
  QCOMPARE(cache.size(), 2);
  QVERIFY(std::abs((scaled->max - scaled->min).x() - 2 * (a->max - a->min).x()) < 1e-5f);
  QVERIFY_THROWS_EXCEPTION(std::runtime_error, loadMeshData(QStringLiteral("/nonexistent/link.stl")));
}

void TestView3dOffscreen::linkPosesEqualForwardKinematics() {
  Qt3DCore::QEntity root;
  RobotScene scene(&root);
  std::mt19937 rng(7);
  for (xmate::XmateType type : model::allRobotTypes()) {
    const model::RobotSpec& spec = model::robotSpec(type);
    const model::ArmModel arm = model::makeArmModel(model::loadRobotChain(spec), spec);
    scene.setModel(type);
    QCOMPARE(scene.linkCount(), spec.dof + 1);
    for (int trial = 0; trial < 20; ++trial) {
      const std::array<double, 7> q = randomPose(spec, rng);
      scene.setJointPositions(q);
      model::JointVector jq = model::JointVector::Zero();
      for (int i = 0; i < spec.dof; ++i) jq[i] = q[size_t(i)];
      model::LinkFrames frames;
      model::forwardKinematics(arm, jq, frames);
      QVERIFY(maxDifference(scene.linkTransform(0), QMatrix4x4()) < 1e-6);
      for (int i = 0; i < spec.dof; ++i) {
        QVERIFY2(maxDifference(scene.linkTransform(i + 1), toMatrix(frames.links[size_t(i)])) < 1e-5,
                 qPrintable(QStringLiteral("link %1").arg(i + 1)));
      }
    }
  }
}

void TestView3dOffscreen::tcpFrameFollowsFlangeUntilSet() {
  Qt3DCore::QEntity root;
  RobotScene scene(&root);
  scene.setModel(xmate::XMATE3_PRO);
  const std::array<double, 7> q{0.3, 0.4, -0.2, 1.1, 0.1, 0.9, 0.2};
  scene.setJointPositions(q);
  const QVector3D flange = scene.poser()->flangePose(q).column(3).toVector3D();
  QVERIFY((scene.tcpPosition() - flange).length() < 1e-6f);
  std::array<double, 16> pose{1, 0, 0, 0.4, 0, 1, 0, 0.1, 0, 0, 1, 0.6, 0, 0, 0, 1};
  scene.setTcpPose(toMatrix(pose));
  QVERIFY((scene.tcpPosition() - QVector3D(0.4f, 0.1f, 0.6f)).length() < 1e-6f);
}

void TestView3dOffscreen::tintsMarkLimitsAndOverload() {
  const model::RobotSpec& spec = model::robotSpec(xmate::XMATE7_PRO);
  TintInputs in;
  in.dof = 7;
  in.lower = spec.q_min;
  in.upper = spec.q_max;
  in.q[1] = spec.q_max[1] - 4.0 * M_PI / 180;  // within 5° of the upper limit
  in.q[2] = spec.q_min[2] + 6.0 * M_PI / 180;  // just outside the margin
  in.tau_ext[4] = -12;
  in.thresholds[4] = 10;  // exceeded
  in.tau_ext[5] = 50;     // no threshold set: ignored
  std::vector<LinkTint> tints = linkTints(in);
  QCOMPARE(int(tints.size()), 7);
  QCOMPARE(tints[0], LinkTint::kNone);
  QCOMPARE(tints[1], LinkTint::kNearLimit);
  QCOMPARE(tints[2], LinkTint::kNone);
  QCOMPARE(tints[4], LinkTint::kOverload);
  QCOMPARE(tints[5], LinkTint::kNone);
  in.collision = true;
  for (LinkTint t : linkTints(in)) QCOMPARE(t, LinkTint::kOverload);

  Qt3DCore::QEntity root;
  RobotScene scene(&root);
  scene.setModel(xmate::XMATE7_PRO);
  const QColor housing = scene.linkColor(2);
  scene.setLinkTints(tints);
  QCOMPARE(scene.linkColor(2), RobotScene::amber());
  QCOMPARE(scene.linkColor(5), RobotScene::red());
  QCOMPARE(scene.linkColor(1), housing);
  scene.setLinkTints({});
  QCOMPARE(scene.linkColor(2), housing);
}

void TestView3dOffscreen::sceneShowsBoxWaypointsPath() {
  Qt3DCore::QEntity root;
  RobotScene scene(&root);
  scene.setModel(xmate::XMATE7);
  QVERIFY(!scene.safetyBoxVisible());
  QMatrix4x4 frame;
  frame.translate(0.5f, 0, 0.4f);
  scene.setSafetyBox(true, QVector3D(1.0f, 0.8f, 0.6f), frame);
  QVERIFY(scene.safetyBoxVisible());
  scene.setSafetyBox(false, QVector3D(1.0f, 0.8f, 0.6f), frame);
  QVERIFY(!scene.safetyBoxVisible());
  scene.setWaypoints({{0.5f, 0, 0.5f}, {0.5f, 0.2f, 0.5f}, {0.4f, 0.2f, 0.3f}});
  QCOMPARE(scene.waypointCount(), 3);
  scene.setWaypoints({{0.5f, 0, 0.5f}});
  QCOMPARE(scene.waypointCount(), 1);
  scene.setPlannedPath({{0.5f, 0, 0.5f}, {0.5f, 0.1f, 0.5f}, {0.5f, 0.2f, 0.5f}});
  QCOMPARE(scene.plannedPathPointCount(), 3);
  // Switching the model keeps the overlays.
  scene.setModel(xmate::XMATE3_PRO);
  QCOMPARE(scene.waypointCount(), 1);
  QCOMPARE(scene.linkCount(), 8);
}

void TestView3dOffscreen::springForceIsClamped() {
  const QVector3D tcp(0.5f, 0, 0.5f);
  QVector3D f = springForce(tcp, tcp + QVector3D(0.1f, 0, 0), 150, 60);
  QVERIFY(std::abs(f.x() - 15.0f) < 1e-4f && f.y() == 0 && f.z() == 0);
  f = springForce(tcp, tcp + QVector3D(0, 3, 4), 150, 60);
  QVERIFY(std::abs(f.length() - 60.0f) < 1e-3f);
  QVERIFY((f.normalized() - QVector3D(0, 0.6f, 0.8f)).length() < 1e-5f);
  QCOMPARE(springForce(tcp, tcp, 150, 60), QVector3D());
}

void TestView3dOffscreen::cameraRayHitsProjectedPoint() {
  OrbitCamera camera = OrbitCamera::framing(1.0);
  const QSizeF viewport(800, 600);
  const QVector3D point(0.3f, -0.2f, 0.7f);
  QPointF pixel;
  QVERIFY(camera.project(point, viewport, pixel));
  const Ray ray = camera.ray(pixel, viewport);
  const QVector3D on_plane = intersectPlane(ray, point, camera.forward());
  QVERIFY2((on_plane - point).length() < 1e-4f, qPrintable(QString::number(double((on_plane - point).length()))));
  // The target is in the middle of the view; orbiting and zooming keep it there.
  QVERIFY(camera.project(camera.target, viewport, pixel));
  QVERIFY(std::abs(pixel.x() - 400) < 1e-3 && std::abs(pixel.y() - 300) < 1e-3);
  camera.rotate(120, -40);
  camera.zoom(3);
  QVERIFY(camera.project(camera.target, viewport, pixel));
  QVERIFY(std::abs(pixel.x() - 400) < 1e-3 && std::abs(pixel.y() - 300) < 1e-3);
  QVERIFY(camera.pitch_deg <= 85 && camera.pitch_deg >= -85);
  // Panning moves the target across the screen by the dragged amount.
  const QVector3D before = camera.target;
  camera.pan(50, 0, 600);
  QVERIFY(camera.project(before, viewport, pixel));
  QVERIFY2(std::abs(pixel.x() - 450) < 0.5, qPrintable(QString::number(pixel.x())));
}

void TestView3dOffscreen::softwareRenderersAreRecognised() {
  QVERIFY(isSoftwareRenderer(QStringLiteral("llvmpipe (LLVM 15.0.6, 256 bits)")));
  QVERIFY(isSoftwareRenderer(QStringLiteral("softpipe")));
  QVERIFY(isSoftwareRenderer(QStringLiteral("Mesa X11 Software Rasterizer")));
  QVERIFY(!isSoftwareRenderer(QStringLiteral("Mesa Intel(R) UHD Graphics 620 (KBL GT2)")));
  QVERIFY(!isSoftwareRenderer(QStringLiteral("NVIDIA GeForce RTX 3060/PCIe/SSE2")));
  QVERIFY(!isSoftwareRenderer(QString()));
}

namespace {

std::vector<const model::RobotSpec*> kukaSpecs() {
  std::vector<const model::RobotSpec*> specs;
  for (const model::RobotSpec& spec : model::allRobotSpecs())
    if (spec.family == model::RobotFamily::kKuka) specs.push_back(&spec);
  return specs;
}

bool contains(const CorrectionEnvelope& e, const QVector3D& p, float tolerance = 1e-5f) {
  for (int axis = 0; axis < 3; ++axis)
    if (p[axis] < e.min[axis] - tolerance || p[axis] > e.max[axis] + tolerance) return false;
  return true;
}

}  // namespace

// Both KUKA models: base + 6 links with meshes, posed by the core's forward kinematics; the arm
// starts where the KUKA simulator starts.
void TestView3dOffscreen::kukaModelsLoadAndPose() {
  const std::vector<const model::RobotSpec*> specs = kukaSpecs();
  QCOMPARE(int(specs.size()), 2);
  Qt3DCore::QEntity root;
  RobotScene scene(&root);
  std::mt19937 rng(11);
  for (const model::RobotSpec* spec : specs) {
    const QString name = QString::fromLatin1(spec->name.data(), qsizetype(spec->name.size()));
    const ArmPoser poser(*spec);
    QCOMPARE(poser.spec().name, spec->name);
    QCOMPARE(poser.dof(), 6);
    QCOMPARE(int(poser.links().size()), 7);
    for (const LinkVisual& link : poser.links()) {
      QVERIFY2(!link.mesh.isEmpty(), qPrintable(name + '/' + link.name));
      QVERIFY2(loadMeshData(link.mesh, link.scale).triangleCount() > 100, qPrintable(name + '/' + link.name));
    }
    scene.setModel(*spec);
    QCOMPARE(scene.linkCount(), 7);
    QCOMPARE(scene.poser()->spec().name, spec->name);
    // Home: the KUKA simulator's start pose (A1..A6 = 0, -90, 90, 0, 90, 0 deg).
    const std::array<double, 6> start_deg = xmate::sim::KrcConfig{}.start_deg;
    for (int i = 0; i < 6; ++i)
      QVERIFY(std::abs(scene.jointPositions()[size_t(i)] - start_deg[size_t(i)] * M_PI / 180) < 1e-9);
    QCOMPARE(scene.jointPositions()[6], 0.0);
    const model::ArmModel arm = model::makeArmModel(model::loadRobotChain(*spec), *spec);
    for (int trial = 0; trial < 10; ++trial) {
      const std::array<double, 7> q = randomPose(*spec, rng);
      scene.setJointPositions(q);
      model::JointVector jq = model::JointVector::Zero();
      for (int i = 0; i < 6; ++i) jq[i] = q[size_t(i)];
      model::LinkFrames frames;
      model::forwardKinematics(arm, jq, frames);
      for (int i = 0; i < 6; ++i)
        QVERIFY2(maxDifference(scene.linkTransform(i + 1), toMatrix(frames.links[size_t(i)])) < 1e-5,
                 qPrintable(name + QStringLiteral(" link %1").arg(i + 1)));
      QVERIFY((scene.tcpPosition() - toMatrix(model::flangePose(arm, jq)).column(3).toVector3D()).length() < 1e-5f);
    }
  }
  // Back to an xMate: 8 links again.
  scene.setModel(xmate::XMATE7_PRO);
  QCOMPARE(scene.linkCount(), 8);
}

void TestView3dOffscreen::placeholderKeepsAKukaModel() {
  RobotView view;
  QVERIFY(!view.is3D());
  const model::RobotSpec* kr16 = model::findRobotSpec("kr16_2");
  QVERIFY(kr16);
  view.setModel(*kr16);
  QCOMPARE(view.spec().name, kr16->name);
  view.setCorrectionEnvelope(true, QVector3D(0, 0, 0), QVector3D(0.1f, 0.1f, 0.1f));  // ignored, no crash
  view.setPullEnabled(false, QStringLiteral("why"));
  QVERIFY(!view.beginPull(QPointF(10, 10)));
}

// The envelope holds the flange at the start pose and at every corner of the correction limits;
// it grows with the limits and shrinks to the start position without any.
void TestView3dOffscreen::correctionEnvelopeSpansTheLimits() {
  const ArmPoser poser(*model::findRobotSpec("kr6_r900_sixx"));
  const std::array<double, 7> home = ArmPoser::homePose(poser.spec());
  std::array<double, 6> q_on{};
  for (size_t i = 0; i < 6; ++i) q_on[i] = home[i];
  const double d5 = 5 * M_PI / 180;
  std::array<double, 6> lower, upper;
  lower.fill(-d5);
  upper.fill(d5);
  const CorrectionEnvelope e = correctionEnvelope(poser, q_on, lower, upper);
  QVERIFY(e.valid);
  std::array<double, 7> start{};
  std::copy(q_on.begin(), q_on.end(), start.begin());
  const QVector3D flange = poser.flangePose(start).column(3).toVector3D();
  QVERIFY((e.start - flange).length() < 1e-5f);
  QVERIFY(contains(e, flange));
  std::mt19937 rng(3);
  std::uniform_int_distribution<int> side(0, 1);
  for (int trial = 0; trial < 20; ++trial) {
    std::array<double, 7> q = start;
    for (size_t i = 0; i < 6; ++i) q[i] += side(rng) ? upper[i] : lower[i];
    QVERIFY(contains(e, poser.flangePose(q).column(3).toVector3D(), 1e-4f));
  }
  const QVector3D size = e.max - e.min;
  for (int axis = 0; axis < 3; ++axis) {
    // +-5 deg on every axis of a 0.9 m arm: centimetres, not metres.
    QVERIFY2(size[axis] > 0.01f && size[axis] < 0.5f, qPrintable(QString::number(double(size[axis]))));
  }
  // Only A1 may move (+-5 deg about the vertical axis): no height change.
  std::array<double, 6> none{};
  std::array<double, 6> a1_lower = none, a1_upper = none;
  a1_lower[0] = -d5;
  a1_upper[0] = d5;
  const CorrectionEnvelope a1 = correctionEnvelope(poser, q_on, a1_lower, a1_upper);
  QVERIFY(a1.max.z() - a1.min.z() < 1e-5f);
  QVERIFY(a1.max.y() - a1.min.y() > 0.01f);
  // Wider limits, larger box; no limits, a point.
  lower.fill(-2 * d5);
  upper.fill(2 * d5);
  const CorrectionEnvelope wide = correctionEnvelope(poser, q_on, lower, upper);
  QVERIFY(contains(wide, e.min) && contains(wide, e.max));
  QVERIFY((wide.max - wide.min).length() > (e.max - e.min).length());
  // The sample context's +-90 deg: random corrections stay within the box, give or take the
  // sampling's centimetres.
  lower.fill(-M_PI / 2);
  upper.fill(M_PI / 2);
  const CorrectionEnvelope big = correctionEnvelope(poser, q_on, lower, upper);
  double worst = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    std::array<double, 7> q = start;
    for (int i = 0; i < 6; ++i) {
      std::uniform_real_distribution<double> d(std::max(q_on[size_t(i)] + lower[size_t(i)], poser.lower(i)),
                                               std::min(q_on[size_t(i)] + upper[size_t(i)], poser.upper(i)));
      q[size_t(i)] = d(rng);
    }
    const QVector3D p = poser.flangePose(q).column(3).toVector3D();
    for (int axis = 0; axis < 3; ++axis)
      worst = std::max({worst, double(big.min[axis] - p[axis]), double(p[axis] - big.max[axis])});
  }
  QVERIFY2(worst < 0.03, qPrintable(QString::number(worst)));
  const CorrectionEnvelope still = correctionEnvelope(poser, q_on, none, none);
  QVERIFY((still.max - still.min).length() < 1e-6f);
  QVERIFY((still.min - flange).length() < 1e-5f);
}

void TestView3dOffscreen::sceneShowsCorrectionEnvelope() {
  Qt3DCore::QEntity root;
  RobotScene scene(&root);
  scene.setModel(*model::findRobotSpec("kr6_r900_sixx"));
  QVERIFY(!scene.correctionEnvelopeVisible());
  scene.setCorrectionEnvelope(true, QVector3D(0.4f, -0.1f, 0.5f), QVector3D(0.5f, 0.1f, 0.6f));
  QVERIFY(scene.correctionEnvelopeVisible());
  QCOMPARE(scene.correctionEnvelopeMin(), QVector3D(0.4f, -0.1f, 0.5f));
  QCOMPARE(scene.correctionEnvelopeMax(), QVector3D(0.5f, 0.1f, 0.6f));
  scene.setModel(*model::findRobotSpec("kr16_2"));  // a model change keeps the overlays
  QVERIFY(scene.correctionEnvelopeVisible());
  scene.setCorrectionEnvelope(false);
  QVERIFY(!scene.correctionEnvelopeVisible());
}

QTEST_MAIN(TestView3dOffscreen)
#include "test_view3d_offscreen.moc"
