#include "mpmx/app/md/budget.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "mpmx/core/error.hpp"
#include "mpmx/core/machine.hpp"
#include "mpmx/particles/tile_planes.hpp"

namespace mpmx::app::md {

MdBudget estimate_md(const MdConfig& c, double cutoff) {
  MdBudget b;
  const double reach = cutoff + c.options.skin;
  // The cell: fcc's cube of 4 atoms, or the oriented lattice's periodic tile.
  particles::LatticeSpec spec = c.lattice;
  spec.constant = c.lattice_constant;
  const particles::TilePlanes tile = particles::tile_planes(spec);
  const double* len = tile.length.data();
  const double per_cell = static_cast<double>(tile.atoms);
  double n[3];
  double filled = 1.0;  // the part of the cells that holds atoms
  if (c.bar) {
    n[0] = c.bar_config.cells_x, n[1] = n[2] = c.bar_config.cells_yz;
    b.size_key = "bar.cells_x and bar.cells_yz";
  } else if (c.jet) {
    const JetConfig& j = c.jet_config;
    n[0] = j.nx(), n[1] = j.ny(), n[2] = j.nz();
    filled = 1.0 - j.notch_depth_A() / (2.0 * n[0] * len[0]);  // the V notch: half its depth's share
    b.size_key = "jet.cells and jet.scale";
  } else if (c.rod) {
    const RodConfig& r = c.rod_config;
    n[0] = r.target_cells[0] + r.flyer_cells, n[1] = r.target_cells[1], n[2] = r.target_cells[2];
    b.size_key = "rod.target_cells and rod.flyer_cells";
  } else {
    for (int d = 0; d < 3; ++d) n[d] = c.cells[d];
    b.size_key = "lattice.cells";
  }
  b.atoms = std::round(per_cell * n[0] * n[1] * n[2] * filled);
  b.images = reach / std::min({n[0] * len[0], n[1] * len[1], n[2] * len[2]});
  // Locals plus ghosts: the box grown by the reach on every side (an upper bound: the
  // bar's x has vacuum instead of images).
  const double density = per_cell / (len[0] * len[1] * len[2]);
  double entries = density;
  for (int d = 0; d < 3; ++d) entries *= n[d] * len[d] + 2.0 * reach;
  entries = std::max(entries, b.atoms);
  const double pairs = b.atoms * 0.5 * (4.0 / 3.0) * M_PI * reach * reach * reach * density;
  b.bytes = kBytesFixed + kBytesPerLocal * b.atoms + kBytesPerEntry * entries + kBytesPerPair * pairs +
            (c.bar || c.jet ? kBytesPerEntryPerAtom * entries : 0.0) + (c.jet ? kBytesPerJetAtom * b.atoms : 0.0);
  const double steps = static_cast<double>(c.relax_steps) + static_cast<double>(c.steps);
  b.atom_steps = b.atoms * (steps + c.scan_points);
  b.work_key = c.relax_steps > 0 ? "thermal.relax_steps + run.steps" : "run.steps";
  if (c.rod) {
    b.atom_steps = b.atoms * (static_cast<double>(c.rod_equilibrate_steps) + static_cast<double>(c.steps));
    b.work_key = "rod.equilibrate_steps + run.steps";
  }
  if (c.jet) {
    b.work_key = "jet.duration_ps and jet.scale";
    b.bins = static_cast<double>(c.jet_bins[0]) * c.jet_bins[1];
    const double records = c.jet_every > 0 ? static_cast<double>(c.steps / c.jet_every) + 1.0 : 1.0;
    b.output_bytes = 230.0 * b.bins * records;  // a CSV row (about 150 bytes) and a .vti cell (80)
  }
  return b;
}

void check_md_budget(const MdBudget& b, std::uint64_t memory_bytes, bool force) {
  if (!(b.images <= kMaxImages))
    throw InputError(fmt::format("{}: the potential's cutoff plus run.skin reaches {:.4g} times across the box's "
                                 "shortest edge: at most {} periodic images are tracked; make the box larger",
                                 b.size_key, b.images, kMaxImages));
  // More bins than atoms leaves most of them empty and writes a table per record no
  // reader wants (1e6 bins for 350 atoms: 859 MB).
  if (b.bins > 0 && b.bins > b.atoms)
    throw InputError(fmt::format("jet.bins: {:.4g} bins for {:.4g} atoms (about {} of bin tables over the run): "
                                 "use at most one bin per atom",
                                 b.bins, b.atoms, format_bytes(b.output_bytes)));
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

}  // namespace mpmx::app::md
