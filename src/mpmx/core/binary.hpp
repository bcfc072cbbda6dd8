#pragma once
// Reading a binary payload (a checkpoint's, an MD box's saved state) without trusting
// it: a count is checked against the bytes still there before anything is sized by it.
#include <cstddef>
#include <cstdint>
#include <iosfwd>

namespace mpmx {

// A count read from a payload stream (u64), refused unless the `bytes_each` bytes per
// item it announces are still there: a damaged count never reaches an allocation.
std::uint64_t read_count(std::istream& in, std::size_t bytes_each, const char* what);

// The payload byte `in` stands at (for messages), or -1.
long long payload_offset(std::istream& in);

}  // namespace mpmx
