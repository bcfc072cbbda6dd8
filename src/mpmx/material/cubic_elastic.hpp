#pragma once
// cubic_elastic: a cubic crystal (C11, C12, C44, its cube axes along the grid axes at the
// start), hypoelastic with the Jaumann rate (jaumann.hpp):
//
//   sigma_dot = Q [C : (Q^T D Q)] Q^T + W sigma - sigma W,
//
// Q the crystal axes of the point, turned with the material by the same half-step
// Hughes-Winget rotations Rh as the stress (Q^{n+1} = Rh Rh Q^n), so that the anisotropy
// follows the lattice through a rotation; Q = I until the point spins, and for
// C12 = lambda, C44 = mu, C11 = lambda + 2 mu the law is isotropic and Q plays no part.
// The strain array is integrated with the same objective step, eps^{n+1} =
// Rh (Rh eps^n Rh^T + dt D) Rh^T, and for a linear C the step of sigma,
// Rh (Rh sigma^n Rh^T + dt Qm [C : (Qm^T D Qm)] Qm^T) Rh^T with Qm = Rh Q^n, is then
// algebraically the same as sigma = Q [C : (Q^T eps Q)] Q^T (by induction), which is
// how it is evaluated: stress and strain never drift apart by round-off.
// In the crystal frame (tensor shear components, not engineering):
//   sigma_xx = C11 eps_xx + C12 (eps_yy + eps_zz),  sigma_xy = 2 C44 eps_xy  (= C44 gamma_xy)
// 2-D is plane strain (D_zz = 0, eps_zz = 0, the spin about z only): sigma_zz = C12
// (eps_xx + eps_yy) is not stored (out_of_plane_stress gives it). 1-D is uniaxial strain:
// eps_xx += dt L_xx, sigma_xx = C11 eps_xx (the lateral stresses, C12 eps_xx, not stored).
#include <memory>
#include <vector>

#include "mpmx/material/jaumann.hpp"
#include "mpmx/material/material.hpp"
#include "mpmx/material/model.hpp"

namespace mpmx::material {

struct CubicConstants {
  double c11 = 0.0, c12 = 0.0, c44 = 0.0;

  // The crystal-frame stress of a crystal-frame strain (plane strain in 2-D: eps_zz = 0).
  template <int Dim>
  jaumann::Mat<Dim> stress(const jaumann::Mat<Dim>& eps) const {
    jaumann::Mat<Dim> s;
    for (int a = 0; a < Dim; ++a)
      for (int b = 0; b < Dim; ++b) {
        if (a != b) {
          s(a, b) = 2.0 * c44 * eps(a, b);
          continue;
        }
        double lateral = 0.0;  // written so that eps_yy = 0 gives C11 eps_xx exactly
        for (int c = 0; c < Dim; ++c)
          if (c != a) lateral += eps(c, c);
        s(a, a) = c11 * eps(a, a) + c12 * lateral;
      }
    return s;
  }
  // rho v^2 of the fastest plane wave a Dim-dimensional run can carry: the largest
  // eigenvalue of the Christoffel matrix over the directions <100>, <110> (and <111>
  // in 3-D), where a cubic crystal's wave speeds take their extremes: C11, C44,
  // (C11 + C12 + 2 C44) / 2, (C11 - C12) / 2, (C11 + 2 C12 + 4 C44) / 3,
  // (C11 - C12 + C44) / 3. 1-D (uniaxial strain along x): C11. The crystal may turn in
  // the plane (2-D) or anyhow (3-D), so every such direction counts. For copper
  // (C11, C12, C44 = 170, 123, 76 GPa) it is 222.5 GPa in 2-D and 240 GPa in 3-D:
  // sqrt(C11 / rho) would be 14% and 19% low, too low for the CFL limit.
  double wave_modulus(int dim) const;
};

template <int Dim>
class CubicElastic final : public Material<Dim> {
 public:
  using Mat = jaumann::Mat<Dim>;

  explicit CubicElastic(const CubicConstants& c) : c_(c) {}

  std::string name() const override { return "cubic_elastic"; }
  // sigma = C : eps from the initial strain array, crystal axes along the grid.
  void initialize(const Points<Dim>& p) override;
  void update_stress(const Points<Dim>& p, double dt) override;
  // sqrt(wave_modulus(Dim) / rho) at the current density (see CubicConstants).
  double sound_speed(const Points<Dim>& p, std::size_t q) const override;
  // 0.5 V sigma : eps, the small-strain energy: a hypoelastic law derives from no
  // potential, so this is exact only to first order in the strain (the work V sigma : D
  // dt differs from its change by 0.5 dV sigma : eps each step).
  bool keeps_energy_account() const override { return true; }
  double stored_energy(const Points<Dim>& p, std::size_t q) const override;
  // The crystal axes of every point (Dim x Dim, row-major), in point order.
  void save(std::ostream& out) const override;
  void load(std::istream& in) override;
  long long state_points() const override {
    return axes_.empty() ? -1 : static_cast<long long>(axes_.size() / (Dim * Dim));
  }

  const CubicConstants& constants() const { return c_; }
  // The crystal axes of point q as columns in the grid frame (identity in 1-D).
  Mat axes(std::size_t q) const;
  // sigma_zz in 2-D (plane strain), sigma_yy = sigma_zz in 1-D (uniaxial strain); 0 in 3-D.
  double out_of_plane_stress(const Points<Dim>& p, std::size_t q) const;

 private:
  void set_stress(const Points<Dim>& p, std::size_t q) const;

  CubicConstants c_;
  std::vector<double> axes_;  // Dim * Dim per point (Dim >= 2)
};

extern template class CubicElastic<1>;
extern template class CubicElastic<2>;
extern template class CubicElastic<3>;

// The [material] table of model = "cubic_elastic": density, c11, c12, c44.
struct CubicElasticModel final : Model {
  double rho = 1.0;
  CubicConstants c;
  std::string source = "the deck";        // constants_from = "potential": which crystal
  std::vector<std::string> warnings;      // what the potential's file contradicts
  std::string units;                      // case.units, for the notes

  std::string name() const override { return "cubic_elastic"; }
  double density() const override { return rho; }
  bool solid() const override { return true; }
  // `density` is the unstrained crystal's, as for md_closure: a point at initial strain
  // e starts at density / (1 + e).
  bool density_of_unstrained() const override { return true; }
  double wave_speed(int dim, double density, double pressure) const override;
  std::vector<std::string> check_notes() const override;
  std::vector<std::pair<std::string, double>> constants() const override;
  std::string constants_source() const override { return source; }
  std::unique_ptr<Material<1>> make1() const override;
  std::unique_ptr<Material<2>> make2() const override;
  std::unique_ptr<Material<3>> make3() const override;
};

// The elastic constants of a table: c11, c12, c44 given as numbers, checked for Born
// stability.
CubicConstants read_cubic_constants(Table& m, const Context& ctx);

// The registry entry (app/mpm/materials.hpp). constants_from = "potential" takes the
// constants and the density of an MD potential's 0 K crystal (Context::crystal_of).
struct CubicElasticEntry {
  static constexpr std::string_view name = "cubic_elastic";
  static std::shared_ptr<const Model> read(Table& m, const Context& ctx);
};

}  // namespace mpmx::material
