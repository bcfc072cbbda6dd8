#pragma once
// The table a registry entry reads its parameters from: named values with checked
// getters, every problem recorded against its key (the key, the value, the reason) and
// a usable fallback returned, so that reading goes on and every error is reported at
// once. The engines read through this alone and know nothing of TOML; io::Section
// implements it for a deck's tables. Integers come only checked against their limits:
// no deck value reaches an int unchecked.
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace mpmx {

class Table {
 public:
  virtual ~Table() = default;

  virtual const std::string& path() const = 0;  // "material", "material.md", "" (the root)
  virtual bool present() const = 0;
  virtual bool has(std::string_view key) const = 0;

  virtual double number(std::string_view key) = 0;                   // required
  virtual double number(std::string_view key, double fallback) = 0;  // optional
  // The value must lie in [lo, hi]; on any error the value returned lies there too.
  virtual std::int64_t integer(std::string_view key, std::int64_t lo, std::int64_t hi) = 0;
  virtual std::int64_t integer(std::string_view key, std::int64_t fallback, std::int64_t lo, std::int64_t hi) = 0;
  virtual int integer_int(std::string_view key, int lo, int hi) = 0;
  virtual int integer_int(std::string_view key, int fallback, int lo, int hi) = 0;
  virtual std::vector<std::int64_t> integers(std::string_view key, std::int64_t lo, std::int64_t hi) = 0;
  // An array of arrays of integers, each entry in [lo, hi]; {} after an error.
  virtual std::vector<std::vector<std::int64_t>> integer_rows(std::string_view key, std::int64_t lo,
                                                              std::int64_t hi) = 0;
  virtual bool boolean(std::string_view key, bool fallback) = 0;
  virtual std::string string(std::string_view key) = 0;
  virtual std::string string(std::string_view key, std::string fallback) = 0;
  // One of `allowed` (the error lists them).
  virtual std::string choice(std::string_view key, const std::vector<std::string>& allowed) = 0;
  virtual std::string choice(std::string_view key, const std::vector<std::string>& allowed, std::string fallback) = 0;
  virtual std::vector<double> numbers(std::string_view key) = 0;
  virtual std::vector<double> numbers(std::string_view key, std::vector<double> fallback) = 0;
  virtual std::vector<std::string> strings(std::string_view key, std::vector<std::string> fallback) = 0;

  // A sub-table: required, or optional (absent: present() is false).
  virtual std::unique_ptr<Table> sub(std::string_view key) = 0;
  virtual std::unique_ptr<Table> optional_sub(std::string_view key) = 0;

  // Range checks: record "key = value: reason" unless ok.
  virtual void check(bool ok, std::string_view key, std::string_view reason) = 0;
  virtual void positive(std::string_view key, double value) = 0;
  virtual void non_negative(std::string_view key, double value) = 0;
  // A temperature in K, from 0 to 1e6.
  virtual void temperature(std::string_view key, double value) = 0;
  // An error not tied to one key of this table.
  virtual void error(std::string_view reason) = 0;

  virtual std::string key_path(std::string_view key) const = 0;
  virtual std::string value_text(std::string_view key) const = 0;
};

}  // namespace mpmx
