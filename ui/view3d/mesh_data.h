// SPDX-License-Identifier: Apache-2.0
// Link meshes for the 3D view: an STL (or any format assimp reads) loaded into indexed triangles
// with smooth normals, scaled to metres, plus a cache so each file is read once per view.
#pragma once

#include <QString>
#include <QVector3D>

#include <map>
#include <memory>
#include <tuple>
#include <utility>
#include <vector>

namespace rci::ui {

struct MeshData {
  std::vector<float> vertices;  // interleaved x y z nx ny nz, metres in the link's visual frame
  std::vector<quint32> indices; // three per triangle
  QVector3D min, max;           // bounding box of the vertices
  int vertexCount() const { return static_cast<int>(vertices.size() / 6); }
  int triangleCount() const { return static_cast<int>(indices.size() / 3); }
};

// Reads file with assimp, merges all its meshes, applies scale (per axis) to the positions and
// the matching inverse-transpose to the normals. Normals are smoothed across edges under 45°, so
// round housings look round and rims stay crisp. Throws std::runtime_error naming the file and the
// reason (missing, unreadable, no triangles).
MeshData loadMeshData(const QString& file, const QVector3D& scale = QVector3D(1, 1, 1));

// Keeps every mesh loaded so far, keyed by file and scale.
class MeshCache {
 public:
  std::shared_ptr<const MeshData> get(const QString& file, const QVector3D& scale);
  int size() const { return static_cast<int>(meshes_.size()); }

 private:
  std::map<std::pair<QString, std::tuple<float, float, float>>, std::shared_ptr<const MeshData>> meshes_;
};

}  // namespace rci::ui
