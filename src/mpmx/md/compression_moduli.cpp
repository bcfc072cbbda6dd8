#include "mpmx/md/compression_moduli.hpp"

#include <algorithm>
#include <cmath>

#include "mpmx/core/error.hpp"
#include "mpmx/md/elastic_constants.hpp"
#include "mpmx/md/equilibrium.hpp"
#include "mpmx/md/system.hpp"

namespace mpmx::md {

namespace {

constexpr double kDelta = 1e-4;  // ln L step: O(delta^2) of a modulus, far above round-off

std::array<double, 6> stress_of(const particles::Crystal& c, const Potential& pot) {
  SystemOptions o;
  o.threads = 1;  // the same numbers on every thread count
  System s(c, pot, o);
  s.refresh();
  return voigt_stress(s.stress_gpa());
}

// The crystal with each axis a's length times f[a].
particles::Crystal scaled(particles::Crystal c, const std::array<double, 3>& f) {
  for (int a = 0; a < 3; ++a)
    if (f[a] != 1.0) strain_voigt(c.atoms, c.box, a, f[a] - 1.0);
  return c;
}

// d sigma_aa / d ln L_a of state c, by central differences.
double longitudinal(const particles::Crystal& c, const Potential& pot, int a) {
  std::array<double, 3> up{1, 1, 1}, down{1, 1, 1};
  up[a] = std::exp(kDelta), down[a] = std::exp(-kDelta);
  return (stress_of(scaled(c, up), pot)[a] - stress_of(scaled(c, down), pot)[a]) / (2 * kDelta);
}

}  // namespace

double CompressionModuli::modulus_at(double j) const {
  if (J.empty()) return 0.0;
  if (!(j > J.front())) return modulus.front();
  if (!(j < J.back())) return modulus.back();
  const auto it = std::upper_bound(J.begin(), J.end(), j);
  const std::size_t k = static_cast<std::size_t>(it - J.begin());
  const double w = (j - J[k - 1]) / (J[k] - J[k - 1]);
  return (1 - w) * modulus[k - 1] + w * modulus[k];
}

double CompressionModuli::shock_compression(int axis, double up, double rho0, double gpa_per_unit) const {
  // Rayleigh line minus curve, from J = 1 downwards: the first sign change.
  const auto& p = uniaxial[axis];
  auto gap = [&](std::size_t k) { return rho0 * up * up / (1.0 - J[k]) * gpa_per_unit - p[k]; };
  std::size_t k = J.size();
  while (k > 0 && !(J[k - 1] < 1.0)) --k;  // the rows below J = 1
  for (; k >= 2; --k) {
    const double hi = gap(k - 1), lo = gap(k - 2);
    if (hi > 0 && lo <= 0) return J[k - 2] + (J[k - 1] - J[k - 2]) * lo / (lo - hi);
  }
  return std::nan("");
}

CompressionModuli compression_moduli(const Potential& pot, const particles::LatticeSpec& spec, double j_min,
                                     double j_max, int rows) {
  if (!(j_min > 0 && j_max > j_min && rows >= 2)) throw InputError("compression moduli: J from j_min > 0 to j_max");
  const particles::Crystal base = particles::oriented_crystal(spec, equilibrium_tiles(spec));
  CompressionModuli t;
  for (int r = 0; r < rows; ++r) {
    const double j = j_min + (j_max - j_min) * r / (rows - 1);
    t.J.push_back(j);
    double m = 0.0;
    for (int a = 0; a < 3; ++a) {
      std::array<double, 3> f{1, 1, 1};
      f[a] = j;
      const particles::Crystal c = scaled(base, f);
      t.uniaxial[a].push_back(-stress_of(c, pot)[a]);
      t.uniaxial_modulus[a].push_back(longitudinal(c, pot, a));
      m = std::max(m, t.uniaxial_modulus[a].back());
    }
    const double l = std::cbrt(j);
    const particles::Crystal h = scaled(base, {l, l, l});
    const double e = std::exp(kDelta / 3);
    const auto s_up = stress_of(scaled(h, {e, e, e}), pot), s_down = stress_of(scaled(h, {1 / e, 1 / e, 1 / e}), pot);
    m = std::max(m, (s_up[0] + s_up[1] + s_up[2] - s_down[0] - s_down[1] - s_down[2]) / 3.0 / (2 * kDelta));
    for (int a = 0; a < 3; ++a) m = std::max(m, longitudinal(h, pot, a));
    t.modulus.push_back(m);
  }
  // Under compression the stiffest the crystal has been between J and 1: the perfect
  // lattice's uniaxial path softens locally (at J 0.91 and 0.72 for copper, its Bain
  // path's bifurcations), and a point compressed to J passed the stiffer states on the way.
  for (std::size_t k = t.J.size() - 1; k-- > 0;)
    if (t.J[k] < 1.0) t.modulus[k] = std::max(t.modulus[k], t.modulus[k + 1]);
  return t;
}

}  // namespace mpmx::md
