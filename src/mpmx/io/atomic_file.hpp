#pragma once
// One file written whole or not at all: the bytes go to `path + ".tmp"`, which is
// renamed over `path` only once written and flushed, so a run that fails (or is killed)
// midway never leaves a cut or empty file where an earlier run's complete one was.
#include <string>
#include <string_view>

namespace mpmx::io {

// Throws RunError when the file cannot be written (disk full, no permission).
void write_file_atomic(const std::string& path, std::string_view bytes);

}  // namespace mpmx::io
