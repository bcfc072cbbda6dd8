#include "mpmx/mpm/manufactured.hpp"

#include <cmath>


namespace mpmx::mpm {

template <int Dim>
Manufactured<Dim>::Manufactured(const reference::AxisAligned& solution, const Particles<Dim>& initial)
    : m_(solution) {
  reference::validate(m_);
  for (int a = 0; a < Dim; ++a) X_[a] = initial.x[a];
}

template <int Dim>
void Manufactured<Dim>::start(Particles<Dim>& p) const {
  for (int a = 0; a < Dim; ++a)
    for (std::size_t q = 0; q < p.size(); ++q) p.v[a][q] = reference::velocity(m_, X_[a][q], 0.0);
}

template <int Dim>
double Manufactured<Dim>::add_body_force(const Particles<Dim>& p, const Stencil<Dim>& st, double t,
                                         Grid<Dim>& g) const {
  const int w = st.width;
  double power = 0.0;
  for (std::size_t q = 0; q < p.size(); ++q) {
    double X[Dim], mb[Dim];
    for (int a = 0; a < Dim; ++a) X[a] = X_[a][q];
    for (int a = 0; a < Dim; ++a) mb[a] = p.mass[q] * reference::body_force(m_, X, a, t);
    for (int a = 0; a < Dim; ++a) power += mb[a] * p.v[a][q];
    for (int k = 0; k < w; ++k) {
      const std::size_t e = q * w + k;
      for (int a = 0; a < Dim; ++a) g.force[a][st.node[e]] += mb[a] * st.S[e];
    }
  }
  return power;
}

template <int Dim>
reference::ErrorNorms Manufactured<Dim>::displacement_error(const Particles<Dim>& p, double t) const {
  double l1 = 0.0, l2 = 0.0, V = 0.0;
  for (std::size_t q = 0; q < p.size(); ++q) {
    double e2 = 0.0;
    for (int a = 0; a < Dim; ++a) {
      const double e = p.x[a][q] - X_[a][q] - reference::displacement(m_, X_[a][q], t);
      e2 += e * e;
    }
    l1 += p.volume0[q] * std::sqrt(e2);
    l2 += p.volume0[q] * e2;
    V += p.volume0[q];
  }
  return {l1 / V / m_.A, std::sqrt(l2 / V) / m_.A};
}

template class Manufactured<1>;
template class Manufactured<2>;
template class Manufactured<3>;

}  // namespace mpmx::mpm
