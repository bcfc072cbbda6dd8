#pragma once
// Reading a binary payload (a checkpoint's, an MD box's saved state) without trusting
// it: a count is checked against the bytes still there before anything is sized by it.
// Values are raw bytes in the machine's order (a checkpoint is resumed where it was made).
#include <cstddef>
#include <cstdint>
#include <istream>
#include <ostream>
#include <string>
#include <type_traits>
#include <vector>

#include "mpmx/core/error.hpp"

namespace mpmx {

// A count read from a payload stream (u64), refused unless the `bytes_each` bytes per
// item it announces are still there: a damaged count never reaches an allocation.
std::uint64_t read_count(std::istream& in, std::size_t bytes_each, const char* what);

// The payload byte `in` stands at (for messages), or -1.
long long payload_offset(std::istream& in);

// One value of a trivially copyable type; the values of a vector (no count).
template <class T>
void write_raw(std::ostream& out, const T& v) {
  static_assert(std::is_trivially_copyable_v<T>);
  out.write(reinterpret_cast<const char*>(&v), sizeof(T));
}
template <class T>
void write_values(std::ostream& out, const std::vector<T>& v) {
  static_assert(std::is_trivially_copyable_v<T>);
  out.write(reinterpret_cast<const char*>(v.data()), static_cast<std::streamsize>(v.size() * sizeof(T)));
}

// Their readers: InputError "the `what` is truncated" when the payload ends first.
template <class T>
T read_raw(std::istream& in, const char* what) {
  static_assert(std::is_trivially_copyable_v<T>);
  T v{};
  in.read(reinterpret_cast<char*>(&v), sizeof(T));
  if (!in) throw InputError(std::string("the ") + what + " is truncated");
  return v;
}
template <class T>
void read_values(std::istream& in, std::vector<T>& v, std::size_t n, const char* what) {
  static_assert(std::is_trivially_copyable_v<T>);
  v.resize(n);
  in.read(reinterpret_cast<char*>(v.data()), static_cast<std::streamsize>(n * sizeof(T)));
  if (!in) throw InputError(std::string("the ") + what + " is truncated");
}

}  // namespace mpmx
