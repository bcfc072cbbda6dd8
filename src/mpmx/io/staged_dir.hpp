#pragma once
// A run's output folder, held by the run for its life (io/folder_lock.hpp) and written
// through a staging folder inside it (OUT/.staging): the run writes there, and only a run
// that ends (completed, or stopped by the physics or by Ctrl-C with its tables, run.json
// and checkpoint consistent) is moved into OUT, file by file. A run that fails otherwise
// (bad input found late, the disk full, killed) leaves OUT as it was, and a folder made
// for a run that never wrote anything is removed.
//
// OUT/.mpmx-files (io/run_manifest.hpp) says which run owns the folder and which files it
// wrote. A run of another deck or command is refused unless `overwrite`; then the earlier
// run's files all go when this one is published. A rerun of the same deck and command
// replaces the files it writes again and each folder it writes again (vtk/) whole, as
// far as mpmx wrote it. A file mpmx did not write is never removed or replaced by a folder.
#include <optional>
#include <set>
#include <string>

#include "mpmx/core/error.hpp"
#include "mpmx/io/folder_lock.hpp"

namespace mpmx::io {

// Who writes the folder: the owner text (io::run_owner; "" for a caller that does not
// say: it is then taken as the folder's own) and whether another owner's files may go.
struct FolderOwner {
  std::string run;
  bool overwrite = false;
};

class StagedDir {
 public:
  enum class Mode {
    fresh,     // a new run: a staging folder left by a killed run is cleared
    resume,    // a run resumed from the checkpoint in the staging folder, kept
    in_place,  // a run resumed from OUT's checkpoint writes in OUT itself
  };
  explicit StagedDir(std::string out, Mode mode = Mode::fresh, FolderOwner owner = {});
  StagedDir(const StagedDir&) = delete;
  StagedDir& operator=(const StagedDir&) = delete;
  ~StagedDir();

  // Where the run writes (the caller creates it once its inputs are validated).
  const std::string& path() const { return staging_; }
  // Moves every file of the staging folder into OUT, removes what it replaces, records
  // the folder's files in its manifest and removes the staging folder. In place: records
  // the files the run added.
  void publish();

  // OUT/.staging of a run folder.
  static std::string staging_of(const std::string& out);

 private:
  std::string out_, staging_;
  Mode mode_;
  FolderOwner owner_;
  std::optional<FolderLock> lock_;
  std::set<std::string> before_;  // in place: OUT's files when the run began
  bool out_existed_ = false, published_ = false;
};

// Records `files` (relative), just written into OUT itself outside a publish (a fit's
// interrupt checkpoint), as `owner`'s; another owner's files in OUT go first (the run was
// let in by --overwrite).
void record_written(const std::string& out, const std::string& owner, const std::set<std::string>& files);

// `run(dir)` writing into a staging folder of `out`, published when it returns or when
// the physics stops it (RunError: a partial result, consistent in itself; its message
// then names `out`); anything else leaves `out` as it was.
template <class F>
auto run_staged(const std::string& out, F&& run, FolderOwner owner = {}) {
  StagedDir stage(out, StagedDir::Mode::fresh, std::move(owner));
  try {
    auto r = run(stage.path());
    stage.publish();
    return r;
  } catch (const RunError& e) {
    stage.publish();
    std::string why = e.what();
    for (std::size_t at; (at = why.find(stage.path())) != std::string::npos;) why.replace(at, stage.path().size(), out);
    throw RunError(why);
  }
}

}  // namespace mpmx::io
