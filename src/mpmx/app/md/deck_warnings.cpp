#include "mpmx/app/md/deck_warnings.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "mpmx/core/units.hpp"
#include "mpmx/md/declared_lattice.hpp"
#include "mpmx/md/equilibrium.hpp"

namespace mpmx::app::md {

namespace {
// A static box off its potential's minimum by more than this (GPa) is not a crystal at
// rest: 1 GPa is about 0.7% of a metal's lattice constant.
constexpr double kRestingStressGpa = 1.0;
// A hot crystal is built expanded, its static tension balancing the thermal pressure
// gamma 3 kB T / V (Mie-Gruneisen; gamma up to 3, Pb's 2.7 the largest of the metals):
// that much tension more is the deck's intent (a constant from NPT at its temperature).
constexpr double kLargestGruneisen = 3.0;
}  // namespace

std::vector<std::string> md_deck_warnings(const MdConfig& c, const Potential& pot) {
  std::vector<std::string> out;
  const int types = c.lattice.style == particles::LatticeStyle::b2 ? 2 : 1;
  for (int t = 0; t < std::min(types, pot.types()); ++t)
    if (const std::string w = mpmx::md::lattice_contradiction(pot, t, c.lattice.style, c.lattice.constant); !w.empty())
      out.push_back(w);
  // The crystal as built, static: its stress is where the run starts (before any
  // temperature, which adds its own pressure).
  if (c.strain_x == 0.0) {
    const std::array<int, 3> tiles = mpmx::md::equilibrium_tiles(c.lattice);
    System s(particles::oriented_crystal(c.lattice, tiles), pot);
    const Mat3 sigma = s.stress_gpa();
    const double volume = s.box().volume() / static_cast<double>(s.atoms().size());
    const double thermal =
        kLargestGruneisen * 3.0 * units::boltzmann_eV_per_K * c.temperature / volume * units::eV_per_A3_in_GPa;
    bool off = false;
    for (const double v : {sigma[0], sigma[4], sigma[8]}) off = off || v < -kRestingStressGpa || v > kRestingStressGpa + thermal;
    if (off) {
      std::string where;
      try {
        const double a0 = mpmx::md::lattice_equilibrium(pot, c.lattice).lattice_constant;
        where = fmt::format("; this potential's {} crystal rests at a = {:.6g} A", particles::lattice_name(c.lattice.style), a0);
      } catch (const std::exception&) {  // no minimum in the scanned range: say only the stress
      }
      out.push_back(fmt::format("the static {} box at a = {:g} A is stressed: sigma xx, yy, zz = {:.3g}, {:.3g}, "
                                "{:.3g} GPa (tension positive), beyond what {} K explains{}",
                                particles::lattice_name(c.lattice.style), c.lattice.constant, sigma[0], sigma[4],
                                sigma[8], c.temperature, where));
    }
  }
  return out;
}

}  // namespace mpmx::app::md
