#include "mpmx/app/run_folder.hpp"

#include <filesystem>

#include <fmt/format.h>

#include "mpmx/core/ranks.hpp"

namespace mpmx::app {

std::string checkpoint_path(const std::string& out_dir) { return out_dir + "/checkpoint.bin"; }

RunFolder::RunFolder(const std::string& out, bool resume, io::FolderOwner owner) : checkpoints(!out.empty()) {
  namespace fs = std::filesystem;
  if (resume && !checkpoints) throw InputError("resuming needs the run's output directory");
  const bool resume_staged = resume && !fs::exists(checkpoint_path(out)) &&
                             fs::exists(checkpoint_path(io::StagedDir::staging_of(out)));
  if (resume && !resume_staged && !fs::exists(checkpoint_path(out)))
    throw InputError(fmt::format("no checkpoint to resume from: {} does not exist", checkpoint_path(out)));
  const bool staged = checkpoints && (!resume || ranks::max({resume_staged ? 1.0 : 0.0})[0] > 0.0);
  using Mode = io::StagedDir::Mode;
  const Mode mode = !resume ? Mode::fresh : staged ? Mode::resume : Mode::in_place;
  ranks::together([&] {  // a folder rank 0 cannot make (or lock) stops every rank
    if (checkpoints && ranks::root()) stage.emplace(out, mode, std::move(owner));
  });
  dir = staged ? io::StagedDir::staging_of(out) : out;
}

}  // namespace mpmx::app
