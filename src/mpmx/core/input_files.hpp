#pragma once
// The files a run reads besides its deck (a potential file, a reference's history), each
// with a digest of its bytes as read. A checkpoint records them and --resume refuses one
// that changed since: a run continued on other inputs would mix two runs in one table.
#include <cstdint>
#include <map>
#include <string>

namespace mpmx {

// The 64-bit FNV-1a digest of a file's bytes; throws InputError when it cannot be read.
std::uint64_t file_digest(const std::string& path);

// Records `path` (made absolute) and its digest now: called by whoever reads an input
// file. The latest reading of a path wins.
void note_input_file(const std::string& path);

// The files noted so far in this process, absolute path -> digest.
const std::map<std::string, std::uint64_t>& input_files();

}  // namespace mpmx
