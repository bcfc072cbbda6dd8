#include "mpmx/dpd/particles.hpp"

namespace mpmx::dpd {

void Particles::resize(std::size_t n) {
  particles::Atoms::resize(n);
  mass.resize(n, 0.0);
  u.resize(n, 0.0);
  group.resize(n, kMobile);
}

void Particles::push_back(double px, double py, double pz, double m, int t, std::int64_t ident) {
  particles::Atoms::push_back(px, py, pz, t, ident);
  mass.push_back(m);
  u.push_back(0.0);
  group.push_back(kMobile);
}

namespace {
template <class T>
void apply(std::vector<T>& v, const std::vector<std::size_t>& order) {
  std::vector<T> tmp(v.size());
  for (std::size_t k = 0; k < order.size(); ++k) tmp[k] = v[order[k]];
  v.swap(tmp);
}
}  // namespace

void Particles::permute(const std::vector<std::size_t>& order) {
  particles::Atoms::permute(order);
  apply(mass, order);
  apply(u, order);
  apply(group, order);
}

}  // namespace mpmx::dpd
