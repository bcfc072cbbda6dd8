#include "mpmx/md/potential/registry.hpp"

#include <variant>

namespace mpmx::md {

PotentialSpec read_potential(Table& t, const std::string& deck_dir) {
  const std::string style = t.choice("style", Potentials::names(), std::string(EamSpec::name));
  return Potentials::with(
      style, [&]<class Entry>() -> PotentialSpec { return Entry::read(t, deck_dir); },
      [] { return PotentialSpec{}; });  // a style that is no string: recorded by choice()
}

bool complete(const PotentialSpec& spec) {
  return std::visit([](const auto& s) { return s.complete(); }, spec);
}

}  // namespace mpmx::md
