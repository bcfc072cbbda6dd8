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
  parent_of(dotted, leaf).insert_or_assign(leaf, value);
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
void RunRecord::set(std::string_view dotted, toml::array values) {
  std::string leaf;
  parent_of(dotted, leaf).insert_or_assign(leaf, std::move(values));
}

void RunRecord::append(std::string_view dotted, toml::table table) {
  std::string leaf;
  toml::table& parent = parent_of(dotted, leaf);
  if (!parent.contains(leaf) || !parent[leaf].is_array()) parent.insert_or_assign(leaf, toml::array{});
  parent[leaf].as_array()->push_back(std::move(table));
}

std::string RunRecord::json() const { return json_text(root_); }

namespace {

// Stands for null in the formatter's output (toml++ has no null), then replaced.
constexpr std::string_view kNullMark = "@@mpmx-non-finite-null@@";

bool non_finite(const toml::node& n) {
  return n.is_floating_point() && !std::isfinite(n.as_floating_point()->get());
}

// Replaces every non-finite number under `n` by the mark, noting its dotted key.
void mark_non_finite(toml::node& n, const std::string& path, std::vector<std::string>& found) {
  if (auto* t = n.as_table()) {
    std::vector<std::string> keys;
    for (auto&& [k, v] : *t) {
      const std::string key = path.empty() ? std::string(k.str()) : path + "." + std::string(k.str());
      if (non_finite(v)) {
        keys.emplace_back(k.str());
        found.push_back(key);
      } else {
        mark_non_finite(v, key, found);
      }
    }
    for (const auto& k : keys) t->insert_or_assign(k, std::string(kNullMark));
  } else if (auto* a = n.as_array()) {
    for (std::size_t i = 0; i < a->size(); ++i) {
      const std::string key = fmt::format("{}[{}]", path, i);
      if (non_finite(*a->get(i))) {
        found.push_back(key);
        a->replace(a->cbegin() + static_cast<std::ptrdiff_t>(i), std::string(kNullMark));
      } else {
        mark_non_finite(*a->get(i), key, found);
      }
    }
  }
}

}  // namespace

std::string json_text(const toml::table& table) {
  toml::table t = table;
  std::vector<std::string> found;
  mark_non_finite(t, "", found);
  if (!found.empty()) {
    toml::array names;
    for (const auto& f : found) names.push_back(f);
    t.insert_or_assign("non_finite", std::move(names));
  }
  std::ostringstream os;
  os << toml::json_formatter{t} << '\n';
  std::string s = os.str();
  if (found.empty()) return s;
  const std::string mark = fmt::format("\"{}\"", kNullMark);
  std::string out;
  out.reserve(s.size());
  for (std::size_t at = 0;;) {
    const std::size_t hit = s.find(mark, at);
    out.append(s, at, hit == std::string::npos ? std::string::npos : hit - at);
    if (hit == std::string::npos) break;
    out += "null";
    at = hit + mark.size();
  }
  return out;
}

void RunRecord::write(const std::string& path) const { write_file_atomic(path, json()); }

}  // namespace mpmx::io
