// ctest-label: slow
// D0 (VALIDATION.md; seed 004 sec. 2.2): the MD-to-DPD fit from the example deck at
// reduced length (7 densities over rho0 (1 +- 10%), shorter MD and DPDE runs): the
// fitted DPDE isotherm of Morse mesoparticles of 8 atoms lies within 2% of the MD
// pressure range of Sutton-Chen copper at 298 K at every sampled density, and its
// zero-pressure density within 0.5% of MD's. examples/D0_md_to_dpd_fit.toml is the full
// case (`mpmx fit-dpd`).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "mpmx/app/dpd/fit_config.hpp"
#include "mpmx/multiscale/isotherm.hpp"

namespace {

using namespace mpmx;

TEST(DpdFitD0, FittedDpdeReproducesTheSuttonChenIsotherm) {
  // One literal: GCC 12 warns (-Warray-bounds) of operator+ on a temporary here, wrongly.
  io::Deck deck = io::Deck::from_file(MPMX_SOURCE_DIR "/examples/D0_md_to_dpd_fit.toml");
  app::dpd::FitConfig c = app::dpd::read_fit_config(deck);
  c.density_ratios = {0.9, 0.94, 0.97, 1.0, 1.03, 1.06, 1.1};
  c.md.equilibrate_steps = 1000, c.md.sample_steps = 1000, c.md.threads = 2;
  c.fit.dpd.equilibrate_steps = 500, c.fit.dpd.sample_steps = 1000, c.fit.dpd.threads = 2;
  c.fit.iterations = 2;
  const md::Potential pot(c.md_potential);
  std::vector<double> lattice;
  for (double r : c.density_ratios) lattice.push_back(c.lattice_constant / std::cbrt(r));
  const auto md = multiscale::md_isotherm(pot, lattice, c.md);
  c.fit.dpd.mass = c.fit.atoms_per_particle * pot.mass(0);
  const multiscale::FitResult fit = multiscale::fit_morse(md, c.fit);
  std::vector<double> pm, pd;
  for (std::size_t k = 0; k < md.size(); ++k) {
    pm.push_back(md[k].pressure), pd.push_back(fit.dpd[k].pressure);
    std::printf("rho/rho0 %.2f: MD %8.3f GPa (T %.0f K), DPDE %8.3f GPa\n", c.density_ratios[k], pm[k],
                md[k].temperature, pd[k]);
  }
  const double z_md = multiscale::zero_pressure_density(c.density_ratios, pm);
  const double z_dpd = multiscale::zero_pressure_density(c.density_ratios, pd);
  std::printf("Morse D0 %.5f eV, alpha %.5f 1/A, r0 %.5f A: max deviation %.3g of the range; zero pressure at "
              "rho/rho0 %.5f (MD) %.5f (DPDE)\n",
              fit.potential.d0, fit.potential.alpha, fit.potential.r0, fit.max_deviation_over_range, z_md, z_dpd);
  EXPECT_LT(fit.max_deviation_over_range, 0.02);
  EXPECT_LT(std::abs(z_dpd - z_md) / z_md, 0.005);
}

}  // namespace
