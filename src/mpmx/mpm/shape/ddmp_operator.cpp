#include "mpmx/mpm/shape/ddmp_operator.hpp"

#include <algorithm>
#include <atomic>
#include <cstddef>

#include "mpmx/mpm/active_lines.hpp"
#include "mpmx/mpm/node_runs.hpp"
#include "mpmx/mpm/shape/ddmp.hpp"

namespace mpmx::mpm::shape {

namespace {

constexpr int pow3(int d) { return d == 0 ? 1 : 3 * pow3(d - 1); }

// The 3^d neighbour offsets o (each -1, 0, 1 per axis, x fastest) and their storage steps.
template <int Dim>
struct Neighbourhood {
  static constexpr int n = pow3(Dim);
  std::array<std::array<int, Dim>, n> o;
  std::array<std::ptrdiff_t, n> step;
  explicit Neighbourhood(const Grid<Dim>& g) {
    for (int c = 0; c < n; ++c) {
      int cc = c;
      step[c] = 0;
      for (int a = 0; a < Dim; ++a) {
        o[c][a] = cc % 3 - 1;
        cc /= 3;
        step[c] += static_cast<std::ptrdiff_t>(o[c][a]) * g.stride[a];
      }
    }
  }
};

// Storage index along each axis of node storage index i.
template <int Dim>
std::array<int, Dim> axis_indices(const Grid<Dim>& g, std::size_t i) {
  std::array<int, Dim> s;
  for (int a = 0; a < Dim; ++a)
    s[a] = static_cast<int>(i / static_cast<std::size_t>(g.stride[a]) %
                            static_cast<std::size_t>(g.cells[a] + 1 + 2 * Grid<Dim>::ghost));
  return s;
}

// Storage indices along each axis of line l's nodes (x left to the caller).
template <int Dim>
std::array<int, Dim> axis_indices_of_line(const Grid<Dim>& g, std::size_t l) {
  auto s = g.line_first(l);
  for (int a = 0; a < Dim; ++a) s[a] += Grid<Dim>::ghost;
  return s;
}

// Calls f(storage index, storage indices along each axis) for every marked node of the
// grid's active lines; lines on the threads, so one writer per node.
template <int Dim, class F>
void for_each_marked(const Grid<Dim>& g, const std::uint8_t* mark, int threads, F&& f) {
  for_each_range(g, g.active_lo, g.active_hi, threads, [&](std::size_t l, std::size_t i0, int lo, int hi) {
    auto s = axis_indices_of_line(g, l);
    for (int x = lo; x <= hi; ++x) {
      const std::size_t i = i0 + static_cast<std::size_t>(x);
      if (!mark[i]) continue;
      s[0] = x + Grid<Dim>::ghost;
      f(i, s);
    }
  });
}

// K^d_{j, j+o} for every d, from node j's axis indices sj: D along d, M / V across.
template <int Dim>
void row_entries(const Stencil<Dim>& st, const std::array<int, Dim>& sj, const std::array<int, Dim>& o,
                 double* K) {
  double kd[Dim], kb[Dim];
  for (int a = 0; a < Dim; ++a) {
    const std::size_t r = 3 * static_cast<std::size_t>(sj[a]) + static_cast<std::size_t>(o[a] + 1);
    kd[a] = (*st.smooth)[a].d3[r];
    kb[a] = (*st.smooth)[a].b3[r];
  }
  for (int d = 0; d < Dim; ++d) {
    double k = kd[d];
    for (int a = 0; a < Dim; ++a)
      if (a != d) k *= kb[a];
    K[d] = k;
  }
}

}  // namespace

template <int Dim>
void mark_smoothing_nodes(const Grid<Dim>& g, Stencil<Dim>& st, std::vector<std::uint8_t>& scratch, int threads) {
  const std::size_t n = g.storage;
  st.smooth_marks.resize(2 * n);
  scratch.resize(n);
  std::uint8_t* touched = st.smooth_marks.data();
  std::uint8_t* reach = touched + n;
#pragma omp parallel for schedule(static) num_threads(threads) if (threads > 1)
  for (std::size_t i = 0; i < n; ++i) touched[i] = 0;
  // Points sharing a node mark it alike: relaxed atomic stores of the same value.
#pragma omp parallel for schedule(static) num_threads(threads) if (threads > 1)
  for (std::size_t e = 0; e < st.node.size(); ++e)
    std::atomic_ref<std::uint8_t>(touched[st.node[e]]).store(1, std::memory_order_relaxed);
  // The reach: the 3^d box around every touched node. The dilation swaps its two arrays
  // once per axis, so starting from the one that makes the result land in `reach`.
  std::uint8_t* start = Dim % 2 == 1 ? scratch.data() : reach;
  std::uint8_t* other = Dim % 2 == 1 ? reach : scratch.data();
#pragma omp parallel for schedule(static) num_threads(threads) if (threads > 1)
  for (std::size_t i = 0; i < n; ++i) start[i] = touched[i];
  dilate_marks(g, start, other, threads);
}

namespace {

// The operator's nonzero entries for a row of the grid's interior (both neighbours on
// every axis, so every interior row is the same), in the order row_entries visits them:
// offset c, then d. Skipping the zeros (D's centre) keeps each sum's order and bits.
template <int Dim>
struct InteriorRow {
  std::vector<int> c, d;
  std::vector<double> K;
  InteriorRow(const Stencil<Dim>& st, const Grid<Dim>& g, const Neighbourhood<Dim>& nb) {
    std::array<int, Dim> s;
    for (int a = 0; a < Dim; ++a) s[a] = Grid<Dim>::ghost + std::min(1, g.cells[a] - 1);  // grid index 1
    for (int k = 0; k < nb.n; ++k) {
      double Kd[Dim];
      row_entries<Dim>(st, s, nb.o[k], Kd);
      for (int e = 0; e < Dim; ++e)
        if (Kd[e] != 0.0) c.push_back(k), d.push_back(e), K.push_back(Kd[e]);
    }
  }
};

// Whether grid index t along each axis lies at least `margin` nodes inside the grid.
template <int Dim>
bool inside(const Grid<Dim>& g, const std::type_identity_t<std::array<int, Dim>>& s, int margin) {
  for (int a = 0; a < Dim; ++a) {
    const int t = s[a] - Grid<Dim>::ghost;
    if (t < margin || t > g.cells[a] - margin) return false;
  }
  return true;
}

}  // namespace

template <int Dim>
void add_smoothed_force(Grid<Dim>& g, const Stencil<Dim>& st, int threads) {
  const Neighbourhood<Dim> nb(g);
  const InteriorRow<Dim> row(st, g, nb);
  const auto& T = g.smooth_stress;
  const std::uint8_t* touched = st.smooth_marks.data();
  const std::uint8_t* reach = touched + g.storage;
  // Each node of the reach gathers from its neighbours j = i - o the entry K^d_{j, i}:
  // one writer per node, the same sum in the same order for any thread count. A node two
  // inside the grid has only interior rows around it.
  for_each_marked(g, reach, threads, [&](std::size_t i, const std::array<int, Dim>& si) {
    double f[Dim] = {};
    if (inside(g, si, 2)) {
      for (std::size_t t = 0; t < row.K.size(); ++t) {
        const std::size_t j = static_cast<std::size_t>(static_cast<std::ptrdiff_t>(i) - nb.step[row.c[t]]);
        const int d = row.d[t];
        for (int a = 0; a < Dim; ++a) f[a] += T[a * Dim + d][j] * row.K[t];
      }
    } else {
      for (int c = 0; c < nb.n; ++c) {
        std::array<int, Dim> sj, o;
        for (int a = 0; a < Dim; ++a) {
          o[a] = nb.o[c][a];
          sj[a] = si[a] - o[a];
        }
        const std::size_t j = static_cast<std::size_t>(static_cast<std::ptrdiff_t>(i) - nb.step[c]);
        double K[Dim];
        row_entries<Dim>(st, sj, o, K);
        for (int a = 0; a < Dim; ++a)
          for (int d = 0; d < Dim; ++d) f[a] += T[a * Dim + d][j] * K[d];
      }
    }
    for (int a = 0; a < Dim; ++a) g.force[a][i] -= f[a];
  });
  // T back to zero where the points put it.
  for_each_marked(g, touched, threads, [&g](std::size_t i, const std::array<int, Dim>&) {
    for (int c = 0; c < Dim * Dim; ++c) g.smooth_stress[c][i] = 0.0;
  });
}

namespace {

// H^{ab}_j = sum_i K^b_ji v(a, i) at the stencil's nodes, one writer per node.
template <int Dim, class Velocity>
void smoothed_gradient_of(const Stencil<Dim>& st, Velocity v, Grid<Dim>& g, int threads) {
  for (auto& h : g.smooth_gradient)
    if (h.size() != g.storage) h.assign(g.storage, 0.0);
  const Neighbourhood<Dim> nb(g);
  const InteriorRow<Dim> row(st, g, nb);
  const std::uint8_t* touched = st.smooth_marks.data();
  const std::size_t last = g.storage;
  for_each_marked(g, touched, threads, [&](std::size_t j, const std::array<int, Dim>& sj) {
    double H[Dim][Dim] = {};
    if (inside(g, sj, 1)) {  // an interior row
      for (std::size_t t = 0; t < row.K.size(); ++t) {
        const std::size_t i = static_cast<std::size_t>(static_cast<std::ptrdiff_t>(j) + nb.step[row.c[t]]);
        const int b = row.d[t];
        for (int a = 0; a < Dim; ++a) H[a][b] += row.K[t] * v(a, i);
      }
    } else {
      for (int c = 0; c < nb.n; ++c) {
        const std::ptrdiff_t i = static_cast<std::ptrdiff_t>(j) + nb.step[c];
        if (i < 0 || static_cast<std::size_t>(i) >= last) continue;  // a clamped ghost's row is zero
        double K[Dim];
        row_entries<Dim>(st, sj, nb.o[c], K);
        for (int a = 0; a < Dim; ++a) {
          const double va = v(a, static_cast<std::size_t>(i));
          for (int b = 0; b < Dim; ++b) H[a][b] += K[b] * va;
        }
      }
    }
    for (int a = 0; a < Dim; ++a)
      for (int b = 0; b < Dim; ++b) g.smooth_gradient[a * Dim + b][j] = H[a][b];
  });
}

}  // namespace

template <int Dim>
void smoothed_gradient(const Stencil<Dim>& st, const std::type_identity_t<std::array<const double*, Dim>>& v,
                       Grid<Dim>& g, int threads) {
  smoothed_gradient_of(st, [&v](int a, std::size_t i) { return v[a][i]; }, g, threads);
}

template <int Dim>
void smoothed_gradient(const Stencil<Dim>& st, const std::type_identity_t<std::array<const double*, Dim>>& vL,
                       const std::type_identity_t<std::array<const double*, Dim>>& vn, VelocityWeights w,
                       Grid<Dim>& g, int threads) {
  smoothed_gradient_of(st, [&](int a, std::size_t i) { return w.L * vL[a][i] + w.n * vn[a][i]; }, g, threads);
}

template <int Dim>
Stencil<Dim> expanded(const Stencil<Dim>& st, const Grid<Dim>& g) {
  if (!st.smoothed()) return st;
  const std::size_t n = st.width > 0 ? st.node.size() / static_cast<std::size_t>(st.width) : 0;
  std::array<int, Dim> W, X;
  int wide = 1;
  for (int a = 0; a < Dim; ++a) {
    W[a] = Dim == 1 ? st.width : st.box[a];
    X[a] = W[a] + 2;
    wide *= X[a];
  }
  Stencil<Dim> out;
  out.reset(n, wide);
  out.box = X;
  const Neighbourhood<Dim> nb(g);
  for (std::size_t q = 0; q < n; ++q) {
    const std::size_t e0 = q * static_cast<std::size_t>(st.width), x0 = q * static_cast<std::size_t>(wide);
    const auto first = axis_indices(g, static_cast<std::size_t>(st.node[e0]));  // a box never starts clamped
    for (int k = 0; k < wide; ++k) {  // the widened box's nodes
      std::array<int, Dim> idx;
      int kk = k;
      for (int a = 0; a < Dim; ++a) {
        idx[a] = first[a] - Grid<Dim>::ghost - 1 + kk % X[a];
        kk /= X[a];
      }
      out.node[x0 + k] = static_cast<int>(g.index_clamped(idx));
    }
    for (int k = 0; k < st.width; ++k) {
      const std::size_t e = e0 + k;
      std::array<int, Dim> ok, sj;
      int kk = k, at = 0, stride = 1;
      bool inside = true;
      for (int a = 0; a < Dim; ++a) {
        ok[a] = kk % W[a];
        kk /= W[a];
        at += (ok[a] + 1) * stride;
        stride *= X[a];
        sj[a] = first[a] + ok[a];
        inside = inside && sj[a] <= g.cells[a] + 2 * Grid<Dim>::ghost;
      }
      out.S[x0 + at] += st.S[e];
      for (int d = 0; d < Dim; ++d) out.G[d][x0 + at] += st.G[d][e];
      if (!inside || st.R[e] == 0.0) continue;
      for (int c = 0; c < nb.n; ++c) {
        double K[Dim];
        row_entries<Dim>(st, sj, nb.o[c], K);
        int to = 0;
        stride = 1;
        for (int a = 0; a < Dim; ++a) {
          to += (ok[a] + 1 + nb.o[c][a]) * stride;
          stride *= X[a];
        }
        for (int d = 0; d < Dim; ++d) out.G[d][x0 + to] += st.R[e] * K[d];
      }
    }
  }
  return out;
}

#define MPMX_DDMP_OPERATOR(D)                                                                                  \
  template void mark_smoothing_nodes<D>(const Grid<D>&, Stencil<D>&, std::vector<std::uint8_t>&, int);             \
  template void add_smoothed_force<D>(Grid<D>&, const Stencil<D>&, int);                                       \
  template void smoothed_gradient<D>(const Stencil<D>&, const std::array<const double*, D>&, Grid<D>&, int);   \
  template void smoothed_gradient<D>(const Stencil<D>&, const std::array<const double*, D>&,                   \
                                     const std::array<const double*, D>&, VelocityWeights, Grid<D>&, int);     \
  template Stencil<D> expanded<D>(const Stencil<D>&, const Grid<D>&);
MPMX_DDMP_OPERATOR(1)
MPMX_DDMP_OPERATOR(2)
MPMX_DDMP_OPERATOR(3)
#undef MPMX_DDMP_OPERATOR

}  // namespace mpmx::mpm::shape
