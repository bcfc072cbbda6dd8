#include "mpmx/core/input_files.hpp"
#include "mpmx/reference/jet_history.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include <fmt/format.h>

#include "mpmx/core/error.hpp"
#include "mpmx/core/file_text.hpp"
#include "mpmx/io/vtk.hpp"

namespace mpmx::reference {

namespace fs = std::filesystem;

namespace {

std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  if (!in) throw InputError(fmt::format("{} cannot be read", p.string()));
  note_input_file(p.string());  // pinned by a checkpoint
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

struct Bin {
  int ix = 0, iy = 0, atoms = 0;
  double x = 0, y = 0, sxx = 0;
};

// ix,iy,x_A,y_A,atoms,...,sxx_GPa (column 10), as app/md/jet_run.cpp writes them.
std::vector<Bin> read_bins(const fs::path& path) {
  std::ifstream in(path);
  if (!in) throw InputError(fmt::format("direct-MD jet bins {} cannot be read", path.string()));
  note_input_file(path.string());
  std::string line;
  std::getline(in, line);
  if (line.rfind("ix,iy,x_A,y_A,atoms,density_g_cm3,temperature_K,vx_km_s,vy_km_s,sxx_GPa", 0) != 0)
    throw InputError(fmt::format("{}: header {} is not that of a jet bin table", path.string(), quote_excerpt(line)));
  std::vector<Bin> bins;
  int lineno = 1;
  while (std::getline(in, line)) {
    ++lineno;
    if (line.empty()) continue;
    std::istringstream ss(line);
    std::string f[10];
    for (auto& s : f) std::getline(ss, s, ',');
    Bin b;
    try {
      b.ix = std::stoi(f[0]), b.iy = std::stoi(f[1]);
      b.x = std::stod(f[2]), b.y = std::stod(f[3]);
      b.atoms = std::stoi(f[4]);
      b.sxx = std::stod(f[9]);
    } catch (const std::exception&) {
      throw InputError(fmt::format("{}:{}: cannot read {}", path.string(), lineno, quote_excerpt(line)));
    }
    if (b.ix < 0 || b.iy < 0 || b.ix > 1'000'000 || b.iy > 1'000'000)
      throw InputError(fmt::format("{}:{}: bin index out of range", path.string(), lineno));
    // A bin with atoms and no finite stress would drop out of eq. 7.12 and take the
    // comparison with it (a nan in the pooled sums).
    if (b.atoms > 0 && !std::isfinite(b.sxx))
      throw InputError(fmt::format("{}:{}: bin ({}, {}) holds {} atoms and sxx_GPa = {}: not a number the "
                                   "comparison can use",
                                   path.string(), lineno, b.ix, b.iy, b.atoms, f[9]));
    bins.push_back(b);
  }
  if (bins.empty()) throw InputError(fmt::format("{}: no bins", path.string()));
  return bins;
}

}  // namespace

JetHistory JetHistory::read(const std::string& dir) {
  JetHistory h;
  h.dir_ = dir;
  const fs::path d(dir);
  if (!fs::exists(d / "md_bins.pvd"))
    throw InputError(fmt::format("direct-MD jet run {} has no md_bins.pvd (run the direct-MD deck first: "
                                 "mpmx md examples/J1_*.toml --out DIR)",
                                 dir));
  // The piston's face from run.json (our own flat key; no JSON library needed for one number).
  const std::string run = slurp(d / "run.json");
  auto number = [&](const std::string& key) {
    const std::string quoted = "\"" + key + "\"";
    const char* const white = " \t\r\n";
    std::size_t at = run.find(quoted);
    if (at != std::string::npos) at = run.find_first_not_of(white, at + quoted.size());
    if (at != std::string::npos && run[at] == ':') {
      at = run.find_first_not_of(white, at + 1);
      double v = 0;
      if (at != std::string::npos && std::from_chars(run.data() + at, run.data() + run.size(), v).ec == std::errc())
        return v;
    }
    throw InputError(fmt::format("{}/run.json: no jet.{} (not a jet run?)", dir, key));
  };
  h.piston_face_ = number("piston_face_A");
  const double x0 = number("x0_A"), length = number("length_A"), ly = number("ly_A");

  io::vtk::Series series((d / "md_bins.pvd").string());
  try {
    series.restore_up_to(std::numeric_limits<double>::infinity());
  } catch (const std::exception& e) {
    throw InputError(e.what());
  }
  for (const auto& [t, file] : series.entries()) {
    const fs::path csv = d / "bins" / (fs::path(file).stem().string() + ".csv");
    const auto bins = read_bins(csv);
    int nx = 0, ny = 0;
    for (const auto& b : bins) nx = std::max(nx, b.ix + 1), ny = std::max(ny, b.iy + 1);
    if (static_cast<std::size_t>(nx) * ny != bins.size())
      throw InputError(fmt::format("{}: {} bins are not a full {} x {} grid", csv.string(), bins.size(), nx, ny));
    if (h.times_.empty()) {  // the bins cover the sample's length and period (app/md/jet_run.cpp)
      h.nx_ = nx, h.ny_ = ny;
      h.x0_ = x0, h.dx_ = length / nx, h.dy_ = ly / ny;
    } else if (nx != h.nx_ || ny != h.ny_) {
      throw InputError(fmt::format("{}: {} x {} bins, the first record had {} x {}", csv.string(), nx, ny, h.nx_,
                                   h.ny_));
    } else if (t <= h.times_.back()) {
      throw InputError(fmt::format("{}: record times must increase", (d / "md_bins.pvd").string()));
    }
    std::vector<double> s(bins.size(), std::nan(""));
    for (const auto& b : bins)
      if (b.atoms > 0) s[static_cast<std::size_t>(b.ix + nx * b.iy)] = b.sxx;
    h.times_.push_back(t);
    h.sxx_.push_back(std::move(s));
  }
  if (h.times_.empty()) throw InputError(fmt::format("{}/md_bins.pvd lists no records", dir));
  return h;
}

std::size_t JetHistory::nearest(double t) const {
  auto it = std::lower_bound(times_.begin(), times_.end(), t);
  if (it == times_.end()) return times_.size() - 1;
  if (it != times_.begin() && t - *(it - 1) < *it - t) --it;
  return static_cast<std::size_t>(it - times_.begin());
}

bool JetHistory::has(double t) const {
  const double interval = times_.size() > 1 ? times_[1] - times_[0] : 1.0;
  // A record at t, to the rounding of the times written (not the nearest of any distance:
  // a time between records was compared with the nearer one).
  return std::abs(times_[nearest(t)] - t) <= 1e-3 * interval + 1e-9;
}

double JetHistory::sxx(double t, double x, double y) const {
  const double fx = (x - x0_) / dx_;
  if (!(fx >= 0.0) || fx >= nx_) return std::nan("");
  const int ix = static_cast<int>(fx);
  double fy = std::fmod(y / dy_, static_cast<double>(ny_));
  if (fy < 0) fy += ny_;
  const int iy = std::min(static_cast<int>(fy), ny_ - 1);
  return sxx_[nearest(t)][static_cast<std::size_t>(ix + nx_ * iy)];
}

}  // namespace mpmx::reference
