#include "mpmx/core/binary.hpp"

#include <istream>

#include <fmt/format.h>

#include "mpmx/core/error.hpp"

namespace mpmx {

long long payload_offset(std::istream& in) {
  if (!in) return -1;
  return static_cast<long long>(in.tellg());
}

std::uint64_t read_count(std::istream& in, std::size_t bytes_each, const char* what) {
  const long long at = payload_offset(in);
  std::uint64_t n = 0;
  in.read(reinterpret_cast<char*>(&n), sizeof n);
  if (!in) throw InputError(fmt::format("payload byte {}: the {} count is truncated", at, what));
  const auto here = in.tellg();
  in.seekg(0, std::ios::end);
  const auto end = in.tellg();
  in.seekg(here);
  const std::uint64_t left = here >= 0 && end >= here ? static_cast<std::uint64_t>(end - here) : 0;
  if (bytes_each > 0 && n > left / bytes_each)
    throw InputError(fmt::format("payload byte {}: the {} count {} needs {} bytes per item, only {} bytes are left",
                                 at, what, n, bytes_each, left));
  return n;
}

}  // namespace mpmx
