#include "mpmx/app/run_tables.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>

#include <fmt/format.h>

#include "mpmx/core/error.hpp"

namespace mpmx::app {

namespace fs = std::filesystem;

std::ofstream& RunTables::open(const std::string& name, std::string_view header) {
  const std::string path = (fs::path(dir_) / name).string();
  std::ofstream& f = files_[name];
  if (auto it = resume_.find(name); it != resume_.end()) {
    std::error_code ec;
    const auto size = fs::file_size(path, ec);
    if (ec || size < static_cast<std::uintmax_t>(it->second))
      throw InputError(fmt::format("cannot resume {}: it holds {} bytes, the checkpoint recorded {}", path,
                                   ec ? 0 : size, it->second));
    fs::resize_file(path, static_cast<std::uintmax_t>(it->second), ec);
    if (ec) throw SystemError(fmt::format("cannot resume {}: {}", path, ec.message()));
    f.open(path, std::ios::binary | std::ios::app);
  } else {
    f.open(path, std::ios::binary | std::ios::trunc);
    f << header;
  }
  if (!f) throw SystemError(fmt::format("cannot write {}: {}", path, std::strerror(errno)));
  return f;
}

TableMarks RunTables::marks() {
  // A table not opened since the resume keeps its checkpoint's length (Output::marks).
  TableMarks m = resume_;
  for (auto& [name, f] : files_) {
    f.flush();
    if (!f) throw SystemError(fmt::format("writing {}/{}: {}", dir_, name, std::strerror(errno)));
    m[name] = static_cast<std::int64_t>(fs::file_size(fs::path(dir_) / name));
  }
  return m;
}

}  // namespace mpmx::app
