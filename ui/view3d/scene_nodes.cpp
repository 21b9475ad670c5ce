// SPDX-License-Identifier: Apache-2.0
// Qt3D building blocks of the 3D view (scene_nodes.h).
#include "scene_nodes.h"

#include <Qt3DCore/QAttribute>
#include <Qt3DCore/QBuffer>
#include <Qt3DExtras/QPerVertexColorMaterial>

#include <cstring>

namespace rci::ui {
namespace {

using Qt3DCore::QAttribute;

QAttribute* makeAttribute(Qt3DCore::QBuffer* buffer, const QString& name, int offset, int stride, int count,
                          Qt3DCore::QNode* parent) {
  auto* a = new QAttribute(parent);
  a->setName(name);
  a->setAttributeType(QAttribute::VertexAttribute);
  a->setVertexBaseType(QAttribute::Float);
  a->setVertexSize(3);
  a->setBuffer(buffer);
  a->setByteOffset(uint(offset));
  a->setByteStride(uint(stride));
  a->setCount(uint(count));
  return a;
}

template <typename T>
QByteArray bytesOf(const std::vector<T>& v) {
  QByteArray bytes(qsizetype(v.size() * sizeof(T)), Qt::Uninitialized);
  if (!v.empty()) std::memcpy(bytes.data(), v.data(), v.size() * sizeof(T));
  return bytes;
}

}  // namespace

Qt3DRender::QGeometryRenderer* makeMeshRenderer(const MeshData& mesh, Qt3DCore::QNode* parent) {
  auto* renderer = new Qt3DRender::QGeometryRenderer(parent);
  auto* geometry = new Qt3DCore::QGeometry(renderer);
  auto* vertices = new Qt3DCore::QBuffer(geometry);
  vertices->setData(bytesOf(mesh.vertices));
  auto* indices = new Qt3DCore::QBuffer(geometry);
  indices->setData(bytesOf(mesh.indices));
  const int stride = 6 * sizeof(float);
  geometry->addAttribute(makeAttribute(vertices, QAttribute::defaultPositionAttributeName(), 0, stride,
                                       mesh.vertexCount(), geometry));
  geometry->addAttribute(makeAttribute(vertices, QAttribute::defaultNormalAttributeName(), 3 * sizeof(float),
                                       stride, mesh.vertexCount(), geometry));
  auto* index = new QAttribute(geometry);
  index->setAttributeType(QAttribute::IndexAttribute);
  index->setVertexBaseType(QAttribute::UnsignedInt);
  index->setBuffer(indices);
  index->setCount(uint(mesh.indices.size()));
  geometry->addAttribute(index);
  renderer->setGeometry(geometry);
  renderer->setPrimitiveType(Qt3DRender::QGeometryRenderer::Triangles);
  renderer->setVertexCount(int(mesh.indices.size()));
  return renderer;
}

Qt3DExtras::QPhongMaterial* makeSolidMaterial(const QColor& color, Qt3DCore::QNode* parent) {
  auto* material = new Qt3DExtras::QPhongMaterial(parent);
  material->setSpecular(QColor::fromRgbF(0.35f, 0.35f, 0.35f));
  material->setShininess(60);
  setSolidColor(material, color);
  return material;
}

void setSolidColor(Qt3DExtras::QPhongMaterial* material, const QColor& color) {
  material->setDiffuse(color);
  material->setAmbient(QColor::fromRgbF(color.redF() * 0.38f, color.greenF() * 0.38f, color.blueF() * 0.4f));
}

Qt3DCore::QEntity* makeEntity(Qt3DCore::QNode* parent, Qt3DCore::QTransform** transform) {
  auto* entity = new Qt3DCore::QEntity(parent);
  auto* t = new Qt3DCore::QTransform(entity);
  entity->addComponent(t);
  if (transform) *transform = t;
  return entity;
}

LineSet::LineSet(Qt3DCore::QEntity* parent, Kind kind) {
  entity_ = makeEntity(parent, &transform_);
  renderer_ = new Qt3DRender::QGeometryRenderer(entity_);
  auto* geometry = new Qt3DCore::QGeometry(renderer_);
  buffer_ = new Qt3DCore::QBuffer(geometry);
  buffer_->setData(QByteArray(6 * sizeof(float), '\0'));  // never empty: the renderer warns about empty buffers
  const int stride = 6 * sizeof(float);
  position_ = makeAttribute(buffer_, QAttribute::defaultPositionAttributeName(), 0, stride, 0, geometry);
  color_ = makeAttribute(buffer_, QAttribute::defaultColorAttributeName(), 3 * sizeof(float), stride, 0, geometry);
  geometry->addAttribute(position_);
  geometry->addAttribute(color_);
  renderer_->setGeometry(geometry);
  renderer_->setPrimitiveType(kind == Kind::kStrip ? Qt3DRender::QGeometryRenderer::LineStrip
                                                   : Qt3DRender::QGeometryRenderer::Lines);
  renderer_->setVertexCount(0);
  entity_->addComponent(renderer_);
  entity_->addComponent(new Qt3DExtras::QPerVertexColorMaterial(entity_));
}

void LineSet::setLines(const std::vector<QVector3D>& points, const std::vector<QColor>& colors) {
  std::vector<float> data;
  data.reserve(points.size() * 6);
  for (size_t i = 0; i < points.size(); ++i) {
    const QColor c = i < colors.size() ? colors[i] : QColor(Qt::white);
    data.insert(data.end(), {points[i].x(), points[i].y(), points[i].z(), float(c.redF()), float(c.greenF()),
                             float(c.blueF())});
  }
  if (data.empty()) data.assign(6, 0.0f);  // see the constructor
  buffer_->setData(bytesOf(data));
  count_ = int(points.size());
  position_->setCount(uint(count_));
  color_->setCount(uint(count_));
  renderer_->setVertexCount(count_);
  entity_->setEnabled(visible_ && count_ >= 2);
}

void LineSet::setVisible(bool visible) {
  visible_ = visible;
  entity_->setEnabled(visible_ && count_ >= 2);
}

void LineSet::setLines(const std::vector<QVector3D>& points, const QColor& color) {
  setLines(points, std::vector<QColor>(points.size(), color));
}

}  // namespace rci::ui
