#include "mpmx/io/atomic_file.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstring>

#include <fmt/format.h>

#include "mpmx/core/error.hpp"

namespace mpmx::io {

AtomicWriter::AtomicWriter(std::string path) : path_(std::move(path)), tmp_(path_ + ".tmp") {
  f_ = std::fopen(tmp_.c_str(), "wb");
  if (!f_) fail("cannot create " + tmp_);
}

AtomicWriter::~AtomicWriter() {
  if (f_) std::fclose(f_);
  if (!done_) std::remove(tmp_.c_str());
}

void AtomicWriter::write(const void* data, std::size_t bytes) {
  if (bytes > 0 && std::fwrite(data, 1, bytes, f_) != bytes) fail("write failed");
}

void AtomicWriter::overwrite(std::size_t offset, std::string_view s) {
  // The seek flushes what is buffered: a full disk said as the write it is.
  if (std::fflush(f_) != 0) fail("write failed");
  if (std::fseek(f_, static_cast<long>(offset), SEEK_SET) != 0) fail("seek failed");
  write(s);
  if (std::fseek(f_, 0, SEEK_END) != 0) fail("seek failed");
}

void AtomicWriter::commit() {
  std::FILE* f = f_;
  f_ = nullptr;
  // Flushed and synced before the rename: a crash or a power cut then leaves the earlier
  // file or this one whole, never a name pointing at bytes not yet on the disk. A full
  // disk shows up here rather than in fwrite.
  const bool written = std::fflush(f) == 0 && fsync(fileno(f)) == 0;
  const int err = errno;
  if (std::fclose(f) != 0 || !written) {
    if (!written) errno = err;
    fail("write failed");
  }
  if (std::rename(tmp_.c_str(), path_.c_str()) != 0) fail("cannot rename " + tmp_);
  done_ = true;
}

void AtomicWriter::fail(const std::string& what) const {
  const int err = errno;
  throw SystemError(fmt::format("writing {}: {}: {}", path_, what, std::strerror(err)));
}

void write_file_atomic(const std::string& path, std::string_view bytes) {
  AtomicWriter w(path);
  w.write(bytes);
  w.commit();
}

}  // namespace mpmx::io
