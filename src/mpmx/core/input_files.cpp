#include "mpmx/core/input_files.hpp"

#include <filesystem>
#include <fstream>
#include <mutex>

#include <fmt/format.h>

#include "mpmx/core/error.hpp"

namespace mpmx {

namespace {

std::mutex g_mutex;
std::map<std::string, std::uint64_t> g_files;

}  // namespace

std::uint64_t file_digest(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(fmt::format("cannot read {}", path));
  std::uint64_t h = 0xcbf29ce484222325ULL;
  char block[1 << 16];
  while (in.read(block, sizeof block) || in.gcount() > 0) {
    const auto n = static_cast<std::size_t>(in.gcount());
    for (std::size_t i = 0; i < n; ++i) h = (h ^ static_cast<unsigned char>(block[i])) * 0x100000001b3ULL;
  }
  return h;
}

void note_input_file(const std::string& path) {
  std::error_code ec;
  const std::string absolute = std::filesystem::absolute(path, ec).lexically_normal().string();
  const std::uint64_t digest = file_digest(path);
  const std::lock_guard<std::mutex> lock(g_mutex);
  g_files[ec ? path : absolute] = digest;
}

const std::map<std::string, std::uint64_t>& input_files() { return g_files; }

}  // namespace mpmx
