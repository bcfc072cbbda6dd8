#pragma once
// Where a resumable run (`run`, `md`, `dpd`) writes: a fresh run in OUT/.staging
// (io/staged_dir.hpp), moved into OUT once it ends (completed, stopped by the physics or
// interrupted with its checkpoint); a resumed run where its checkpoint lies (OUT, or the
// staging folder of a run that was killed before it ended). Either way the run holds OUT's
// lock for its life. Under MPI the ranks agree on
// it after all have looked, before rank 0 (the only writer) touches the folder.
#include <optional>
#include <string>

#include "mpmx/core/error.hpp"
#include "mpmx/io/staged_dir.hpp"

namespace mpmx::app {

// The checkpoint of a run directory.
std::string checkpoint_path(const std::string& out_dir);

struct RunFolder {
  bool checkpoints = false;  // a folder to write checkpoints (and everything else) into
  std::optional<io::StagedDir> stage;
  std::string dir;

  // `out` "": a run that writes nothing (tests). `resume`: OUT's checkpoint must exist.
  // The folder is locked (and its owner checked) until the RunFolder goes.
  RunFolder(const std::string& out, bool resume, io::FolderOwner owner = {});
  // Moves a staged run's files into OUT (for a run resumed in OUT: records its new files).
  void publish() {
    if (stage) stage->publish();
  }
};

// `run(dir)` in the folder of `out`, published when it returns or when the physics stops
// it (RunError: a partial result, its message then naming `out`); anything else leaves
// `out` as it was. One process (md, dpd).
template <class F>
auto run_resumable(const std::string& out, bool resume, io::FolderOwner owner, F&& run) {
  RunFolder folder(out, resume, std::move(owner));
  try {
    auto r = run(folder.dir);
    folder.publish();
    return r;
  } catch (const RunError& e) {
    folder.publish();
    std::string why = e.what();
    for (std::size_t at; (at = why.find(folder.dir)) != std::string::npos && folder.dir != out;)
      why.replace(at, folder.dir.size(), out);
    throw RunError(why);
  }
}

}  // namespace mpmx::app
