#pragma once
// One output folder, one run: a run holds an exclusive lock on its --out folder (flock on
// the folder itself, so no lock file is left among the user's) from before it writes
// anything until it ends. A second run into the same folder meets the lock and is refused
// (InputError, exit status 2) before it touches a file; the system drops the lock of a
// process that dies, so a killed run never leaves the folder locked.
#include <string>

namespace mpmx::io {

class FolderLock {
 public:
  // Locks the folder `dir`, which must exist.
  explicit FolderLock(const std::string& dir);
  ~FolderLock();
  FolderLock(const FolderLock&) = delete;
  FolderLock& operator=(const FolderLock&) = delete;

 private:
  int fd_ = -1;
};

}  // namespace mpmx::io
