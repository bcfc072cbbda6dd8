#include "mpmx/particles/atoms.hpp"

namespace mpmx::particles {

void Atoms::resize(std::size_t n) {
  for (auto* v : {&x, &y, &z, &vx, &vy, &vz, &fx, &fy, &fz}) v->resize(n, 0.0);
  type.resize(n, 0);
  id.resize(n, 0);
}

void Atoms::push_back(double px, double py, double pz, int t, std::int64_t ident) {
  x.push_back(px);
  y.push_back(py);
  z.push_back(pz);
  for (auto* v : {&vx, &vy, &vz, &fx, &fy, &fz}) v->push_back(0.0);
  type.push_back(t);
  id.push_back(ident);
}

namespace {
template <class T>
void apply(std::vector<T>& v, const std::vector<std::size_t>& order, std::vector<T>& tmp) {
  tmp.resize(v.size());
  for (std::size_t k = 0; k < order.size(); ++k) tmp[k] = v[order[k]];
  v.swap(tmp);
}
}  // namespace

void Atoms::permute(const std::vector<std::size_t>& order) {
  std::vector<double> td;
  for (auto* v : {&x, &y, &z, &vx, &vy, &vz, &fx, &fy, &fz}) apply(*v, order, td);
  std::vector<int> ti;
  apply(type, order, ti);
  std::vector<std::int64_t> tl;
  apply(id, order, tl);
}

}  // namespace mpmx::particles
