#include "mpmx/app/md/lammps_jet.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

#include <fmt/format.h>

#include "mpmx/app/md/lammps_bar.hpp"
#include "mpmx/core/error.hpp"
#include "mpmx/core/units.hpp"

namespace mpmx::app::md {

namespace fs = std::filesystem;

void write_lammps_jet(const System& sys, const JetGeometry& geo, const BinGrid& g, const PotentialSpec& spec,
                      double dt, std::int64_t steps, std::int64_t every, std::int64_t dump_every,
                      const std::string& dir) {
  if (!(dt > 0)) throw InputError(fmt::format("dt = {}: must be positive", dt));
  if (every < 1 || steps < 0 || steps % every != 0)
    throw InputError(fmt::format("steps = {}, record every {}: the LAMMPS route writes the bins' stress every "
                                 "record only, so steps must be a non-negative multiple of it",
                                 steps, every));
  const std::string pair = lammps_pair_lines(spec, sys.potential());
  fs::create_directories(dir);
  write_lammps_data(sys, (fs::path(dir) / kLammpsJetData).string(), "direct-MD jet");
  const double ly = g.ny * g.dy;
  // stress/atom is -(m v v + W) in bar A^3 (LAMMPS's nktv2p) -> GPa of the bin.
  const double to_gpa = units::eV_per_A3_in_GPa / (units::lammps_nktv2p * g.volume());
  std::ofstream in(fs::path(dir) / kLammpsJetInput);
  in << fmt::format(
      "# mpmx {}: direct-MD jet ({} atoms, {} x {} bins), the LAMMPS route of `mpmx md DECK --lammps`.\n"
      "# Writes {}: every {} steps, {} rows 'bin sxx syy szz sxy sxz syz' (GPa, Cauchy sign,\n"
      "# eq. 2.25 per bin, bin = ix + nx iy + 1) - the numbers of mpmx's bins/md_bins_STEP.csv.\n"
      "units metal\n"
      "atom_style atomic\n"
      "# x free and shrink-wrapped to the sample (mpmx's x is periodic over a vacuum wider than\n"
      "# 2 (cutoff + skin) plus half the sample, so no pair crosses it there either: same forces).\n"
      "boundary s p p\n"
      "read_data {}\n"
      "# The crystal jet.data's atoms are cut from (mpmx's [lattice]), its origin site at\n"
      "# x y z = {:.17g} {:.17g} {:.17g} A. The atoms and velocities come from jet.data;\n"
      "# this line names their lattice, as later commands in lattice units use it.\n"
      "{}"
      "# The ranks split x where the atoms are, not the box evenly (its vacuum would leave ranks idle),\n"
      "# and again every record as the block compresses and the jet grows.\n"
      "balance 1.0 shift x 20 1.02\n",
      MPMX_VERSION, sys.atoms().size(), g.nx, g.ny, kLammpsJetStress, every, g.nx * g.ny, kLammpsJetData,
      geo.origin[0], geo.origin[1], geo.origin[2], lammps_lattice_line(geo.lattice));
  if (sys.step() != 0) in << fmt::format("reset_timestep {}\n", sys.step());
  in << pair;
  in << fmt::format(
      "neighbor {:.17g} bin\n"
      "neigh_modify every 1 delay 0 check yes\n"
      "timestep {:.17g}\n"
      "# The rigid piston (sec. 7.1): its atoms, ids 1..{}, start at rest and are not integrated.\n"
      "group piston id <= {}\n"
      "group block subtract all piston\n"
      "fix nve block nve\n"
      "fix balance all balance {} 1.05 shift x 20 1.02\n"
      "# Bins exactly as mpmx's bin_fields(): ix = floor((x - x0) / dx) in [0, nx), y wrapped\n"
      "# periodically; atoms outside the x range count nowhere (chunk 0, discarded).\n"
      "variable ix atom floor((x-{:.17g})/{:.17g})\n"
      "variable iyr atom floor((y/{:.17g}-floor(y/{:.17g}))*{})\n"
      "variable iy atom v_iyr-(v_iyr>{})*(v_iyr-{})\n"
      "variable bin atom (v_ix>=0)*(v_ix<{})*(v_ix+1+{}*v_iy)\n"
      "compute bin all chunk/atom v_bin limit {} exact nchunk once discard yes\n"
      "compute bincom all temp/chunk bin com yes\n"
      "compute sa all stress/atom bincom ke pair\n"
      "# bar A^3 per atom -> GPa of the bin: {} / (nktv2p * dx * dy * lz)\n"
      "variable sxx atom c_sa[1]*{:.17g}\n"
      "variable syy atom c_sa[2]*{:.17g}\n"
      "variable szz atom c_sa[3]*{:.17g}\n"
      "variable sxy atom c_sa[4]*{:.17g}\n"
      "variable sxz atom c_sa[5]*{:.17g}\n"
      "variable syz atom c_sa[6]*{:.17g}\n"
      "# One reduce/chunk per component (see in.bar: LAMMPS 29Sep2021 with several inputs).\n"
      "compute rxx all reduce/chunk bin sum v_sxx\n"
      "compute ryy all reduce/chunk bin sum v_syy\n"
      "compute rzz all reduce/chunk bin sum v_szz\n"
      "compute rxy all reduce/chunk bin sum v_sxy\n"
      "compute rxz all reduce/chunk bin sum v_sxz\n"
      "compute ryz all reduce/chunk bin sum v_syz\n"
      "fix out all ave/time {} 1 {} c_rxx c_ryy c_rzz c_rxy c_rxz c_ryz mode vector file {} format \" %.17g\"\n",
      sys.options().skin, dt, geo.piston_atoms, geo.piston_atoms, every, g.x0, g.dx, ly, ly, g.ny, g.ny - 1, g.ny - 1, g.nx, g.nx,
      g.nx * g.ny, units::eV_per_A3_in_GPa, to_gpa, to_gpa, to_gpa, to_gpa, to_gpa, to_gpa, every, every,
      kLammpsJetStress);
  if (dump_every > 0)
    in << fmt::format("dump frames all custom {} dump.lammpstrj id type x y z vx vy vz\n"
                      "dump_modify frames sort id\n",
                      dump_every);
  in << fmt::format(
      "thermo_style custom step temp pe ke etotal press\n"
      "thermo_modify norm no\n"
      "thermo {}\n"
      "run {}\n",
      every, steps);
  if (!in)
    throw SystemError(
        fmt::format("error writing {}: {}", (fs::path(dir) / kLammpsJetInput).string(), std::strerror(errno)));
}

}  // namespace mpmx::app::md
