#pragma once
// Helpers shared by the DPD tests: the Cu mesoparticle model used before the D0 fit
// (Girifalco-Weizer's Cu Morse scaled to mesoparticles of 8 atoms on the coarse fcc
// lattice of constant 2a: lengths x2, energies x8), a soft DPD fluid in metal units, and
// a brute-force reference for the conservative forces.
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "mpmx/core/units.hpp"
#include "mpmx/dpd/setup.hpp"
#include "mpmx/dpd/system.hpp"
#include "mpmx/particles/rng.hpp"

namespace mpmx::test {

inline constexpr double kCuMesoMass = 8 * 63.546;  // amu
inline constexpr double kCoarseLattice = 7.23;     // Angstrom (2a, seed 004 sec. 4.1.1)
inline constexpr double kSeedGamma = 0.2;          // amu/ps (seed 004 sec. 2.2)
// The mesoparticle's internal heat capacity: 8 atoms x 3 kB less the centre of mass's 3 kB.
inline constexpr double kCuMesoCv = 21 * units::boltzmann_eV_per_K;

inline dpd::MorsePotential cu_meso_morse(double rc = 12.0) {
  dpd::MorsePotential m;
  m.d0 = 8 * 0.3429;      // eV
  m.alpha = 1.3588 / 2;   // 1/Angstrom
  m.r0 = 2 * 2.866;       // Angstrom
  m.rc = rc;
  m.shift = true;
  m.update_offset();
  return m;
}

// A DPD fluid in metal units: particles of 100 amu, rc = 10 Angstrom, a = 25 kT/rc at
// T = 300 K (Groot and Warren's water-like a = 25), density 3/rc^3.
struct SoftFluid {
  double mass = 100.0, rc = 10.0, temperature = 300.0;
  double kt() const { return 8.617343e-5 * temperature; }
  double tau() const { return rc * std::sqrt(mass * 1.0364269e-4 / kt()); }  // ps
  dpd::SoftPotential potential() const { return {.a = 25.0 * kt() / rc, .rc = rc}; }
  double gamma() const { return 4.5 * mass / tau(); }  // amu/ps (Groot-Warren gamma = 4.5)
};

inline dpd::Domain cube(double l, std::array<bool, 3> periodic = {true, true, true}) {
  dpd::Domain d;
  d.box.lx = d.box.ly = d.box.lz = l;
  d.periodic = periodic;
  return d;
}

// Brute-force conservative forces, energy and virial over all images within the cutoff.
struct Reference {
  std::vector<double> fx, fy, fz;
  double energy = 0;
  std::array<double, 6> virial{};
};

template <class Pot>
Reference brute_force(const dpd::Particles& p, const dpd::Domain& d, const Pot& pot) {
  const std::size_t n = p.size();
  Reference r;
  r.fx.assign(n, 0.0), r.fy.assign(n, 0.0), r.fz.assign(n, 0.0);
  const double rc = pot.cutoff();
  int range[3];
  for (int k = 0; k < 3; ++k) range[k] = d.periodic[k] ? static_cast<int>(std::ceil(rc / d.length(k))) + 1 : 0;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j)
      for (int a = -range[0]; a <= range[0]; ++a)
        for (int b = -range[1]; b <= range[1]; ++b)
          for (int c = -range[2]; c <= range[2]; ++c) {
            if (i == j && a == 0 && b == 0 && c == 0) continue;
            const double dx = p.x[i] - p.x[j] - a * d.box.lx, dy = p.y[i] - p.y[j] - b * d.box.ly,
                         dz = p.z[i] - p.z[j] - c * d.box.lz;
            const double r2 = dx * dx + dy * dy + dz * dz;
            if (r2 >= rc * rc) continue;
            double e, fr;
            pot.eval(r2, e, fr);
            r.fx[i] += fr * dx, r.fy[i] += fr * dy, r.fz[i] += fr * dz;
            r.energy += 0.5 * e;
            const double w[6] = {dx * dx, dy * dy, dz * dz, dx * dy, dx * dz, dy * dz};
            for (int k = 0; k < 6; ++k) r.virial[k] += 0.5 * w[k] * fr;
          }
  return r;
}

}  // namespace mpmx::test
