#pragma once
// Shape schemes, chosen by name in the deck ([scheme] name = ...).
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "mpmx/mpm/grid.hpp"
#include "mpmx/mpm/particles.hpp"

namespace mpmx::mpm {

enum class Scheme { mpm, ugimp, cpgimp, cpdi, ddmp, ddmp_subpoints };

Scheme scheme_from_name(std::string_view name);
std::string scheme_name(Scheme s);
const std::vector<std::string>& scheme_names();

// Whether the particle domain length follows the deformation (cpGIMP, CPDI,
// sub-points) rather than staying fixed (uGIMP) or not existing (MPM, DDMP).
bool tracks_domain(Scheme s);

struct SchemeOptions {
  Scheme scheme = Scheme::mpm;
  int subpoints = 1;  // ddmp_subpoints only
  bool midpoint_gradient = true;  // x and grad v advanced with v^{n+1/2} (eqs. 3.14, 4.10) or v^L
};

namespace shape {
struct DdmpTable;
}

// Fills the stencil (S_ip, G_ip) of every particle at its current position with the
// scheme chosen once for the run.
class ShapeEvaluator {
 public:
  ShapeEvaluator(SchemeOptions opt, const Grid<1>& grid);
  ~ShapeEvaluator();
  ShapeEvaluator(ShapeEvaluator&&) noexcept;
  void operator()(const Grid<1>& grid, const Particles<1>& p, Stencil<1>& st) const;
  const SchemeOptions& options() const { return opt_; }

 private:
  SchemeOptions opt_;
  std::unique_ptr<shape::DdmpTable> ddmp_;
};

}  // namespace mpmx::mpm
