#include "mpmx/app/mpm/checkpoint.hpp"

#include <cmath>
#include <istream>
#include <ostream>

#include <fmt/format.h>

#include "mpmx/core/error.hpp"

namespace mpmx::app {

using namespace mpm;

namespace {
constexpr char kMagic[8] = {'M', 'P', 'M', 'X', 'S', 'T', '0', '3'};

template <int Dim, class F>
void each_array(Particles<Dim>& p, F&& f) {
  for (int a = 0; a < Dim; ++a) f(p.x[a]), f(p.v[a]);
  for (auto* v : {&p.mass, &p.volume, &p.volume0, &p.viscous_pressure}) f(*v);
  for (int c = 0; c < Dim * Dim; ++c) f(p.length[c]), f(p.strain[c]), f(p.stress[c]), f(p.grad_v[c]);
  if constexpr (Dim == 2) f(p.stress_zz);
  if (!p.viscous[0].empty())
    for (int c = 0; c < Dim * Dim; ++c) f(p.viscous[c]);
}
}  // namespace

io::CheckedKind run_checkpoint_kind(const std::string& deck_text, std::size_t points) {
  // 2: sigma_zz in 2-D, the body force's work; 3: the input files' digests; 4: what each MD box owes of eq. 7.11;
  // 5: the steps' log (dt = "cfl")
  // 6: md_closure's merges by state (their tallies)
  return {"mpm_run", 6, io::text_hash(deck_text), points};
}

template <int Dim>
void save_state(CheckpointOut& out, const State<Dim>& s) {
  out.stream().write(kMagic, 8);
  out.integer(s.step);
  out.number(s.time);
  const Tallies& t = s.tallies;
  for (double v : {t.boundary_impulse[0], t.boundary_impulse[1], t.boundary_impulse[2], t.boundary_work,
                   t.body_work, t.stress_work, t.max_force_sum, t.node_mass})
    out.number(v);
  auto& p = const_cast<Particles<Dim>&>(s.particles);
  each_array(p, [&](std::vector<double>& v) { out.numbers(v); });
  out.text(s.material->name());
  s.material->save(out.stream());
}

template <int Dim>
void load_state(CheckpointIn& in, State<Dim>& s) {
  char magic[8] = {};
  const long long at = in.offset();
  in.stream().read(magic, 8);
  if (!in.stream() || std::string(magic, 8) != std::string(kMagic, 8))
    throw in.refuse(at, "not the state of an mpmx run (or one from another version)");
  const long long at_step = in.offset();
  s.step = in.integer();
  if (s.step < 0) throw in.refuse(at_step, fmt::format("a negative step count {}", s.step));
  const long long at_time = in.offset();
  s.time = in.number();
  if (!(std::isfinite(s.time) && s.time >= 0.0)) throw in.refuse(at_time, fmt::format("a time of {}", s.time));
  Tallies& t = s.tallies;
  for (double* v : {&t.boundary_impulse[0], &t.boundary_impulse[1], &t.boundary_impulse[2], &t.boundary_work,
                    &t.body_work, &t.stress_work, &t.max_force_sum, &t.node_mass})
    *v = in.number();
  const std::size_t n = s.particles.size();
  each_array(s.particles, [&](std::vector<double>& v) {
    // Read aside and kept only when whole: a refused checkpoint leaves the state as it was.
    const long long at_v = in.offset();
    std::vector<double> read = in.numbers();
    if (read.size() != n) throw in.refuse(at_v, fmt::format("{} particles, the deck makes {}", read.size(), n));
    for (double x : read)
      if (!std::isfinite(x)) throw in.refuse(at_v, "a non-finite particle value");
    v.swap(read);
  });
  const long long at_m = in.offset();
  const std::string material = in.text();
  if (material != s.material->name())
    throw in.refuse(at_m, fmt::format("the material is {}, the deck's {}", material, s.material->name()));
  const long long at_state = in.offset();
  try {
    s.material->load(in.stream());
  } catch (const InputError& e) {
    throw in.refuse(at_state, fmt::format("the {} state: {}", material, e.what()));
  }
  const long long points = s.material->state_points();
  if (points >= 0 && points != static_cast<long long>(n))
    throw in.refuse(at_state, fmt::format("the {} state holds {} points, the deck makes {}", material, points, n));
}

template void save_state<1>(CheckpointOut&, const State<1>&);
template void save_state<2>(CheckpointOut&, const State<2>&);
template void save_state<3>(CheckpointOut&, const State<3>&);
template void load_state<1>(CheckpointIn&, State<1>&);
template void load_state<2>(CheckpointIn&, State<2>&);
template void load_state<3>(CheckpointIn&, State<3>&);

}  // namespace mpmx::app
