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

// The file a save replaces: `path`, or where a symbolic link at `path` points (followed to its end,
// relative links resolved against the link's folder), so the link stays a link.
std::string resolveLinks(const std::string& path) {
  std::string target = path;
  for (int hops = 0; hops < 40; ++hops) {  // the kernel's own limit (ELOOP)
    struct stat st {};
    if (::lstat(target.c_str(), &st) != 0 || !S_ISLNK(st.st_mode)) return target;
    std::vector<char> buffer(size_t(st.st_size > 0 ? st.st_size : 4095) + 1);
    const ssize_t n = ::readlink(target.c_str(), buffer.data(), buffer.size() - 1);
    if (n < 0) return target;
    const std::string link(buffer.data(), size_t(n));
    target = link.front() == '/' ? link : folderOf(target) + "/" + link;
  }
  throw std::runtime_error("cannot save " + path + ": it is a chain of more than 40 symbolic links (a loop?); "
                           "save under another name");
}

}  // namespace

void writeFileAtomically(const std::string& requested, const std::string& contents) {
  if (requested.empty()) throw std::runtime_error("cannot save: no file name given");
  const std::string path = resolveLinks(requested);
  std::string pattern = path + ".tmp-XXXXXX";
  std::vector<char> name(pattern.begin(), pattern.end());
  name.push_back('\0');
  const int fd = ::mkstemp(name.data());
  if (fd < 0) failWith(path, "creating a temporary file next to it", errno);
  const std::string temp(name.data());
  // mkstemp makes it 0600: keep the permissions of the file it replaces, else an ordinary file's
  // (0666 less the umask).
  struct stat existing {};
  if (::stat(path.c_str(), &existing) == 0) {
    ::fchmod(fd, existing.st_mode & 07777);
  } else {
    const mode_t mask = ::umask(0);
    ::umask(mask);
    ::fchmod(fd, 0666 & ~mask);
  }
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
