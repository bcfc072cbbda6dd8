#include "mpmx/app/md/ensemble_averages.hpp"

#include <cmath>
#include <fstream>
#include <sstream>
#include <vector>

#include <fmt/format.h>

#include "mpmx/core/error.hpp"

namespace mpmx::app::md {

namespace {

constexpr int kBlocks = 10;

struct Stat {
  double mean = 0, sem = 0;
};

Stat block_stat(const std::vector<double>& x) {
  Stat s;
  const std::size_t n = x.size(), len = n / kBlocks;
  for (double v : x) s.mean += v / static_cast<double>(n);
  if (len == 0) return s;
  std::array<double, kBlocks> m{};
  for (int b = 0; b < kBlocks; ++b) {
    for (std::size_t k = b * len; k < (b + 1) * len; ++k) m[b] += x[k];
    m[b] /= static_cast<double>(len);
  }
  double mb = 0, var = 0;
  for (double v : m) mb += v / kBlocks;
  for (double v : m) var += (v - mb) * (v - mb) / (kBlocks - 1);
  s.sem = std::sqrt(var / kBlocks);
  return s;
}

toml::table entry(const Stat& s, bool with_error) {
  toml::table t{{"mean", s.mean}};
  if (with_error) t.insert("standard_error", s.sem);
  return t;
}

}  // namespace

toml::table ensemble_averages(const std::string& thermo_csv, std::int64_t first_step,
                              const std::array<double, 3>& per_length) {
  std::ifstream in(thermo_csv);
  if (!in) throw SystemError(fmt::format("cannot read {} back for its averages", thermo_csv));
  std::string line;
  std::getline(in, line);  // the header: step,time_ps,pe,ke,etotal,T,sxx,syy,szz,sxy,sxz,syz,lx,ly,lz
  std::vector<std::vector<double>> col(15);
  while (std::getline(in, line)) {
    std::vector<double> v;
    std::stringstream ss(line);
    for (std::string f; std::getline(ss, f, ',');) v.push_back(std::strtod(f.c_str(), nullptr));
    if (v.size() != 15 || v[0] < static_cast<double>(first_step)) continue;
    for (int c = 0; c < 15; ++c) col[c].push_back(v[c]);
  }
  const std::size_t rows = col[0].size();
  const bool with_error = rows >= 2 * kBlocks;
  toml::table out{{"from_step", first_step},
                  {"rows", static_cast<std::int64_t>(rows)},
                  {"method", with_error ? "mean of the thermo rows from from_step on; standard error from 10 block means"
                                        : "mean of the thermo rows from from_step on (fewer than 20: no error given)"}};
  if (rows == 0) return out;
  out.insert("temperature_K", entry(block_stat(col[5]), with_error));
  std::vector<double> p(rows);
  for (std::size_t k = 0; k < rows; ++k) p[k] = -(col[6][k] + col[7][k] + col[8][k]) / 3.0;
  out.insert("pressure_GPa", entry(block_stat(p), with_error));
  const char* names[6] = {"sxx_GPa", "syy_GPa", "szz_GPa", "sxy_GPa", "sxz_GPa", "syz_GPa"};
  for (int c = 0; c < 6; ++c) out.insert(names[c], entry(block_stat(col[6 + c]), with_error));
  const char* lengths[3] = {"lx_A", "ly_A", "lz_A"};
  const char* constants[3] = {"lattice_constant_x_A", "lattice_constant_y_A", "lattice_constant_z_A"};
  for (int d = 0; d < 3; ++d) {
    const Stat l = block_stat(col[12 + d]);
    out.insert(lengths[d], entry(l, with_error));
    out.insert(constants[d], entry({l.mean * per_length[d], l.sem * per_length[d]}, with_error));
  }
  out.insert("potential_energy_per_atom_eV", entry(block_stat(col[2]), with_error));
  return out;
}

}  // namespace mpmx::app::md
