#include "mpmx/app/mpm/run_summary.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include <fmt/format.h>

#include "mpmx/core/machine.hpp"
#include "mpmx/core/ranks.hpp"
#include "mpmx/core/units.hpp"
#include "mpmx/mpm/phase_times.hpp"

namespace mpmx::app {

double norm(const std::array<double, 3>& v) { return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }

namespace {

template <int Dim>
void record_conservation(const RunResultOf<Dim>& r, io::RunRecord& rec) {
  rec.set("conservation.mass.particles", r.mass_particles);
  rec.set("conservation.mass.nodes", r.mass_nodes);
  rec.set("conservation.mass.relative_error", std::abs(r.mass_nodes - r.mass_particles) / r.mass_particles);
  if constexpr (Dim == 1) {
    rec.set("conservation.momentum.initial", r.momentum_initial);
    rec.set("conservation.momentum.final", r.momentum_final);
    rec.set("conservation.momentum.boundary_impulse", r.boundary_impulse);
  } else {  // vector norms, and the vectors
    auto vec = [](const std::array<double, 3>& v) { return std::vector<double>(v.begin(), v.begin() + Dim); };
    rec.set("conservation.momentum.initial", norm(r.momentum_initial_vec));
    rec.set("conservation.momentum.final", norm(r.momentum_final_vec));
    rec.set("conservation.momentum.boundary_impulse", norm(r.boundary_impulse_vec));
    rec.set("conservation.momentum.initial_vector", vec(r.momentum_initial_vec));
    rec.set("conservation.momentum.final_vector", vec(r.momentum_final_vec));
    rec.set("conservation.momentum.boundary_impulse_vector", vec(r.boundary_impulse_vec));
    rec.set("conservation.energy.stored_initial", r.stored_initial);
    rec.set("conservation.energy.stored_final", r.stored_final);
    const double e0 = r.kinetic_initial + r.stored_initial, e1 = r.kinetic_final + r.stored_final;
    rec.set("conservation.energy.total_initial", e0);
    rec.set("conservation.energy.total_final", e1);
    // Over the initial total, or the energy in play where larger (a piston starts a
    // bar at rest: all it has is the piston's work).
    const double scale = std::max(std::abs(e0), r.energy_scale());
    rec.set("conservation.energy.total_relative_change", scale > 0.0 ? (e1 - e0 - r.boundary_work) / scale : 0.0);
  }
  rec.set("conservation.momentum.relative_error", r.momentum_scale > 0 ? r.momentum_error() / r.momentum_scale : 0.0);
  rec.set("conservation.momentum.max_internal_force_sum", r.max_force_sum);
  rec.set("conservation.energy.kinetic_initial", r.kinetic_initial);
  rec.set("conservation.energy.kinetic_final", r.kinetic_final);
  rec.set("conservation.energy.stress_work", r.stress_work);
  rec.set("conservation.energy.boundary_work", r.boundary_work);
  rec.set("conservation.energy.error", r.energy_error());
  rec.set("conservation.energy.relative_error", r.energy_scale() > 0 ? r.energy_error() / r.energy_scale() : 0.0);
  if (std::isfinite(r.energy_growth)) rec.set("conservation.energy.growth", r.energy_growth);
  if (r.body_work != 0.0) rec.set("conservation.energy.body_work", r.body_work);
}

// A law with a model inside every point (md_closure's boxes): their work and figures.
template <int Dim>
void record_subscale(const RunResultOf<Dim>& r, io::RunRecord& rec) {
  const material::Subscale* sub = r.state.material->subscale();
  if (!sub) return;
  rec.set("md_atom_steps", r.md_atom_steps);
  rec.set("md_atom_steps_per_second", r.wall_seconds > 0 ? r.md_atom_steps / r.wall_seconds : 0.0);
  for (const auto& figure : sub->figures())  // a pair, not a binding: clang 14 cannot capture one
    std::visit([&](auto v) { rec.set(figure.first, v); }, figure.second);
}

}  // namespace

template <int Dim>
void record_run(const MpmConfig& c, const RunResultOf<Dim>& r, const std::string& failure,
                const std::string& checkpoint, io::RunRecord& rec) {
  const auto& s = r.state;
  rec.set("status", r.energy_grew           ? "energy_growth"
                    : !failure.empty()      ? "stopped"
                    : r.interrupted         ? "interrupted"
                                            : "completed");
  if (r.interrupted) rec.set("checkpoint", checkpoint);
  if (std::isfinite(r.stress_vs_direct_md)) rec.set("errors.stress_vs_direct_md", r.stress_vs_direct_md);
  if (const auto u = units::unit_system(c.units)) {  // for readers of the tables (tools/plot)
    rec.set("units.name", std::string(u->name));
    rec.set("units.length_A", u->length_A);
    rec.set("units.time_ps", u->time_ps);
    rec.set("units.stress_GPa", u->stress_GPa);
  }
  record_subscale(r, rec);
  rec.set("rank_imbalance", r.rank_imbalance);
  if (r.ranks > 1) rec.set("rebalances", static_cast<std::int64_t>(r.rebalances));
  if (!failure.empty()) rec.set("error", failure);
  rec.set("dim", static_cast<std::int64_t>(Dim));
  rec.set("steps", static_cast<std::int64_t>(r.steps));
  rec.set("time", s.time);
  rec.set("wall_seconds", r.wall_seconds);
  rec.set("particles", static_cast<std::int64_t>(s.particles.size()));
  // The largest rank's peak resident memory.
  rec.set("peak_memory_bytes", static_cast<std::int64_t>(ranks::max({static_cast<double>(peak_memory_bytes())})[0]));
  rec.set("particle_steps_per_second",
          r.wall_seconds > 0 ? static_cast<double>(s.particles.size()) * r.steps / r.wall_seconds : 0.0);
  if (s.phases.total() > 0)  // the stencil step's phases, seconds of this invocation (not the fused 1-D step's)
    for (std::size_t k = 0; k < mpm::kPhaseNames.size(); ++k)
      rec.set(fmt::format("phases.{}", mpm::kPhaseNames[k]), s.phases.seconds[k]);
  for (const auto& [f, e] : r.errors) {
    rec.set(fmt::format("errors.{}.l1", f), e.l1);
    rec.set(fmt::format("errors.{}.l2", f), e.l2);
    if (e.peak > 0.0) rec.set(fmt::format("errors.{}.peak", f), e.peak);
  }
  record_conservation(r, rec);
}

template void record_run<1>(const MpmConfig&, const RunResultOf<1>&, const std::string&, const std::string&,
                            io::RunRecord&);
template void record_run<2>(const MpmConfig&, const RunResultOf<2>&, const std::string&, const std::string&,
                            io::RunRecord&);
template void record_run<3>(const MpmConfig&, const RunResultOf<3>&, const std::string&, const std::string&,
                            io::RunRecord&);

}  // namespace mpmx::app
