#include "mpmx/mpm/checkpoint.hpp"

#include <istream>
#include <ostream>

#include <fmt/format.h>

#include "mpmx/core/error.hpp"

namespace mpmx::mpm {

namespace {
constexpr char kMagic[8] = {'M', 'P', 'M', 'X', 'S', 'T', '0', '2'};

template <class F>
void each_array(Particles<1>& p, F&& f) {
  for (auto* v : {&p.x[0], &p.v[0], &p.mass, &p.volume, &p.volume0, &p.length[0], &p.strain[0], &p.stress[0],
                  &p.grad_v[0], &p.viscous_pressure, &p.entropy})
    f(*v);
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

void save_state(CheckpointOut& out, const State<1>& s) {
  out.stream().write(kMagic, 8);
  out.integer(s.step);
  out.number(s.time);
  const Tallies& t = s.tallies;
  for (double v : {t.boundary_impulse, t.boundary_work, t.stress_work, t.max_force_sum, t.node_mass}) out.number(v);
  auto& p = const_cast<Particles<1>&>(s.particles);
  each_array(p, [&](std::vector<double>& v) { out.numbers(v); });
  out.text(s.material->name());
  s.material->save(out.stream());
}

void load_state(CheckpointIn& in, State<1>& s) {
  char magic[8] = {};
  in.stream().read(magic, 8);
  if (!in.stream() || std::string(magic, 8) != std::string(kMagic, 8))
    throw InputError("not an mpmx run checkpoint (or one from another version)");
  s.step = in.integer();
  s.time = in.number();
  Tallies& t = s.tallies;
  for (double* v : {&t.boundary_impulse, &t.boundary_work, &t.stress_work, &t.max_force_sum, &t.node_mass})
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

}  // namespace mpmx::mpm
