// SPDX-License-Identifier: Apache-2.0
// test_robot_description: for every model (xMate and KUKA), the committed URDF and meshes against
// the DH table, the robot spec and the generator; and the URDF loader's conversions and error messages.
#include <QTemporaryDir>
#include <QtTest>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <random>
#include <set>
#include <string>
#include <vector>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <assimp/Importer.hpp>
#include <assimp/scene.h>

#include "generator/mass_properties.h"
#include "generator/robot_generator.h"
#include "generator/stl_io.h"
#include "mesh_checks.h"
#include "model/chain.h"
#include "model/resource_locator.h"
#include "model/robot_spec.h"
#include "model/urdf_loader.h"

namespace fs = std::filesystem;
using xmate::model::Chain;
using xmate::model::ChainLink;
using xmate::model::RobotSpec;

namespace {

constexpr int kRandomConfigurations = 1000;
constexpr double kPoseTolerance = 1e-9;        // m and rotation-matrix entries
constexpr double kStlTolerance = 1e-6;         // m, committed vs regenerated vertices
constexpr std::uintmax_t kMaxMeshBytes = 300 * 1024;
constexpr double kMinExtent = 0.02, kMaxExtent = 1.0;  // m, plausible link sizes
constexpr double kMeshVolumeTolerance = 0.01;  // relative: 40-gon tessellation vs exact solids (~0.6 %)
constexpr double kMeshInertiaTolerance = 0.01; // relative Frobenius norm (~0.5 %)
constexpr double kMeshComTolerance = 1e-4;     // m (~1e-5)

const RobotSpec& fetchSpec() {
  QFETCH(QString, model);
  const RobotSpec* spec = xmate::model::findRobotSpec(model.toStdString());
  if (!spec) qFatal("unknown model in test data");
  return *spec;
}

void addModelRows() {
  QTest::addColumn<QString>("model");
  for (const RobotSpec& spec : xmate::model::allRobotSpecs())
    QTest::newRow(std::string(spec.name).c_str()) << QString::fromStdString(std::string(spec.name));
}

// Walks the loaded chain joint by joint: origin, then the rotation about the joint axis.
Eigen::Isometry3d chainFlangePose(const Chain& chain, const std::array<double, 7>& q) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  for (int i = 0; i < chain.dof; ++i) t = t * chain.joints[i].origin * Eigen::AngleAxisd(q[i], chain.joints[i].axis);
  return t * chain.flange;
}

std::vector<const ChainLink*> allLinks(const Chain& chain) {
  std::vector<const ChainLink*> links{&chain.base};
  for (int i = 0; i < chain.dof; ++i) links.push_back(&chain.links[i]);
  return links;
}

rci_test::IndexedMesh toIndexed(const xmate::robotgen::TriangleMesh& mesh) { return {mesh.vertices, mesh.triangles}; }

rci_test::IndexedMesh stlMesh(const fs::path& file) {
  std::vector<std::array<Eigen::Vector3d, 3>> soup;
  for (const auto& t : xmate::robotgen::readBinaryStl(file))
    soup.push_back({t.vertices[0].cast<double>(), t.vertices[1].cast<double>(), t.vertices[2].cast<double>()});
  return rci_test::weld(soup);
}

std::string readFile(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

fs::path writeFile(const QTemporaryDir& dir, const std::string& name, const std::string& text) {
  const fs::path file = fs::path(dir.path().toStdString()) / name;
  std::ofstream(file, std::ios::binary) << text;
  return file;
}

// The what() of the std::runtime_error f throws, or an empty string when it does not throw.
QString errorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::runtime_error& e) {
    return QString::fromStdString(e.what());
  }
  return {};
}

// A small serial URDF: base_link, one joint per entry of joint_types (joint1.., link1..), then a
// fixed joint to `end_link` (none when empty). joint1_origin and base_body customise the first parts.
std::string tinyUrdf(const std::vector<std::string>& joint_types, const std::string& end_link = "flange",
                     const std::string& base_body = "",
                     const std::string& joint1_origin = R"(<origin xyz="0 0 0.1" rpy="0 0 0"/>)") {
  std::string s = "<?xml version=\"1.0\"?>\n<robot name=\"tiny\">\n  <link name=\"base_link\">" + base_body + "</link>\n";
  std::string parent = "base_link";
  for (std::size_t i = 0; i < joint_types.size(); ++i) {
    const std::string n = std::to_string(i + 1);
    s += "  <joint name=\"joint" + n + "\" type=\"" + joint_types[i] + "\"><parent link=\"" + parent +
         "\"/><child link=\"link" + n + "\"/>" + (i == 0 ? joint1_origin : R"(<origin xyz="0 0 0.1" rpy="0 0 0"/>)") +
         R"(<axis xyz="0 0 1"/><limit lower="-1" upper="1" velocity="2" effort="3"/></joint>)" + "\n";
    s += "  <link name=\"link" + n + "\"/>\n";
    parent = "link" + n;
  }
  if (!end_link.empty())
    s += "  <joint name=\"flange_joint\" type=\"fixed\"><parent link=\"" + parent + "\"/><child link=\"" + end_link +
         "\"/><origin xyz=\"0 0 0.05\" rpy=\"0 0 0\"/></joint>\n  <link name=\"" + end_link + "\"/>\n";
  return s + "</robot>\n";
}

const std::vector<std::string> kSixRevolute(6, "revolute");

}  // namespace

class TestRobotDescription : public QObject {
  Q_OBJECT

 private slots:
  void loadsAndMatchesSpec_data() { addModelRows(); }
  void loadsAndMatchesSpec() {
    const RobotSpec& spec = fetchSpec();
    const Chain chain = xmate::model::loadRobotChain(spec);
    QCOMPARE(chain.name, std::string(spec.name));
    QCOMPARE(chain.dof, spec.dof);
    QCOMPARE(chain.base.name, std::string("base_link"));
    for (int i = 0; i < spec.dof; ++i) {
      const auto& j = chain.joints[i];
      QCOMPARE(j.name, "joint" + std::to_string(i + 1));
      QCOMPARE(chain.links[i].name, "link" + std::to_string(i + 1));
      // Exact: the file holds shortest round-trip decimals of the spec's doubles.
      QVERIFY(j.lower == spec.q_min[i]);
      QVERIFY(j.upper == spec.q_max[i]);
      QVERIFY(j.velocity == spec.dq_max[i]);
      QVERIFY(j.effort == spec.tau_max[i]);
      QVERIFY(j.axis.isApprox(spec.dh[i].axis_sign * Eigen::Vector3d::UnitZ()));  // KUKA A1, A4, A6: -z
    }
    for (const ChainLink* link : allLinks(chain)) {
      QVERIFY2(fs::path(link->mesh).is_absolute(), link->mesh.c_str());
      QVERIFY2(fs::is_regular_file(link->mesh), link->mesh.c_str());
      QCOMPARE(fs::path(link->mesh).filename().string(), link->name + ".stl");
      QVERIFY(link->mesh_scale == Eigen::Vector3d::Ones());
    }
  }

  void flangePoseMatchesDh_data() { addModelRows(); }
  void flangePoseMatchesDh() {
    const RobotSpec& spec = fetchSpec();
    const Chain chain = xmate::model::loadRobotChain(spec);
    std::mt19937_64 rng(20240611);
    double worst = 0;
    for (int n = 0; n < kRandomConfigurations; ++n) {
      std::array<double, 7> q{};
      for (int i = 0; i < spec.dof; ++i) q[i] = std::uniform_real_distribution<double>(spec.q_min[i], spec.q_max[i])(rng);
      const Eigen::Isometry3d urdf = chainFlangePose(chain, q);
      const Eigen::Isometry3d dh = xmate::model::dhFlangePose(spec, q);
      worst = std::max({worst, (urdf.translation() - dh.translation()).cwiseAbs().maxCoeff(),
                        (urdf.linear() - dh.linear()).cwiseAbs().maxCoeff()});
    }
    QVERIFY2(worst < kPoseTolerance, qPrintable(QString("largest flange pose difference %1").arg(worst)));
  }

  void committedFilesAreCurrent_data() { addModelRows(); }
  void committedFilesAreCurrent() {
    const RobotSpec& spec = fetchSpec();
    QTemporaryDir tmp;
    QVERIFY(tmp.isValid());
    const fs::path fresh = tmp.path().toStdString();
    const fs::path committed = xmate::model::dataDirectory();
    const auto robot = xmate::robotgen::generateRobot(spec);
    xmate::robotgen::writeRobot(robot, fresh);

    const auto urdf = xmate::robotgen::urdfRelativePath(spec.name);
    QVERIFY2(readFile(committed / urdf) == readFile(fresh / urdf),
             qPrintable(QString::fromStdString((committed / urdf).string() +
                                               " differs from the generator's output; build the target regenerate-robots")));
    std::set<std::string> expected;
    for (const auto& link : robot.links) {
      const auto rel = xmate::robotgen::meshRelativePath(spec.name, link.shell.name);
      expected.insert(rel.filename().string());
      const auto old_tris = xmate::robotgen::readBinaryStl(committed / rel);
      const auto new_tris = xmate::robotgen::readBinaryStl(fresh / rel);
      QVERIFY2(old_tris.size() == new_tris.size(), qPrintable(QString::fromStdString(rel.string() + ": triangle count differs")));
      double worst = 0;
      for (std::size_t t = 0; t < new_tris.size(); ++t) {
        for (int v = 0; v < 3; ++v)
          worst = std::max(worst, double((old_tris[t].vertices[v] - new_tris[t].vertices[v]).cwiseAbs().maxCoeff()));
        worst = std::max(worst, double((old_tris[t].normal - new_tris[t].normal).cwiseAbs().maxCoeff()));
      }
      QVERIFY2(worst <= kStlTolerance, qPrintable(QString::fromStdString(rel.string() + " is stale; build regenerate-robots")));
    }
    std::set<std::string> present;
    for (const auto& entry : fs::directory_iterator(committed / "meshes" / std::string(spec.name)))
      present.insert(entry.path().filename().string());
    QVERIFY2(present == expected, "meshes/<model>/ holds files the generator does not write");
  }

  void meshesLoadWithAssimp_data() { addModelRows(); }
  void meshesLoadWithAssimp() {
    const Chain chain = xmate::model::loadRobotChain(fetchSpec());
    for (const ChainLink* link : allLinks(chain)) {
      QVERIFY2(fs::file_size(link->mesh) < kMaxMeshBytes, link->mesh.c_str());
      Assimp::Importer importer;
      const aiScene* scene = importer.ReadFile(link->mesh, 0);
      QVERIFY2(scene && scene->mNumMeshes > 0, importer.GetErrorString());
      Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e9), hi = -lo;
      unsigned faces = 0;
      for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
        const aiMesh* mesh = scene->mMeshes[m];
        faces += mesh->mNumFaces;
        for (unsigned v = 0; v < mesh->mNumVertices; ++v) {
          const Eigen::Vector3d p(mesh->mVertices[v].x, mesh->mVertices[v].y, mesh->mVertices[v].z);
          lo = lo.cwiseMin(p);
          hi = hi.cwiseMax(p);
        }
      }
      QCOMPARE(std::size_t(faces), xmate::robotgen::readBinaryStl(link->mesh).size());
      const Eigen::Vector3d extent = hi - lo;
      QVERIFY2(extent.minCoeff() >= kMinExtent && extent.maxCoeff() <= kMaxExtent,
               qPrintable(QString("%1: bounding box %2 x %3 x %4 m").arg(QString::fromStdString(link->name))
                              .arg(extent.x()).arg(extent.y()).arg(extent.z())));
    }
  }

  void meshesAreClosedAndMatchTheSolids_data() { addModelRows(); }
  void meshesAreClosedAndMatchTheSolids() {
    const RobotSpec& spec = fetchSpec();
    const auto robot = xmate::robotgen::generateRobot(spec);
    for (const auto& link : robot.links) {
      const auto where = QString::fromStdString(robot.name + "/" + link.shell.name);
      const std::string in_memory = rci_test::edgeProblem(toIndexed(link.mesh));
      QVERIFY2(in_memory.empty(), qPrintable(where + " (generator mesh): " + QString::fromStdString(in_memory)));
      const fs::path file = xmate::model::dataDirectory() / xmate::robotgen::meshRelativePath(spec.name, link.shell.name);
      const std::string on_disk = rci_test::edgeProblem(stlMesh(file));
      QVERIFY2(on_disk.empty(), qPrintable(where + " (STL file): " + QString::fromStdString(on_disk)));
      // Outward-facing: the signed volume is positive and close to the exact volume of the solids.
      const double exact = xmate::robotgen::totalVolume(link.shell.solids);
      const double meshed = rci_test::meshMassProperties(toIndexed(link.mesh)).volume;
      QVERIFY2(std::abs(meshed - exact) < kMeshVolumeTolerance * exact,
               qPrintable(where + QString(": mesh volume %1 vs solids %2 m^3").arg(meshed).arg(exact)));
    }
  }

  void inertiasArePhysical_data() { addModelRows(); }
  void inertiasArePhysical() {
    const RobotSpec& spec = fetchSpec();
    const Chain chain = xmate::model::loadRobotChain(spec);
    const auto links = allLinks(chain);
    for (std::size_t i = 0; i < links.size(); ++i) {
      const ChainLink& link = *links[i];
      const auto where = QString::fromStdString(link.name);
      if (spec.link_mass[i] > 0) QVERIFY2(link.mass == spec.link_mass[i], qPrintable(where + ": mass differs from the spec"));
      QVERIFY2(link.mass > 0, qPrintable(where + ": no mass"));
      const Eigen::Matrix3d& I = link.inertia;
      QVERIFY2((I - I.transpose()).cwiseAbs().maxCoeff() == 0, qPrintable(where + ": inertia not symmetric"));
      const Eigen::Vector3d eig = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(I).eigenvalues();
      QVERIFY2(eig.minCoeff() > 0, qPrintable(where + ": inertia not positive definite"));
      for (const Eigen::Vector3d& m : {Eigen::Vector3d(I.diagonal()), eig}) {
        QVERIFY2(m[0] + m[1] >= m[2] && m[1] + m[2] >= m[0] && m[2] + m[0] >= m[1],
                 qPrintable(where + ": inertia violates the triangle inequality"));
      }
    }
  }

  // The inertials written to the URDF against the tetrahedron-method integrals of the meshes.
  void inertiasMatchTheMeshes_data() { addModelRows(); }
  void inertiasMatchTheMeshes() {
    const RobotSpec& spec = fetchSpec();
    const Chain chain = xmate::model::loadRobotChain(spec);
    const auto robot = xmate::robotgen::generateRobot(spec);
    const auto links = allLinks(chain);
    for (std::size_t i = 0; i < links.size(); ++i) {
      const ChainLink& link = *links[i];
      const auto mesh = rci_test::meshMassProperties(toIndexed(robot.links[i].mesh));
      const double density = link.mass / mesh.volume;
      const Eigen::Matrix3d inertia = density * mesh.inertia_per_density;
      const double com_error = (link.com - mesh.centroid).norm();
      const double inertia_error = (link.inertia - inertia).norm() / inertia.norm();
      QVERIFY2(com_error < kMeshComTolerance && inertia_error < kMeshInertiaTolerance,
               qPrintable(QString("%1: com off by %2 m, inertia by %3 (relative)")
                              .arg(QString::fromStdString(link.name)).arg(com_error).arg(inertia_error)));
    }
  }

  void loaderConvertsFramesInertiaAndMeshes() {
    QTemporaryDir tmp;
    QVERIFY(tmp.isValid());
    const std::string base_body =
        R"(<inertial><origin xyz="0.1 0.2 0.3" rpy="0 0 1.5707963267948966"/><mass value="2"/>)"
        R"(<inertia ixx="1" ixy="0" ixz="0" iyy="2" iyz="0" izz="3"/></inertial>)"
        R"(<visual><origin xyz="0 0 0.5" rpy="0 0 0"/><geometry><mesh filename="parts/base.stl" scale="0.001 0.001 0.001"/></geometry></visual>)";
    std::vector<std::string> types = kSixRevolute;
    types[5] = "continuous";
    const fs::path file = writeFile(tmp, "frames.urdf",
                                    tinyUrdf(types, "flange", base_body, R"(<origin xyz="0.1 0.2 0.3" rpy="0.3 -0.2 0.5"/>)"));
    const Chain chain = xmate::model::loadChain(file);
    QCOMPARE(chain.dof, 6);
    // URDF rpy means R = Rz(yaw) Ry(pitch) Rx(roll).
    const Eigen::Matrix3d expected = (Eigen::AngleAxisd(0.5, Eigen::Vector3d::UnitZ()) *
                                      Eigen::AngleAxisd(-0.2, Eigen::Vector3d::UnitY()) *
                                      Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitX())).toRotationMatrix();
    QVERIFY((chain.joints[0].origin.linear() - expected).cwiseAbs().maxCoeff() < 1e-12);
    QVERIFY(chain.joints[0].origin.translation().isApprox(Eigen::Vector3d(0.1, 0.2, 0.3)));
    // The inertia is given in the inertial frame (turned 90 deg about z): in link axes Ixx and Iyy swap.
    QVERIFY((chain.base.inertia - Eigen::Vector3d(2, 1, 3).asDiagonal().toDenseMatrix()).cwiseAbs().maxCoeff() < 1e-12);
    QVERIFY(chain.base.com.isApprox(Eigen::Vector3d(0.1, 0.2, 0.3)));
    QCOMPARE(chain.base.mass, 2.0);
    QCOMPARE(fs::path(chain.base.mesh), (fs::path(tmp.path().toStdString()) / "parts" / "base.stl").lexically_normal());
    QVERIFY(chain.base.mesh_scale.isApprox(Eigen::Vector3d::Constant(0.001)));
    QVERIFY(chain.base.visual_origin.translation().isApprox(Eigen::Vector3d(0, 0, 0.5)));
    QCOMPARE(chain.joints[0].lower, -1.0);
    QCOMPARE(chain.joints[0].velocity, 2.0);
    QCOMPARE(chain.joints[0].effort, 3.0);
    QVERIFY(std::isinf(chain.joints[5].upper) && chain.joints[5].upper > 0);  // continuous: no position limit
    QVERIFY(chain.flange.translation().isApprox(Eigen::Vector3d(0, 0, 0.05)));
  }

  void loaderResolvesPackagePaths() {
    QTemporaryDir tmp;
    QVERIFY(tmp.isValid());
    const std::string body =
        R"(<visual><geometry><mesh filename="package://rci/meshes/xmate7_pro/link1.stl"/></geometry></visual>)";
    const Chain chain = xmate::model::loadChain(writeFile(tmp, "pkg.urdf", tinyUrdf(kSixRevolute, "flange", body)));
    QCOMPARE(fs::path(chain.base.mesh), (xmate::model::dataDirectory() / "meshes" / "xmate7_pro" / "link1.stl").lexically_normal());
  }

  void loaderErrorsNameTheProblem() {
    QTemporaryDir tmp;
    QVERIFY(tmp.isValid());
    const fs::path missing = fs::path(tmp.path().toStdString()) / "missing.urdf";
    QString e = errorOf([&] { xmate::model::loadChain(missing); });
    QVERIFY2(e.contains("not found") && e.contains(QString::fromStdString(missing.string())), qPrintable(e));

    e = errorOf([&] { xmate::model::loadChain(writeFile(tmp, "broken.urdf", "<robot name=\"x\">\n<link name=\"a\">\n</robot>\n")); });
    QVERIFY2(e.contains("malformed XML") && e.contains("line"), qPrintable(e));

    e = errorOf([&] { xmate::model::loadChain(writeFile(tmp, "nolinks.urdf", "<robot name=\"x\"><joint name=\"j\"/></robot>")); });
    QVERIFY2(e.contains("not a valid URDF"), qPrintable(e));

    std::string branching = tinyUrdf(kSixRevolute);
    branching.insert(branching.find("</robot>"),
                     "  <joint name=\"side\" type=\"fixed\"><parent link=\"link2\"/><child link=\"camera\"/></joint>\n"
                     "  <link name=\"camera\"/>\n");
    e = errorOf([&] { xmate::model::loadChain(writeFile(tmp, "branching.urdf", branching)); });
    QVERIFY2(e.contains("branches") && e.contains("link2"), qPrintable(e));

    std::vector<std::string> with_prismatic = kSixRevolute;
    with_prismatic[2] = "prismatic";
    e = errorOf([&] { xmate::model::loadChain(writeFile(tmp, "prismatic.urdf", tinyUrdf(with_prismatic))); });
    QVERIFY2(e.contains("prismatic") && e.contains("joint3"), qPrintable(e));

    e = errorOf([&] { xmate::model::loadChain(writeFile(tmp, "five.urdf", tinyUrdf(std::vector<std::string>(5, "revolute")))); });
    QVERIFY2(e.contains("only 5 revolute joints"), qPrintable(e));

    e = errorOf([&] { xmate::model::loadChain(writeFile(tmp, "eight.urdf", tinyUrdf(std::vector<std::string>(8, "revolute")))); });
    QVERIFY2(e.contains("more than 7"), qPrintable(e));

    e = errorOf([&] { xmate::model::loadChain(writeFile(tmp, "noflange.urdf", tinyUrdf(kSixRevolute, ""))); });
    QVERIFY2(e.contains("no flange"), qPrintable(e));

    e = errorOf([&] { xmate::model::loadChain(writeFile(tmp, "tool.urdf", tinyUrdf(kSixRevolute, "tool0"))); });
    QVERIFY2(e.contains("tool0") && e.contains("flange"), qPrintable(e));

    QVERIFY(errorOf([&] { xmate::model::loadChain(writeFile(tmp, "good.urdf", tinyUrdf(kSixRevolute))); }).isEmpty());
  }
};

QTEST_APPLESS_MAIN(TestRobotDescription)
#include "test_robot_description.moc"
