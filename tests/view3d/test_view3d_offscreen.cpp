// SPDX-License-Identifier: Apache-2.0
// The 3D view without a display: the factory's placeholder (no hang under the offscreen platform),
// link meshes of every model through assimp, link poses against the core's FK, tints, camera maths,
// recognising software OpenGL renderers.
#include <QLabel>
#include <QSignalSpy>
#include <QtTest>

#include <Qt3DCore/QEntity>

#include <cmath>
#include <random>

#include "model/kinematics.h"
#include "model/urdf_loader.h"
#include "session/session.h"
#include "view3d/arm_poser.h"
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

QTEST_MAIN(TestView3dOffscreen)
#include "test_view3d_offscreen.moc"
