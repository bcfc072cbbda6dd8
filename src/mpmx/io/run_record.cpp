#include "mpmx/io/run_record.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "mpmx/core/error.hpp"

namespace mpmx::io {

toml::table& RunRecord::parent_of(std::string_view dotted, std::string& leaf) {
  toml::table* t = &root_;
  std::size_t start = 0;
  for (;;) {
    std::size_t dot = dotted.find('.', start);
    if (dot == std::string_view::npos) {
      leaf = std::string(dotted.substr(start));
      return *t;
    }
    std::string part(dotted.substr(start, dot - start));
    if (!t->contains(part) || !(*t)[part].is_table()) t->insert_or_assign(part, toml::table{});
    t = (*t)[part].as_table();
    start = dot + 1;
  }
}

void RunRecord::set(std::string_view dotted, double value) {
  std::string leaf;
  // JSON has no NaN or Inf: such a value is written as a string that says so.
  if (std::isfinite(value))
    parent_of(dotted, leaf).insert_or_assign(leaf, value);
  else
    parent_of(dotted, leaf).insert_or_assign(leaf, fmt::format("{}", value));
}
void RunRecord::set(std::string_view dotted, std::int64_t value) {
  std::string leaf;
  parent_of(dotted, leaf).insert_or_assign(leaf, value);
}
void RunRecord::set(std::string_view dotted, bool value) {
  std::string leaf;
  parent_of(dotted, leaf).insert_or_assign(leaf, value);
}
void RunRecord::set(std::string_view dotted, std::string value) {
  std::string leaf;
  parent_of(dotted, leaf).insert_or_assign(leaf, std::move(value));
}
void RunRecord::set(std::string_view dotted, const std::vector<double>& values) {
  toml::array a;
  for (double v : values) a.push_back(v);
  std::string leaf;
  parent_of(dotted, leaf).insert_or_assign(leaf, std::move(a));
}
void RunRecord::set(std::string_view dotted, toml::table table) {
  std::string leaf;
  parent_of(dotted, leaf).insert_or_assign(leaf, std::move(table));
}

void RunRecord::append(std::string_view dotted, toml::table table) {
  std::string leaf;
  toml::table& parent = parent_of(dotted, leaf);
  if (!parent.contains(leaf) || !parent[leaf].is_array()) parent.insert_or_assign(leaf, toml::array{});
  parent[leaf].as_array()->push_back(std::move(table));
}

std::string RunRecord::json() const {
  std::ostringstream os;
  os << toml::json_formatter{root_};
  os << '\n';
  return os.str();
}

void RunRecord::write(const std::string& path) const { write_file_atomic(path, json()); }

void write_file_atomic(const std::string& path, std::string_view text) {
  std::string tmp = path + ".tmp";
  {
    std::ofstream f(tmp, std::ios::binary | std::ios::trunc);
    if (!f) throw RunError(fmt::format("cannot write {}", tmp));
    f.write(text.data(), static_cast<std::streamsize>(text.size()));
    if (!f) throw RunError(fmt::format("cannot write {}", tmp));
  }
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) throw RunError(fmt::format("cannot move {} to {}: {}", tmp, path, ec.message()));
}

}  // namespace mpmx::io
