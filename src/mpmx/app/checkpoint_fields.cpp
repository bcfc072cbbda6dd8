#include "mpmx/app/checkpoint_fields.hpp"

#include <filesystem>
#include <istream>
#include <ostream>

#include <fmt/format.h>

#include "mpmx/core/binary.hpp"
#include "mpmx/core/input_files.hpp"

namespace mpmx::app {

void CheckpointOut::number(double v) { out_.write(reinterpret_cast<const char*>(&v), sizeof v); }
void CheckpointOut::integer(std::int64_t v) { out_.write(reinterpret_cast<const char*>(&v), sizeof v); }
void CheckpointOut::text(const std::string& s) {
  integer(static_cast<std::int64_t>(s.size()));
  out_.write(s.data(), static_cast<std::streamsize>(s.size()));
}
void CheckpointOut::numbers(const std::vector<double>& v) {
  integer(static_cast<std::int64_t>(v.size()));
  write_values(out_, v);
}

void CheckpointOut::integers(const std::vector<std::int64_t>& v) {
  integer(static_cast<std::int64_t>(v.size()));
  write_values(out_, v);
}
void CheckpointOut::rows(const std::vector<std::vector<double>>& v) {
  integer(static_cast<std::int64_t>(v.size()));
  for (const auto& r : v) numbers(r);
}

void CheckpointOut::marks(const TableMarks& m) {
  integer(static_cast<std::int64_t>(m.size()));
  for (const auto& [name, bytes] : m) {
    text(name);
    integer(bytes);
  }
}

void CheckpointOut::inputs() {
  const auto& files = input_files();
  integer(static_cast<std::int64_t>(files.size()));
  for (const auto& [path, digest] : files) {
    text(path);
    integer(static_cast<std::int64_t>(digest));
  }
}

long long CheckpointIn::offset() const {
  const long long at = payload_offset(in_);
  return at < 0 ? -1 : at + static_cast<long long>(base_);
}
InputError CheckpointIn::refuse(long long at, const std::string& why) const {
  return InputError(fmt::format("checkpoint {}: byte {}: {}", name_, at, why));
}
void CheckpointIn::check(long long at, const char* what) {
  if (!in_) throw refuse(at, fmt::format("the file ends inside {}: truncated", what));
}
template <class T>
T CheckpointIn::scalar(const char* what) {
  const long long at = offset();
  T v{};
  in_.read(reinterpret_cast<char*>(&v), sizeof v);
  check(at, what);
  return v;
}
double CheckpointIn::number() { return scalar<double>("a number"); }
std::int64_t CheckpointIn::integer() { return scalar<std::int64_t>("an integer"); }
std::string CheckpointIn::text() {
  const long long at = offset();
  std::uint64_t n = 0;
  try {
    n = read_count(in_, 1, "text");
  } catch (const InputError& e) {
    throw refuse(at, e.what());
  }
  std::string s(static_cast<std::size_t>(n), '\0');
  in_.read(s.data(), static_cast<std::streamsize>(n));
  check(at, "a text");
  return s;
}
template <class T>
std::vector<T> CheckpointIn::list(const char* what) {
  const long long at = offset();
  std::uint64_t n = 0;
  try {
    n = read_count(in_, sizeof(T), what);
  } catch (const InputError& e) {
    throw refuse(at, e.what());
  }
  std::vector<T> v;
  read_values(in_, v, static_cast<std::size_t>(n), what);  // the count was checked: whole
  return v;
}
std::vector<double> CheckpointIn::numbers() { return list<double>("number list"); }

std::vector<std::int64_t> CheckpointIn::integers() { return list<std::int64_t>("integer list"); }
std::vector<std::vector<double>> CheckpointIn::rows() {
  const long long at = offset();
  std::uint64_t n = 0;
  try {
    n = read_count(in_, sizeof(std::int64_t), "row");  // each row holds its length at least
  } catch (const InputError& e) {
    throw refuse(at, e.what());
  }
  std::vector<std::vector<double>> v(static_cast<std::size_t>(n));
  for (auto& r : v) r = numbers();
  return v;
}

TableMarks CheckpointIn::marks() {
  TableMarks m;
  const long long at_count = offset();
  const std::int64_t count = integer();
  if (count < 0) throw refuse(at_count, fmt::format("a table count of {}", count));
  for (std::int64_t k = 0; k < count; ++k) {
    const long long at_name = offset();
    const std::string name = text();
    // A table of the run directory itself: never a path that leads out of it.
    if (name.empty() || name.find_first_of("/\\") != std::string::npos || name.front() == '.')
      throw refuse(at_name, fmt::format("'{}' is not a table name of a run directory", name));
    const long long at = offset();
    const std::int64_t bytes = integer();
    if (bytes < 0) throw refuse(at, fmt::format("a table length of {} bytes", bytes));
    m[name] = bytes;
  }
  return m;
}

void CheckpointIn::check_inputs() {
  const long long at_count = offset();
  const std::int64_t count = integer();
  if (count < 0) throw refuse(at_count, fmt::format("an input file count of {}", count));
  for (std::int64_t k = 0; k < count; ++k) {
    const std::string path = text();
    const auto pinned = static_cast<std::uint64_t>(integer());
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec))
      throw InputError(fmt::format("cannot resume from {}: the run read {}, which is no longer there; restore it, "
                                   "or run afresh without --resume",
                                   name_, path));
    if (const std::uint64_t now = file_digest(path); now != pinned)
      throw InputError(fmt::format("cannot resume from {}: {} changed since the checkpoint was written (digest "
                                   "{:016x}, now {:016x}); a resumed run on other inputs would mix two runs: restore "
                                   "the file, or run afresh without --resume",
                                   name_, path, pinned, now));
  }
}

void CheckpointIn::end() {
  if (in_.peek() != std::char_traits<char>::eof()) throw refuse(offset(), "trailing bytes after the state");
}

}  // namespace mpmx::app
