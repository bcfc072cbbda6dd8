#include "mpmx/md/potential/potential.hpp"

#include <filesystem>

#include <fmt/format.h>

#include "mpmx/core/error.hpp"

namespace mpmx::md {

namespace fs = std::filesystem;

std::string resolve_potential_file(const std::string& name, const std::string& deck_dir) {
  std::vector<fs::path> tried;
  fs::path p(name);
  if (p.is_absolute()) {
    tried.push_back(p);
  } else {
    tried.push_back(deck_dir.empty() ? p : fs::path(deck_dir) / p);
    tried.push_back(fs::path("/usr/share/lammps/potentials") / p);
  }
  // The error_code form: a name the system cannot even look up (too long, bad bytes) is
  // a file not found, not an exception from the filesystem.
  for (const auto& t : tried)
    if (std::error_code ec; fs::is_regular_file(t, ec)) return t.string();
  std::vector<std::string> names;
  for (const auto& t : tried) names.push_back(t.string());
  throw InputError(fmt::format("potential file '{}' not found (tried: {})", name, fmt::join(names, ", ")));
}

namespace {
std::variant<Eam, LennardJones, SuttonChen> make(const PotentialSpec& s) {
  if (s.style == "eam") return Eam(read_eam(s.file), s.elements);
  if (s.style == "lj") return LennardJones(s.epsilon, s.sigma, s.cutoff, s.mass, s.shift);
  if (s.style == "sutton_chen") return SuttonChen(s.epsilon, s.a, s.c, s.n, s.m, s.cutoff, s.mass);
  throw InputError(fmt::format("potential style '{}': expected eam, lj or sutton_chen", s.style));
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
  if (std::holds_alternative<LennardJones>(impl_->v)) return "lj";
  return "sutton_chen";
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
