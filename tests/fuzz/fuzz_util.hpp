#pragma once
// Shared by the libFuzzer targets: a private temporary folder (the only place a target
// writes: readers that take a path get the input as a file there), removed at exit.
#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

namespace mpmx::fuzz {

inline const std::filesystem::path& temp_dir() {
  static const struct Dir {
    std::filesystem::path path;
    Dir() {
      std::string t = (std::filesystem::temp_directory_path() / "mpmx_fuzz_XXXXXX").string();
      if (!mkdtemp(t.data())) std::abort();
      path = t;
    }
    ~Dir() {
      std::error_code ec;
      std::filesystem::remove_all(path, ec);
    }
  } dir;
  return dir.path;
}

// `bytes` as the file `name` in the temporary folder; its path.
inline std::string as_file(const std::string& name, std::string_view bytes) {
  const auto p = temp_dir() / name;
  std::ofstream(p, std::ios::binary | std::ios::trunc).write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  return p.string();
}

inline std::string_view view(const std::uint8_t* data, std::size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

}  // namespace mpmx::fuzz
