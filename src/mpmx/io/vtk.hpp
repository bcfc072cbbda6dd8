#pragma once
// VTK XML files for ParaView: points (.vtu), node grids (.vti) and the time series that
// lists them (.pvd). Takes plain arrays, so any engine can write without io/ knowing it.
// Arrays are Float64 in raw appended binary (UInt64 headers): exact and fast to read.
// Every file is written to `path + ".tmp"` and renamed, so a killed run leaves either
// the old file or the new one, never a truncated one; an I/O failure throws
// mpmx::RunError naming the path. Mismatched array sizes throw std::invalid_argument.
#include <array>
#include <string_view>
#include <string>
#include <utility>
#include <vector>

namespace mpmx::io::vtk {

// One point-data array. ParaView's active Scalars/Vectors/Tensors are the first field
// with 1, 3 and 9 components.
struct Field {
  std::string name;
  int components = 1;          // 1 scalar, 3 vector, 9 tensor (row-major 3x3)
  std::vector<double> values;  // interleaved: values[i * components + c]
};

// Unstructured grid of n vertices (VTK_VERTEX cells); xyz interleaved, size 3n
// (2-D callers pass z = 0). Each field holds n * components values.
void write_points(const std::string& path, const std::vector<double>& xyz,
                  const std::vector<Field>& fields);

// Image data: nodes[d] points per axis (1 for an unused axis), origin, spacing; fields
// over the nodes in x-fastest order.
void write_image(const std::string& path, std::array<int, 3> nodes, std::array<double, 3> origin,
                 std::array<double, 3> spacing, const std::vector<Field>& fields);

// A .pvd collection that grows as records are written; every add() rewrites the file
// atomically, so ParaView can open it while the run goes on.
class Series {
 public:
  explicit Series(std::string path);  // e.g. DIR/particles.pvd
  // `file` is relative to the .pvd's folder, e.g. "vtk/particles_000010.vtu".
  void add(double time, const std::string& file);
  // For resuming a run: re-reads an existing .pvd (none: start empty) and keeps its
  // entries with time <= t. The file itself is rewritten at the next add().
  void restore_up_to(double t);
  // Drops the entries whose file name holds `part` (a stopped run's final record, which a
  // resumed run replaces by its own records).
  void drop_files_containing(std::string_view part);

  const std::vector<std::pair<double, std::string>>& entries() const { return entries_; }

 private:
  void write() const;
  std::string path_;
  std::vector<std::pair<double, std::string>> entries_;  // (time, file) in order added
};

}  // namespace mpmx::io::vtk
