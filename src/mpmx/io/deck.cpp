#include "mpmx/core/input_files.hpp"
#include "mpmx/io/deck.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <sstream>

#include <fmt/format.h>

#include "mpmx/core/error.hpp"
#include "mpmx/core/file_text.hpp"

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

// A key's dotted path, for messages and the known-key set: a key written with control
// characters (TOML allows "a\u001b" = 1) is shown escaped.
std::string join_path(const std::string& prefix, std::string_view key) {
  return prefix.empty() ? escape_controls(key) : prefix + "." + escape_controls(key);
}

constexpr std::int64_t kMin64 = std::numeric_limits<std::int64_t>::min();
constexpr std::int64_t kMax64 = std::numeric_limits<std::int64_t>::max();

// "from 1 to 1000", ">= 1", "<= 7", "" (no limit).
std::string bounds_text(std::int64_t lo, std::int64_t hi) {
  if (lo == kMin64 && hi == kMax64) return "";
  if (hi == kMax64) return fmt::format(">= {}", lo);
  if (lo == kMin64) return fmt::format("<= {}", hi);
  return fmt::format("from {} to {}", lo, hi);
}

// "out of range: must be an integer from 1 to 1000": the reason of an out-of-range value.
std::string limits_reason(std::int64_t lo, std::int64_t hi);

// "an integer from 1 to 1000", "an integer".
std::string range_text(std::int64_t lo, std::int64_t hi) {
  const std::string b = bounds_text(lo, hi);
  return b.empty() ? "an integer" : "an integer " + b;
}

std::string limits_reason(std::int64_t lo, std::int64_t hi) { return "out of range: must be " + range_text(lo, hi); }

// A float where an integer is wanted, shown as one: 4.0, 1e+12, 10.5 (describe() writes 4
// and 1000000000000, which would hide the point of the message).
std::string float_text(double v) {
  if (!std::isfinite(v) || v != std::floor(v)) return fmt::format("{}", v);
  if (std::abs(v) < 1e7) return fmt::format("{:.1f}", v);
  const std::string short_form = fmt::format("{:.6g}", v);  // 1e+12, as most would write it
  return std::strtod(short_form.c_str(), nullptr) == v ? short_form : fmt::format("{:.17g}", v);
}

// Why a floating-point value is not an integer, for the type error.
std::string float_hint(double v) {
  if (!std::isfinite(v)) return "";
  if (v == std::floor(v) && std::abs(v) < 9.2e18)
    return fmt::format(" (write {} without a decimal point or exponent)", static_cast<std::int64_t>(v));
  if (v == std::floor(v)) return " (and it is beyond the 64-bit integer range)";
  return " (it has a fractional part)";
}

}  // namespace

std::string describe(const toml::node& node) {
  if (node.is_table()) return "{...}";
  std::ostringstream os;
  if (const toml::array* a = node.as_array()) {
    // One line, as written: [1, 2, 3].
    os << '[';
    for (std::size_t i = 0; i < a->size(); ++i) os << (i ? ", " : "") << describe(*a->get(i));
    os << ']';
  } else if (auto s = node.value<std::string>(); s && node.is_string()) {
    os << '"' << escape_controls(*s) << '"';  // a deck's text never reaches a terminal raw
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
  deck_->add_key_error(&node, key_path(key),
                       fmt::format("key '{}' = {}: expected {}, got {}", key_path(key), describe(node), want,
                                   type_name(node)));
}

void Section::missing(std::string_view key, std::string_view want) {
  deck_->add_key_error(table_, key_path(key),
                       fmt::format("key '{}' is missing: expected {}", key_path(key), want));
}

double Section::number(std::string_view key) {
  const toml::node* n = get(key);
  if (!n) {
    missing(key, "a number");
    return std::nan("");
  }
  if (auto v = n->value<double>(); v && (n->is_floating_point() || n->is_integer())) {
    if (!std::isfinite(*v)) check(false, key, "must be a finite number (nan and inf are not accepted)");
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
  bool ok = false;
  return checked_integer(key, *n, kMin64, kMax64, 0, ok);
}

std::int64_t Section::integer(std::string_view key, std::int64_t fallback) {
  if (!has(key)) {
    get(key);
    return fallback;
  }
  return integer(key);
}

std::int64_t Section::checked_integer(std::string_view key, const toml::node& n, std::int64_t lo,
                                      std::int64_t hi, std::int64_t on_error, bool& ok) {
  ok = false;
  if (!n.is_integer()) {
    if (n.is_floating_point()) {
      deck_->add_key_error(&n, key_path(key),
                           fmt::format("key '{}' = {}: expected an integer, got a number{}", key_path(key),
                                       float_text(n.as_floating_point()->get()),
                                       float_hint(n.as_floating_point()->get())));
    } else {
      type_error(key, n, "an integer");
    }
    return on_error;
  }
  const std::int64_t v = n.as_integer()->get();
  if (v < lo || v > hi) {
    deck_->add_key_error(&n, key_path(key),
                         fmt::format("key '{}' = {}: {}", key_path(key), v, limits_reason(lo, hi)));
    return std::clamp(v, lo, hi);
  }
  ok = true;
  return v;
}

std::int64_t Section::integer(std::string_view key, std::int64_t lo, std::int64_t hi) {
  const toml::node* n = get(key);
  if (!n) {
    missing(key, range_text(lo, hi));
    return lo;
  }
  bool ok = false;
  return checked_integer(key, *n, lo, hi, lo, ok);
}

std::int64_t Section::integer(std::string_view key, std::int64_t fallback, std::int64_t lo, std::int64_t hi) {
  const toml::node* n = get(key);
  if (!n) return fallback;
  bool ok = false;
  return checked_integer(key, *n, lo, hi, std::clamp(fallback, lo, hi), ok);
}

int Section::integer_int(std::string_view key, int lo, int hi) {
  return static_cast<int>(integer(key, std::int64_t{lo}, std::int64_t{hi}));
}

int Section::integer_int(std::string_view key, int fallback, int lo, int hi) {
  return static_cast<int>(integer(key, std::int64_t{fallback}, std::int64_t{lo}, std::int64_t{hi}));
}

const toml::array* Section::array_at(std::string_view key, const toml::node* n, const std::string& want) {
  if (!n) {
    missing(key, want);
    return nullptr;
  }
  const toml::array* a = n->as_array();
  if (!a) type_error(key, *n, want);
  return a;
}

std::vector<std::int64_t> Section::integers(std::string_view key, std::int64_t lo, std::int64_t hi) {
  const toml::node* n = get(key);
  const std::string b = bounds_text(lo, hi);
  const std::string want = b.empty() ? "an array of integers" : "an array of integers, each " + b;
  const toml::array* a = array_at(key, n, want);
  if (!a) return {};
  std::vector<std::int64_t> out;
  for (std::size_t i = 0; i < a->size(); ++i) {
    const toml::node& e = *a->get(i);
    if (!e.is_integer()) {
      const bool fp = e.is_floating_point();
      const std::string hint = fp ? float_hint(e.as_floating_point()->get()) : "";
      deck_->add_key_error(&e, key_path(key),
                           fmt::format("key '{}' = {}: entry {} is {}, expected an integer{}", key_path(key),
                                       describe(*n), i + 1, fp ? float_text(e.as_floating_point()->get()) : describe(e),
                                       hint));
      return {};
    }
    const std::int64_t v = e.as_integer()->get();
    if (v < lo || v > hi) {
      deck_->add_key_error(&e, key_path(key),
                           fmt::format("key '{}' = {}: entry {} = {}: {}", key_path(key),
                                       describe(*n), i + 1, v, limits_reason(lo, hi)));
      return {};
    }
    out.push_back(v);
  }
  return out;
}

std::vector<std::vector<std::int64_t>> Section::integer_rows(std::string_view key, std::int64_t lo, std::int64_t hi) {
  const toml::node* n = get(key);
  const toml::array* a = array_at(key, n, "an array of arrays of integers, each " + bounds_text(lo, hi));
  if (!a) return {};
  std::vector<std::vector<std::int64_t>> out;
  for (std::size_t r = 0; r < a->size(); ++r) {
    const toml::array* row = a->get(r)->as_array();
    if (!row) {
      deck_->add_key_error(a->get(r), key_path(key),
                           fmt::format("key '{}' = {}: row {} is {}, expected an array of integers", key_path(key),
                                       describe(*n), r + 1, describe(*a->get(r))));
      return {};
    }
    std::vector<std::int64_t> values;
    for (std::size_t i = 0; i < row->size(); ++i) {
      const toml::node& e = *row->get(i);
      if (!e.is_integer() || e.as_integer()->get() < lo || e.as_integer()->get() > hi) {
        deck_->add_key_error(&e, key_path(key),
                             fmt::format("key '{}' = {}: row {} entry {} is {}, expected an integer {}", key_path(key),
                                         describe(*n), r + 1, i + 1, describe(e), bounds_text(lo, hi)));
        return {};
      }
      values.push_back(e.as_integer()->get());
    }
    out.push_back(std::move(values));
  }
  return out;
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
    deck_->add_key_error(n, key_path(key),
                         fmt::format("key '{}' = \"{}\": not one of {}", key_path(key), escape_controls(v), list));
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
  for (std::size_t i = 0; i < a->size(); ++i) {
    const toml::node& e = *a->get(i);
    if (!(e.is_floating_point() || e.is_integer())) {
      type_error(key, *n, "an array of numbers");
      return {};
    }
    const double v = *e.value<double>();
    if (!std::isfinite(v)) {
      deck_->add_key_error(&e, key_path(key),
                           fmt::format("key '{}' = {}: entry {} is {}: every entry must be a finite number "
                                       "(nan and inf are not accepted)",
                                       key_path(key), describe(*n), i + 1, describe(e)));
      return {};
    }
    out.push_back(v);
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

std::unique_ptr<Table> Section::sub(std::string_view key) { return std::make_unique<Section>(table(key)); }
std::unique_ptr<Table> Section::optional_sub(std::string_view key) {
  return std::make_unique<Section>(optional_table(key));
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
  deck_->add_key_error(n ? n : table_, key_path(key),
                       fmt::format("key '{}' = {}: {}", key_path(key), value_text(key), reason));
}

void Section::positive(std::string_view key, double value) {
  check(value > 0.0, key, "must be positive");
}

void Section::non_negative(std::string_view key, double value) {
  check(value >= 0.0, key, "must not be negative");
}

void Section::temperature(std::string_view key, double value) {
  check(value >= 0.0 && value <= 1e6, key, "must be a temperature from 0 to 1e6 K");
}

bool Section::failed(std::string_view key) const { return deck_->has_key_error(key_path(key)); }

void Section::ignore(std::string_view key) { deck_->mark_known(key_path(key)); }

void Section::error(std::string_view reason) {
  deck_->add_error(table_, fmt::format("[{}]: {}", path_.empty() ? "deck" : path_, reason));
}

// ---------------------------------------------------------------- Deck

Deck::Deck(Deck&&) noexcept = default;
Deck& Deck::operator=(Deck&&) noexcept = default;
Deck::~Deck() = default;

Deck Deck::from_file(const std::string& file, std::string_view what) {
  namespace fs = std::filesystem;
  if (file.empty()) throw InputError(fmt::format("the {} name is empty", what));
  if (const std::string why = file_problem(file, what); !why.empty()) {
    std::error_code ec;
    throw InputError(
        fmt::format("{}: {}{}", short_path(file), why, fs::is_directory(file, ec) ? " (give a .toml file)" : ""));
  }
  Deck d;
  d.name_ = file;
  note_input_file(file);  // pinned by a checkpoint (a potential file read as a deck too)
  try {
    d.table_ = std::make_unique<toml::table>(toml::parse_file(file));
  } catch (const toml::parse_error& e) {
    const auto& b = e.source().begin;
    // The parser quotes the bytes it met: a binary file's are escaped, not sent to the terminal.
    throw InputError(fmt::format("{}:{}:{}: {}", file, b.line, b.column, escape_unprintable(e.description())));
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

bool Deck::has_key_error(const std::string& key_path) const {
  if (errored_keys_.count(key_path)) return true;
  // A table above it: "a" or "a.b" for "a.b.c", "a[0]" for "a[0].b".
  for (std::size_t i = 0; i < key_path.size(); ++i)
    if ((key_path[i] == '.' || key_path[i] == '[') && errored_keys_.count(key_path.substr(0, i))) return true;
  return false;
}

bool Deck::add_key_error(const toml::node* where, const std::string& key_path, std::string message) {
  if (has_key_error(key_path)) return false;
  errored_keys_.insert(key_path);
  add_error(where, std::move(message));
  return true;
}

void Deck::add_error(const toml::node* where, std::string message) {
  // Escaped whole: the deck's name and what a file the deck names said are a user's text too.
  if (where && where->source().begin.line > 0)
    errors_.push_back(escape_controls(fmt::format("{}:{}: {}", name_, where->source().begin.line, message), true));
  else
    errors_.push_back(escape_controls(fmt::format("{}: {}", name_, message), true));
}

void Deck::collect_unknown(const toml::table& t, const std::string& prefix) {
  for (const auto& [k, v] : t) {
    std::string path = join_path(prefix, k.str());
    if (!known_.count(path) && has_key_error(path)) continue;  // its error said what is wrong with it
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
