#include "mpmx/md/declared_lattice.hpp"

#include <cmath>
#include <filesystem>

#include <fmt/format.h>

#include "mpmx/md/equilibrium.hpp"
#include "mpmx/md/potential/eam.hpp"

namespace mpmx::md {

namespace {
// How far a deck's constant may sit from the file's before it is worth a word: thermal
// expansion to the melt is 2-3%, a different crystal or element 8% and more.
constexpr double kConstantTolerance = 0.05;
}  // namespace

std::optional<particles::LatticeSpec> declared_lattice(const Potential& pot, int type) {
  const Eam* eam = pot.eam();
  if (!eam || type < 0 || type >= static_cast<int>(eam->declared_lattices().size())) return std::nullopt;
  const DeclaredLattice& d = eam->declared_lattices()[static_cast<std::size_t>(type)];
  if (d.name != "fcc" && d.name != "bcc" && d.name != "hcp") return std::nullopt;
  particles::LatticeSpec s;
  s.style = particles::lattice_style(d.name);
  s.constant = d.constant;
  return s;
}

std::string lattice_contradiction(const Potential& pot, int type, particles::LatticeStyle style, double constant) {
  const auto d = declared_lattice(pot, type);
  if (!d || style == particles::LatticeStyle::b2) return "";  // b2 pairs two elements: no one element's crystal
  const Eam& eam = *pot.eam();
  const std::string said =
      fmt::format("{} declares {} {} at a = {:g} A", std::filesystem::path(eam.file()).filename().string(),
                  eam.type_names()[static_cast<std::size_t>(type)], particles::lattice_name(d->style), d->constant);
  if (style != d->style) {
    // The file's word is a convention: the potential's own crystal is the one of least
    // energy. Where the deck's lies no higher than the file's, the file is what is wrong.
    const int types = pot.types();
    if (types == 1) {
      particles::LatticeSpec mine;
      mine.style = style;
      try {
        const double e_mine = lattice_equilibrium(pot, mine).energy_per_atom;
        const double e_file = lattice_equilibrium(pot, *d).energy_per_atom;
        if (e_mine <= e_file + 1e-6) return "";
        return fmt::format("the deck builds {} on a {} lattice, but {}, and this potential's {} crystal lies {:.4g} "
                           "eV/atom below its {} at their 0 K minima",
                           eam.type_names()[static_cast<std::size_t>(type)], particles::lattice_name(style), said,
                           particles::lattice_name(d->style), e_mine - e_file, particles::lattice_name(style));
      } catch (const std::exception&) {  // a crystal without a minimum: the file's word stands alone
      }
    }
    return fmt::format("the deck builds {} on a {} lattice, but {} (LAMMPS ignores that line, and a file may name "
                       "another crystal than the element's: make sure the deck's is the one meant)",
                       eam.type_names()[static_cast<std::size_t>(type)], particles::lattice_name(style), said);
  }
  if (constant > 0 && std::abs(constant / d->constant - 1.0) > kConstantTolerance)
    return fmt::format("the deck's lattice constant {:g} A is {:+.1f}% from the file's: {}", constant,
                       100.0 * (constant / d->constant - 1.0), said);
  return "";
}

}  // namespace mpmx::md
