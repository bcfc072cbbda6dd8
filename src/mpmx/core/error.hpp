#pragma once
// Errors mpmx reports to a user: what, where, why. Thrown, caught once in the CLI.
#include <stdexcept>
#include <string>

namespace mpmx {

// Bad input: a deck key, a potential file line, a command-line value.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The simulation itself went wrong (NaN, particle left the grid): the run stops.
class RunError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The machine failed the run: a write refused (disk full, read-only, a folder gone). Not
// the input's fault nor mpmx's: exit status 1, the file and the system's reason said.
class SystemError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Stopped on request (Ctrl-C) after writing a checkpoint: the message says how to resume.
class Interrupted : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace mpmx
