#include "mpmx/dpd/potential/registry.hpp"

#include <filesystem>

#include <fmt/format.h>

#include "mpmx/core/error.hpp"

namespace mpmx::dpd {

namespace {

template <std::size_t I = 0>
void collect_names(std::vector<std::string>& out) {
  if constexpr (I < std::variant_size_v<PairPotential>) {
    out.emplace_back(std::variant_alternative_t<I, PairPotential>::name);
    collect_names<I + 1>(out);
  }
}

template <std::size_t I = 0>
PairPotential read_by_name(const std::string& style, io::Section& s) {
  if constexpr (I < std::variant_size_v<PairPotential>) {
    using P = std::variant_alternative_t<I, PairPotential>;
    if (style == P::name) return P::read(s);
    return read_by_name<I + 1>(style, s);
  } else {
    return PairPotential{};
  }
}

}  // namespace

std::vector<std::string> pair_potential_names() {
  std::vector<std::string> names;
  collect_names(names);
  return names;
}

PairPotential read_pair_potential(io::Section s, const std::string& deck_dir) {
  if (s.has("file")) {
    s.check(!s.has("style"), "style", "give either file or style and parameters, not both");
    std::filesystem::path path = s.string("file");
    if (path.is_relative() && !deck_dir.empty()) path = deck_dir / path;
    try {
      io::Deck d = io::Deck::from_file(path.string());
      io::Section inner = d.root().table("potential");
      inner.check(!inner.has("file"), "file", "a potential file cannot name another");
      PairPotential p = inner.has("file") ? PairPotential{} : read_pair_potential(inner);
      d.finish();
      return p;
    } catch (const InputError& e) {
      s.check(false, "file", e.what());
      return PairPotential{};
    }
  }
  const std::string style = s.choice("style", pair_potential_names());
  return read_by_name(style, s);
}

double cutoff(const PairPotential& p) {
  return std::visit([](const auto& q) { return q.cutoff(); }, p);
}

std::string describe(const PairPotential& p) {
  return std::visit([](const auto& q) { return q.describe(); }, p);
}

std::string style_name(const PairPotential& p) {
  return std::visit([](const auto& q) { return std::string(q.name); }, p);
}

std::string SoftPotential::describe() const { return fmt::format("dpd: a = {} eV/A, rc = {} A", a, rc); }

SoftPotential SoftPotential::read(io::Section& s) {
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

MorsePotential MorsePotential::read(io::Section& s) {
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

NmPotential NmPotential::read(io::Section& s) {
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
