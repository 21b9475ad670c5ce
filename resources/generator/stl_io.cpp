// SPDX-License-Identifier: Apache-2.0
// Binary STL writer and reader (see stl_io.h). Bytes are assembled explicitly in little-endian
// order so the output does not depend on the host.
#include "generator/stl_io.h"

#include <bit>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <stdexcept>

namespace xmate::robotgen {
namespace {

constexpr std::size_t kHeaderBytes = 80;
constexpr std::size_t kTriangleBytes = 50;  // 12 floats + 2 attribute bytes

void putU32(std::string& out, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) out.push_back(char((v >> (8 * i)) & 0xFF));
}

void putFloat(std::string& out, float f) { putU32(out, std::bit_cast<std::uint32_t>(f)); }

void putVector(std::string& out, const Eigen::Vector3d& v) {
  for (int i = 0; i < 3; ++i) putFloat(out, float(v[i]));
}

std::uint32_t getU32(const std::string& in, std::size_t at) {
  std::uint32_t v = 0;
  for (int i = 0; i < 4; ++i) v |= std::uint32_t(static_cast<unsigned char>(in[at + i])) << (8 * i);
  return v;
}

Eigen::Vector3f getVector(const std::string& in, std::size_t at) {
  Eigen::Vector3f v;
  for (int i = 0; i < 3; ++i) v[i] = std::bit_cast<float>(getU32(in, at + 4 * i));
  return v;
}

}  // namespace

std::string binaryStl(const TriangleMesh& mesh, std::string_view header) {
  if (header.size() > kHeaderBytes || header.starts_with("solid"))
    throw std::invalid_argument("binaryStl: the header must be at most 80 characters and not start with \"solid\"");
  std::string out(header);
  out.resize(kHeaderBytes, ' ');
  putU32(out, std::uint32_t(mesh.triangles.size()));
  for (const auto& t : mesh.triangles) {
    const Eigen::Vector3d& a = mesh.vertices[t[0]];
    const Eigen::Vector3d& b = mesh.vertices[t[1]];
    const Eigen::Vector3d& c = mesh.vertices[t[2]];
    putVector(out, (b - a).cross(c - a).normalized());
    putVector(out, a);
    putVector(out, b);
    putVector(out, c);
    out.append(2, '\0');
  }
  return out;
}

std::vector<StlTriangle> readBinaryStl(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw std::runtime_error("STL file not found or unreadable: " + file.string());
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (bytes.size() < kHeaderBytes + 4)
    throw std::runtime_error("STL file too short to be binary STL: " + file.string());
  const std::uint32_t count = getU32(bytes, kHeaderBytes);
  if (bytes.size() != kHeaderBytes + 4 + std::size_t(count) * kTriangleBytes)
    throw std::runtime_error("STL file " + file.string() + " says it holds " + std::to_string(count) +
                             " triangles but its size does not match; it is truncated or not binary STL");
  std::vector<StlTriangle> triangles(count);
  for (std::uint32_t i = 0; i < count; ++i) {
    const std::size_t at = kHeaderBytes + 4 + std::size_t(i) * kTriangleBytes;
    triangles[i].normal = getVector(bytes, at);
    for (int v = 0; v < 3; ++v) triangles[i].vertices[v] = getVector(bytes, at + 12 + 12 * v);
  }
  return triangles;
}

}  // namespace xmate::robotgen
