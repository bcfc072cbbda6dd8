#include "mpmx/mpm/nodal_fields.hpp"

#include "mpmx/core/error.hpp"

namespace mpmx::mpm {

double NodalFields::field(const std::string& f, std::size_t i) const {
  if (f == "velocity") return velocity[i];
  if (f == "strain") return strain[i];
  if (f == "stress") return stress[i];
  if (f == "pressure") return -stress[i];
  if (f == "density") return density[i];
  throw InputError("unknown field '" + f + "'");
}

NodalFields nodal_fields(const State<1>& s) {
  const auto& g = s.grid;
  const auto& p = s.particles;
  Stencil<1> st;
  (*s.shape)(g, p, st);
  std::vector<double> m(g.storage, 0.0), mv(g.storage, 0.0), me(g.storage, 0.0), ms(g.storage, 0.0);
  for (std::size_t q = 0; q < p.size(); ++q)
    for (int k = 0; k < st.width; ++k) {
      const std::size_t e = q * st.width + k;
      const double w = p.mass[q] * st.S[e];
      const int i = st.node[e];
      m[i] += w;
      mv[i] += w * p.v[0][q];
      me[i] += w * p.strain[0][q];
      ms[i] += w * p.stress[0][q];
    }
  NodalFields n;
  const int N = g.cells[0];
  for (int j = 0; j <= N; ++j) {
    const std::size_t i = g.index1(j);
    const double V = g.dx[0] * ((j > 0 ? 0.5 : 0.0) + (j < N ? 0.5 : 0.0));
    const double inv = m[i] > 0.0 ? 1.0 / m[i] : 0.0;
    n.x.push_back(g.node_x(j));
    n.mass.push_back(m[i]);
    n.volume.push_back(V);
    n.velocity.push_back(mv[i] * inv);
    n.strain.push_back(me[i] * inv);
    n.stress.push_back(ms[i] * inv);
    n.density.push_back(m[i] / V);
  }
  // Held ends carry their boundary velocity (ADMPM eq. 5.24; a piston's while it pushes).
  for (int f = 0; f < 2; ++f) {
    double& v = f == 0 ? n.velocity.front() : n.velocity.back();
    if (s.boundary.face[f].holds(0, f, v, s.time)) v = s.boundary.face[f].velocity(s.time, 0, f);
  }
  return n;
}

}  // namespace mpmx::mpm
