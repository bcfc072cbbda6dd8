#include "mpmx/core/input_files.hpp"
#include "mpmx/reference/bar_history.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "mpmx/core/error.hpp"
#include "mpmx/core/file_text.hpp"

namespace mpmx::reference {

BarHistory BarHistory::read(const std::string& path) {
  std::ifstream in(path);
  if (!in)
    throw InputError(fmt::format("direct-MD stress history {} cannot be read (run the direct-MD deck "
                                 "first: mpmx md DECK --out DIR writes DIR/bar_stress.csv)",
                                 path));
  note_input_file(path);  // pinned by a checkpoint
  BarHistory h;
  h.path_ = path;
  std::string line;
  std::getline(in, line);
  if (line.rfind("step,time_ps,bin,x_A,sxx_GPa", 0) != 0)
    throw InputError(fmt::format("{}: header {} is not that of a bar stress table "
                                 "(step,time_ps,bin,x_A,sxx_GPa,...)",
                                 path, quote_excerpt(line)));
  int lineno = 1;
  while (std::getline(in, line)) {
    ++lineno;
    if (line.empty()) continue;
    std::istringstream ss(line);
    std::string f[5];
    for (auto& s : f) std::getline(ss, s, ',');
    double t = 0, sxx = 0;
    long bin = -1;
    try {
      t = std::stod(f[1]);
      bin = std::stol(f[2]);
      sxx = std::stod(f[4]);
    } catch (const std::exception&) {
      throw InputError(fmt::format("{}:{}: cannot read {}", path, lineno, quote_excerpt(line)));
    }
    if (h.times_.empty() || t > h.times_.back() + 1e-9) {
      if (!h.times_.empty() && static_cast<int>(h.sxx_.back().size()) != h.bins_)
        throw InputError(fmt::format("{}:{}: the record before t = {} ps has {} bins, the first had {}", path,
                                     lineno, t, h.sxx_.back().size(), h.bins_));
      h.times_.push_back(t);
      h.sxx_.emplace_back();
    } else if (std::abs(t - h.times_.back()) > 1e-9) {
      throw InputError(fmt::format("{}:{}: time {} ps goes back (rows must be in time order)", path, lineno, t));
    }
    auto& rec = h.sxx_.back();
    if (bin != static_cast<long>(rec.size()))
      throw InputError(fmt::format("{}:{}: bin {} where bin {} was expected", path, lineno, bin, rec.size()));
    rec.push_back(sxx);
    if (h.times_.size() == 1) h.bins_ = static_cast<int>(rec.size());
  }
  if (h.times_.empty() || h.bins_ == 0) throw InputError(fmt::format("{}: no stress records", path));
  return h;
}

std::size_t BarHistory::nearest(double t) const {
  const auto it = std::lower_bound(times_.begin(), times_.end(), t);
  if (it == times_.end()) return times_.size() - 1;
  if (it == times_.begin()) return 0;
  const std::size_t k = static_cast<std::size_t>(it - times_.begin());
  return t - times_[k - 1] < times_[k] - t ? k - 1 : k;
}

bool BarHistory::has(double t) const {
  const std::size_t k = nearest(t);
  const double spacing = times_.size() > 1 ? (times_.back() - times_.front()) / (times_.size() - 1) : 0.0;
  return std::abs(times_[k] - t) <= 0.5 * spacing + 1e-9;
}

double BarHistory::sxx(double t, double xi) const {
  const auto& rec = sxx_[nearest(t)];
  const int b = std::clamp(static_cast<int>(std::floor(xi * bins_)), 0, bins_ - 1);
  return rec[static_cast<std::size_t>(b)];
}

double Eq712::value() const {
  return squared_reference > 0 ? std::sqrt(squared_difference / squared_reference) : 0.0;
}

}  // namespace mpmx::reference
