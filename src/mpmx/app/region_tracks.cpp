#include "mpmx/app/region_tracks.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <set>
#include <sstream>

#include <fmt/format.h>

#include "mpmx/core/error.hpp"
#include "mpmx/io/atomic_file.hpp"

namespace mpmx::app {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::size_t id_index(std::int64_t id, std::size_t size) {
  if (id < 0 || static_cast<std::size_t>(id) >= size)
    throw RunError(fmt::format("region tracks: particle id {} was not there at the run's start", id));
  return static_cast<std::size_t>(id);
}

}  // namespace

void read_track_settings(io::Section& root, io::Section& an, std::int64_t thermo, TrackSettings& a) {
  std::set<std::string> names;
  for (auto& t : root.tables("track")) {
    TrackSpec s;
    s.name = t.string("name");
    t.check(!s.name.empty() && names.insert(s.name).second, "name", "must be a new, non-empty track name");
    const auto x = t.numbers("x");
    if (x.size() == 2 && x[1] > x[0]) s.lo = x[0], s.hi = x[1];
    else t.check(false, "x", "expected [lower, upper] with upper > lower (Angstrom)");
    a.tracks.push_back(s);
  }
  a.every = an.integer("every", 5, 1, 1000000);
  an.check(thermo % std::max<std::int64_t>(a.every, 1) == 0, "every", "must divide run.thermo");
  a.onset = an.number("onset", 0.3);
  an.positive("onset", a.onset);
  a.onset_direction = an.integer_int("onset_direction", 1, -1, 1);
  an.check(a.onset_direction == 1 || a.onset_direction == -1, "onset_direction",
           "must be 1 (the wave pushes along +x) or -1 (along -x)");
  if (an.has("wave_speed")) {
    const auto w = an.strings("wave_speed", {});
    if (w.size() == 2 && names.count(w[0]) && names.count(w[1]) && w[0] != w[1]) a.wave_speed = {w[0], w[1]};
    else an.check(false, "wave_speed", "expected two different names of [[track]] regions");
  }
  auto pr = root.optional_table("profile");
  if (pr.present()) {
    a.profile_bins = pr.integer_int("bins", 1, 100000);
    a.profile_every = pr.integer("every", 1, std::numeric_limits<std::int64_t>::max());
    pr.check(a.profile_every % std::max<std::int64_t>(a.every, 1) == 0, "every",
             "must be a positive multiple of analysis.every");
  }
}

RegionTracks::RegionTracks(const TrackSettings& settings, const TrackFrame& f,
                           const std::function<bool(std::size_t)>& tracked)
    : spec_(settings), t0_(f.time) {
  std::int64_t max_id = 0;
  for (auto id : f.id) {
    if (id < 0) throw RunError(fmt::format("region tracks: particle id {} is negative", id));
    max_id = std::max(max_id, id);
  }
  x0_.assign(static_cast<std::size_t>(max_id) + 1, kNaN);
  profile_lo_ = std::numeric_limits<double>::infinity(), profile_hi_ = -profile_lo_;
  for (std::size_t i = 0; i < f.id.size(); ++i) {
    if (!tracked(i)) continue;
    x0_[static_cast<std::size_t>(f.id[i])] = f.x[i];
    profile_lo_ = std::min(profile_lo_, f.x[i]), profile_hi_ = std::max(profile_hi_, f.x[i]);
  }
  track_ids_.resize(spec_.tracks.size());
  for (std::size_t t = 0; t < spec_.tracks.size(); ++t) {
    for (std::size_t i = 0; i < f.id.size(); ++i)
      if (!std::isnan(x0_[static_cast<std::size_t>(f.id[i])]) && f.x[i] >= spec_.tracks[t].lo &&
          f.x[i] < spec_.tracks[t].hi)
        track_ids_[t].push_back(f.id[i]);
    if (track_ids_[t].empty())
      throw InputError(fmt::format("track \"{}\": no particle has x in [{}, {}) A at the run's start",
                                   spec_.tracks[t].name, spec_.tracks[t].lo, spec_.tracks[t].hi));
  }
  record(f);
}

void RegionTracks::record(const TrackFrame& f) {
  const double t = f.time - t0_;
  const bool want_profile = spec_.profile_bins > 0 && spec_.profile_every > 0;
  std::vector<double> u, vx;
  if (!spec_.tracks.empty() || want_profile) {
    u.assign(x0_.size(), kNaN);
    vx.assign(x0_.size(), 0.0);
    for (std::size_t i = 0; i < f.id.size(); ++i) {
      const std::size_t id = id_index(f.id[i], x0_.size());
      if (!std::isnan(x0_[id])) u[id] = f.x[i] - x0_[id];
      vx[id] = f.vx[i];
    }
  }
  if (!spec_.tracks.empty()) {
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

double RegionTracks::onset_time(std::size_t k) const {
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

double RegionTracks::wave_speed() const {
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

void RegionTracks::write(const std::string& dir) const {
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

void RegionTracks::summarize(toml::table& t) const {
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
}

void RegionTracks::save(CheckpointOut& out) const {
  out.numbers({t0_, profile_lo_, profile_hi_});
  out.numbers(x0_);
  out.integer(static_cast<std::int64_t>(track_ids_.size()));
  for (const auto& ids : track_ids_) out.integers(ids);
  out.numbers(times_);
  out.numbers(profile_times_);
  for (const auto* v : {&track_u_, &track_v_, &profile_u_}) out.rows(*v);
}

RegionTracks RegionTracks::load(const TrackSettings& spec, CheckpointIn& in, const std::string& what) {
  RegionTracks r(spec);
  const long long at = in.offset();
  auto refuse = [&](const std::string& why) { return in.refuse(at, fmt::format("{}: {}", what, why)); };
  const auto k = in.numbers();
  if (k.size() != 3) throw refuse("its start is not 3 numbers");
  r.t0_ = k[0], r.profile_lo_ = k[1], r.profile_hi_ = k[2];
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
  r.times_ = in.numbers();
  r.profile_times_ = in.numbers();
  for (auto* v : {&r.track_u_, &r.track_v_, &r.profile_u_}) *v = in.rows();
  auto rows_of = [](const std::vector<std::vector<double>>& v, std::size_t n, std::size_t width) {
    if (v.size() != n) return false;
    for (const auto& row : v)
      if (row.size() != width) return false;
    return true;
  };
  if (!spec.tracks.empty() && (!rows_of(r.track_u_, r.times_.size(), spec.tracks.size()) ||
                               !rows_of(r.track_v_, r.times_.size(), spec.tracks.size())))
    throw refuse("its track records do not match its times");
  if (!rows_of(r.profile_u_, r.profile_times_.size(), static_cast<std::size_t>(spec.profile_bins)) &&
      !r.profile_times_.empty())
    throw refuse("its profiles do not match the deck's bins");
  return r;
}

}  // namespace mpmx::app
