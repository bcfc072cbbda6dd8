#pragma once
// What the run loops of `mpmx md` and `mpmx dpd` share: their tables (fresh, or cut back
// to a checkpoint's lengths), the stop at a record boundary on Ctrl-C or SIGTERM (or
// --stop-after), and the checkpoint written there and read back by --resume.
//
// A checkpoint (OUT/checkpoint.bin) is framed and checked as the continuum's
// (io/checked_file.hpp: the kind, the deck's hash, a count the deck fixes): the deck's
// text, the run's own state (its engine's system and whatever it tracks), then the
// tables' lengths. The reader refuses a damaged or foreign file with the byte and the
// reason (InputError, exit status 2) before the run touches a table.
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>

#include <toml++/toml.h>

#include "mpmx/app/checkpoint_fields.hpp"
#include "mpmx/app/run_tables.hpp"
#include "mpmx/core/interrupt.hpp"

namespace mpmx::app {

struct RunControlOptions {
  bool quiet = false;           // no progress line
  bool resume = false;          // continue from DIR/checkpoint.bin
  std::int64_t stop_after = 0;  // stop as if interrupted at the first record at or past this step (tests)
  std::string out;              // the folder run.json and messages name (OUT; "": the run's own folder)
};

class RunControl {
 public:
  // `kind`: the checkpoint's kind (at most 8 characters); `version`: its payload's format
  // (2: with the input files' digests; a kind raises its own when its state grows). Holds the Ctrl-C and SIGTERM handlers
  // from here on.
  RunControl(std::string dir, std::string_view kind, const toml::table& deck_echo, const RunControlOptions& o,
             std::uint32_t version = 2);

  const RunControlOptions& options() const { return o_; }
  bool resuming() const { return o_.resume; }
  // On --resume: checks the checkpoint's frame (`count` is the deck's) and deck, lets
  // `read` take the run's state, then cuts the tables back.
  void resume(std::uint64_t count, const std::function<void(CheckpointIn&)>& read);
  // The run's tables (after resume() on a resumed run).
  RunTables& tables() { return *tables_; }

  // Whether the run is to stop at this record (a signal came, or --stop-after).
  bool stop_due(std::int64_t step) const;
  // Writes the checkpoint (`write` adds the run's state) and marks the run interrupted.
  void checkpoint(std::uint64_t count, const std::function<void(CheckpointOut&)>& write);
  bool interrupted() const { return interrupted_; }
  // Where run.json says the checkpoint is (OUT/checkpoint.bin).
  std::string shown_checkpoint() const;
  // A run that completed checks its tables were written whole and removes the checkpoint
  // it resumed from.
  void finished();

 private:
  std::string dir_, kind_, deck_text_;
  std::uint32_t version_;
  RunControlOptions o_;
  InterruptGuard guard_;
  std::optional<RunTables> tables_;
  bool interrupted_ = false;
};

}  // namespace mpmx::app
