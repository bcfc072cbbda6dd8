#include "mpmx/io/folder_lock.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include <fmt/format.h>

#include "mpmx/core/error.hpp"
#include "mpmx/core/file_text.hpp"

namespace mpmx::io {

FolderLock::FolderLock(const std::string& dir) {
  fd_ = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd_ < 0)
    throw SystemError(fmt::format("--out {}: cannot open the folder to lock it: {}", short_path(dir),
                                  std::strerror(errno)));
  if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    const int err = errno;
    ::close(fd_);
    fd_ = -1;
    if (err == EWOULDBLOCK)
      throw InputError(fmt::format("--out {}: another mpmx run is writing into this folder (it holds the folder's "
                                   "lock); wait for it to end, or give another --out",
                                   short_path(dir)));
    throw SystemError(fmt::format("--out {}: cannot lock the folder: {}", short_path(dir), std::strerror(err)));
  }
}

FolderLock::~FolderLock() {
  if (fd_ >= 0) ::close(fd_);  // closing drops the lock
}

}  // namespace mpmx::io
