#include "mpmx/md/potential/potential.hpp"

#include <fmt/format.h>

namespace mpmx::md {

namespace {
KernelsOf<Potentials>::type make(const PotentialSpec& spec) {
  return std::visit([](const auto& s) -> KernelsOf<Potentials>::type { return s.make(); }, spec);
}
}  // namespace

Potential::Potential(const PotentialSpec& spec) : impl_(std::make_shared<const Impl>(Impl{make(spec)})) {}

double Potential::cutoff() const {
  return std::visit([](const auto& p) { return p.cutoff(); }, impl_->v);
}

int Potential::types() const {
  if (const auto* e = eam()) return e->types();
  return 1;
}

double Potential::mass(int type) const {
  if (const auto* e = eam()) return e->masses().at(type);
  return std::visit(
      [](const auto& p) -> double {
        if constexpr (std::is_same_v<std::decay_t<decltype(p)>, Eam>) return 0.0;
        else return p.mass();
      },
      impl_->v);
}

std::string Potential::describe() const {
  if (const auto* e = eam()) return fmt::format("eam {} ({})", e->file(), fmt::join(e->type_names(), " "));
  return Potentials::names()[impl_->v.index()];
}

ForceSums Potential::compute(const Neighbors& nb, ForceWork& w, bool mixed) const {
  if (const auto* e = eam()) return mixed ? e->compute_mixed(nb, w) : e->compute(nb, w);
  return std::visit(
      [&](const auto& p) -> ForceSums {
        if constexpr (std::is_same_v<std::decay_t<decltype(p)>, Eam>) return {};
        else return p.compute(nb, w);
      },
      impl_->v);
}

}  // namespace mpmx::md
