#include "mpmx/app/dpd/fit_checkpoint.hpp"

#include <sstream>

#include <fmt/format.h>

#include "mpmx/app/checkpoint_fields.hpp"
#include "mpmx/core/error.hpp"
#include "mpmx/io/checked_file.hpp"

namespace mpmx::app::dpd {

namespace {

constexpr std::string_view kKind = "fit_dpd";

io::CheckedKind kind_of(const std::string& deck_text, std::size_t densities) {
  return {kKind, 2, io::text_hash(deck_text), densities};  // 2: the input files' digests
}

}  // namespace

std::string FitProgress::stage() const {
  if (!md) return "before the MD isotherm was measured";
  if (round) return fmt::format("after fit round {}", round->next - 1);
  return md_elastic ? "after the MD crystal's elastic constants" : "after the MD isotherm";
}

void write_fit_checkpoint(const std::string& path, const std::string& deck_text, std::size_t densities,
                          const FitProgress& p) {
  io::CheckedWriter file(path, kind_of(deck_text, densities));
  CheckpointOut w(file.stream());
  w.text(deck_text);
  w.inputs();
  w.integer(p.md ? 1 : 0);
  if (p.md) {
    std::vector<double> v;
    for (const auto& q : *p.md) v.insert(v.end(), {q.lattice_constant, q.pressure, q.pressure_error, q.temperature});
    w.numbers(v);
  }
  w.integer(p.md_elastic ? 1 : 0);
  if (const auto& e = p.md_elastic) w.numbers({e->c11, e->c12, e->c11_error, e->c12_error, e->pressure, e->strain});
  w.integer(p.round ? 1 : 0);
  if (const auto& r = p.round) {
    w.integer(r->next);
    w.numbers(r->theta);
    w.numbers(r->thermal);
    w.numbers({r->thermal11, r->thermal12});
    w.integer(r->evaluations);
  }
  file.commit();
}

FitProgress read_fit_checkpoint(const std::string& path, const std::string& deck_text, std::size_t densities) {
  std::istringstream f(io::read_checked(path, kind_of(deck_text, densities)), std::ios::binary);
  CheckpointIn in(f, path, io::kCheckedHeaderBytes);
  if (in.text() != deck_text)
    throw InputError(fmt::format("{} was written for another deck (the deck changed since); run afresh without "
                                 "--resume",
                                 path));
  in.check_inputs();
  // A flag is 0 or 1; a list has the length the deck fixes.
  auto flag = [&] {
    const long long at = in.offset();
    const std::int64_t v = in.integer();
    if (v != 0 && v != 1) throw in.refuse(at, fmt::format("a stage flag is {}, not 0 or 1", v));
    return v == 1;
  };
  auto list = [&](std::size_t n, const char* what) {
    const long long at = in.offset();
    std::vector<double> v = in.numbers();
    if (v.size() != n) throw in.refuse(at, fmt::format("{} holds {} numbers where the deck makes {}", what, v.size(), n));
    return v;
  };
  FitProgress p;
  if (flag()) {
    const std::vector<double> v = list(4 * densities, "the MD isotherm");
    p.md.emplace();
    for (std::size_t k = 0; k < densities; ++k) p.md->push_back({v[4 * k], v[4 * k + 1], v[4 * k + 2], v[4 * k + 3]});
  }
  if (flag()) {
    const std::vector<double> v = list(6, "the MD elastic constants");
    p.md_elastic = multiscale::CubicConstants{v[0], v[1], v[2], v[3], v[4], v[5]};
  }
  if (flag()) {
    multiscale::FitRound r;
    const long long at = in.offset();
    const std::int64_t next = in.integer();
    if (next < 1 || next > 1000000) throw in.refuse(at, fmt::format("the next fit round is {}", next));
    r.next = static_cast<int>(next);
    r.theta = list(3, "the fit's parameters");
    r.thermal = list(densities, "the thermal pressures");
    const std::vector<double> t = list(2, "the thermal elastic constants");
    r.thermal11 = t[0], r.thermal12 = t[1];
    const long long at_e = in.offset();
    const std::int64_t e = in.integer();
    if (e < 0 || e > 1000000000) throw in.refuse(at_e, fmt::format("the objective's evaluations are {}", e));
    r.evaluations = static_cast<int>(e);
    p.round = r;
  }
  in.end();
  if (!p.md && (p.md_elastic || p.round)) throw in.refuse(in.offset(), "later stages without the MD isotherm");
  return p;
}

}  // namespace mpmx::app::dpd
