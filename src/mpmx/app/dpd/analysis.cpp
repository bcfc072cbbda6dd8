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

// The particles the tracks follow: the mobile ones and a concurrent run's continuum points.
std::function<bool(std::size_t)> tracked_of(const System& s) {
  return [&s](std::size_t i) {
    const int g = s.particles().group[i];
    return g == kMobile || s.groups()[g].external;
  };
}

TrackFrame frame_of(const System& s) {
  const Particles& p = s.particles();
  return TrackFrame{s.time(), p.id, p.x, p.vx};
}

}  // namespace

Recorder::Recorder(const AnalysisSpec& spec, const System& s)
    : spec_(spec), tracks_(spec, frame_of(s), tracked_of(s)) {
  length_ = s.domain().length(0);
  area_ = s.domain().length(1) * s.domain().length(2);
  if (!spec_.grips[0].empty()) {
    grip_[0] = grip_index(s, spec_.grips[0]);
    grip_[1] = grip_index(s, spec_.grips[1]);
    sep0_ = group_mean_x(s.particles(), grip_[1]) - group_mean_x(s.particles(), grip_[0]);
    record_grips(s);
  }
}

void Recorder::record(const System& s) {
  tracks_.record(frame_of(s));
  if (grip_[0] >= 0) record_grips(s);
}

void Recorder::record_grips(const System& s) {
  const Particles& p = s.particles();
  const double sep = group_mean_x(p, grip_[1]) - group_mean_x(p, grip_[0]);
  strain_.push_back((sep - sep0_) / length_);
  // The rod pulls the left grip to +x and the right one to -x: tension positive.
  const double f = 0.5 * (s.group_force(grip_[0])[0] - s.group_force(grip_[1])[0]);
  stress_.push_back(f / area_ * units::eV_per_A3_in_GPa);
}

void Recorder::save(CheckpointOut& out) const {
  out.numbers({length_, area_, sep0_});
  out.integers({grip_[0], grip_[1]});
  out.numbers(strain_);
  out.numbers(stress_);
  tracks_.save(out);
}

Recorder Recorder::load(const AnalysisSpec& spec, const System& s, CheckpointIn& in) {
  const long long at = in.offset();
  auto refuse = [&](const std::string& why) { return in.refuse(at, fmt::format("the DPD analysis: {}", why)); };
  const auto k = in.numbers();
  if (k.size() != 3) throw refuse("its start is not 3 numbers");
  const auto grips = in.integers();
  const auto groups = static_cast<std::int64_t>(s.groups().size());
  if (grips.size() != 2 || (grips[0] >= 0) != !spec.grips[0].empty())
    throw refuse("its grips are not the deck's");
  for (int g = 0; g < 2; ++g)
    if (grips[g] < -1 || grips[g] >= groups) throw refuse(fmt::format("grip group {}", grips[g]));
  auto strain = in.numbers();
  auto stress = in.numbers();
  Recorder r(spec, RegionTracks::load(spec, in, "the DPD analysis"));
  r.length_ = k[0], r.area_ = k[1], r.sep0_ = k[2];
  r.grip_[0] = static_cast<int>(grips[0]), r.grip_[1] = static_cast<int>(grips[1]);
  const std::size_t records = r.tracks_.times().size();
  if (r.grip_[0] >= 0 && (strain.size() != records || stress.size() != records))
    throw refuse("its tensile records do not match its times");
  r.strain_ = std::move(strain), r.stress_ = std::move(stress);
  return r;
}

double Recorder::wave_speed() const { return tracks_.wave_speed(); }

void Recorder::write(const std::string& dir) const {
  namespace fs = std::filesystem;
  tracks_.write(dir);
  if (grip_[0] >= 0) {
    const auto& times = tracks_.times();
    std::ostringstream os;
    os << "time_ps,strain,stress_GPa\n";
    for (std::size_t r = 0; r < times.size(); ++r)
      os << fmt::format("{:.6f},{:.8g},{:.8g}\n", times[r], strain_[r], stress_[r]);
    io::write_file_atomic((fs::path(dir) / "stress_strain.csv").string(), os.str());
  }
}

toml::table Recorder::summary() const {
  toml::table t;
  auto finite = [](double v) { return std::isfinite(v) ? v : -1.0; };
  tracks_.summarize(t);
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
