#pragma once
// Shape schemes, chosen by name in the deck ([scheme] name = ...). On the regular grid
// of any dimension every scheme is built from one-dimensional factors along each axis
// (hat, GIMP average, DDMP's smoothed gradient), combined as tensor products; CPDI's
// deformed domains and the sub-points' lattice are placed by the particle's domain
// vectors. 1-D is the case of one factor.
#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "mpmx/mpm/grid.hpp"
#include "mpmx/mpm/particles.hpp"

namespace mpmx::mpm {

// A scheme's id: its place in the list of shape/schemes.hpp (one file per scheme).
enum class Scheme { mpm, ugimp, cpgimp, cpdi, ddmp, ddmp_subpoints };

// What the step needs to know of each scheme (from its entry).
struct SchemeInfo {
  Scheme scheme;
  std::string name;
  bool tracks_domain;   // the domain follows the deformation (cpGIMP, CPDI, sub-points)
  bool ddmp;            // the modified gradient of eq. 3.31 / 7.2 (and its wider support)
  bool subpoints;       // integrates the gradient over sub-points (eqs. 4.5-4.6, 6.1-6.3)
};
const std::vector<SchemeInfo>& schemes();
const SchemeInfo& scheme_info(Scheme s);
Scheme scheme_from_name(std::string_view name);
std::string scheme_name(Scheme s);
std::vector<std::string> scheme_names();
inline bool tracks_domain(Scheme s) { return scheme_info(s).tracks_domain; }

// DDMP's alpha in 2-D and 3-D: eq. 7.3 over the cell's nodes, or the product of the
// 1-D alphas' factors, 0.5 prod_a q_a^(3/2), which reduces to the 1-D scheme on a
// problem that does not vary across y and z (q = 1 at a cell's centre).
enum class DdmpAlpha { eq_7_3, axis_product };

struct SchemeOptions {
  Scheme scheme = Scheme::mpm;
  int subpoints = 1;  // ddmp_subpoints along x (1-D: the count)
  std::array<int, 3> subpoints_axes{1, 1, 1};  // ddmp_subpoints per axis (their product in all)
  DdmpAlpha alpha = DdmpAlpha::eq_7_3;
  bool midpoint_gradient = true;  // x and grad v advanced with v^{n+1/2} (eqs. 3.14, 4.10) or v^L
  bool musl = false;              // grad v from the re-mapped new velocities (mpm/musl.hpp); x with v^L
};

namespace shape {
struct DdmpTable;
}

// Fills the stencil (S_ip, G_ip) of every particle at its current position with the
// scheme chosen once for the run.
template <int Dim>
class ShapeEvaluator {
 public:
  ShapeEvaluator(SchemeOptions opt, const Grid<Dim>& grid);
  ~ShapeEvaluator();
  ShapeEvaluator(ShapeEvaluator&&) noexcept;
  void operator()(const Grid<Dim>& grid, const Particles<Dim>& p, Stencil<Dim>& st) const;
  const SchemeOptions& options() const { return opt_; }
  void set_threads(int threads) { threads_ = threads > 0 ? threads : 1; }

 private:
  SchemeOptions opt_;
  int threads_ = 1;
  std::shared_ptr<std::vector<shape::DdmpTable>> ddmp_;  // one per axis (DDMP schemes), shared with the stencils
  mutable std::vector<std::uint8_t> mark_;  // scratch of DDMP's node marks
};

template <class G>
ShapeEvaluator(SchemeOptions, const G&) -> ShapeEvaluator<G::dim>;

}  // namespace mpmx::mpm
