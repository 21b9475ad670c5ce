// SPDX-License-Identifier: Apache-2.0
// Small Qt3D building blocks of the 3D view: a triangle mesh from MeshData, coloured line sets
// (grid, box edges, path, spring) that can be replaced at run time, and lit solid parts.
#pragma once

#include <QColor>
#include <QVector3D>

#include <Qt3DCore/QEntity>
#include <Qt3DCore/QGeometry>
#include <Qt3DCore/QTransform>
#include <Qt3DExtras/QPhongMaterial>
#include <Qt3DRender/QGeometryRenderer>

#include <vector>

#include "mesh_data.h"

namespace Qt3DCore {
class QBuffer;
}

namespace rci::ui {

// Indexed triangles with normals, ready to draw.
Qt3DRender::QGeometryRenderer* makeMeshRenderer(const MeshData& mesh, Qt3DCore::QNode* parent);

// A Phong material that reads well on a dark background: ambient a third of the colour, soft
// specular highlight.
Qt3DExtras::QPhongMaterial* makeSolidMaterial(const QColor& color, Qt3DCore::QNode* parent);
void setSolidColor(Qt3DExtras::QPhongMaterial* material, const QColor& color);

// An entity drawing coloured line segments (pairs of points) or a strip; replaceable.
class LineSet {
 public:
  enum class Kind { kSegments, kStrip };
  LineSet(Qt3DCore::QEntity* parent, Kind kind);
  // points: pairs (kSegments) or a polyline (kStrip); colors: one per point.
  void setLines(const std::vector<QVector3D>& points, const std::vector<QColor>& colors);
  void setLines(const std::vector<QVector3D>& points, const QColor& color);
  void setVisible(bool visible);
  Qt3DCore::QEntity* entity() const { return entity_; }
  Qt3DCore::QTransform* transform() const { return transform_; }
  int pointCount() const { return count_; }

 private:
  Qt3DCore::QEntity* entity_;
  Qt3DCore::QTransform* transform_;
  Qt3DCore::QBuffer* buffer_;
  Qt3DCore::QAttribute* position_;
  Qt3DCore::QAttribute* color_;
  Qt3DRender::QGeometryRenderer* renderer_;
  int count_ = 0;
  bool visible_ = true;
};

// An entity of its own under parent, placed by a new transform; components added by the caller.
Qt3DCore::QEntity* makeEntity(Qt3DCore::QNode* parent, Qt3DCore::QTransform** transform = nullptr);

}  // namespace rci::ui
