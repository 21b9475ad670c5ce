// SPDX-License-Identifier: Apache-2.0
// writeFileAtomically / readFile (atomic_file.h), with POSIX calls so the data reach the disk
// before the rename makes them visible.
#include "teach/atomic_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace xmate::teach {
namespace {

std::string folderOf(const std::string& path) {
  const auto slash = path.rfind('/');
  if (slash == std::string::npos) return ".";
  if (slash == 0) return "/";
  return path.substr(0, slash);
}

[[noreturn]] void failWith(const std::string& path, const std::string& step, int error) {
  throw std::runtime_error("cannot save " + path + ": " + step + " failed (" + std::strerror(error) +
                           "); the previous file is unchanged -- check the folder exists, is writable and "
                           "the disk is not full");
}

void writeAll(int fd, const std::string& contents, const std::string& path, const std::string& temp) {
  size_t done = 0;
  while (done < contents.size()) {
    const ssize_t n = ::write(fd, contents.data() + done, contents.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) {
      const int e = errno;
      ::close(fd);
      ::unlink(temp.c_str());
      failWith(path, "writing the temporary file", e);
    }
    done += size_t(n);
  }
}

}  // namespace

void writeFileAtomically(const std::string& path, const std::string& contents) {
  if (path.empty()) throw std::runtime_error("cannot save: no file name given");
  std::string pattern = path + ".tmp-XXXXXX";
  std::vector<char> name(pattern.begin(), pattern.end());
  name.push_back('\0');
  const int fd = ::mkstemp(name.data());
  if (fd < 0) failWith(path, "creating a temporary file next to it", errno);
  const std::string temp(name.data());
  ::fchmod(fd, 0644);  // mkstemp makes it 0600; a saved program is an ordinary file
  writeAll(fd, contents, path, temp);
  if (::fsync(fd) != 0) {
    const int e = errno;
    ::close(fd);
    ::unlink(temp.c_str());
    failWith(path, "flushing the temporary file to disk", e);
  }
  if (::close(fd) != 0) {
    const int e = errno;
    ::unlink(temp.c_str());
    failWith(path, "closing the temporary file", e);
  }
  if (::rename(temp.c_str(), path.c_str()) != 0) {
    const int e = errno;
    ::unlink(temp.c_str());
    failWith(path, "renaming the temporary file over it", e);
  }
  // Make the rename itself durable (best effort: some file systems refuse fsync on a folder).
  const int dir = ::open(folderOf(path).c_str(), O_RDONLY | O_DIRECTORY);
  if (dir >= 0) {
    ::fsync(dir);
    ::close(dir);
  }
}

std::string readFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot open " + path + ": " + std::strerror(errno) + "; check the path");
  std::ostringstream s;
  s << in.rdbuf();
  if (in.bad()) throw std::runtime_error("cannot read " + path + ": " + std::strerror(errno));
  return s.str();
}

}  // namespace xmate::teach
