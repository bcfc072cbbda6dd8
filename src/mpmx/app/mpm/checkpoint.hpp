#pragma once
// Checkpoints of a continuum run: the whole state (particles, tallies, time, the
// material's per-point state such as every MD box) plus whatever the run loop needs to
// carry on, in one binary file written atomically. A run resumed from it continues
// bit-for-bit (tests/app/mpm/interrupt_test.cpp, tests/app/mpm/mpm_run_nd_test.cpp).
#include <cstdint>
#include <iosfwd>
#include <string>
#include <vector>

#include "mpmx/core/error.hpp"

#include "mpmx/io/checked_file.hpp"
#include "mpmx/mpm/state.hpp"

namespace mpmx::app {

// The framing of a continuum run's checkpoint file (io/checked_file.hpp): the deck's
// canonical text and its point count identify the run it resumes.
io::CheckedKind run_checkpoint_kind(const std::string& deck_text, std::size_t points);

// Plain binary fields, in the order written (the payload of the framed file).
class CheckpointOut {
 public:
  explicit CheckpointOut(std::ostream& out) : out_(out) {}
  void number(double v);
  void integer(std::int64_t v);
  void text(const std::string& s);
  void numbers(const std::vector<double>& v);
  std::ostream& stream() { return out_; }

 private:
  std::ostream& out_;
};

class CheckpointIn {
 public:
  // `base`: the payload's offset in the file, so messages give file byte offsets.
  CheckpointIn(std::istream& in, std::string name, std::size_t base = 0)
      : in_(in), name_(std::move(name)), base_(base) {}
  double number();
  std::int64_t integer();
  std::string text();
  std::vector<double> numbers();
  std::istream& stream() { return in_; }
  // The file byte the next field starts at (for messages).
  long long offset() const;
  const std::string& name() const { return name_; }
  // An InputError naming the file, the byte and the reason.
  InputError refuse(long long at, const std::string& why) const;

 private:
  void check(long long at, const char* what);
  std::istream& in_;
  std::string name_;
  std::size_t base_ = 0;
};

template <int Dim>
void save_state(CheckpointOut& out, const mpm::State<Dim>& s);
// `s` made by make_state(config, false): same grid, scheme and material, no per-point
// material state yet. Throws InputError when the checkpoint does not fit it.
template <int Dim>
void load_state(CheckpointIn& in, mpm::State<Dim>& s);

}  // namespace mpmx::app
