#include "mpmx/mpm/shape/scheme.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "mpmx/core/error.hpp"
#include "mpmx/mpm/shape/axis.hpp"
#include "mpmx/mpm/shape/ddmp.hpp"
#include "mpmx/mpm/shape/ddmp_operator.hpp"

namespace mpmx::mpm {

const std::vector<SchemeInfo>& schemes() {
  static const std::vector<SchemeInfo> s{
      {Scheme::mpm, "mpm", false, false, false},
      {Scheme::ugimp, "ugimp", false, false, false},
      {Scheme::cpgimp, "cpgimp", true, false, false},
      {Scheme::cpdi, "cpdi", true, false, false},
      {Scheme::ddmp, "ddmp", false, true, false},
      {Scheme::ddmp_subpoints, "ddmp_subpoints", true, true, true},
  };
  return s;
}

const SchemeInfo& scheme_info(Scheme s) { return schemes()[static_cast<std::size_t>(s)]; }

std::vector<std::string> scheme_names() {
  std::vector<std::string> n;
  for (const auto& s : schemes()) n.push_back(s.name);
  return n;
}

Scheme scheme_from_name(std::string_view name) {
  for (const auto& s : schemes())
    if (s.name == name) return s.scheme;
  throw InputError(fmt::format("unknown scheme '{}' (one of {})", name, fmt::join(scheme_names(), ", ")));
}

std::string scheme_name(Scheme s) { return scheme_info(s).name; }

template <int Dim>
ShapeEvaluator<Dim>::ShapeEvaluator(SchemeOptions opt, const Grid<Dim>& grid) : opt_(opt) {
  if (scheme_info(opt_.scheme).ddmp) {
    ddmp_ = std::make_shared<std::vector<shape::DdmpTable>>();
    for (int d = 0; d < Dim; ++d) ddmp_->emplace_back(grid.cells[d], grid.dx[d]);
  }
}
template <int Dim>
ShapeEvaluator<Dim>::~ShapeEvaluator() = default;
template <int Dim>
ShapeEvaluator<Dim>::ShapeEvaluator(ShapeEvaluator&&) noexcept = default;

namespace {

using shape::Axis;

// The particle's position in cell units, checked to lie at most a cell off the grid.
template <int Dim>
std::array<double, Dim> cell_coords(const Grid<Dim>& g, const Particles<Dim>& p, std::size_t q) {
  std::array<double, Dim> xi;
  for (int d = 0; d < Dim; ++d) {
    xi[d] = (p.x[d][q] - g.lower[d]) * g.inv_dx[d];
    shape::require_inside(xi[d], g.cells[d], q, p.x[d][q]);
  }
  return xi;
}

// The offsets of the entry after o in a stencil box of widths W, x fastest (an odometer:
// no division per entry, which in the wide boxes of sub-points took a good part of the step).
template <int Dim>
void next_entry(std::array<int, Dim>& o, const std::array<int, Dim>& W) {
  for (int a = 0; a < Dim && ++o[a] == W[a]; ++a) o[a] = 0;
}

// The stencil's node indices for the box starting at ax[d].first.
template <int Dim>
void set_nodes(const Grid<Dim>& g, const Axis* ax, const std::array<int, Dim>& W, int width, int* node) {
  std::array<int, Dim> o{};
  for (int k = 0; k < width; ++k, next_entry<Dim>(o, W)) {
    std::array<int, Dim> idx;
    for (int d = 0; d < Dim; ++d) idx[d] = ax[d].first + o[d];
    node[k] = static_cast<int>(g.index_clamped(idx));
  }
}

// S = prod_a S_a, G_d = S_d' prod_{a != d} S_a: the tensor product of 1-D factors,
// entries x fastest.
template <int Dim>
void separable(const Axis* ax, const std::array<int, Dim>& W, int width, double* S, std::array<double*, Dim> G) {
  std::array<int, Dim> o{};
  for (int k = 0; k < width; ++k) {
    double s = 1.0;
    for (int a = 0; a < Dim; ++a) s *= ax[a].S[o[a]];
    S[k] = s;
    for (int d = 0; d < Dim; ++d) {
      double gd = ax[d].G[o[d]];
      for (int a = 0; a < Dim; ++a)
        if (a != d) gd *= ax[a].S[o[a]];
      G[d][k] = gd;
    }
    next_entry<Dim>(o, W);
  }
}

// Eq. 7.2 at one evaluation point of weight w, factored (particles.hpp, Stencil): on
// the 2^d hat nodes at box offsets `at`, G_d += w alpha dS_d prod S and R += w (1 - alpha)
// prod S; the smoothed part is the grid's operator applied to R (ddmp_operator.hpp).
template <int Dim>
void add_ddmp(const Axis* ax, const std::array<int, Dim>& at, double w, const std::array<int, Dim>& W,
              DdmpAlpha form, std::array<double*, Dim> G, double* R) {
  double q[Dim];
  for (int a = 0; a < Dim; ++a) q[a] = ax[a].q;
  const double alpha = form == DdmpAlpha::eq_7_3 ? shape::ddmp_alpha_nd<Dim>(q) : shape::ddmp_alpha_product<Dim>(q);
  const double sharp = w * alpha, smooth = w * (1.0 - alpha);
  for (int k = 0; k < (1 << Dim); ++k) {
    std::array<int, Dim> o;
    int flat = 0, stride = 1;
    for (int a = 0; a < Dim; ++a) {
      o[a] = at[a] + (k >> a & 1);
      flat += o[a] * stride;
      stride *= W[a];
    }
    double s = 1.0;
    for (int a = 0; a < Dim; ++a) s *= ax[a].S[o[a]];
    R[flat] += smooth * s;
    for (int d = 0; d < Dim; ++d) {
      double g = ax[d].G[o[d]];
      for (int a = 0; a < Dim; ++a)
        if (a != d) g *= ax[a].S[o[a]];
      G[d][flat] += sharp * g;
    }
  }
}

}  // namespace

template <int Dim>
void ShapeEvaluator<Dim>::operator()(const Grid<Dim>& g, const Particles<Dim>& p, Stencil<Dim>& st) const {
  const std::size_t n = p.size();
  const Scheme scheme = opt_.scheme;
  const bool corners = scheme == Scheme::cpdi && Dim > 1;  // CPDI's deformed domains
  // Sub-points per axis (1-D: the deck's count).
  std::array<int, Dim> nsub;
  for (int d = 0; d < Dim; ++d)
    nsub[d] = scheme != Scheme::ddmp_subpoints ? 1 : Dim == 1 ? opt_.subpoints : opt_.subpoints_axes[d];
  auto half = [&](std::size_t q, int d) { return 0.5 * p.length[d * Dim + d][q] * g.inv_dx[d]; };
  // Position of corner or sub-point `c` of particle q in cell units, from its domain
  // vectors: x + sum_b r_b u_b with u_b = s_b / 2 (corners) or (s_b + 1/2) / n - 1/2.
  int points = 1;  // corners or sub-points per particle
  for (int d = 0; d < Dim; ++d) points *= corners ? 2 : nsub[d];
  std::vector<std::array<double, Dim>> unit(points);  // the u_b of each, once per step
  for (int c = 0; c < points; ++c)
    for (int b = 0, rest = c; b < Dim; ++b) {
      const int s = corners ? c >> b & 1 : rest % nsub[b];
      rest /= nsub[b];
      unit[c][b] = corners ? (s ? 0.5 : -0.5) : (s + 0.5) / nsub[b] - 0.5;
    }
  auto place = [&](std::size_t q, const std::array<double, Dim>& xi, int c) {
    std::array<double, Dim> at = xi;
    const std::array<double, Dim>& u = unit[c];
    for (int a = 0; a < Dim; ++a)
      for (int b = 0; b < Dim; ++b) at[a] += p.length[a * Dim + b][q] * g.inv_dx[a] * u[b];
    return at;
  };

  // Pass 1: every point on the grid (or a cell past it: the first one that is not is
  // named), and the box width along each axis, the widest particle's. A minimum and
  // maxima: the same for any thread count.
  const bool hat = scheme == Scheme::mpm || scheme == Scheme::ddmp;
  const bool domain = scheme == Scheme::ugimp || scheme == Scheme::cpgimp || (scheme == Scheme::cpdi && Dim == 1);
  std::size_t off_grid = n;
  int widest[Dim];
  std::fill_n(widest, Dim, 2);
#pragma omp parallel for schedule(static) reduction(min : off_grid) reduction(max : widest) num_threads(threads_) if (threads_ > 1)
  for (std::size_t q = 0; q < n; ++q) {
    std::array<double, Dim> xi;
    bool inside = true;
    for (int d = 0; d < Dim; ++d) {
      xi[d] = (p.x[d][q] - g.lower[d]) * g.inv_dx[d];
      inside = inside && shape::within_reach(xi[d], g.cells[d]);
    }
    if (!inside) {
      off_grid = std::min(off_grid, q);
      continue;
    }
    if (hat) continue;
    if (domain) {
      for (int d = 0; d < Dim; ++d) widest[d] = std::max(widest[d], shape::domain_width(xi[d], half(q, d), g.cells[d]));
      continue;
    }
    std::array<int, Dim> lo, hi;
    lo.fill(1 << 30);
    hi.fill(-(1 << 30));
    for (int c = 0; c < points; ++c) {
      const auto at = place(q, xi, c);
      for (int d = 0; d < Dim; ++d) {
        const int cell = shape::ddmp_cell(at[d], g.cells[d]);
        lo[d] = std::min(lo[d], cell);
        hi[d] = std::max(hi[d], cell + 1);
      }
    }
    for (int d = 0; d < Dim; ++d) widest[d] = std::max(widest[d], hi[d] - lo[d] + 1);
  }
  if (off_grid < n) cell_coords(g, p, off_grid);  // throws with its number and position
  std::array<int, Dim> W;
  for (int d = 0; d < Dim; ++d) W[d] = widest[d];
  int width = 1;
  for (int d = 0; d < Dim; ++d) {
    shape::require_width(W[d]);
    width *= W[d];
  }
  const bool factored = scheme_info(scheme).ddmp;
  st.reset(n, width, false, factored);  // each particle's entries are cleared by its thread below
  st.box = W;
  if (factored) st.smooth = ddmp_;

  // The nodes of a hat's box (mpm, ddmp), which never reaches past the grid: the first
  // node plus a fixed step per entry.
  std::array<int, 1 << Dim> hat_step{};
  for (int k = 0; k < (1 << Dim); ++k)
    for (int a = 0; a < Dim; ++a) hat_step[k] += (k >> a & 1) * g.stride[a];
  auto hat_nodes = [&](const Axis* ax, int* node) {
    std::array<int, Dim> first;
    for (int d = 0; d < Dim; ++d) first[d] = ax[d].first;
    const int base = static_cast<int>(g.index(first));
    for (int k = 0; k < (1 << Dim); ++k) node[k] = base + hat_step[k];
  };

  // Pass 2: every particle's factors and their products, each particle on its own.
#pragma omp parallel for schedule(static) num_threads(threads_)
  for (std::size_t q = 0; q < n; ++q) {
    Axis ax[Dim];
    std::array<double, Dim> xi;
    for (int d = 0; d < Dim; ++d) xi[d] = (p.x[d][q] - g.lower[d]) * g.inv_dx[d];
    const std::size_t e = q * static_cast<std::size_t>(width);
    std::array<double*, Dim> G;
    for (int d = 0; d < Dim; ++d) G[d] = &st.G[d][e];
    double* S = &st.S[e];
    if (scheme != Scheme::mpm) {  // the others add into their entries
      std::fill(S, S + width, 0.0);
      for (int d = 0; d < Dim; ++d) std::fill(G[d], G[d] + width, 0.0);
      if (factored) std::fill(&st.R[e], &st.R[e] + width, 0.0);
    }
    switch (scheme) {
      case Scheme::mpm: {
        // The products unrolled (the same, in the same order, as separable()).
        for (int d = 0; d < Dim; ++d) shape::hat_axis(xi[d], g.cells[d], g.inv_dx[d], ax[d]);
        for (int k = 0; k < (1 << Dim); ++k) {
          double sk = 1.0;
          for (int a = 0; a < Dim; ++a) sk *= ax[a].S[k >> a & 1];
          S[k] = sk;
          for (int d = 0; d < Dim; ++d) {
            double gd = ax[d].G[k >> d & 1];
            for (int a = 0; a < Dim; ++a)
              if (a != d) gd *= ax[a].S[k >> a & 1];
            G[d][k] = gd;
          }
        }
        hat_nodes(ax, &st.node[e]);
        continue;
      }
      case Scheme::ugimp:
      case Scheme::cpgimp:
      case Scheme::cpdi:
        if (!corners) {
          for (int d = 0; d < Dim; ++d) {
            ax[d].clear(W[d]);
            shape::domain_axis(xi[d], half(q, d), g.cells[d], g.inv_dx[d], scheme != Scheme::cpdi, W[d], ax[d]);
          }
          separable<Dim>(ax, W, width, S, G);
        } else {
          // CPDI: S_ip the mean of the corner values; grad S_ip the mean gradient of their
          // multilinear interpolant over the parallelogram (parallelepiped), 2 R^-T g with
          // g_b = sum_c s_b S(x_c) / 2^d and R the domain vectors as columns.
          std::array<int, Dim> lo;
          lo.fill(1 << 30);
          for (int c = 0; c < points; ++c) {
            const auto at = place(q, xi, c);
            for (int d = 0; d < Dim; ++d) lo[d] = std::min(lo[d], shape::ddmp_cell(at[d], g.cells[d]));
          }
          for (int d = 0; d < Dim; ++d) ax[d].first = lo[d];
          std::array<std::vector<double>, Dim> gxi;
          for (auto& v : gxi) v.assign(width, 0.0);
          for (int c = 0; c < points; ++c) {
            const auto at = place(q, xi, c);
            Axis cx[Dim];
            for (int d = 0; d < Dim; ++d) {
              cx[d].clear(W[d]);
              const int cell = shape::ddmp_cell(at[d], g.cells[d]);
              for (int k = 0; k < 2; ++k) {
                const int i = cell + k;
                cx[d].S[cell - lo[d] + k] = shape::hat_ext(at[d], i, g.cells[d]);
              }
            }
            std::array<int, Dim> o{};
            for (int k = 0; k < width; ++k, next_entry<Dim>(o, W)) {
              double s = 1.0;
              for (int a = 0; a < Dim; ++a) s *= cx[a].S[o[a]];
              S[k] += s / points;
              for (int b = 0; b < Dim; ++b) gxi[b][k] += ((c >> b & 1) ? s : -s) / points;
            }
          }
          // R^-T by the cofactors of R (2-D, 3-D).
          double R[3][3] = {}, inv[3][3] = {};
          for (int a = 0; a < Dim; ++a)
            for (int b = 0; b < Dim; ++b) R[a][b] = p.length[a * Dim + b][q];
          if constexpr (Dim == 2) {
            const double det = R[0][0] * R[1][1] - R[0][1] * R[1][0];
            inv[0][0] = R[1][1] / det, inv[0][1] = -R[0][1] / det;
            inv[1][0] = -R[1][0] / det, inv[1][1] = R[0][0] / det;
          } else if constexpr (Dim == 3) {
            const double det = R[0][0] * (R[1][1] * R[2][2] - R[1][2] * R[2][1]) -
                               R[0][1] * (R[1][0] * R[2][2] - R[1][2] * R[2][0]) +
                               R[0][2] * (R[1][0] * R[2][1] - R[1][1] * R[2][0]);
            for (int a = 0; a < 3; ++a)
              for (int b = 0; b < 3; ++b) {
                const int a1 = (b + 1) % 3, a2 = (b + 2) % 3, b1 = (a + 1) % 3, b2 = (a + 2) % 3;
                inv[a][b] = (R[a1][b1] * R[a2][b2] - R[a1][b2] * R[a2][b1]) / det;  // (R^-1)_ab
              }
          }
          for (int k = 0; k < width; ++k)
            for (int d = 0; d < Dim; ++d) {
              double v = 0.0;
              for (int b = 0; b < Dim; ++b) v += inv[b][d] * gxi[b][k];  // (R^-T)_db = (R^-1)_bd
              G[d][k] = 2.0 * v;
            }
        }
        break;
      case Scheme::ddmp: {
        for (int d = 0; d < Dim; ++d) shape::ddmp_axis(xi[d], g.cells[d], g.inv_dx[d], 0, ax[d]);
        for (int k = 0; k < width; ++k) {
          double s = 1.0;
          for (int a = 0; a < Dim; ++a) s *= ax[a].S[k >> a & 1];
          S[k] = s;
        }
        add_ddmp<Dim>(ax, std::array<int, Dim>{}, 1.0, W, opt_.alpha, G, &st.R[e]);
        hat_nodes(ax, &st.node[e]);
        continue;
      }
      case Scheme::ddmp_subpoints: {
        // The box: the cells of the sub-points (the particle's own lies among them); each
        // sub-point located once, kept for the gradient below.
        thread_local std::vector<std::array<shape::CellPos, Dim>> sub;
        sub.resize(static_cast<std::size_t>(points));
        std::array<int, Dim> lo;
        lo.fill(1 << 30);
        for (int c = 0; c < points; ++c) {
          const auto at = place(q, xi, c);
          for (int d = 0; d < Dim; ++d) {
            sub[c][d] = shape::locate(shape::clamp_to_grid(at[d], g.cells[d]), g.cells[d]);
            lo[d] = std::min(lo[d], sub[c][d].cell);
          }
        }
        // S: the hat at the particle itself.
        Axis px[Dim];
        for (int d = 0; d < Dim; ++d) {
          px[d].clear(W[d]);
          const shape::CellPos own = shape::locate(shape::clamp_to_grid(xi[d], g.cells[d]), g.cells[d]);
          shape::ddmp_axis(own, g.inv_dx[d], own.cell - lo[d], px[d]);
        }
        std::array<int, Dim> o{};
        for (int k = 0; k < width; ++k, next_entry<Dim>(o, W)) {
          double s = 1.0;
          for (int a = 0; a < Dim; ++a) s *= px[a].S[o[a]];
          S[k] = s;
        }
        // G, R: the volume-weighted mean of eq. 7.2 over the sub-points (eqs. 4.5-4.6).
        const double w = 1.0 / points;
        for (int c = 0; c < points; ++c) {
          std::array<int, Dim> off;
          for (int d = 0; d < Dim; ++d) {
            off[d] = sub[c][d].cell - lo[d];
            shape::ddmp_axis(sub[c][d], g.inv_dx[d], off[d], ax[d]);
          }
          add_ddmp<Dim>(ax, off, w, W, opt_.alpha, G, &st.R[e]);
        }
        for (int d = 0; d < Dim; ++d) ax[d].first = lo[d];
        break;
      }
    }
    set_nodes<Dim>(g, ax, W, width, &st.node[e]);
  }
  if (factored) shape::mark_smoothing_nodes(g, st, mark_, threads_);
}

template class ShapeEvaluator<1>;
template class ShapeEvaluator<2>;
template class ShapeEvaluator<3>;

}  // namespace mpmx::mpm
