#include "mpmx/md/budget.hpp"

#include <cmath>

#include <fmt/format.h>

#include "mpmx/core/error.hpp"
#include "mpmx/core/machine.hpp"

namespace mpmx::md {

namespace {

// Bytes, fitted to the peak RSS of `mpmx md` (Cu EAM, Release): boxes of 500, 32,000
// and 131,072 atoms (14.5, 65 and 221 MB) and a 144,000-atom bar (287 MB, estimate
// within 2%); refitted to the tiled force loop with boxes of 32,000, 131,072 and 340,736
// atoms (86.7, 303 and 743 MB). Per local atom: its fields and copies (300), and per
// pair of its half list the list, its tiled copy and the force passes' pair buffers
// (36); per entry of locals plus ghosts (positions in three layouts, type, owner, image,
// bins, forces, density) 110, and 56 more for a bar's per-atom energy and virial; a
// jet's atom 1,500 more (its records and tiles' per-atom tallies: the s = 0.05 and 0.1
// samples, 28 and 122 MB); the program and potential tables 16 MiB.
constexpr double kBytesPerLocal = 300.0;
constexpr double kBytesPerPair = 36.0;
constexpr double kBytesPerEntry = 110.0;
constexpr double kBytesPerEntryPerAtom = 56.0;
constexpr double kBytesPerJetAtom = 1500.0;
constexpr double kBytesFixed = 16.0 * 1024 * 1024;

}  // namespace

double box_bytes(const double n[3], double a, double reach) {
  const double atoms = 4.0 * n[0] * n[1] * n[2], density = 4.0 / (a * a * a);
  double entries = density;
  for (int d = 0; d < 3; ++d) entries *= n[d] * a + 2.0 * reach;
  entries = std::max(entries, atoms);
  const double pairs = atoms * 0.5 * (4.0 / 3.0) * M_PI * reach * reach * reach * density;
  return kBytesPerLocal * atoms + kBytesPerEntry * entries + kBytesPerPair * pairs;
}

double compact_box_bytes(double atoms) {
  constexpr double kBytesPerAtom = 9 * 8 + 4 + 8;  // x, v, f; type; id
  constexpr double kBytesPerBox = 2048;            // the System itself, its vectors and stream
  return kBytesPerAtom * atoms + kBytesPerBox;
}

MdBudget estimate_md(const MdConfig& c, double cutoff) {
  MdBudget b;
  const double a = c.lattice_constant, reach = cutoff + c.options.skin;
  double n[3];
  double filled = 1.0;  // the part of the cells that holds atoms
  if (c.bar) {
    n[0] = c.bar_config.cells_x, n[1] = n[2] = c.bar_config.cells_yz;
    b.size_key = "bar.cells_x and bar.cells_yz";
  } else if (c.jet) {
    const JetConfig& j = c.jet_config;
    n[0] = j.nx(), n[1] = j.ny(), n[2] = j.nz();
    filled = 1.0 - j.notch_depth_A() / (2.0 * n[0] * a);  // the V notch: half its depth's share
    b.size_key = "jet.cells and jet.scale";
  } else {
    for (int d = 0; d < 3; ++d) n[d] = c.cells[d];
    b.size_key = "lattice.cells";
  }
  b.atoms = std::round(4.0 * n[0] * n[1] * n[2] * filled);
  // Locals plus ghosts: the box grown by the reach on every side (an upper bound: the
  // bar's x has vacuum instead of images).
  const double density = 4.0 / (a * a * a);
  double entries = density;
  for (int d = 0; d < 3; ++d) entries *= n[d] * a + 2.0 * reach;
  entries = std::max(entries, b.atoms);
  const double pairs = b.atoms * 0.5 * (4.0 / 3.0) * M_PI * reach * reach * reach * density;
  b.bytes = kBytesFixed + kBytesPerLocal * b.atoms + kBytesPerEntry * entries + kBytesPerPair * pairs +
            (c.bar || c.jet ? kBytesPerEntryPerAtom * entries : 0.0) + (c.jet ? kBytesPerJetAtom * b.atoms : 0.0);
  const double steps = static_cast<double>(c.relax_steps) + static_cast<double>(c.steps);
  b.atom_steps = b.atoms * (steps + c.scan_points);
  b.work_key = c.relax_steps > 0 ? "thermal.relax_steps + run.steps" : "run.steps";
  if (c.jet) b.work_key = "jet.duration_ps and jet.scale";
  return b;
}

void check_md_budget(const MdBudget& b, std::uint64_t memory_bytes, bool force) {
  if (memory_bytes > 0 && b.bytes > static_cast<double>(memory_bytes))
    throw InputError(fmt::format(
        "{}: {:.4g} atoms need about {} of memory ({:.4g} bytes), more than this machine's {}: make the "
        "system smaller",
        b.size_key, b.atoms, format_bytes(b.bytes), b.bytes, format_bytes(static_cast<double>(memory_bytes))));
  if (!force && b.atom_steps > kMdWorkLimit)
    throw InputError(fmt::format(
        "{}: {:.4g} atoms x {:.4g} steps = {:.4g} atom-steps, about {:.3g} days at {:.2g} atom-steps/s: more "
        "than the {:.3g} atom-steps (a day) a run takes without --force",
        b.work_key, b.atoms, b.atom_steps / b.atoms, b.atom_steps,
        b.atom_steps / kMdAtomStepsPerSecond / 86400.0, kMdAtomStepsPerSecond, kMdWorkLimit));
}

}  // namespace mpmx::md
