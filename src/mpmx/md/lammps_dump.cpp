#include "mpmx/md/lammps_dump.hpp"

#include <algorithm>
#include <iterator>
#include <numeric>

#include <fmt/format.h>

#include "mpmx/md/structure.hpp"

namespace mpmx::md {

void write_lammps_dump(std::ostream& out, std::int64_t step, const Atoms& a, const Box& b,
                       const std::vector<DumpColumn>& more) {
  out << fmt::format("ITEM: TIMESTEP\n{}\nITEM: NUMBER OF ATOMS\n{}\n", step, a.size());
  if (b.xy == 0 && b.xz == 0 && b.yz == 0) {
    out << fmt::format("ITEM: BOX BOUNDS pp pp pp\n0 {:.16g}\n0 {:.16g}\n0 {:.16g}\n", b.lx, b.ly, b.lz);
  } else {
    const double xlo = std::min({0.0, b.xy, b.xz, b.xy + b.xz});
    const double xhi = b.lx + std::max({0.0, b.xy, b.xz, b.xy + b.xz});
    const double ylo = std::min(0.0, b.yz), yhi = b.ly + std::max(0.0, b.yz);
    out << fmt::format("ITEM: BOX BOUNDS xy xz yz pp pp pp\n{:.16g} {:.16g} {:.16g}\n{:.16g} {:.16g} {:.16g}\n"
                       "0 {:.16g} {:.16g}\n",
                       xlo, xhi, b.xy, ylo, yhi, b.xz, b.lz, b.yz);
  }
  out << "ITEM: ATOMS id type x y z vx vy vz";
  for (const auto& c : more) out << ' ' << c.name;
  out << '\n';
  // Rows by id, as LAMMPS's `dump_modify sort id` writes them: the engine keeps its atoms
  // in spatial order, and a reader that numbers atoms by row (LAMMPS's `rerun ... add
  // yes`, a script comparing files row by row) would otherwise pair one atom's columns
  // with another's.
  std::vector<std::size_t> order(a.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t p, std::size_t q) { return a.id[p] < a.id[q]; });
  std::string line;
  for (const std::size_t i : order) {
    line = fmt::format("{} {} {:.10g} {:.10g} {:.10g} {:.8g} {:.8g} {:.8g}", a.id[i], a.type[i] + 1, a.x[i], a.y[i],
                       a.z[i], a.vx[i], a.vy[i], a.vz[i]);
    for (const auto& c : more) fmt::format_to(std::back_inserter(line), " {:.10g}", c.values[i]);
    line += '\n';
    out << line;
  }
}

const std::vector<std::string>& dump_field_names() {
  static const std::vector<std::string> names{"pe", "stress", "structure"};
  return names;
}

bool dump_needs_per_atom(const std::vector<std::string>& fields) {
  return std::any_of(fields.begin(), fields.end(), [](const std::string& f) { return f == "pe" || f == "stress"; });
}

std::string dump_fields_problem(const std::vector<std::string>& fields) {
  const auto& known = dump_field_names();
  for (const std::string& f : fields) {
    if (std::find(known.begin(), known.end(), f) == known.end())
      return fmt::format("'{}' is not a per-atom field (fields: pe, stress, structure)", f);
    if (std::count(fields.begin(), fields.end(), f) > 1) return fmt::format("'{}' is named twice", f);
  }
  return {};
}

void write_dump_frame(std::ostream& out, const System& sys, const std::vector<std::string>& fields, int threads,
                      std::int64_t step) {
  const Atoms atoms = sys.snapshot();
  const std::size_t n = atoms.size();
  std::vector<DumpColumn> more;
  for (const std::string& f : fields) {
    if (f == "pe") {
      const auto& e = sys.per_atom_energy();
      more.push_back({"pe", std::vector<double>(e.begin(), e.begin() + static_cast<std::ptrdiff_t>(n))});
    } else if (f == "stress") {
      const std::vector<double> s = sys.atom_stress_gpa();
      const char* names[6] = {"sxx", "syy", "szz", "sxy", "sxz", "syz"};
      for (int c = 0; c < 6; ++c) {
        DumpColumn col{names[c], std::vector<double>(n)};
        for (std::size_t i = 0; i < n; ++i) col.values[i] = s[6 * i + c];
        more.push_back(std::move(col));
      }
    } else if (f == "structure") {
      const auto labels = adaptive_cna(atoms, sys.box(), sys.potential().cutoff(), threads);
      DumpColumn col{"structure", std::vector<double>(n)};
      for (std::size_t i = 0; i < n; ++i) col.values[i] = static_cast<double>(labels[i]);
      more.push_back(std::move(col));
    }
  }
  write_lammps_dump(out, step >= 0 ? step : sys.step(), atoms, sys.box(), more);
}

}  // namespace mpmx::md
