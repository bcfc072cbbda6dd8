#include "mpmx/io/checked_file.hpp"

#include <filesystem>
#include <fstream>
#include <istream>
#include <ostream>
#include <streambuf>
#include <vector>

#include <fmt/format.h>
#include <zlib.h>

#include "mpmx/core/error.hpp"
#include "mpmx/io/atomic_file.hpp"

namespace mpmx::io {

namespace {

// Header layout (little-endian), byte offsets:
//   0 magic "MPMXCKPT"   8 kind (8 bytes, zero-padded)   16 version u32   20 payload CRC-32 u32
//  24 deck hash u64      32 count u64                   40 payload bytes u64
//  48 header CRC-32 u32 over bytes 0..47                 52 zero u32
constexpr char kMagic[8] = {'M', 'P', 'M', 'X', 'C', 'K', 'P', 'T'};
enum : std::size_t { kKind = 8, kVersion = 16, kPayloadCrc = 20, kDeck = 24, kCount = 32, kSize = 40, kHeaderCrc = 48, kPad = 52 };

void put(std::string& s, std::size_t at, std::uint64_t v, int bytes) {
  for (int b = 0; b < bytes; ++b) s[at + b] = static_cast<char>((v >> (8 * b)) & 0xff);
}
std::uint64_t get(std::string_view s, std::size_t at, int bytes) {
  std::uint64_t v = 0;
  for (int b = 0; b < bytes; ++b) v |= std::uint64_t{static_cast<unsigned char>(s[at + b])} << (8 * b);
  return v;
}
std::string kind_field(std::string_view kind) {
  std::string k(8, '\0');
  k.replace(0, std::min<std::size_t>(kind.size(), 8), kind.substr(0, 8));
  return k;
}
std::string printable(std::string_view s) {
  std::string r;
  for (char c : s) {
    if (c == '\0') break;
    r += (c >= 32 && c < 127) ? c : '?';
  }
  return r;
}

}  // namespace

std::uint64_t text_hash(std::string_view text) {
  std::uint64_t h = 0xcbf29ce484222325ULL;
  for (char c : text) h = (h ^ static_cast<unsigned char>(c)) * 0x100000001b3ULL;
  return h;
}

std::uint32_t crc32_of(std::string_view bytes) {
  // zlib takes a uInt length: feed large payloads in pieces.
  uLong crc = crc32(0L, Z_NULL, 0);
  for (std::size_t at = 0; at < bytes.size();) {
    const std::size_t n = std::min<std::size_t>(bytes.size() - at, 1u << 30);
    crc = crc32(crc, reinterpret_cast<const Bytef*>(bytes.data() + at), static_cast<uInt>(n));
    at += n;
  }
  return static_cast<std::uint32_t>(crc);
}

namespace {

std::string header(const CheckedKind& k, std::uint32_t payload_crc, std::uint64_t payload_bytes) {
  std::string h(kCheckedHeaderBytes, '\0');
  h.replace(0, 8, kMagic, 8);
  h.replace(kKind, 8, kind_field(k.kind));
  put(h, kVersion, k.version, 4);
  put(h, kPayloadCrc, payload_crc, 4);
  put(h, kDeck, k.deck_hash, 8);
  put(h, kCount, k.count, 8);
  put(h, kSize, payload_bytes, 8);
  put(h, kHeaderCrc, crc32_of(std::string_view(h).substr(0, kHeaderCrc)), 4);
  return h;
}

}  // namespace

std::string frame(const CheckedKind& k, std::string_view payload) {
  return header(k, crc32_of(payload), payload.size()).append(payload);
}

std::string_view unframe(std::string_view b, const CheckedKind& k, const std::string& name) {
  auto refuse = [&](std::size_t at, const std::string& why) {
    return InputError(fmt::format("checkpoint {}: byte {}: {}", name, at, why));
  };
  if (b.size() < kCheckedHeaderBytes)
    throw refuse(b.size(), fmt::format("the file ends inside its {}-byte header (it holds {} bytes): truncated "
                                       "or not a checkpoint",
                                       kCheckedHeaderBytes, b.size()));
  if (b.substr(0, 8) != std::string_view(kMagic, 8))
    throw refuse(0, "not an mpmx checkpoint (its first 8 bytes are not MPMXCKPT)");
  const std::uint32_t header_crc = crc32_of(b.substr(0, kHeaderCrc));
  if (get(b, kHeaderCrc, 4) != header_crc || get(b, kPad, 4) != 0)
    throw refuse(kHeaderCrc, "the header's checksum does not match: the header is damaged");
  if (b.substr(kKind, 8) != kind_field(k.kind))
    throw refuse(kKind, fmt::format("a checkpoint of kind '{}', not '{}'", printable(b.substr(kKind, 8)), k.kind));
  if (const auto v = get(b, kVersion, 4); v != k.version)
    throw refuse(kVersion, fmt::format("format version {}, this mpmx reads version {} (written by another mpmx "
                                       "version): run afresh without --resume",
                                       v, k.version));
  const std::uint64_t size = get(b, kSize, 8), held = b.size() - kCheckedHeaderBytes;
  if (size != held)
    throw refuse(kSize, fmt::format("the header announces {} payload bytes, the file holds {}: {}", size, held,
                                    size > held ? "truncated" : "trailing bytes"));
  if (get(b, kDeck, 8) != k.deck_hash)
    throw refuse(kDeck, "written for another deck (the deck changed since): run afresh without --resume");
  if (const auto n = get(b, kCount, 8); n != k.count)
    throw refuse(kCount, fmt::format("holds {} points, the deck makes {}", n, k.count));
  const std::string_view payload = b.substr(kCheckedHeaderBytes);
  if (get(b, kPayloadCrc, 4) != crc32_of(payload))
    throw refuse(kCheckedHeaderBytes, fmt::format("the checksum over bytes {}..{} does not match: the payload is "
                                                  "damaged",
                                                  kCheckedHeaderBytes, b.size()));
  return payload;
}

// A stream buffer that passes its bytes to the file a block at a time, its CRC and
// count kept on the way.
struct CheckedWriter::Impl : std::streambuf {
  Impl(const std::string& path, const CheckedKind& k) : file(path), kind(k), block(1 << 20) {
    file.write(std::string(kCheckedHeaderBytes, '\0'));  // filled in by commit()
    setp(block.data(), block.data() + block.size());
    out.exceptions(std::ios::badbit);  // the file's RunError (disk full) reaches the caller as it is
  }
  void drain() {
    const std::string_view b(pbase(), static_cast<std::size_t>(pptr() - pbase()));
    crc = crc32(crc, reinterpret_cast<const Bytef*>(b.data()), static_cast<uInt>(b.size()));
    bytes += b.size();
    file.write(b);
    setp(block.data(), block.data() + block.size());
  }
  int_type overflow(int_type c) override {
    drain();
    if (!traits_type::eq_int_type(c, traits_type::eof())) {
      *pptr() = traits_type::to_char_type(c);
      pbump(1);
    }
    return traits_type::not_eof(c);
  }
  int sync() override {
    drain();
    return 0;
  }
  AtomicWriter file;
  CheckedKind kind;
  std::vector<char> block;  // at most 1 MiB: crc32 takes it in one call
  uLong crc = crc32(0L, Z_NULL, 0);
  std::uint64_t bytes = 0;
  std::ostream out{this};
};

CheckedWriter::CheckedWriter(const std::string& path, const CheckedKind& k) : impl_(std::make_unique<Impl>(path, k)) {}
CheckedWriter::~CheckedWriter() = default;
std::ostream& CheckedWriter::stream() { return impl_->out; }

void CheckedWriter::commit() {
  Impl& w = *impl_;
  w.drain();
  w.file.overwrite(0, header(w.kind, static_cast<std::uint32_t>(w.crc), w.bytes));
  w.file.commit();
}

std::string read_checked(const std::string& path, const CheckedKind& k) {
  // A folder opens as a stream on Linux and fails only inside the read.
  if (std::error_code ec; std::filesystem::is_directory(path, ec))
    throw InputError(fmt::format("the checkpoint {} is a folder, not a file", path));
  std::ifstream f(path, std::ios::binary);
  if (!f) throw InputError(fmt::format("cannot open the checkpoint {}", path));
  // One string of the file's size, the payload returned in it (a resumed jet's checkpoint
  // is hundreds of MB: one copy in memory).
  std::error_code ec;
  const auto size = std::filesystem::file_size(path, ec);
  std::string bytes(ec ? 0 : static_cast<std::size_t>(size), '\0');
  if (ec || !f.read(bytes.data(), static_cast<std::streamsize>(bytes.size())))
    throw InputError(fmt::format("cannot read the checkpoint {}", path));
  unframe(bytes, k, path);
  bytes.erase(0, kCheckedHeaderBytes);
  return bytes;
}

}  // namespace mpmx::io
