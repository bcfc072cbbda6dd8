#pragma once
// The framing shared by every checkpoint kind: a fixed header (magic, kind, format
// version, a hash of the deck's canonical text, a count the deck fixes, the payload's
// size and CRC-32, the header's own CRC-32) before an opaque payload. A reader trusts no
// byte it has not checked: a damaged, truncated or foreign file is refused with the byte
// offset and the reason (InputError, exit status 2), before any of the payload is parsed.
#include <cstdint>
#include <iosfwd>
#include <memory>
#include <string>
#include <string_view>

#include "mpmx/core/binary.hpp"

namespace mpmx::io {

// What a reader expects; `kind` is at most 8 characters ("mpm_run").
struct CheckedKind {
  std::string_view kind;
  std::uint32_t version = 1;
  std::uint64_t deck_hash = 0;  // text_hash of the deck's canonical text
  std::uint64_t count = 0;      // e.g. the particles the deck makes
};

inline constexpr std::size_t kCheckedHeaderBytes = 56;

// FNV-1a 64 of a text: the deck identity kept in the header.
std::uint64_t text_hash(std::string_view text);

// zlib's CRC-32 of a byte range.
std::uint32_t crc32_of(std::string_view bytes);

// Header + payload, as written.
std::string frame(const CheckedKind& k, std::string_view payload);

// The payload of `bytes` once every header field and both checksums agree with `k`;
// `name` (the file) starts each message. Throws InputError otherwise.
std::string_view unframe(std::string_view bytes, const CheckedKind& k, const std::string& name);

// frame() of what is written to stream(), written atomically to `path` (through path +
// ".tmp") as it comes: the CRC and size kept as the bytes pass, the header filled in by
// commit(). A checkpoint of a few hundred MB of MD boxes costs no copy of itself in
// memory. Leaving without commit() leaves `path` as it was.
class CheckedWriter {
 public:
  CheckedWriter(const std::string& path, const CheckedKind& k);
  ~CheckedWriter();
  CheckedWriter(const CheckedWriter&) = delete;
  CheckedWriter& operator=(const CheckedWriter&) = delete;

  std::ostream& stream();
  void commit();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// The payload of the file at `path` once unframed (read whole, into one string).
std::string read_checked(const std::string& path, const CheckedKind& k);

// The payload readers' count check and offset (core/binary.hpp), under io's names too.
using mpmx::payload_offset;
using mpmx::read_count;

}  // namespace mpmx::io
