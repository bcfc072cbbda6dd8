#include "mpmx/particles/oriented_lattice.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <numeric>
#include <tuple>
#include <utility>

#include <fmt/format.h>

#include "mpmx/core/error.hpp"

namespace mpmx::particles {

namespace {

using V3 = std::array<double, 3>;

// The conventional cell: its sites (fractions of the cell) and its lattice translations
// within the cell (the Bravais points: centring vectors, the origin first).
struct Cell {
  std::vector<V3> sites, centring;
  std::vector<int> kinds;  // each site's type offset (empty: all 0)
};

Cell conventional_cell(LatticeStyle s) {
  switch (s) {
    case LatticeStyle::fcc:
      return {{{0, 0, 0}, {0.5, 0.5, 0}, {0.5, 0, 0.5}, {0, 0.5, 0.5}},
              {{0, 0, 0}, {0.5, 0.5, 0}, {0.5, 0, 0.5}, {0, 0.5, 0.5}},
              {}};
    case LatticeStyle::bcc:
      return {{{0, 0, 0}, {0.5, 0.5, 0.5}}, {{0, 0, 0}, {0.5, 0.5, 0.5}}, {}};
    case LatticeStyle::b2:  // simple cubic with a two-site basis
      return {{{0, 0, 0}, {0.5, 0.5, 0.5}}, {{0, 0, 0}}, {0, 1}};
    case LatticeStyle::hcp:  // LAMMPS's basis (lattice.cpp), two Bravais points
      return {{{0, 0, 0}, {0.5, 0.5, 0}, {0.5, 5.0 / 6.0, 0.5}, {0, 1.0 / 3.0, 0.5}}, {{0, 0, 0}, {0.5, 0.5, 0}}, {}};
  }
  return {};
}

V3 cell_lengths(const LatticeSpec& s) {
  const double a = s.constant;
  if (s.style == LatticeStyle::hcp) return {a, std::sqrt(3.0) * a, s.c_over_a * a};
  return {a, a, a};
}

std::string row_text(const std::array<int, 3>& v) { return fmt::format("[{},{},{}]", v[0], v[1], v[2]); }

long dot(const std::array<int, 3>& u, const std::array<int, 3>& v) {
  return long{u[0]} * v[0] + long{u[1]} * v[1] + long{u[2]} * v[2];
}

bool is_translation(const V3& t, const Cell& cell) {
  for (const V3& c : cell.centring) {
    bool whole = true;
    for (int k = 0; k < 3; ++k) whole = whole && std::abs(t[k] - c[k] - std::round(t[k] - c[k])) < 1e-12;
    if (whole) return true;
  }
  return false;
}

// The shortest translation along `d` (its fractions of the cell): half or all of d over
// the gcd of its entries (every lattice here has its points at halves of the cell).
V3 edge_translation(const std::array<int, 3>& d, const Cell& cell) {
  const int g = std::gcd(std::gcd(std::abs(d[0]), std::abs(d[1])), std::abs(d[2]));
  const V3 half = {0.5 * d[0] / g, 0.5 * d[1] / g, 0.5 * d[2] / g};
  if (is_translation(half, cell)) return half;
  return {2 * half[0], 2 * half[1], 2 * half[2]};
}

// The tile's three edges in fractions of the cell, and the cells its volume holds (the
// edges are orthogonal: their determinant).
std::array<V3, 3> tile_edges(const LatticeSpec& spec, const Cell& cell) {
  return {edge_translation(spec.orient[0], cell), edge_translation(spec.orient[1], cell),
          edge_translation(spec.orient[2], cell)};
}
double cells_in(const std::array<V3, 3>& t) {
  return std::abs(t[0][0] * (t[1][1] * t[2][2] - t[1][2] * t[2][1]) -
                  t[0][1] * (t[1][0] * t[2][2] - t[1][2] * t[2][0]) +
                  t[0][2] * (t[1][0] * t[2][1] - t[1][1] * t[2][0]));
}

}  // namespace

LatticeStyle lattice_style(const std::string& name) {
  if (name == "bcc") return LatticeStyle::bcc;
  if (name == "hcp") return LatticeStyle::hcp;
  if (name == "b2") return LatticeStyle::b2;
  if (name == "fcc") return LatticeStyle::fcc;
  throw InputError(fmt::format("lattice type \"{}\": expected fcc, bcc, hcp or b2", name));
}

const char* lattice_name(LatticeStyle s) {
  switch (s) {
    case LatticeStyle::bcc: return "bcc";
    case LatticeStyle::hcp: return "hcp";
    case LatticeStyle::b2: return "b2";
    case LatticeStyle::fcc: break;
  }
  return "fcc";
}

std::string orient_problem(const LatticeSpec& spec) {
  const Orient& o = spec.orient;
  static const char* axis[3] = {"x", "y", "z"};
  for (int d = 0; d < 3; ++d)
    if (o[d] == std::array<int, 3>{0, 0, 0}) return fmt::format("the {} direction is the zero vector", axis[d]);
  if (spec.style == LatticeStyle::hcp)
    for (int d = 0; d < 3; ++d)
      if ((o[d][0] != 0) + (o[d][1] != 0) + (o[d][2] != 0) != 1)
        return fmt::format(
            "the {} direction {} is off the hcp cell's axes ([1,0,0] = a1 [2-1-10], [0,1,0] = [01-10], [0,0,1] = "
            "c [0001]), along which alone a periodic box tiles the crystal (sqrt 3 and c/a are irrational)",
            axis[d], row_text(o[d]));
  for (int d = 0; d < 3; ++d)
    for (int e = d + 1; e < 3; ++e)
      if (dot(o[d], o[e]) != 0)
        return fmt::format("the {} and {} directions {} and {} are not orthogonal (dot product {})", axis[d], axis[e],
                           row_text(o[d]), row_text(o[e]), dot(o[d], o[e]));
  const long det = o[0][0] * (long{o[1][1]} * o[2][2] - long{o[1][2]} * o[2][1]) -
                   o[0][1] * (long{o[1][0]} * o[2][2] - long{o[1][2]} * o[2][0]) +
                   o[0][2] * (long{o[1][0]} * o[2][1] - long{o[1][1]} * o[2][0]);
  if (det < 0)
    return fmt::format("{} x {} is opposite to {}: the set is left-handed (reverse one direction)", row_text(o[0]),
                       row_text(o[1]), row_text(o[2]));
  if (const double atoms = lattice_tile_atoms(spec); !(atoms <= static_cast<double>(kMaxTileAtoms)))
    return fmt::format("{}, {} and {} repeat in a periodic tile of {:.0f} atoms, more than the {} a tile may hold "
                       "(smaller Miller indices tile a smaller box)",
                       row_text(o[0]), row_text(o[1]), row_text(o[2]), atoms, kMaxTileAtoms);
  return {};
}

double lattice_tile_atoms(const LatticeSpec& spec) {
  for (const auto& d : spec.orient)
    if (d == std::array<int, 3>{0, 0, 0}) return 0.0;
  const Cell cell = conventional_cell(spec.style);
  return std::round(cells_in(tile_edges(spec, cell)) * static_cast<double>(cell.sites.size()));
}

double nearest_neighbour_ratio(const LatticeSpec& spec) {
  switch (spec.style) {
    case LatticeStyle::fcc: return 1.0 / std::sqrt(2.0);
    case LatticeStyle::bcc:
    case LatticeStyle::b2: return std::sqrt(3.0) / 2.0;
    case LatticeStyle::hcp: return std::min(1.0, std::sqrt(1.0 / 3.0 + 0.25 * spec.c_over_a * spec.c_over_a));
  }
  return 1.0;
}

LatticeTile lattice_tile(const LatticeSpec& spec) {
  if (const std::string why = orient_problem(spec); !why.empty()) throw InputError("lattice orient: " + why);
  if (!(spec.constant > 0) || (spec.style == LatticeStyle::hcp && !(spec.c_over_a > 0)))
    throw InputError(fmt::format("{} lattice: a = {}, c/a = {}: both must be positive", lattice_name(spec.style),
                                 spec.constant, spec.c_over_a));
  const Cell cell = conventional_cell(spec.style);
  const V3 L = cell_lengths(spec);
  const std::array<V3, 3> t = tile_edges(spec, cell);  // in fractions of the cell
  LatticeTile tile;
  for (int d = 0; d < 3; ++d) {
    double sq = 0;
    for (int k = 0; k < 3; ++k) sq += t[d][k] * L[k] * t[d][k] * L[k];
    tile.length[d] = std::sqrt(sq);
  }
  // Cells the tile's volume holds, times the sites of each (orient_problem bounds it).
  tile.atoms = std::llround(lattice_tile_atoms(spec));
  // Every site of the cells that overlap the tile, kept where its tile coordinates lie in
  // [0, 1); a coordinate within 1e-9 of a whole number is that number, so that a site on
  // a face is kept on one side only.
  int lo[3], hi[3];
  for (int k = 0; k < 3; ++k) {
    double mn = 0, mx = 0;
    for (int s = 1; s < 8; ++s) {
      double c = 0;
      for (int d = 0; d < 3; ++d)
        if (s >> d & 1) c += t[d][k];
      mn = std::min(mn, c), mx = std::max(mx, c);
    }
    lo[k] = static_cast<int>(std::floor(mn)) - 1, hi[k] = static_cast<int>(std::ceil(mx)) + 1;
  }
  double tt[3];
  for (int d = 0; d < 3; ++d) {
    tt[d] = 0;
    for (int k = 0; k < 3; ++k) tt[d] += t[d][k] * L[k] * t[d][k] * L[k];
  }
  struct Site {
    V3 f;
    int kind;
  };
  std::vector<Site> found;
  found.reserve(static_cast<std::size_t>(tile.atoms));
  // A long skewed tile's bounding box holds thousands of times the tile's cells: along the
  // third cell axis only the cells whose sites can lie in the tile are visited (each tile
  // coordinate is linear in k; a cell's margin each side covers the rounding).
  auto k_range = [&](double i, double j, const V3& b) {
    int k0 = lo[2], k1 = hi[2];
    for (int d = 0; d < 3 && k0 <= k1; ++d) {
      const double base = ((i + b[0]) * L[0] * t[d][0] * L[0] + (j + b[1]) * L[1] * t[d][1] * L[1] +
                           b[2] * L[2] * t[d][2] * L[2]) / tt[d];
      const double slope = L[2] * t[d][2] * L[2] / tt[d];
      if (slope == 0) {
        if (base < -1e-6 || base > 1 + 1e-6) k1 = k0 - 1;
        continue;
      }
      double a = -base / slope, e = (1 - base) / slope;
      if (a > e) std::swap(a, e);
      k0 = std::max(k0, static_cast<int>(std::clamp(std::floor(a) - 1, double(lo[2]), double(hi[2]) + 1)));
      k1 = std::min(k1, static_cast<int>(std::clamp(std::ceil(e) + 1, double(lo[2]) - 1, double(hi[2]))));
    }
    return std::pair<int, int>{k0, k1};
  };
  for (int i = lo[0]; i <= hi[0]; ++i)
    for (int j = lo[1]; j <= hi[1]; ++j)
      for (std::size_t site = 0; site < cell.sites.size(); ++site) {
        const auto [k0, k1] = k_range(i, j, cell.sites[site]);
        for (int k = k0; k <= k1; ++k) {
          const V3& b = cell.sites[site];
          const V3 p = {i + b[0], j + b[1], k + b[2]};
          V3 f;
          bool inside = true;
          for (int d = 0; d < 3 && inside; ++d) {
            double num = 0;  // the site along edge d over the edge's length squared
            for (int c = 0; c < 3; ++c) num += p[c] * L[c] * t[d][c] * L[c];
            f[d] = num / tt[d];
            if (std::abs(f[d] - std::round(f[d])) < 1e-9) f[d] = std::round(f[d]);
            inside = f[d] >= 0 && f[d] < 1;
          }
          if (inside) found.push_back({f, cell.kinds.empty() ? 0 : cell.kinds[site]});
        }
      }
  std::sort(found.begin(), found.end(), [](const Site& u, const Site& v) {
    return std::tie(u.f[2], u.f[1], u.f[0]) < std::tie(v.f[2], v.f[1], v.f[0]);
  });
  for (const Site& x : found) tile.sites.push_back(x.f), tile.kinds.push_back(x.kind);
  if (static_cast<std::int64_t>(tile.sites.size()) != tile.atoms)
    throw RunError(fmt::format("{} lattice tile: found {} sites for {} atoms", lattice_name(spec.style),
                               tile.sites.size(), tile.atoms));
  return tile;
}

Crystal oriented_crystal(const LatticeSpec& spec, const std::array<int, 3>& tiles, double strain_x, int type) {
  if (spec.plain_fcc()) return fcc(tiles[0], tiles[1], tiles[2], spec.constant, strain_x, type);
  const LatticeTile tile = lattice_tile(spec);
  if (tiles[0] < 1 || tiles[1] < 1 || tiles[2] < 1 || !(strain_x > -1.0))
    throw InputError(fmt::format("{} lattice: tiles {}x{}x{}, strain {}: need tiles >= 1, strain > -1",
                                 lattice_name(spec.style), tiles[0], tiles[1], tiles[2], strain_x));
  Crystal c;
  const double sx = 1.0 + strain_x;
  const V3& L = tile.length;
  c.box.lx = tiles[0] * L[0] * sx;
  c.box.ly = tiles[1] * L[1];
  c.box.lz = tiles[2] * L[2];
  std::int64_t id = 1;
  for (int k = 0; k < tiles[2]; ++k)
    for (int j = 0; j < tiles[1]; ++j)
      for (int i = 0; i < tiles[0]; ++i)
        for (std::size_t s = 0; s < tile.sites.size(); ++s) {
          const V3& f = tile.sites[s];
          c.atoms.push_back((i + f[0]) * L[0] * sx, (j + f[1]) * L[1], (k + f[2]) * L[2], type + tile.kinds[s], id++);
        }
  return c;
}

}  // namespace mpmx::particles
