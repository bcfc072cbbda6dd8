#pragma once
// The exit status of every `mpmx` command (docs/guide.md, "Exit codes"): one table, so a
// script can tell a typo in a deck from a run the physics stopped.
namespace mpmx::exit_code {

inline constexpr int done = 0;           // finished (also --help, --version, a passing check)
inline constexpr int internal = 1;       // a bug or the machine failed us (out of memory, disk full)
inline constexpr int bad_input = 2;      // the command line, a deck or a file it names is wrong: nothing ran
inline constexpr int stopped = 3;        // the physics stopped the run (NaN, a point left the grid): partial result written
inline constexpr int interrupted = 130;  // Ctrl-C: checkpoint written, resumable (128 + SIGINT)

}  // namespace mpmx::exit_code
