#pragma once
// One file written whole or not at all: the bytes go to `path + ".tmp"`, which is
// renamed over `path` only once written and flushed, so a run that fails (or is killed)
// midway never leaves a cut or empty file where an earlier run's complete one was.
#include <cstdio>
#include <string>
#include <string_view>

namespace mpmx::io {

// A file streamed to `path + ".tmp"` and renamed over `path` on commit(); an error or
// leaving without commit() removes the temporary. Errors are SystemError naming the path,
// what failed and the system's reason (disk full, no permission).
class AtomicWriter {
 public:
  explicit AtomicWriter(std::string path);
  ~AtomicWriter();
  AtomicWriter(const AtomicWriter&) = delete;
  AtomicWriter& operator=(const AtomicWriter&) = delete;

  void write(const void* data, std::size_t bytes);
  void write(std::string_view s) { write(s.data(), s.size()); }
  // Bytes over those already written at `offset` (a header filled in last).
  void overwrite(std::size_t offset, std::string_view s);
  void commit();

 private:
  [[noreturn]] void fail(const std::string& what) const;
  std::string path_, tmp_;
  std::FILE* f_ = nullptr;
  bool done_ = false;
};

// The whole of `bytes` as `path`, through an AtomicWriter.
void write_file_atomic(const std::string& path, std::string_view bytes);

}  // namespace mpmx::io
