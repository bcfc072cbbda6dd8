#pragma once
// A TOML deck read into typed values with every error named: the key, the value, the
// reason, the line. Keys a reader never asked for are reported as unknown (with the
// closest known key as a hint) when the reader calls Deck::finish().
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include <toml++/toml.h>

#include "mpmx/core/table.hpp"

namespace mpmx::io {

class Deck;

// A view of one table of the deck ("" is the root). Getters record the key as known;
// a wrong type or an out-of-range value is recorded as an error, and a usable
// fallback is returned so that reading goes on and every error is reported at once.
// A key is reported once: the first error on a key (or on a table above it) wins, so a
// missing or mistyped value is not reported again by the range checks that follow.
// Numbers are finite: nan and inf (TOML allows both) are refused naming the key.
class Section final : public Table {
 public:
  Section(Deck* deck, const toml::table* table, std::string path);

  const std::string& path() const override { return path_; }
  bool present() const override { return table_ != nullptr; }
  bool has(std::string_view key) const override;

  double number(std::string_view key) override;                     // required
  double number(std::string_view key, double fallback) override;    // optional
  // Integers are read as 64-bit. Without limits any 64-bit value passes; prefer the
  // checked forms below.
  std::int64_t integer(std::string_view key);
  std::int64_t integer(std::string_view key, std::int64_t fallback);
  // Checked integers: the value must lie in [lo, hi] (the key's limits); otherwise the
  // error names the key, the value and the range. A float (`cells = 1e12`, `4.0`) or a
  // string is a type error saying an integer is needed. On any error the value returned
  // lies in [lo, hi] (the fallback, lo, or the value clamped), so that reading goes on
  // with a value that is safe to size things by.
  std::int64_t integer(std::string_view key, std::int64_t lo, std::int64_t hi) override;                        // required
  std::int64_t integer(std::string_view key, std::int64_t fallback, std::int64_t lo, std::int64_t hi) override;  // optional
  // The same for a value kept in an int: the limits are ints, so no 64-bit value is ever
  // narrowed unchecked.
  int integer_int(std::string_view key, int lo, int hi) override;
  int integer_int(std::string_view key, int fallback, int lo, int hi) override;
  // An array of integers, each in [lo, hi] (the error names the entry).
  std::vector<std::int64_t> integers(std::string_view key, std::int64_t lo, std::int64_t hi) override;
  // An array of arrays of integers (`orient = [[1,1,0],[-1,1,0],[0,0,1]]`), each entry in
  // [lo, hi]; {} after an error (which names the row and entry).
  std::vector<std::vector<std::int64_t>> integer_rows(std::string_view key, std::int64_t lo,
                                                      std::int64_t hi) override;
  bool boolean(std::string_view key, bool fallback) override;
  std::string string(std::string_view key) override;
  std::string string(std::string_view key, std::string fallback) override;
  // A string that must be one of `allowed` (the error lists them).
  std::string choice(std::string_view key, const std::vector<std::string>& allowed) override;
  std::string choice(std::string_view key, const std::vector<std::string>& allowed,
                     std::string fallback) override;
  std::vector<double> numbers(std::string_view key) override;                      // required
  std::vector<double> numbers(std::string_view key, std::vector<double> fallback) override;
  std::vector<std::string> strings(std::string_view key, std::vector<std::string> fallback) override;

  Section table(std::string_view key);            // required sub-table
  Section optional_table(std::string_view key);   // absent -> present() == false
  // Array of tables ([[key]]): one Section each.
  std::vector<Section> tables(std::string_view key);
  // The same as Tables, for readers that see only the Table interface.
  std::unique_ptr<Table> sub(std::string_view key) override;
  std::unique_ptr<Table> optional_sub(std::string_view key) override;

  // Range checks: record "key = value: reason" unless ok.
  void check(bool ok, std::string_view key, std::string_view reason) override;
  void positive(std::string_view key, double value) override;
  void non_negative(std::string_view key, double value) override;
  // A temperature in K: from 0 to 1e6 K (beyond, no potential or mesoparticle model
  // means anything, and the velocities it draws overflow the run's figures).
  void temperature(std::string_view key, double value) override;
  // An error not tied to one key of this table.
  void error(std::string_view reason) override;
  // Whether `key` (or a table above it) has an error recorded.
  bool failed(std::string_view key) const;
  // Marks `key` read without reading it, for a reader that refused the key that gives it
  // a meaning: one error per mistake, not one more for each key that follows from it.
  void ignore(std::string_view key);

  std::string key_path(std::string_view key) const override;
  std::string value_text(std::string_view key) const override;

 private:
  const toml::node* get(std::string_view key);
  void type_error(std::string_view key, const toml::node& node, std::string_view want);
  void missing(std::string_view key, std::string_view want);
  // The array at `n` (the node of `key`), or nullptr after saying it is missing or not one.
  const toml::array* array_at(std::string_view key, const toml::node* n, const std::string& want);
  // The checked integer at a present node: type and range; `ok` false on any error.
  std::int64_t checked_integer(std::string_view key, const toml::node& n, std::int64_t lo, std::int64_t hi,
                               std::int64_t on_error, bool& ok);

  Deck* deck_;
  const toml::table* table_;
  std::string path_;
};

class Deck {
 public:
  // Parses the file; a syntax error throws InputError naming file, line and column; so
  // does a path that is missing or a directory.
  // `what` names the file in those messages ("deck file", "potential file").
  static Deck from_file(const std::string& file, std::string_view what = "deck file");
  static Deck from_string(std::string_view text, std::string name = "deck");

  Deck(Deck&&) noexcept;
  Deck& operator=(Deck&&) noexcept;
  ~Deck();

  Section root();
  const toml::table& table() const { return *table_; }
  const std::string& name() const { return name_; }

  // Adds "unknown key" errors for keys nobody read (and no error named already), then
  // throws InputError listing every error (one per line) if there is any.
  void finish();

  void add_error(const toml::node* where, std::string message);
  // An error about one key (a dotted path): recorded unless that key, or a table above
  // it, already has one (returns whether it was recorded).
  bool add_key_error(const toml::node* where, const std::string& key_path, std::string message);
  bool has_key_error(const std::string& key_path) const;
  void mark_known(const std::string& path);
  const std::vector<std::string>& errors() const { return errors_; }

 private:
  Deck() = default;
  void collect_unknown(const toml::table& t, const std::string& prefix);

  std::unique_ptr<toml::table> table_;
  std::string name_;
  std::set<std::string> known_;
  std::set<std::string> errored_keys_;
  std::vector<std::string> errors_;
};

// Text of a TOML value as a user wrote it, for messages.
std::string describe(const toml::node& node);

}  // namespace mpmx::io
