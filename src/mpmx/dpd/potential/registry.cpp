#include "mpmx/dpd/potential/registry.hpp"

#include <fmt/format.h>

namespace mpmx::dpd {

std::vector<std::string> pair_potential_names() { return PairPotentials::names(); }

PairPotential read_pair_potential(Table& s) {
  const std::string style = s.choice("style", pair_potential_names());
  return PairPotentials::with(
      style, [&]<class Entry>() -> PairPotential { return Entry::read(s); },
      [] { return PairPotential{}; });  // a style that is no string: recorded by choice()
}

double cutoff(const PairPotential& p) {
  return std::visit([](const auto& q) { return q.cutoff(); }, p);
}

std::string describe(const PairPotential& p) {
  return std::visit([](const auto& q) { return q.describe(); }, p);
}

std::string style_name(const PairPotential& p) { return pair_potential_names()[p.index()]; }

std::string SoftPotential::describe() const { return fmt::format("dpd: a = {} eV/A, rc = {} A", a, rc); }

SoftPotential SoftPotential::read(Table& s) {
  SoftPotential p;
  p.a = s.number("a");
  s.non_negative("a", p.a);
  p.rc = s.number("cutoff");
  s.positive("cutoff", p.rc);
  return p;
}

std::string MorsePotential::describe() const {
  return fmt::format("morse: D0 = {} eV, alpha = {} 1/A, r0 = {} A, rc = {} A{}", d0, alpha, r0, rc,
                     shift ? ", shifted" : "");
}

MorsePotential MorsePotential::read(Table& s) {
  MorsePotential p;
  p.d0 = s.number("d0");
  s.positive("d0", p.d0);
  p.alpha = s.number("alpha");
  s.positive("alpha", p.alpha);
  p.r0 = s.number("r0");
  s.positive("r0", p.r0);
  p.rc = s.number("cutoff");
  s.check(p.rc > p.r0, "cutoff", "must exceed r0 (the minimum lies inside the cutoff)");
  p.shift = s.boolean("shift", true);
  p.update_offset();
  return p;
}

std::string NmPotential::describe() const {
  return fmt::format("nm: E0 = {} eV, r0 = {} A, n = {}, m = {}, rc = {} A{}", e0, r0, n, m, rc,
                     shift ? ", shifted" : "");
}

NmPotential NmPotential::read(Table& s) {
  NmPotential p;
  p.e0 = s.number("e0");
  s.positive("e0", p.e0);
  p.r0 = s.number("r0");
  s.positive("r0", p.r0);
  p.n = s.number("n");
  p.m = s.number("m");
  s.check(p.m > 0, "m", "must be positive");
  s.check(p.n > p.m, "n", "must exceed m");
  p.rc = s.number("cutoff");
  s.check(p.rc > p.r0, "cutoff", "must exceed r0 (the minimum lies inside the cutoff)");
  p.shift = s.boolean("shift", true);
  if (p.n > p.m && p.m > 0) p.update_offset();
  return p;
}

}  // namespace mpmx::dpd
