#include "mpmx/io/deck.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include <fmt/format.h>

#include "mpmx/core/error.hpp"

namespace mpmx::io {

namespace {

std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diag = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diag = up;
    }
  }
  return row[b.size()];
}

std::string type_name(const toml::node& n) {
  switch (n.type()) {
    case toml::node_type::table: return "a table";
    case toml::node_type::array: return "an array";
    case toml::node_type::string: return "a string";
    case toml::node_type::integer: return "an integer";
    case toml::node_type::floating_point: return "a number";
    case toml::node_type::boolean: return "a boolean";
    default: return "a date/time";
  }
}

std::string join_path(const std::string& prefix, std::string_view key) {
  return prefix.empty() ? std::string(key) : prefix + "." + std::string(key);
}

}  // namespace

std::string describe(const toml::node& node) {
  if (node.is_table()) return "{...}";
  std::ostringstream os;
  if (node.is_array()) {
    os << toml::json_formatter{*node.as_array(), toml::format_flags::none};
  } else if (auto s = node.value<std::string>(); s && node.is_string()) {
    os << '"' << *s << '"';
  } else if (node.is_floating_point()) {
    os << fmt::format("{}", node.as_floating_point()->get());
  } else if (node.is_integer()) {
    os << node.as_integer()->get();
  } else if (node.is_boolean()) {
    os << (node.as_boolean()->get() ? "true" : "false");
  } else {
    os << "(date/time)";
  }
  return os.str();
}

// ---------------------------------------------------------------- Section

Section::Section(Deck* deck, const toml::table* table, std::string path)
    : deck_(deck), table_(table), path_(std::move(path)) {}

bool Section::has(std::string_view key) const {
  return table_ && table_->contains(key);
}

std::string Section::key_path(std::string_view key) const { return join_path(path_, key); }

std::string Section::value_text(std::string_view key) const {
  if (!table_) return "(absent)";
  const toml::node* n = table_->get(key);
  return n ? describe(*n) : "(absent)";
}

const toml::node* Section::get(std::string_view key) {
  deck_->mark_known(key_path(key));
  return table_ ? table_->get(key) : nullptr;
}

void Section::type_error(std::string_view key, const toml::node& node, std::string_view want) {
  deck_->add_error(&node, fmt::format("key '{}' = {}: expected {}, got {}", key_path(key),
                                      describe(node), want, type_name(node)));
}

void Section::missing(std::string_view key, std::string_view want) {
  deck_->add_error(table_, fmt::format("key '{}' is missing: expected {}", key_path(key), want));
}

double Section::number(std::string_view key) {
  const toml::node* n = get(key);
  if (!n) {
    missing(key, "a number");
    return std::nan("");
  }
  if (auto v = n->value<double>(); v && (n->is_floating_point() || n->is_integer())) {
    if (!std::isfinite(*v)) check(false, key, "must be finite");
    return *v;
  }
  type_error(key, *n, "a number");
  return std::nan("");
}

double Section::number(std::string_view key, double fallback) {
  if (!has(key)) {
    get(key);
    return fallback;
  }
  return number(key);
}

std::int64_t Section::integer(std::string_view key) {
  const toml::node* n = get(key);
  if (!n) {
    missing(key, "an integer");
    return 0;
  }
  if (n->is_integer()) return n->as_integer()->get();
  type_error(key, *n, "an integer");
  return 0;
}

std::int64_t Section::integer(std::string_view key, std::int64_t fallback) {
  if (!has(key)) {
    get(key);
    return fallback;
  }
  return integer(key);
}

bool Section::boolean(std::string_view key, bool fallback) {
  const toml::node* n = get(key);
  if (!n) return fallback;
  if (n->is_boolean()) return n->as_boolean()->get();
  type_error(key, *n, "true or false");
  return fallback;
}

std::string Section::string(std::string_view key) {
  const toml::node* n = get(key);
  if (!n) {
    missing(key, "a string");
    return {};
  }
  if (n->is_string()) return n->as_string()->get();
  type_error(key, *n, "a string");
  return {};
}

std::string Section::string(std::string_view key, std::string fallback) {
  if (!has(key)) {
    get(key);
    return fallback;
  }
  return string(key);
}

std::string Section::choice(std::string_view key, const std::vector<std::string>& allowed) {
  const toml::node* n = table_ ? table_->get(key) : nullptr;
  std::string v = string(key);
  if (n && n->is_string() && std::find(allowed.begin(), allowed.end(), v) == allowed.end()) {
    std::string list;
    for (const auto& a : allowed) list += (list.empty() ? "" : ", ") + a;
    deck_->add_error(n, fmt::format("key '{}' = \"{}\": not one of {}", key_path(key), v, list));
    return allowed.front();
  }
  return n ? v : allowed.front();
}

std::string Section::choice(std::string_view key, const std::vector<std::string>& allowed,
                            std::string fallback) {
  if (!has(key)) {
    get(key);
    return fallback;
  }
  return choice(key, allowed);
}

std::vector<double> Section::numbers(std::string_view key) {
  const toml::node* n = get(key);
  if (!n) {
    missing(key, "an array of numbers");
    return {};
  }
  std::vector<double> out;
  const toml::array* a = n->as_array();
  if (!a) {
    type_error(key, *n, "an array of numbers");
    return out;
  }
  for (const auto& e : *a) {
    if (!(e.is_floating_point() || e.is_integer())) {
      type_error(key, *n, "an array of numbers");
      return {};
    }
    out.push_back(*e.value<double>());
  }
  return out;
}

std::vector<double> Section::numbers(std::string_view key, std::vector<double> fallback) {
  if (!has(key)) {
    get(key);
    return fallback;
  }
  return numbers(key);
}

std::vector<std::string> Section::strings(std::string_view key, std::vector<std::string> fallback) {
  const toml::node* n = get(key);
  if (!n) return fallback;
  std::vector<std::string> out;
  const toml::array* a = n->as_array();
  if (!a) {
    type_error(key, *n, "an array of strings");
    return fallback;
  }
  for (const auto& e : *a) {
    if (!e.is_string()) {
      type_error(key, *n, "an array of strings");
      return fallback;
    }
    out.push_back(e.as_string()->get());
  }
  return out;
}

Section Section::table(std::string_view key) {
  Section s = optional_table(key);
  if (!s.present() && !(table_ && table_->contains(key))) missing(key, "a table");
  return s;
}

Section Section::optional_table(std::string_view key) {
  const toml::node* n = get(key);
  if (!n) return Section(deck_, nullptr, key_path(key));
  if (!n->is_table()) {
    type_error(key, *n, "a table");
    return Section(deck_, nullptr, key_path(key));
  }
  return Section(deck_, n->as_table(), key_path(key));
}

std::vector<Section> Section::tables(std::string_view key) {
  const toml::node* n = get(key);
  std::vector<Section> out;
  if (!n) return out;
  const toml::array* a = n->as_array();
  if (!a || !a->is_array_of_tables()) {
    type_error(key, *n, "an array of tables ([[" + std::string(key) + "]])");
    return out;
  }
  for (std::size_t i = 0; i < a->size(); ++i) {
    std::string p = fmt::format("{}[{}]", key_path(key), i);
    deck_->mark_known(p);
    out.emplace_back(deck_, a->get(i)->as_table(), p);
  }
  return out;
}

void Section::check(bool ok, std::string_view key, std::string_view reason) {
  if (ok) return;
  const toml::node* n = table_ ? table_->get(key) : nullptr;
  deck_->add_error(n ? n : table_,
                   fmt::format("key '{}' = {}: {}", key_path(key), value_text(key), reason));
}

void Section::positive(std::string_view key, double value) {
  check(value > 0.0, key, "must be positive");
}

void Section::non_negative(std::string_view key, double value) {
  check(value >= 0.0, key, "must not be negative");
}

void Section::error(std::string_view reason) {
  deck_->add_error(table_, fmt::format("[{}]: {}", path_.empty() ? "deck" : path_, reason));
}

// ---------------------------------------------------------------- Deck

Deck::Deck(Deck&&) noexcept = default;
Deck& Deck::operator=(Deck&&) noexcept = default;
Deck::~Deck() = default;

Deck Deck::from_file(const std::string& file) {
  Deck d;
  d.name_ = file;
  try {
    d.table_ = std::make_unique<toml::table>(toml::parse_file(file));
  } catch (const toml::parse_error& e) {
    const auto& b = e.source().begin;
    throw InputError(fmt::format("{}:{}:{}: {}", file, b.line, b.column, e.description()));
  }
  return d;
}

Deck Deck::from_string(std::string_view text, std::string name) {
  Deck d;
  d.name_ = std::move(name);
  try {
    d.table_ = std::make_unique<toml::table>(toml::parse(text, d.name_));
  } catch (const toml::parse_error& e) {
    const auto& b = e.source().begin;
    throw InputError(fmt::format("{}:{}:{}: {}", d.name_, b.line, b.column, e.description()));
  }
  return d;
}

Section Deck::root() { return Section(this, table_.get(), ""); }

void Deck::mark_known(const std::string& path) { known_.insert(path); }

void Deck::add_error(const toml::node* where, std::string message) {
  if (where && where->source().begin.line > 0)
    errors_.push_back(fmt::format("{}:{}: {}", name_, where->source().begin.line, message));
  else
    errors_.push_back(fmt::format("{}: {}", name_, message));
}

void Deck::collect_unknown(const toml::table& t, const std::string& prefix) {
  for (const auto& [k, v] : t) {
    std::string path = join_path(prefix, k.str());
    if (!known_.count(path)) {
      // Suggest the nearest key that was asked for in the same table.
      std::string best;
      std::size_t best_d = 4;
      for (const auto& kn : known_) {
        auto dot = kn.rfind('.');
        std::string parent = dot == std::string::npos ? "" : kn.substr(0, dot);
        std::string leaf = dot == std::string::npos ? kn : kn.substr(dot + 1);
        if (parent != prefix) continue;
        std::size_t d = edit_distance(leaf, k.str());
        if (d < best_d) best_d = d, best = leaf;
      }
      std::string hint = best.empty() ? "" : fmt::format(" (did you mean '{}'?)", best);
      add_error(&v, fmt::format("unknown key '{}'{}", path, hint));
      continue;
    }
    if (const toml::table* sub = v.as_table()) {
      collect_unknown(*sub, path);
    } else if (const toml::array* a = v.as_array(); a && a->is_array_of_tables()) {
      for (std::size_t i = 0; i < a->size(); ++i)
        collect_unknown(*a->get(i)->as_table(), fmt::format("{}[{}]", path, i));
    }
  }
}

void Deck::finish() {
  collect_unknown(*table_, "");
  if (errors_.empty()) return;
  std::string all;
  for (const auto& e : errors_) all += (all.empty() ? "" : "\n") + e;
  throw InputError(all);
}

}  // namespace mpmx::io
