#include "mpmx/md/elastic_constants.hpp"

#include <cmath>
#include <vector>

#include <Eigen/Dense>

#include "mpmx/core/error.hpp"
#include "mpmx/md/system.hpp"

namespace mpmx::md {

namespace {

// Voigt component k as (row, column) of the 3x3 stress or strain.
constexpr int kVoigt[6][2] = {{0, 0}, {1, 1}, {2, 2}, {1, 2}, {0, 2}, {0, 1}};

particles::Crystal strained(particles::Crystal c, int j, double e) {
  strain_voigt(c.atoms, c.box, j, e);
  return c;
}

// FIRE (Bitzek et al. 2006) on the positions at a fixed box, unit masses: the atoms of a
// crystal with a basis find their places in the strained cell. Returns the largest force
// left (eV/A).
double relax(System& s, double tolerance) {
  const std::size_t n = s.atoms().size();
  std::vector<double> v(3 * n, 0.0);
  double dt = 0.1, alpha = 0.1;
  int since_uphill = 0;
  double fmax = 0;
  for (int it = 0; it < 100000; ++it) {
    s.refresh();
    const Atoms& a = s.atoms();
    double p = 0, vv = 0, ff = 0;
    fmax = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const double f[3] = {a.fx[i], a.fy[i], a.fz[i]};
      for (int d = 0; d < 3; ++d) {
        p += f[d] * v[3 * i + d], vv += v[3 * i + d] * v[3 * i + d], ff += f[d] * f[d];
        fmax = std::max(fmax, std::abs(f[d]));
      }
    }
    if (fmax < tolerance) break;
    if (p > 0) {
      const double mix = ff > 0 ? alpha * std::sqrt(vv / ff) : 0.0;
      for (std::size_t i = 0; i < n; ++i) {
        const double f[3] = {a.fx[i], a.fy[i], a.fz[i]};
        for (int d = 0; d < 3; ++d) v[3 * i + d] = (1 - alpha) * v[3 * i + d] + mix * f[d];
      }
      if (++since_uphill > 5) dt = std::min(1.1 * dt, 0.5), alpha *= 0.99;
    } else {
      std::fill(v.begin(), v.end(), 0.0);
      dt *= 0.5, alpha = 0.1, since_uphill = 0;
    }
    std::vector<double> f(3 * n);
    for (std::size_t i = 0; i < n; ++i) f[3 * i] = a.fx[i], f[3 * i + 1] = a.fy[i], f[3 * i + 2] = a.fz[i];
    Atoms& w = s.edit_atoms();
    for (std::size_t i = 0; i < n; ++i) {
      for (int d = 0; d < 3; ++d) v[3 * i + d] += dt * f[3 * i + d];
      w.x[i] += dt * v[3 * i], w.y[i] += dt * v[3 * i + 1], w.z[i] += dt * v[3 * i + 2];
    }
  }
  return fmax;
}

}  // namespace

void strain_voigt(Atoms& atoms, Box& box, int j, double e) {
  const auto [a, b] = kVoigt[j];
  std::vector<double>* axis[3] = {&atoms.x, &atoms.y, &atoms.z};
  for (std::size_t i = 0; i < atoms.size(); ++i) (*axis[a])[i] += e * (*axis[b])[i];
  if (a == b) {
    double* length[3] = {&box.lx, &box.ly, &box.lz};
    *length[a] *= 1.0 + e;
  } else if (j == 3) {
    box.yz += e * box.lz;
  } else if (j == 4) {
    box.xz += e * box.lz;
  } else {
    box.xy += e * box.ly;
  }
}

std::array<double, 6> voigt_stress(const Mat3& s) {
  std::array<double, 6> r{};
  for (int k = 0; k < 6; ++k) r[k] = s[3 * kVoigt[k][0] + kVoigt[k][1]];
  return r;
}

ElasticTensor elastic_tensor(const Potential& pot, const particles::LatticeSpec& spec, const std::array<int, 3>& tiles,
                             const ElasticOptions& o) {
  if (!(o.strain > 0 && o.strain < 0.05)) throw InputError("elastic constants: the strain must lie in (0, 0.05)");
  const particles::Crystal base = particles::oriented_crystal(spec, tiles);
  // A Bravais lattice (every atom a centre of inversion) has nothing to relax.
  const bool relax_atoms = o.relax && spec.style == particles::LatticeStyle::hcp;
  SystemOptions so;
  so.sort_atoms = false;  // FIRE's velocities follow the atoms by index
  ElasticTensor t;
  t.strain = o.strain;
  t.relaxed = relax_atoms;
  auto stress_of = [&](const particles::Crystal& c) {
    System s(c, pot, so);
    if (relax_atoms) t.largest_force = std::max(t.largest_force, relax(s, o.force_tolerance));
    s.refresh();
    return voigt_stress(s.stress_gpa());
  };
  t.stress = stress_of(base);
  for (int j = 0; j < 6; ++j) {
    const auto plus = stress_of(strained(base, j, o.strain)), minus = stress_of(strained(base, j, -o.strain));
    for (int i = 0; i < 6; ++i) t.box[i][j] = (plus[i] - minus[i]) / (2 * o.strain);
  }
  t.crystal = rotate_to_crystal(t.box, orientation_matrix(spec));
  return t;
}

bool born_stable(const Voigt& c) {
  Eigen::Matrix<double, 6, 6> m;
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) m(i, j) = 0.5 * (c[i][j] + c[j][i]);
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 6, 6>> es(m, Eigen::EigenvaluesOnly);
  return es.eigenvalues().minCoeff() > 0;
}

std::array<std::array<double, 3>, 3> orientation_matrix(const particles::LatticeSpec& spec) {
  std::array<std::array<double, 3>, 3> r{};
  for (int d = 0; d < 3; ++d) {
    const auto& v = spec.orient[d];
    const double norm = std::sqrt(double(v[0]) * v[0] + double(v[1]) * v[1] + double(v[2]) * v[2]);
    for (int k = 0; k < 3; ++k) r[d][k] = v[k] / norm;
  }
  return r;
}

Voigt rotate_to_crystal(const Voigt& box, const std::array<std::array<double, 3>, 3>& r) {
  auto voigt_index = [](int i, int j) {
    if (i == j) return i;
    if (i > j) std::swap(i, j);
    return i == 1 ? 3 : j == 2 ? 4 : 5;  // (1,2) yz, (0,2) xz, (0,1) xy
  };
  Voigt out{};
  for (int p = 0; p < 6; ++p)
    for (int q = 0; q < 6; ++q) {
      const auto [a, b] = kVoigt[p];
      const auto [c, d] = kVoigt[q];
      double sum = 0;
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
          for (int k = 0; k < 3; ++k)
            for (int l = 0; l < 3; ++l)
              sum += r[i][a] * r[j][b] * r[k][c] * r[l][d] * box[voigt_index(i, j)][voigt_index(k, l)];
      out[p][q] = sum;
    }
  return out;
}

}  // namespace mpmx::md
