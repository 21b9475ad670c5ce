// SPDX-License-Identifier: Apache-2.0
// The robot view's Qt3D scene (robot_scene.h).
#include "robot_scene.h"

#include <Qt3DExtras/QConeMesh>
#include <Qt3DExtras/QCylinderMesh>
#include <Qt3DRender/QDirectionalLight>

#include <algorithm>
#include <cmath>

namespace rci::ui {
namespace {

const QColor kGridMinor(0x44, 0x4b, 0x54);
const QColor kGridMajor(0x5a, 0x63, 0x6e);
const QColor kBoxColor(0x4f, 0xb3, 0xff);
const QColor kEnvelopeColor(0xb3, 0x9d, 0xdb);
const QColor kEnvelopeEdgeColor(0x7a, 0x6f, 0x9c);  // dimmer than the safety box: a background fact
const QColor kWaypointColor(0xff, 0x9f, 0x1c);
const QColor kPathColor(0x4d, 0xd0, 0xe1);
const QColor kSpringColor(0xff, 0xd5, 0x4f);

// One arrow of the TCP frame: a cylinder shaft and a cone tip along +y, turned by rotation.
void addAxis(Qt3DCore::QEntity* frame, const QQuaternion& rotation, const QColor& color) {
  constexpr float kLength = 0.085f, kRadius = 0.0042f, kTip = 0.022f;
  auto* material = makeSolidMaterial(color, frame);
  material->setAmbient(color.darker(170));
  Qt3DCore::QTransform* t = nullptr;
  Qt3DCore::QEntity* shaft = makeEntity(frame, &t);
  t->setRotation(rotation);
  t->setTranslation(rotation.rotatedVector(QVector3D(0, kLength / 2, 0)));
  auto* cylinder = new Qt3DExtras::QCylinderMesh(shaft);
  cylinder->setRadius(kRadius);
  cylinder->setLength(kLength);
  cylinder->setSlices(16);
  shaft->addComponent(cylinder);
  shaft->addComponent(material);
  Qt3DCore::QEntity* tip = makeEntity(frame, &t);
  t->setRotation(rotation);
  t->setTranslation(rotation.rotatedVector(QVector3D(0, kLength + kTip / 2, 0)));
  auto* cone = new Qt3DExtras::QConeMesh(tip);
  cone->setBottomRadius(2.4f * kRadius);
  cone->setTopRadius(0);
  cone->setLength(kTip);
  cone->setSlices(16);
  tip->addComponent(cone);
  tip->addComponent(material);
}

void addDirectionalLight(Qt3DCore::QEntity* root, const QVector3D& direction, float intensity) {
  Qt3DCore::QEntity* entity = makeEntity(root);
  auto* light = new Qt3DRender::QDirectionalLight(entity);
  light->setWorldDirection(direction.normalized());
  light->setIntensity(intensity);
  light->setColor(Qt::white);
  entity->addComponent(light);
}

// The 12 edges of a box of the given size centred at the origin.
std::vector<QVector3D> boxEdges(const QVector3D& size) {
  const QVector3D h = size / 2;
  std::vector<QVector3D> corners;
  for (int i = 0; i < 8; ++i)
    corners.emplace_back((i & 1) ? h.x() : -h.x(), (i & 2) ? h.y() : -h.y(), (i & 4) ? h.z() : -h.z());
  std::vector<QVector3D> lines;
  for (int i = 0; i < 8; ++i)
    for (int bit : {1, 2, 4})
      if (!(i & bit)) lines.insert(lines.end(), {corners[size_t(i)], corners[size_t(i | bit)]});
  return lines;
}

QColor tintColor(LinkTint tint, const QColor& base) {
  switch (tint) {
    case LinkTint::kNearLimit: return RobotScene::amber();
    case LinkTint::kOverload: return RobotScene::red();
    case LinkTint::kNone: break;
  }
  return base;
}

}  // namespace

RobotScene::RobotScene(Qt3DCore::QEntity* root) : root_(root) {
  buildLights();
  buildGround(1.0);
  buildTcpFrame();
  buildSafetyBox();
  buildCorrectionEnvelope();
  waypoint_mesh_ = new Qt3DExtras::QSphereMesh(root_);
  waypoint_mesh_->setRadius(0.015f);
  waypoint_mesh_->setRings(12);
  waypoint_mesh_->setSlices(16);
  waypoint_material_ = makeSolidMaterial(kWaypointColor, root_);
  path_ = std::make_unique<LineSet>(root_, LineSet::Kind::kStrip);
  spring_ = std::make_unique<LineSet>(root_, LineSet::Kind::kSegments);
  spring_->setVisible(false);
  spring_handle_ = makeEntity(root_, &spring_handle_transform_);
  auto* ball = new Qt3DExtras::QSphereMesh(spring_handle_);
  ball->setRadius(0.011f);
  spring_handle_->addComponent(ball);
  spring_handle_->addComponent(makeSolidMaterial(kSpringColor, spring_handle_));
  spring_handle_->setEnabled(false);
}

RobotScene::~RobotScene() = default;

void RobotScene::buildLights() {
  addDirectionalLight(root_, QVector3D(-0.45f, -0.3f, -1.0f), 0.85f);
  addDirectionalLight(root_, QVector3D(0.7f, 0.5f, -0.25f), 0.35f);
  addDirectionalLight(root_, QVector3D(0.2f, -0.9f, 0.35f), 0.18f);
}

void RobotScene::buildGround(double reach) {
  if (!grid_) grid_ = std::make_unique<LineSet>(root_, LineSet::Kind::kSegments);
  const int half_steps = int(std::ceil(reach * 1.5 / 0.5)) * 5;  // whole half-metres, 0.1 m cells
  const float half = half_steps * 0.1f;
  std::vector<QVector3D> points;
  std::vector<QColor> colors;
  for (int i = -half_steps; i <= half_steps; ++i) {
    const float v = i * 0.1f;
    const QColor c = (i % 5 == 0) ? kGridMajor : kGridMinor;
    points.insert(points.end(), {{v, -half, 0}, {v, half, 0}, {-half, v, 0}, {half, v, 0}});
    colors.insert(colors.end(), 4, c);
  }
  // The base frame's x (red) and y (green) axes on the floor.
  points.insert(points.end(), {{0, 0, 0.0005f}, {0.3f, 0, 0.0005f}, {0, 0, 0.0005f}, {0, 0.3f, 0.0005f}});
  colors.insert(colors.end(), {QColor(0xe5, 0x48, 0x48), QColor(0xe5, 0x48, 0x48), QColor(0x4c, 0xc2, 0x5a),
                               QColor(0x4c, 0xc2, 0x5a)});
  grid_->setLines(points, colors);
}

void RobotScene::buildTcpFrame() {
  Qt3DCore::QEntity* frame = makeEntity(root_, &tcp_frame_);
  addAxis(frame, QQuaternion::fromAxisAndAngle(0, 0, 1, -90), QColor(0xe5, 0x39, 0x35));  // x
  addAxis(frame, QQuaternion(), QColor(0x43, 0xa0, 0x47));                                 // y
  addAxis(frame, QQuaternion::fromAxisAndAngle(1, 0, 0, 90), QColor(0x1e, 0x88, 0xe5));   // z
}

void RobotScene::buildSafetyBox() {
  box_ = makeEntity(root_, &box_transform_);
  box_mesh_ = new Qt3DExtras::QCuboidMesh(box_);
  auto* material = new Qt3DExtras::QPhongAlphaMaterial(box_);
  material->setAmbient(kBoxColor.darker(150));
  material->setDiffuse(kBoxColor);
  material->setSpecular(QColor(0, 0, 0));
  material->setAlpha(0.10f);
  box_->addComponent(box_mesh_);
  box_->addComponent(material);
  box_edges_ = std::make_unique<LineSet>(box_, LineSet::Kind::kSegments);
  box_->setEnabled(false);
}

void RobotScene::buildCorrectionEnvelope() {
  envelope_ = makeEntity(root_, &envelope_transform_);
  envelope_->setObjectName(QStringLiteral("correctionEnvelope"));
  envelope_mesh_ = new Qt3DExtras::QCuboidMesh(envelope_);
  auto* material = new Qt3DExtras::QPhongAlphaMaterial(envelope_);
  material->setAmbient(kEnvelopeColor.darker(150));
  material->setDiffuse(kEnvelopeColor);
  material->setSpecular(QColor(0, 0, 0));
  material->setAlpha(0.07f);
  envelope_->addComponent(envelope_mesh_);
  envelope_->addComponent(material);
  envelope_edges_ = std::make_unique<LineSet>(envelope_, LineSet::Kind::kSegments);
  envelope_->setEnabled(false);
}

void RobotScene::clearArm() {
  delete arm_;  // deletes every link entity below it
  arm_ = nullptr;
  links_.clear();
}

void RobotScene::setModel(xmate::XmateType type) { setModel(xmate::model::robotSpec(type)); }

void RobotScene::setModel(const xmate::model::RobotSpec& spec) {
  auto poser = std::make_unique<ArmPoser>(spec);
  std::vector<std::shared_ptr<const MeshData>> meshes;
  for (const LinkVisual& link : poser->links())
    meshes.push_back(link.mesh.isEmpty() ? nullptr : meshes_.get(link.mesh, link.scale));
  clearArm();
  poser_ = std::move(poser);
  arm_ = new Qt3DCore::QEntity(root_);
  for (size_t i = 0; i < meshes.size(); ++i) {
    const LinkVisual& visual = poser_->links()[i];
    LinkNode node;
    node.color = visual.color;
    node.entity = makeEntity(arm_, &node.transform);
    node.entity->setObjectName(visual.name);
    node.material = makeSolidMaterial(visual.color, node.entity);
    if (meshes[i]) {
      Qt3DCore::QTransform* offset = nullptr;
      Qt3DCore::QEntity* shape = makeEntity(node.entity, &offset);
      offset->setMatrix(visual.visual_origin);
      shape->addComponent(makeMeshRenderer(*meshes[i], shape));
      shape->addComponent(node.material);
    }
    links_.push_back(node);
  }
  buildGround(poser_->reach());
  tcp_set_ = false;
  q_ = ArmPoser::homePose(spec);
  updateLinks();
}

void RobotScene::setJointPositions(const std::array<double, 7>& q) {
  q_ = q;
  updateLinks();
}

void RobotScene::updateLinks() {
  if (!poser_) return;
  const std::vector<QMatrix4x4> poses = poser_->linkPoses(q_);
  for (size_t i = 0; i < links_.size() && i < poses.size(); ++i) links_[i].transform->setMatrix(poses[i]);
  if (!tcp_set_) {
    tcp_ = poser_->flangePose(q_);
    tcp_frame_->setMatrix(tcp_);
  }
}

void RobotScene::setTcpPose(const QMatrix4x4& pose) {
  tcp_ = pose;
  tcp_set_ = true;
  tcp_frame_->setMatrix(pose);
}

void RobotScene::setSafetyBox(bool enabled, const QVector3D& size, const QMatrix4x4& frame) {
  box_->setEnabled(enabled);
  box_transform_->setMatrix(frame);
  box_mesh_->setXExtent(size.x());
  box_mesh_->setYExtent(size.y());
  box_mesh_->setZExtent(size.z());
  box_edges_->setLines(boxEdges(size), kBoxColor);
}

bool RobotScene::safetyBoxVisible() const { return box_->isEnabled(); }

void RobotScene::setCorrectionEnvelope(bool visible, const QVector3D& min, const QVector3D& max) {
  envelope_->setEnabled(visible);
  if (!visible) return;
  envelope_min_ = min;
  envelope_max_ = max;
  // At least 2 mm along each axis, so that a limit of 0 on every axis still shows a speck.
  const QVector3D size(std::max(max.x() - min.x(), 0.002f), std::max(max.y() - min.y(), 0.002f),
                       std::max(max.z() - min.z(), 0.002f));
  envelope_transform_->setTranslation((min + max) / 2);
  envelope_mesh_->setXExtent(size.x());
  envelope_mesh_->setYExtent(size.y());
  envelope_mesh_->setZExtent(size.z());
  envelope_edges_->setLines(boxEdges(size), kEnvelopeEdgeColor);
}

bool RobotScene::correctionEnvelopeVisible() const { return envelope_->isEnabled(); }

void RobotScene::setWaypoints(const std::vector<QVector3D>& positions) {
  for (Qt3DCore::QEntity* e : waypoints_) delete e;
  waypoints_.clear();
  for (const QVector3D& p : positions) {
    Qt3DCore::QTransform* t = nullptr;
    Qt3DCore::QEntity* e = makeEntity(root_, &t);
    t->setTranslation(p);
    e->addComponent(waypoint_mesh_);
    e->addComponent(waypoint_material_);
    waypoints_.push_back(e);
  }
}

void RobotScene::setPlannedPath(const std::vector<QVector3D>& points) { path_->setLines(points, kPathColor); }

void RobotScene::setLinkTints(const std::vector<LinkTint>& tints) {
  for (size_t i = 1; i < links_.size(); ++i) {
    const LinkTint tint = i - 1 < tints.size() ? tints[i - 1] : LinkTint::kNone;
    setSolidColor(links_[i].material, tintColor(tint, links_[i].color));
  }
}

void RobotScene::setSpring(bool visible, const QVector3D& from, const QVector3D& to) {
  if (visible) spring_->setLines({from, to}, kSpringColor);
  spring_->setVisible(visible);
  spring_handle_transform_->setTranslation(to);
  spring_handle_->setEnabled(visible);
}

QMatrix4x4 RobotScene::linkTransform(int index) const { return links_.at(size_t(index)).transform->matrix(); }

QColor RobotScene::linkColor(int index) const { return links_.at(size_t(index)).material->diffuse(); }

}  // namespace rci::ui
