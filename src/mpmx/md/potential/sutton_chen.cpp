#include "mpmx/md/potential/sutton_chen.hpp"

#include <cmath>

#include <fmt/format.h>

#include "mpmx/core/error.hpp"
#include "mpmx/md/potential/analytic.hpp"
#include "mpmx/md/potential/eam_kernel.hpp"

namespace mpmx::md {

namespace {

// x^k for the potential's integer exponents (1..100) by squaring: a few multiplications
// where std::pow costs a library call, three per pair (eq. of Sutton and Chen 1990).
inline double int_pow(double x, int k) {
  double r = 1.0;
  for (; k > 0; k >>= 1, x *= x)
    if (k & 1) r *= x;
  return r;
}

}  // namespace

SuttonChen::SuttonChen(double epsilon, double a, double c, int n, int m, double cutoff, double mass)
    : eps_(epsilon), a_(a), c_(c), n_(n), m_(m), cut_(cutoff), mass_(mass) {
  if (!(epsilon > 0 && a > 0 && c > 0 && n > 0 && m > 0 && cutoff > 0 && mass > 0))
    throw InputError(fmt::format("sutton-chen: epsilon {}, a {}, c {}, n {}, m {}, cutoff {}, "
                                 "mass {}: all must be positive",
                                 epsilon, a, c, n, m, cutoff, mass));
}

void SuttonChen::density(double r, int, int, double& at_i, double& at_j) const {
  at_i = at_j = int_pow(a_ / r, m_);
}

void SuttonChen::embed(double rho, int, double& F, double& Fp) const {
  const double s = std::sqrt(rho);
  F = -eps_ * c_ * s;
  Fp = s > 0 ? -0.5 * eps_ * c_ / s : 0.0;
}

void SuttonChen::pair(double r, int, int, double fpi, double fpj, double& phi, double& dedr) const {
  const double q = a_ / r, an = int_pow(q, n_), am = int_pow(q, m_);
  phi = eps_ * an;
  const double dphi = -n_ * phi / r, drho = -m_ * am / r;
  dedr = (fpi + fpj) * drho + dphi;
}

ForceSums SuttonChen::compute(const Neighbors& nb, ForceWork& w) const {
  return eam_compute<double>(*this, nb, w);
}

SuttonChenSpec SuttonChenSpec::read(Table& t, const std::string& /*deck_dir*/) {
  SuttonChenSpec s;
  read_analytic_scale(t, s.epsilon, s.cutoff, s.mass);
  s.a = t.number("a");
  t.positive("a", s.a);
  s.c = t.number("c");
  t.positive("c", s.c);
  s.n = t.integer_int("n", 1, 100);
  s.m = t.integer_int("m", 1, 100);
  return s;
}

std::string SuttonChenSpec::lammps_pair_lines(const SuttonChen& /*made*/) const {
  throw InputError(fmt::format("potential style '{}': the LAMMPS route supports eam (setfl, fs, funcfl) and lj only",
                               name));
}

}  // namespace mpmx::md
