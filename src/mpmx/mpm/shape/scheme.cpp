#include "mpmx/mpm/shape/scheme.hpp"

#include <stdexcept>

#include "mpmx/core/error.hpp"
#include "mpmx/mpm/shape/ddmp.hpp"
#include "mpmx/mpm/shape/domain.hpp"
#include "mpmx/mpm/shape/linear.hpp"

namespace mpmx::mpm {

const std::vector<std::string>& scheme_names() {
  static const std::vector<std::string> names{"mpm", "ugimp", "cpgimp", "cpdi", "ddmp",
                                              "ddmp_subpoints"};
  return names;
}

Scheme scheme_from_name(std::string_view name) {
  const auto& n = scheme_names();
  for (std::size_t i = 0; i < n.size(); ++i)
    if (n[i] == name) return static_cast<Scheme>(i);
  throw InputError("unknown scheme '" + std::string(name) + "'");
}

std::string scheme_name(Scheme s) { return scheme_names()[static_cast<std::size_t>(s)]; }

bool tracks_domain(Scheme s) {
  return s == Scheme::cpgimp || s == Scheme::cpdi || s == Scheme::ddmp_subpoints;
}

ShapeEvaluator::ShapeEvaluator(SchemeOptions opt, const Grid<1>& grid) : opt_(opt) {
  if (opt_.scheme == Scheme::ddmp || opt_.scheme == Scheme::ddmp_subpoints)
    ddmp_ = std::make_unique<shape::DdmpTable>(grid);
}
ShapeEvaluator::~ShapeEvaluator() = default;
ShapeEvaluator::ShapeEvaluator(ShapeEvaluator&&) noexcept = default;

void ShapeEvaluator::operator()(const Grid<1>& g, const Particles<1>& p, Stencil<1>& st) const {
  switch (opt_.scheme) {
    case Scheme::mpm: return shape::evaluate_linear(g, p, st);
    case Scheme::ugimp:
    case Scheme::cpgimp: return shape::evaluate_domain(g, p, st, true);
    case Scheme::cpdi: return shape::evaluate_domain(g, p, st, false);
    case Scheme::ddmp: return shape::evaluate_ddmp(g, *ddmp_, p, st);
    case Scheme::ddmp_subpoints: return shape::evaluate_ddmp_subpoints(g, *ddmp_, p, opt_.subpoints, st);
  }
}

}  // namespace mpmx::mpm
