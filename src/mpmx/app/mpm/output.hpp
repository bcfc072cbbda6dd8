#pragma once
// The tables a 1-D run writes: particles.csv and nodes.csv at the recorded times
// (ADMPM's columns, the point's body and material, the law's own fields such as
// temperature, plus ref_<field> where a reference exists), energy.csv
// over time, front.csv for shock-front cases. Rows of one record are written and
// flushed together, so a stopped run leaves whole records only.
#include <cstdint>
#include <cstdio>
#include <functional>
#include <map>
#include <string>
#include <string_view>

#include <fmt/format.h>
#include <vector>

#include "mpmx/mpm/nodal_fields.hpp"
#include "mpmx/mpm/state.hpp"

namespace mpmx::app {

class Reference;

class Output {
 public:
  // Tables and their lengths in bytes, as a checkpoint records them.
  using Marks = std::map<std::string, std::int64_t>;

  // With `resume`, each table is cut back to its recorded length and appended to, so a
  // resumed run's tables equal an uninterrupted run's. `prefix` names the files
  // (final_: a stopped run's last state, written once).
  Output(const std::string& dir, bool nodes, bool particles, Marks resume = {}, std::string prefix = "");
  ~Output();
  Output(const Output&) = delete;
  Output& operator=(const Output&) = delete;

  void record(const mpm::State<1>& s, const mpm::NodalFields& nf, const Reference* ref);
  void energy(std::int64_t step, double t, double kinetic, double internal, double momentum,
              double boundary_impulse, double ref_total);
  void front(double t, double x, double ref_x);
  // A row of numbers to the table `table` (`header`, a line, heads it): the gauges'
  // histories (gauges.hpp) and the x-t diagram. These tables hold no file open: their rows
  // wait in memory and are appended (the file opened, written, closed) when all of them
  // pass kPendingBytes, at marks() and at close(), so that a deck's thousands of gauges
  // run within the system's limit of open files.
  void row(const std::string& table, std::string_view header, const std::vector<double>& values);
  // Flushes every table and returns their lengths.
  Marks marks();
  // Closes every table; SystemError when the last bytes could not be written.
  void close();

  static constexpr std::size_t kPendingBytes = std::size_t{1} << 20;

 private:
  std::FILE* open(const std::string& name, const char* header);
  // `bytes` to the table `f` (and flushed); SystemError naming it and the system's reason.
  void emit(std::FILE* f, std::string_view bytes, bool flush = false);
  // row()'s tables: the rows not yet in the file, the file's length, and whether the file
  // is yet to be made (its first write truncates it).
  struct RowTable {
    std::string pending;
    std::int64_t written = 0;
    bool fresh = true;
  };
  // Appends every row table's pending rows to its file.
  void flush_rows();
  std::map<std::FILE*, std::string> names_;
  std::string dir_;
  std::FILE* nodes_ = nullptr;
  std::FILE* particles_ = nullptr;
  std::FILE* energy_ = nullptr;
  std::FILE* front_ = nullptr;
  std::map<std::string, RowTable> tables_;  // row()'s, by name
  std::size_t pending_bytes_ = 0;           // over all of them
  bool want_nodes_, want_particles_;
  Marks resume_;
  std::string prefix_;
  std::size_t extra_columns_ = 0;  // the law's fields in particles.csv
  fmt::memory_buffer buf_;  // one record's rows, written at once
};

}  // namespace mpmx::app
