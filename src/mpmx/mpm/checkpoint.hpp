#pragma once
// Checkpoints of a continuum run: the whole state (particles, tallies, time, the
// material's per-point state such as every MD box) plus whatever the run loop needs to
// carry on, in one binary file written atomically. A run resumed from it continues
// bit-for-bit (tests/multiscale/checkpoint_test.cpp).
#include <cstdint>
#include <iosfwd>
#include <string>
#include <vector>

#include "mpmx/mpm/state.hpp"

namespace mpmx::mpm {

// Plain binary fields, in the order written.
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
  CheckpointIn(std::istream& in, std::string name) : in_(in), name_(std::move(name)) {}
  double number();
  std::int64_t integer();
  std::string text();
  std::vector<double> numbers();
  std::istream& stream() { return in_; }

 private:
  void check();
  std::istream& in_;
  std::string name_;
};

template <int Dim>
void save_state(CheckpointOut& out, const State<Dim>& s);
// `s` made by make_state(config, false): same grid, scheme and material, no per-point
// material state yet. Throws InputError when the checkpoint does not fit it.
template <int Dim>
void load_state(CheckpointIn& in, State<Dim>& s);

}  // namespace mpmx::mpm
