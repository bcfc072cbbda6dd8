#pragma once
// One output folder, one run: a run holds an exclusive lock on its --out folder from
// before it writes anything until it ends: flock on OUT/.mpmx-lock, a file that exists
// only while a run holds it. A second run into the same folder meets the lock and is
// refused (InputError, exit status 2) before it touches a file; the system drops the lock
// of a process that dies, so a killed run never leaves the folder locked (its file stays
// until the next run takes and removes it). On a file system that keeps no locks at all
// (ENOLCK, ENOSYS, EOPNOTSUPP) the run goes on unlocked rather than not at all.
#include <string>

namespace mpmx::io {

class FolderLock {
 public:
  // Locks the folder `dir`, which must exist.
  explicit FolderLock(const std::string& dir);
  ~FolderLock();
  FolderLock(const FolderLock&) = delete;
  FolderLock& operator=(const FolderLock&) = delete;

  // The lock file's name in a folder.
  static constexpr const char* kName = ".mpmx-lock";

 private:
  std::string path_;
  int fd_ = -1;
};

}  // namespace mpmx::io
