#include "mpmx/io/folder_lock.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include <fmt/format.h>

#include "mpmx/core/error.hpp"
#include "mpmx/core/file_text.hpp"

namespace mpmx::io {

FolderLock::FolderLock(const std::string& dir) : path_(dir + "/" + kName) {
  // A lock file that the run holding it removes as it ends: a run that opened it just
  // before finds, once it holds the lock, that the name now leads to another file (or
  // none), and tries again.
  for (int attempt = 0; attempt < 100; ++attempt) {
    fd_ = ::open(path_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd_ < 0)
      throw SystemError(fmt::format("--out {}: cannot make the lock file {}: {}", short_path(dir), kName,
                                    std::strerror(errno)));
    if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
      const int err = errno;
      ::close(fd_);
      fd_ = -1;
      if (err == EWOULDBLOCK)
        throw InputError(fmt::format("--out {}: another mpmx run is writing into this folder (it holds the "
                                     "folder's lock); wait for it to end, or give another --out",
                                     short_path(dir)));
      if (err == ENOLCK || err == ENOSYS || err == EOPNOTSUPP) {
        ::unlink(path_.c_str());
        return;  // a file system without locks: unlocked rather than no run at all
      }
      throw SystemError(fmt::format("--out {}: cannot lock {}: {}", short_path(dir), kName, std::strerror(err)));
    }
    struct stat held {}, named {};
    if (::fstat(fd_, &held) == 0 && ::stat(path_.c_str(), &named) == 0 && held.st_dev == named.st_dev &&
        held.st_ino == named.st_ino)
      return;
    ::close(fd_);
    fd_ = -1;
  }
  throw SystemError(fmt::format("--out {}: cannot lock {}: its lock file keeps changing", short_path(dir), kName));
}

FolderLock::~FolderLock() {
  if (fd_ < 0) return;
  ::unlink(path_.c_str());  // while still held: a run that opened it before tries again
  ::close(fd_);
}

}  // namespace mpmx::io
