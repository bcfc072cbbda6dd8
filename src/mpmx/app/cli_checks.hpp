#pragma once
// Checks of command-line values, one short line each naming the option and the value:
// thread counts bounded by the machine, finite non-negative numbers, whole numbers in a
// range, non-empty paths. CLI11 validators, so a bad value is a CLI::ValidationError
// (exit code 2) before any command runs.
#include <cstdint>
#include <initializer_list>
#include <string>

#include <CLI/CLI.hpp>

namespace mpmx::app {

// --threads N: a whole number from 0 (all cores) to max_threads() (4 x the hardware
// threads): "100000 is too many: at most 8 on this machine (4 x 2 hardware threads)".
CLI::Validator thread_count();
// A whole number from lo to hi ("-1 is below 1", "'x' is not a whole number").
CLI::Validator whole_number(std::int64_t lo, std::int64_t hi);
// A finite number >= 0 ("nan is not a finite number").
CLI::Validator finite_non_negative();
// A path that is not empty (`--out ""`).
CLI::Validator non_empty_path();

// Every command's --out when none is given: runs/<deck name>.
std::string out_dir_of(const std::string& out, const std::string& deck);

// The help of every writing command's --overwrite (io/staged_dir.hpp).
inline constexpr const char* kOverwriteHelp =
    "replace the results of another run (another deck or command) in --out: that run's files all go, and only "
    "the files mpmx wrote there (without it such a folder is refused)";

// Every command's --threads: 0 (not given) is every core, and more than the cores is the
// cores (a thread waiting for a core only slows the others; results are the same on any
// count, so the count only decides speed).
int threads_of(int requested);
// `mpmx run`'s --threads: 0 stays 0 (the continuum on one thread, the MD boxes on every
// core), more than the cores is the cores.
int run_threads_of(int requested);
// Threads for one system of `items` (atoms, particles): no more than one per `per_thread`
// items, so that a small system, whose step is over in microseconds, never forks threads
// every step (on a busy machine each fork waits for a core).
int threads_for(int threads, double items, double per_thread);
// Atoms a thread of one MD system needs before it pays: the threaded force loop cuts
// tiles of 2048 atoms or more (particles/neighbor.hpp), and below two tiles a thread
// would fork only for the step's short loops (a 500-atom box ran 19x slower on 2 threads
// than on one while another program held a core).
inline constexpr double kAtomsPerMdThread = 4096;

// The options every command takes: -o/--out, -j/--threads, --resume, -q/--quiet,
// --no-plot and --check, so that a command line written for one command works with
// another. The rule: an option that cannot apply to a command (`check --out`, `md
// --no-plot`: md draws no figures) is accepted and said to be ignored, with the reason,
// one line on stderr; it never changes what the command does.
struct IgnoredOption {
  const char* name;    // "--no-plot"
  const char* reason;  // "md draws no figures"
};
void say_ignored(const CLI::App& command, std::initializer_list<IgnoredOption> options);
// What `--check` (and `mpmx check`) ignores: --out, --threads, --resume, --quiet, --no-plot.
void say_ignored_by_check(const CLI::App& command);

// The shared policy, applied by main() to every command once all are registered: any
// option named --threads, --checkpoint-minutes, --checkpoint-every or --out gets the
// check above, ahead of any check the command added itself. A command that declares
// such an option needs to do nothing more.
void apply_shared_checks(CLI::App& app);

}  // namespace mpmx::app
