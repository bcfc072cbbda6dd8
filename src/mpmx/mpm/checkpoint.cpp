#include "mpmx/mpm/checkpoint.hpp"

#include <istream>
#include <ostream>

#include <fmt/format.h>

#include "mpmx/core/error.hpp"

namespace mpmx::mpm {

namespace {
constexpr char kMagic[8] = {'M', 'P', 'M', 'X', 'S', 'T', '0', '3'};

template <int Dim, class F>
void each_array(Particles<Dim>& p, F&& f) {
  for (int a = 0; a < Dim; ++a) f(p.x[a]), f(p.v[a]);
  for (auto* v : {&p.mass, &p.volume, &p.volume0, &p.viscous_pressure}) f(*v);
  for (int c = 0; c < Dim * Dim; ++c) f(p.length[c]), f(p.strain[c]), f(p.stress[c]), f(p.grad_v[c]);
  if (!p.viscous[0].empty())
    for (int c = 0; c < Dim * Dim; ++c) f(p.viscous[c]);
}
}  // namespace

void CheckpointOut::number(double v) { out_.write(reinterpret_cast<const char*>(&v), sizeof v); }
void CheckpointOut::integer(std::int64_t v) { out_.write(reinterpret_cast<const char*>(&v), sizeof v); }
void CheckpointOut::text(const std::string& s) {
  integer(static_cast<std::int64_t>(s.size()));
  out_.write(s.data(), static_cast<std::streamsize>(s.size()));
}
void CheckpointOut::numbers(const std::vector<double>& v) {
  integer(static_cast<std::int64_t>(v.size()));
  out_.write(reinterpret_cast<const char*>(v.data()), static_cast<std::streamsize>(v.size() * sizeof(double)));
}

void CheckpointIn::check() {
  if (!in_) throw InputError(fmt::format("checkpoint {} is truncated or unreadable", name_));
}
double CheckpointIn::number() {
  double v = 0;
  in_.read(reinterpret_cast<char*>(&v), sizeof v);
  check();
  return v;
}
std::int64_t CheckpointIn::integer() {
  std::int64_t v = 0;
  in_.read(reinterpret_cast<char*>(&v), sizeof v);
  check();
  return v;
}
std::string CheckpointIn::text() {
  const std::int64_t n = integer();
  if (n < 0 || n > (1 << 30)) throw InputError(fmt::format("checkpoint {} is corrupt", name_));
  std::string s(static_cast<std::size_t>(n), '\0');
  in_.read(s.data(), n);
  check();
  return s;
}
std::vector<double> CheckpointIn::numbers() {
  const std::int64_t n = integer();
  if (n < 0 || n > (std::int64_t{1} << 34)) throw InputError(fmt::format("checkpoint {} is corrupt", name_));
  std::vector<double> v(static_cast<std::size_t>(n));
  in_.read(reinterpret_cast<char*>(v.data()), static_cast<std::streamsize>(n * sizeof(double)));
  check();
  return v;
}

template <int Dim>
void save_state(CheckpointOut& out, const State<Dim>& s) {
  out.stream().write(kMagic, 8);
  out.integer(s.step);
  out.number(s.time);
  const Tallies& t = s.tallies;
  for (double v : {t.boundary_impulse[0], t.boundary_impulse[1], t.boundary_impulse[2], t.boundary_work,
                   t.stress_work, t.max_force_sum, t.node_mass})
    out.number(v);
  auto& p = const_cast<Particles<Dim>&>(s.particles);
  each_array(p, [&](std::vector<double>& v) { out.numbers(v); });
  out.text(s.material->name());
  s.material->save(out.stream());
}

template <int Dim>
void load_state(CheckpointIn& in, State<Dim>& s) {
  char magic[8] = {};
  in.stream().read(magic, 8);
  if (!in.stream() || std::string(magic, 8) != std::string(kMagic, 8))
    throw InputError("not an mpmx run checkpoint (or one from another version)");
  s.step = in.integer();
  s.time = in.number();
  Tallies& t = s.tallies;
  for (double* v : {&t.boundary_impulse[0], &t.boundary_impulse[1], &t.boundary_impulse[2], &t.boundary_work,
                    &t.stress_work, &t.max_force_sum, &t.node_mass})
    *v = in.number();
  const std::size_t n = s.particles.size();
  each_array(s.particles, [&](std::vector<double>& v) {
    v = in.numbers();
    if (v.size() != n)
      throw InputError(fmt::format("the checkpoint holds {} particles, the deck makes {}", v.size(), n));
  });
  const std::string material = in.text();
  if (material != s.material->name())
    throw InputError(fmt::format("the checkpoint's material is {}, the deck's {}", material, s.material->name()));
  s.material->load(in.stream());
}

template void save_state<1>(CheckpointOut&, const State<1>&);
template void save_state<2>(CheckpointOut&, const State<2>&);
template void save_state<3>(CheckpointOut&, const State<3>&);
template void load_state<1>(CheckpointIn&, State<1>&);
template void load_state<2>(CheckpointIn&, State<2>&);
template void load_state<3>(CheckpointIn&, State<3>&);

}  // namespace mpmx::mpm
