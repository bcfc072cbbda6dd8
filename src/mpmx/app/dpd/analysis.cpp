#include "mpmx/app/dpd/analysis.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <sstream>

#include <fmt/format.h>

#include "mpmx/core/error.hpp"
#include "mpmx/core/units.hpp"
#include "mpmx/io/atomic_file.hpp"

namespace mpmx::app::dpd {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

int grip_index(const System& s, const std::string& name) {
  const int g = s.group_index(name);
  if (g < 0) throw InputError(fmt::format("tensile.grips: \"{}\" is not a rigid group of the deck", name));
  return g;
}

double group_mean_x(const Particles& p, int g) {
  double sum = 0;
  long n = 0;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.group[i] == g) sum += p.x[i], ++n;
  return n > 0 ? sum / n : 0.0;
}

}  // namespace

Recorder::Recorder(const AnalysisSpec& spec, const System& s) : spec_(spec), t0_(s.time()) {
  const Particles& p = s.particles();
  std::int64_t max_id = 0;
  for (auto id : p.id) max_id = std::max(max_id, id);
  x0_.assign(static_cast<std::size_t>(max_id) + 1, kNaN);
  profile_lo_ = std::numeric_limits<double>::infinity(), profile_hi_ = -profile_lo_;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.group[i] != kMobile && !s.groups()[p.group[i]].external) continue;
    x0_[p.id[i]] = p.x[i];
    profile_lo_ = std::min(profile_lo_, p.x[i]), profile_hi_ = std::max(profile_hi_, p.x[i]);
  }
  track_ids_.resize(spec_.tracks.size());
  for (std::size_t t = 0; t < spec_.tracks.size(); ++t) {
    for (std::size_t i = 0; i < p.size(); ++i)
      if (!std::isnan(x0_[p.id[i]]) && p.x[i] >= spec_.tracks[t].lo && p.x[i] < spec_.tracks[t].hi)
        track_ids_[t].push_back(p.id[i]);
    if (track_ids_[t].empty())
      throw InputError(fmt::format("track \"{}\": no particle has x in [{}, {}) A at the run's start",
                                   spec_.tracks[t].name, spec_.tracks[t].lo, spec_.tracks[t].hi));
  }
  length_ = s.domain().length(0);
  area_ = s.domain().length(1) * s.domain().length(2);
  if (!spec_.grips[0].empty()) {
    grip_[0] = grip_index(s, spec_.grips[0]);
    grip_[1] = grip_index(s, spec_.grips[1]);
    sep0_ = group_mean_x(p, grip_[1]) - group_mean_x(p, grip_[0]);
  }
  record(s);
}

std::vector<double> Recorder::displacement(const System& s) const {
  const Particles& p = s.particles();
  std::vector<double> u(x0_.size(), kNaN);
  for (std::size_t i = 0; i < p.size(); ++i) {
    const auto id = static_cast<std::size_t>(p.id[i]);
    if (!std::isnan(x0_[id])) u[id] = p.x[i] - x0_[id];
  }
  return u;
}

void Recorder::record(const System& s) {
  const double t = s.time() - t0_;
  const bool want_profile = spec_.profile_bins > 0 && spec_.profile_every > 0;
  std::vector<double> u;
  if (!spec_.tracks.empty() || want_profile) u = displacement(s);
  if (!spec_.tracks.empty()) {
    const Particles& p = s.particles();
    std::vector<double> vx(x0_.size(), 0.0);
    for (std::size_t i = 0; i < p.size(); ++i) vx[p.id[i]] = p.vx[i];
    std::vector<double> row(spec_.tracks.size()), vrow(spec_.tracks.size());
    for (std::size_t k = 0; k < track_ids_.size(); ++k) {
      double sum = 0, vsum = 0;
      for (auto id : track_ids_[k]) sum += u[id], vsum += vx[id];
      row[k] = sum / static_cast<double>(track_ids_[k].size());
      vrow[k] = vsum / static_cast<double>(track_ids_[k].size());
    }
    track_u_.push_back(std::move(row));
    track_v_.push_back(std::move(vrow));
  }
  if (grip_[0] >= 0) {
    const Particles& p = s.particles();
    const double sep = group_mean_x(p, grip_[1]) - group_mean_x(p, grip_[0]);
    strain_.push_back((sep - sep0_) / length_);
    // The rod pulls the left grip to +x and the right one to -x: tension positive.
    const double f = 0.5 * (s.group_force(grip_[0])[0] - s.group_force(grip_[1])[0]);
    stress_.push_back(f / area_ * units::eV_per_A3_in_GPa);
  }
  times_.push_back(t);
  if (want_profile) {
    // Every profile_every steps: the record count times `every` steps since the start.
    const std::int64_t n = static_cast<std::int64_t>(times_.size()) - 1;
    if ((n * spec_.every) % spec_.profile_every == 0) {
      const int nb = spec_.profile_bins;
      std::vector<double> sum(nb, 0.0), cnt(nb, 0.0);
      const double w = (profile_hi_ - profile_lo_) / nb;
      for (std::size_t id = 0; id < x0_.size(); ++id) {
        if (std::isnan(x0_[id])) continue;
        const int b = std::clamp(static_cast<int>((x0_[id] - profile_lo_) / w), 0, nb - 1);
        sum[b] += u[id], cnt[b] += 1;
      }
      for (int b = 0; b < nb; ++b) sum[b] = cnt[b] > 0 ? sum[b] / cnt[b] : kNaN;
      profile_times_.push_back(t);
      profile_u_.push_back(std::move(sum));
    }
  }
}

void Recorder::save(CheckpointOut& out) const {
  out.numbers({t0_, length_, area_, sep0_, profile_lo_, profile_hi_});
  out.integers({grip_[0], grip_[1]});
  out.numbers(x0_);
  out.integer(static_cast<std::int64_t>(track_ids_.size()));
  for (const auto& ids : track_ids_) out.integers(ids);
  for (const auto* v : {&times_, &strain_, &stress_, &profile_times_}) out.numbers(*v);
  for (const auto* v : {&track_u_, &track_v_, &profile_u_}) out.rows(*v);
}

Recorder Recorder::load(const AnalysisSpec& spec, const System& s, CheckpointIn& in) {
  Recorder r(spec);
  const long long at = in.offset();
  auto refuse = [&](const std::string& why) { return in.refuse(at, fmt::format("the DPD analysis: {}", why)); };
  const auto k = in.numbers();
  if (k.size() != 6) throw refuse("its start is not 6 numbers");
  r.t0_ = k[0], r.length_ = k[1], r.area_ = k[2], r.sep0_ = k[3], r.profile_lo_ = k[4], r.profile_hi_ = k[5];
  const auto grips = in.integers();
  const auto groups = static_cast<std::int64_t>(s.groups().size());
  if (grips.size() != 2 || (grips[0] >= 0) != !spec.grips[0].empty())
    throw refuse("its grips are not the deck's");
  for (int g = 0; g < 2; ++g) {
    if (grips[g] < -1 || grips[g] >= groups) throw refuse(fmt::format("grip group {}", grips[g]));
    r.grip_[g] = static_cast<int>(grips[g]);
  }
  r.x0_ = in.numbers();
  const std::int64_t tracks = in.integer();
  if (tracks != static_cast<std::int64_t>(spec.tracks.size()))
    throw refuse(fmt::format("{} tracks, the deck has {}", tracks, spec.tracks.size()));
  r.track_ids_.resize(spec.tracks.size());
  for (auto& ids : r.track_ids_) {
    ids = in.integers();
    for (auto id : ids)
      if (id < 0 || id >= static_cast<std::int64_t>(r.x0_.size()) || std::isnan(r.x0_[id]))
        throw refuse(fmt::format("track particle {} has no start position", id));
    if (ids.empty()) throw refuse("an empty track");
  }
  for (auto* v : {&r.times_, &r.strain_, &r.stress_, &r.profile_times_}) *v = in.numbers();
  for (auto* v : {&r.track_u_, &r.track_v_, &r.profile_u_}) *v = in.rows();
  const std::size_t records = r.times_.size();
  auto rows_of = [](const std::vector<std::vector<double>>& v, std::size_t n, std::size_t width) {
    if (v.size() != n) return false;
    for (const auto& row : v)
      if (row.size() != width) return false;
    return true;
  };
  const bool grips_on = r.grip_[0] >= 0;
  if (!spec.tracks.empty() && (!rows_of(r.track_u_, records, spec.tracks.size()) ||
                               !rows_of(r.track_v_, records, spec.tracks.size())))
    throw refuse("its track records do not match its times");
  if (grips_on && (r.strain_.size() != records || r.stress_.size() != records))
    throw refuse("its tensile records do not match its times");
  if (!rows_of(r.profile_u_, r.profile_times_.size(), static_cast<std::size_t>(spec.profile_bins)) &&
      !r.profile_times_.empty())
    throw refuse("its profiles do not match the deck's bins");
  return r;
}

double Recorder::onset_time(std::size_t k) const {
  const double sgn = spec_.onset_direction, th = spec_.onset;
  double lowest = sgn * (track_u_.empty() ? 0.0 : track_u_[0][k]);
  for (std::size_t r = 1; r < track_u_.size(); ++r) {
    const double a = sgn * track_u_[r - 1][k] - lowest;
    lowest = std::min(lowest, sgn * track_u_[r - 1][k]);
    const double b = sgn * track_u_[r][k] - lowest;
    if (b >= th) return a < th && b > a ? times_[r - 1] + (times_[r] - times_[r - 1]) * (th - a) / (b - a) : times_[r];
  }
  return kNaN;
}

double Recorder::wave_speed() const {
  if (spec_.wave_speed[0].empty()) return kNaN;
  std::size_t k[2] = {0, 0};
  for (int j = 0; j < 2; ++j) {
    auto it = std::find_if(spec_.tracks.begin(), spec_.tracks.end(),
                           [&](const TrackSpec& t) { return t.name == spec_.wave_speed[j]; });
    k[j] = static_cast<std::size_t>(it - spec_.tracks.begin());
  }
  const double t1 = onset_time(k[0]), t2 = onset_time(k[1]);
  const double x1 = 0.5 * (spec_.tracks[k[0]].lo + spec_.tracks[k[0]].hi);
  const double x2 = 0.5 * (spec_.tracks[k[1]].lo + spec_.tracks[k[1]].hi);
  return (t2 != t1) ? std::abs(x2 - x1) / std::abs(t2 - t1) : kNaN;
}

void Recorder::write(const std::string& dir) const {
  namespace fs = std::filesystem;
  if (!spec_.tracks.empty()) {
    std::ostringstream os;
    os << "time_ps";
    for (const auto& t : spec_.tracks) os << "," << t.name << "_ux_A";
    for (const auto& t : spec_.tracks) os << "," << t.name << "_vx_A_per_ps";
    os << "\n";
    for (std::size_t r = 0; r < times_.size(); ++r) {
      os << fmt::format("{:.6f}", times_[r]);
      for (double v : track_u_[r]) os << fmt::format(",{:.8g}", v);
      for (double v : track_v_[r]) os << fmt::format(",{:.8g}", v);
      os << "\n";
    }
    io::write_file_atomic((fs::path(dir) / "tracks.csv").string(), os.str());
  }
  if (grip_[0] >= 0) {
    std::ostringstream os;
    os << "time_ps,strain,stress_GPa\n";
    for (std::size_t r = 0; r < times_.size(); ++r)
      os << fmt::format("{:.6f},{:.8g},{:.8g}\n", times_[r], strain_[r], stress_[r]);
    io::write_file_atomic((fs::path(dir) / "stress_strain.csv").string(), os.str());
  }
  if (!profile_times_.empty()) {
    std::ostringstream os;
    os << "time_ps,x0_A,ux_A\n";
    const int nb = spec_.profile_bins;
    const double w = (profile_hi_ - profile_lo_) / nb;
    for (std::size_t r = 0; r < profile_times_.size(); ++r)
      for (int b = 0; b < nb; ++b)
        os << fmt::format("{:.6f},{:.6g},{:.8g}\n", profile_times_[r], profile_lo_ + (b + 0.5) * w, profile_u_[r][b]);
    io::write_file_atomic((fs::path(dir) / "profile.csv").string(), os.str());
  }
}

toml::table Recorder::summary() const {
  toml::table t;
  auto finite = [](double v) { return std::isfinite(v) ? v : -1.0; };
  if (!spec_.tracks.empty()) {
    toml::table tr;
    for (std::size_t k = 0; k < spec_.tracks.size(); ++k)
      tr.insert(spec_.tracks[k].name,
                toml::table{{"onset_ps", finite(onset_time(k))},
                            {"final_ux_A", track_u_.empty() ? 0.0 : track_u_.back()[k]},
                            {"particles", static_cast<std::int64_t>(track_ids_[k].size())}});
    t.insert("tracks", tr);
    t.insert("onset_rise_A", spec_.onset);
    t.insert("onset_direction", spec_.onset_direction);
  }
  if (!spec_.wave_speed[0].empty()) t.insert("wave_speed_m_per_s", finite(100.0 * wave_speed()));
  if (grip_[0] >= 0 && !strain_.empty()) {
    t.insert("tensile", toml::table{{"initial_slope_GPa", finite(initial_slope())},
                                    {"slope_strain", toml::array{spec_.slope_strain[0], spec_.slope_strain[1]}},
                                    {"peak_stress_GPa", peak_stress()},
                                    {"strain_at_peak", peak_strain()},
                                    {"final_strain", strain_.back()}});
  }
  return t;
}

double Recorder::initial_slope() const {
  double sx = 0, sy = 0, sxx = 0, sxy = 0, n = 0;
  for (std::size_t r = 0; r < strain_.size(); ++r) {
    if (strain_[r] < spec_.slope_strain[0] || strain_[r] > spec_.slope_strain[1]) continue;
    sx += strain_[r], sy += stress_[r], sxx += strain_[r] * strain_[r], sxy += strain_[r] * stress_[r], n += 1;
  }
  const double den = n * sxx - sx * sx;
  return (n >= 2 && den > 0) ? (n * sxy - sx * sy) / den : kNaN;
}

double Recorder::peak_stress() const {
  return stress_.empty() ? kNaN : *std::max_element(stress_.begin(), stress_.end());
}

double Recorder::peak_strain() const {
  return stress_.empty() ? kNaN : strain_[std::max_element(stress_.begin(), stress_.end()) - stress_.begin()];
}

}  // namespace mpmx::app::dpd
