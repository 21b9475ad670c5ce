// SPDX-License-Identifier: Apache-2.0
// Loads link meshes with assimp into MeshData (mesh_data.h).
#include "mesh_data.h"

#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <cfloat>
#include <stdexcept>
#include <tuple>

namespace rci::ui {
namespace {

QVector3D toQt(const aiVector3D& v) { return {v.x, v.y, v.z}; }

void appendMesh(const aiMesh& mesh, const QVector3D& scale, MeshData& out) {
  const auto base = static_cast<quint32>(out.vertexCount());
  const QVector3D normal_scale(1.0f / scale.x(), 1.0f / scale.y(), 1.0f / scale.z());
  for (unsigned i = 0; i < mesh.mNumVertices; ++i) {
    const QVector3D p = toQt(mesh.mVertices[i]) * scale;
    const QVector3D n = mesh.HasNormals() ? (toQt(mesh.mNormals[i]) * normal_scale).normalized() : QVector3D(0, 0, 1);
    out.vertices.insert(out.vertices.end(), {p.x(), p.y(), p.z(), n.x(), n.y(), n.z()});
    out.min = QVector3D(std::min(out.min.x(), p.x()), std::min(out.min.y(), p.y()), std::min(out.min.z(), p.z()));
    out.max = QVector3D(std::max(out.max.x(), p.x()), std::max(out.max.y(), p.y()), std::max(out.max.z(), p.z()));
  }
  for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
    const aiFace& face = mesh.mFaces[f];
    if (face.mNumIndices != 3) continue;  // points and lines left by the triangulation
    for (unsigned k = 0; k < 3; ++k) out.indices.push_back(base + face.mIndices[k]);
  }
}

}  // namespace

MeshData loadMeshData(const QString& file, const QVector3D& scale) {
  Assimp::Importer importer;
  importer.SetPropertyFloat(AI_CONFIG_PP_GSN_MAX_SMOOTHING_ANGLE, 45.0f);
  const unsigned steps = aiProcess_Triangulate | aiProcess_DropNormals | aiProcess_GenSmoothNormals |
                         aiProcess_JoinIdenticalVertices;
  const aiScene* scene = importer.ReadFile(file.toStdString(), steps);
  if (!scene || !scene->mRootNode) {
    throw std::runtime_error("Cannot read the mesh " + file.toStdString() + ": " + importer.GetErrorString() +
                             ". Check that the file exists and is an STL/OBJ/DAE mesh (RCI_DATA_DIR).");
  }
  MeshData data;
  data.min = QVector3D(FLT_MAX, FLT_MAX, FLT_MAX);
  data.max = -data.min;
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) appendMesh(*scene->mMeshes[m], scale, data);
  if (data.indices.empty()) {
    throw std::runtime_error("The mesh " + file.toStdString() + " holds no triangles. Regenerate the robot "
                             "descriptions (docs/robot_descriptions.md).");
  }
  return data;
}

std::shared_ptr<const MeshData> MeshCache::get(const QString& file, const QVector3D& scale) {
  const auto key = std::make_pair(file, std::make_tuple(scale.x(), scale.y(), scale.z()));
  auto it = meshes_.find(key);
  if (it == meshes_.end()) it = meshes_.emplace(key, std::make_shared<const MeshData>(loadMeshData(file, scale))).first;
  return it->second;
}

}  // namespace rci::ui
