#pragma once
// run.json: one JSON document per run (the deck echoed, version, timings, conservation,
// error norms), built as a TOML table and written atomically so a reader never sees
// half a file. It is always valid JSON: JSON has no NaN or Inf, so a non-finite number
// (a run the physics stopped) is written as null and named in a root "non_finite" list.
#include <string>
#include <string_view>
#include <vector>

#include <toml++/toml.h>

#include "mpmx/io/atomic_file.hpp"

namespace mpmx::io {

class RunRecord {
 public:
  // Sets a value at a dotted path ("errors.velocity.l1"), creating tables on the way.
  // A non-finite double is kept as it is (a checkpoint's TOML holds it) and written to
  // JSON as null (json_text).
  void set(std::string_view dotted, double value);
  void set(std::string_view dotted, std::int64_t value);
  void set(std::string_view dotted, int value) { set(dotted, static_cast<std::int64_t>(value)); }
  void set(std::string_view dotted, bool value);
  void set(std::string_view dotted, std::string value);
  void set(std::string_view dotted, const char* value) { set(dotted, std::string(value)); }
  void set(std::string_view dotted, const std::vector<double>& values);
  void set(std::string_view dotted, toml::table table);
  void set(std::string_view dotted, toml::array values);
  // Appends a table to the array at `dotted` (created when absent).
  void append(std::string_view dotted, toml::table table);

  const toml::table& table() const { return root_; }
  // Replaces the whole record (a resumed run carries on its predecessor's).
  void assign(toml::table t) { root_ = std::move(t); }
  std::string json() const;
  // Writes DIR/run.json via a temporary file and rename.
  void write(const std::string& path) const;

 private:
  toml::table& parent_of(std::string_view dotted, std::string& leaf);
  toml::table root_;
};


// The JSON text of a table (toml++'s JSON layout), valid JSON whatever it holds: each
// non-finite number becomes null, and the root gets "non_finite": the dotted keys of
// those values ("stress_gpa[0][2]", "box.lx"), in order; no "non_finite" when all are finite.
std::string json_text(const toml::table& table);

}  // namespace mpmx::io
