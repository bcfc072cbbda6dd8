#pragma once
// A run's output folder written through a staging folder inside it (OUT/.staging): the
// run writes there, and only a run that ends (completed, or stopped by the physics or by
// Ctrl-C with its tables, run.json and checkpoint consistent) is moved into OUT, each
// entry replacing the earlier run's of the same name. A run that fails otherwise (bad
// input found late, out of memory, killed) leaves OUT as it was, and a folder made for a
// run that never wrote anything is removed.
#include <string>

#include "mpmx/core/error.hpp"

namespace mpmx::io {

class StagedDir {
 public:
  // `out` is the run's folder; a staging folder left by a killed run is cleared, unless
  // `keep` (a run resumed from the checkpoint it holds).
  explicit StagedDir(std::string out, bool keep = false);
  StagedDir(const StagedDir&) = delete;
  StagedDir& operator=(const StagedDir&) = delete;
  ~StagedDir();

  // Where the run writes (the caller creates it once its inputs are validated).
  const std::string& path() const { return staging_; }
  // Moves every entry of the staging folder into OUT and removes it.
  void publish();

  // OUT/.staging of a run folder.
  static std::string staging_of(const std::string& out);

 private:
  std::string out_, staging_;
  bool keep_ = false, out_existed_ = false, published_ = false;
};

// `run(dir)` writing into a staging folder of `out`, published when it returns or when
// the physics stops it (RunError: a partial result, consistent in itself; its message
// then names `out`); anything else leaves `out` as it was.
template <class F>
auto run_staged(const std::string& out, F&& run) {
  StagedDir stage(out);
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
