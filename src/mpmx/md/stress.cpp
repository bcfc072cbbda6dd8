#include "mpmx/md/stress.hpp"

#include <algorithm>
#include <cmath>

#include "mpmx/core/units.hpp"

namespace mpmx::md {

namespace {

// Sums per group: mass, momentum, m v v, virial; then the stress of each group.
struct Accum {
  double m = 0, p[3] = {0, 0, 0}, mvv[6] = {0, 0, 0, 0, 0, 0}, w[6] = {0, 0, 0, 0, 0, 0};
  void add(double mass, double vx, double vy, double vz) {
    m += mass;
    p[0] += mass * vx, p[1] += mass * vy, p[2] += mass * vz;
    mvv[0] += mass * vx * vx, mvv[1] += mass * vy * vy, mvv[2] += mass * vz * vz;
    mvv[3] += mass * vx * vy, mvv[4] += mass * vx * vz, mvv[5] += mass * vy * vz;
  }
  Mat3 stress(double volume) const {
    // sum m (v - v~)(v - v~) = sum m v v - M v~ v~, v~ = P / M.
    double k[6];
    const double v[3] = {m > 0 ? p[0] / m : 0, m > 0 ? p[1] / m : 0, m > 0 ? p[2] / m : 0};
    const int a[6] = {0, 1, 2, 0, 0, 1}, b[6] = {0, 1, 2, 1, 2, 2};
    for (int c = 0; c < 6; ++c) k[c] = (mvv[c] - m * v[a[c]] * v[b[c]]) * units::mvv2e;
    double s[6];
    for (int c = 0; c < 6; ++c) s[c] = -(k[c] + w[c]) / volume;
    return {s[0], s[3], s[4], s[3], s[1], s[5], s[4], s[5], s[2]};
  }
};

template <class BinOf>
std::vector<Mat3> binned(const Atoms& atoms, const std::vector<double>& mass,
                         const std::vector<double>& w, int nbins, double bin_volume, BinOf bin_of) {
  std::vector<Accum> acc(nbins);
  for (std::size_t i = 0; i < atoms.size(); ++i) {
    const int b = bin_of(i);
    if (b < 0) continue;
    Accum& a = acc[b];
    a.add(mass[atoms.type[i]], atoms.vx[i], atoms.vy[i], atoms.vz[i]);
    for (int c = 0; c < 6; ++c) a.w[c] += w[6 * i + c];
  }
  std::vector<Mat3> out;
  for (const auto& a : acc) out.push_back(a.stress(bin_volume));
  return out;
}

int index_in(double u, double length, int n) {
  const double f = u / length - std::floor(u / length);  // periodic wrap into [0, 1)
  return std::clamp(static_cast<int>(f * n), 0, n - 1);
}

}  // namespace

Mat3 box_stress(const Atoms& atoms, const std::vector<double>& mass, const Sym6& virial,
                double volume) {
  Accum a;
  for (std::size_t i = 0; i < atoms.size(); ++i) a.add(mass[atoms.type[i]], atoms.vx[i], atoms.vy[i], atoms.vz[i]);
  for (int c = 0; c < 6; ++c) a.w[c] = virial[c];
  return a.stress(volume);
}

std::vector<double> atom_stress(const Atoms& atoms, const std::vector<double>& mass,
                                const std::vector<double>& w, double volume) {
  const std::size_t n = atoms.size();
  std::vector<double> out(6 * n, 0.0);
  if (n == 0) return out;
  Accum all;
  for (std::size_t i = 0; i < n; ++i) all.add(mass[atoms.type[i]], atoms.vx[i], atoms.vy[i], atoms.vz[i]);
  const double u[3] = {all.p[0] / all.m, all.p[1] / all.m, all.p[2] / all.m};
  const double per_atom = volume / static_cast<double>(n);
  const int a[6] = {0, 1, 2, 0, 0, 1}, b[6] = {0, 1, 2, 1, 2, 2};
  for (std::size_t i = 0; i < n; ++i) {
    const double m = mass[atoms.type[i]];
    const double v[3] = {atoms.vx[i] - u[0], atoms.vy[i] - u[1], atoms.vz[i] - u[2]};
    for (int c = 0; c < 6; ++c) out[6 * i + c] = -(m * v[a[c]] * v[b[c]] * units::mvv2e + w[6 * i + c]) / per_atom;
  }
  return out;
}

std::vector<Mat3> slab_stress(const Atoms& atoms, const std::vector<double>& mass,
                              const std::vector<double>& w, const Box& box, int nbins) {
  return binned(atoms, mass, w, nbins, box.volume() / nbins,
                [&](std::size_t i) { return index_in(atoms.x[i], box.lx, nbins); });
}

std::vector<Mat3> slab_stress(const Atoms& atoms, const std::vector<double>& mass,
                              const std::vector<double>& w, const Box& box, int nbins, double x0,
                              double x1) {
  const double width = (x1 - x0) / nbins;
  return binned(atoms, mass, w, nbins, width * box.ly * box.lz, [&](std::size_t i) {
    const double u = (atoms.x[i] - x0) / width;
    return u < 0 || u >= nbins ? -1 : static_cast<int>(u);
  });
}

std::vector<Mat3> column_stress(const Atoms& atoms, const std::vector<double>& mass,
                                const std::vector<double>& w, const Box& box, int nx, int ny) {
  return binned(atoms, mass, w, nx * ny, box.volume() / (nx * ny), [&](std::size_t i) {
    return index_in(atoms.x[i], box.lx, nx) + nx * index_in(atoms.y[i], box.ly, ny);
  });
}

}  // namespace mpmx::md
