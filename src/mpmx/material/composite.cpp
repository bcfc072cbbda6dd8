#include "mpmx/material/composite.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace mpmx::material {

template <int Dim>
Points<Dim> block(const Points<Dim>& p, std::size_t begin, std::size_t n) {
  Points<Dim> b = p;
  b.n = n;
  for (auto& a : b.grad_v) a += begin;
  for (auto& a : b.stress) a += begin;
  for (auto& a : b.strain) a += begin;
  for (auto& a : b.length) a += begin;
  for (auto& a : b.viscous)
    if (a) a += begin;
  if (b.stress_zz) b.stress_zz += begin;
  if (b.viscous_pressure) b.viscous_pressure += begin;
  b.mass += begin;
  b.volume += begin;
  b.volume0 += begin;
  return b;
}

template <int Dim>
Composite<Dim>::Composite(std::vector<Part> parts) : parts_(std::move(parts)) {
  std::size_t next = 0;
  for (const auto& part : parts_) {
    if (!part.law || part.begin != next) throw std::logic_error("Composite: parts must cover the points in order");
    next += part.count;
  }
}

template <int Dim>
std::string Composite<Dim>::name() const {
  std::string s;
  for (const auto& part : parts_) {
    if (!s.empty()) s += '+';
    s += part.law->name();
  }
  return s;
}

template <int Dim>
const typename Composite<Dim>::Part& Composite<Dim>::part_of(std::size_t q) const {
  // The last part whose first point is at or before q.
  auto it = std::upper_bound(parts_.begin(), parts_.end(), q,
                             [](std::size_t x, const Part& part) { return x < part.begin; });
  return *(it - 1);
}

template <int Dim>
void Composite<Dim>::initialize(const Points<Dim>& p) {
  for (auto& part : parts_) part.law->initialize(block(p, part.begin, part.count));
}

template <int Dim>
void Composite<Dim>::update_stress(const Points<Dim>& p, double dt) {
  for (auto& part : parts_) part.law->update_stress(block(p, part.begin, part.count), dt);
}

template <int Dim>
double Composite<Dim>::sound_speed(const Points<Dim>& p, std::size_t q) const {
  const Part& part = part_of(q);
  return part.law->sound_speed(block(p, part.begin, part.count), q - part.begin);
}

template <int Dim>
double Composite<Dim>::signal_speed(const Points<Dim>& p, std::size_t q) const {
  const Part& part = part_of(q);
  return part.law->signal_speed(block(p, part.begin, part.count), q - part.begin);
}

template <int Dim>
double Composite<Dim>::stored_energy(const Points<Dim>& p, std::size_t q) const {
  const Part& part = part_of(q);
  return part.law->stored_energy(block(p, part.begin, part.count), q - part.begin);
}

template <int Dim>
void Composite<Dim>::add_viscous_heat(const Points<Dim>& p, const std::array<double*, Dim * Dim>& q, double dt) {
  for (auto& part : parts_) {
    auto qb = q;
    for (auto& a : qb) a += part.begin;
    part.law->add_viscous_heat(block(p, part.begin, part.count), qb, dt);
  }
}

template <int Dim>
std::vector<PointField> Composite<Dim>::point_fields(const Points<Dim>& p) const {
  // Every part's fields, in the order they first appear; NaN at the points of a law
  // that has no such field.
  std::vector<PointField> all;
  for (const auto& part : parts_)
    for (auto& f : part.law->point_fields(block(p, part.begin, part.count))) {
      auto it = std::find_if(all.begin(), all.end(), [&](const PointField& a) { return a.name == f.name; });
      if (it == all.end()) it = all.insert(all.end(), {f.name, std::vector<double>(p.size(), std::nan(""))});
      std::copy(f.values.begin(), f.values.end(), it->values.begin() + static_cast<std::ptrdiff_t>(part.begin));
    }
  return all;
}

template <int Dim>
std::string Composite<Dim>::point_model_dump(std::size_t q, std::int64_t step,
                                             const std::vector<std::string>& fields) const {
  const Part& part = part_of(q);
  return part.law->point_model_dump(q - part.begin, step, fields);
}

template <int Dim>
bool Composite<Dim>::runs_point_model(std::size_t q) const {
  const Part& part = part_of(q);
  return part.law->runs_point_model(q - part.begin);
}

template <int Dim>
void Composite<Dim>::set_threads(int threads) {
  Material<Dim>::set_threads(threads);
  for (auto& part : parts_) part.law->set_threads(threads);
}

template <int Dim>
void Composite<Dim>::save(std::ostream& out) const {
  for (const auto& part : parts_) part.law->save(out);
}

template <int Dim>
void Composite<Dim>::load(std::istream& in) {
  for (auto& part : parts_) part.law->load(in);
}

template Points<2> block<2>(const Points<2>&, std::size_t, std::size_t);
template Points<3> block<3>(const Points<3>&, std::size_t, std::size_t);
template class Composite<2>;
template class Composite<3>;

}  // namespace mpmx::material
