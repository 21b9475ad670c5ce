// SPDX-License-Identifier: Apache-2.0
// Search order and error message for the data root (see resource_locator.h).
#include "model/resource_locator.h"

#include <cstdlib>
#include <stdexcept>
#include <string>
#include <system_error>
#include <vector>

namespace xmate::model {
namespace {

bool holdsRobots(const std::filesystem::path& root) {
  std::error_code ec;
  return std::filesystem::is_regular_file(root / "resources" / "robots" / "xmate7_pro.urdf", ec);
}

std::vector<std::filesystem::path> candidates() {
  std::vector<std::filesystem::path> out;
  if (const char* env = std::getenv("RCI_DATA_DIR"); env && *env) out.emplace_back(env);
  std::error_code ec;
  const auto exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (!ec) out.push_back(exe.parent_path().parent_path() / "share" / "rci");
  out.emplace_back(RCI_INSTALL_DATADIR);
  out.emplace_back(RCI_SOURCE_DATADIR);
  return out;
}

}  // namespace

std::filesystem::path dataDirectory() {
  const auto places = candidates();
  for (const auto& p : places)
    if (holdsRobots(p)) return p;
  std::string msg = "RCI: robot descriptions not found. Looked for resources/robots/xmate7_pro.urdf under:";
  for (const auto& p : places) msg += "\n  " + p.string();
  msg += "\nInstall the package, run from the build tree, or set RCI_DATA_DIR to the folder that holds "
         "resources/ and meshes/.";
  throw std::runtime_error(msg);
}

std::filesystem::path robotDescriptionPath(const RobotSpec& spec) {
  return dataDirectory() / "resources" / "robots" / (std::string(spec.name) + ".urdf");
}

}  // namespace xmate::model
