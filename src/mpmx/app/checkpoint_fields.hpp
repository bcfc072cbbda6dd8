#pragma once
// The fields of a checkpoint's payload (the framing is io/checked_file.hpp): numbers,
// integers, texts, number lists and the run's table lengths, written in order and read
// back without trusting a byte: every count is checked against the bytes left, and a
// refusal names the file, the byte and the reason (InputError, exit status 2). Every
// resumable command's checkpoint (`run`, `md`, `dpd`, `fit-dpd`) is made of them: the
// deck's text, the input files' digests, then the command's own state.
#include <cstdint>
#include <iosfwd>
#include <map>
#include <string>
#include <vector>

#include "mpmx/core/error.hpp"

namespace mpmx::app {

// The tables a run appends to and their lengths in bytes at the checkpoint: a resumed run
// cuts each back to its length and appends, so its tables equal an uninterrupted run's.
using TableMarks = std::map<std::string, std::int64_t>;

// Plain binary fields, in the order written (the payload of the framed file).
class CheckpointOut {
 public:
  explicit CheckpointOut(std::ostream& out) : out_(out) {}
  void number(double v);
  void integer(std::int64_t v);
  void text(const std::string& s);
  void numbers(const std::vector<double>& v);
  void integers(const std::vector<std::int64_t>& v);
  // Rows of numbers (each row's length first).
  void rows(const std::vector<std::vector<double>>& v);
  void marks(const TableMarks& m);
  // The input files read so far and their digests (core/input_files.hpp).
  void inputs();
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
  std::vector<std::int64_t> integers();
  std::vector<std::vector<double>> rows();
  // Table names are refused unless they name a file of the run folder itself.
  TableMarks marks();
  // The input files the checkpoint pinned: refused (naming the file) when one is gone or
  // its bytes changed since, for --resume would then mix two runs' inputs.
  void check_inputs();
  // Refused unless the whole payload was read.
  void end();
  std::istream& stream() { return in_; }
  // The file byte the next field starts at (for messages).
  long long offset() const;
  const std::string& name() const { return name_; }
  // An InputError naming the file, the byte and the reason.
  InputError refuse(long long at, const std::string& why) const;

 private:
  void check(long long at, const char* what);
  template <class T>
  T scalar(const char* what);
  template <class T>
  std::vector<T> list(const char* what);
  std::istream& in_;
  std::string name_;
  std::size_t base_ = 0;
};

}  // namespace mpmx::app
