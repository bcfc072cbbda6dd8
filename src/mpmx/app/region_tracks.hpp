#pragma once
// Region tracks of a wave through a rod (seed 004 fig. 3), one implementation for the
// DPD run and its all-atom MD reference, so the two compare line by line:
//  - a track is the mean x displacement and x velocity of the particles (mesoparticles or
//    atoms) whose x at the run's start lies in [lo, hi);
//  - its onset is the first time the displacement along the wave's direction s (+1 or -1)
//    has risen by `onset` above its lowest value so far, s u(t) - min_{t' <= t} s u(t')
//    >= onset (interpolated between records). The rise above the running minimum, not
//    above the start, because a rod keeps a slow breathing after a short equilibration
//    (the regions drift by a tenth of an Angstrom per ps before the wave comes); a
//    velocity threshold would meet the mean velocity's thermal scatter (0.1-0.2
//    Angstrom/ps over a few hundred particles);
//  - the wave speed is two tracks' centre distance over their onsets' difference;
//  - displacement profiles (seed 004 fig. 8): the mean x displacement in bins of the
//    start's x, every `profile_every` steps.
// Particles the caller leaves out at the start (rigid flyers and grips) are never tracked.
#include <array>
#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include <toml++/toml.h>

#include "mpmx/app/checkpoint_fields.hpp"
#include "mpmx/io/deck.hpp"

namespace mpmx::app {

struct TrackSpec {
  std::string name;
  double lo = 0, hi = 0;  // Angstrom, x at the run's start
};

struct TrackSettings {
  std::vector<TrackSpec> tracks;
  std::int64_t every = 5;                 // steps between records
  double onset = 0.3;                     // Angstrom of rise
  int onset_direction = 1;                // +1: the wave pushes along +x; -1: along -x
  std::array<std::string, 2> wave_speed;  // two track names, or empty
  int profile_bins = 0;
  std::int64_t profile_every = 0;  // steps
};

// A deck's [[track]] tables (name, x = [lower, upper]), the track keys of its [analysis]
// table `analysis` (every, which must divide the run's `thermo`; onset, onset_direction,
// wave_speed) and its [profile] (bins, every), every problem named by key.
void read_track_settings(io::Section& root, io::Section& analysis, std::int64_t thermo, TrackSettings& a);

// The particles at one moment, by index: their ids (0 <= id), x and x velocity.
struct TrackFrame {
  double time = 0;  // ps
  std::span<const std::int64_t> id;
  std::span<const double> x, vx;
};

class RegionTracks {
 public:
  // At the run's start: the reference positions of the particles `tracked(i)` accepts,
  // and the first record. InputError when a track holds no particle.
  RegionTracks(const TrackSettings& settings, const TrackFrame& start,
               const std::function<bool(std::size_t)>& tracked);
  // One record (a profile too when its interval has come).
  void record(const TrackFrame& f);

  // tracks.csv and profile.csv as asked (into dir).
  void write(const std::string& dir) const;
  // run.json's figures: per track its onset, final displacement and particle count; the
  // wave speed (m/s) when asked.
  void summarize(toml::table& t) const;
  double onset_time(std::size_t track) const;  // ps since the start, NaN before the rise
  double wave_speed() const;                   // Angstrom/ps, NaN without the pair or an onset
  const std::vector<double>& times() const { return times_; }  // ps since the start, by record

  // Checkpoint: the start and every record so far. load() gives the tracks of a resumed
  // run (of the deck's settings), InputError for a state that does not fit them; `what`
  // names the run in the message ("the DPD analysis").
  void save(CheckpointOut& out) const;
  static RegionTracks load(const TrackSettings& settings, CheckpointIn& in, const std::string& what);

 private:
  explicit RegionTracks(const TrackSettings& settings) : spec_(settings) {}

  TrackSettings spec_;
  double t0_ = 0;
  std::vector<double> x0_;  // by id, NaN untracked
  std::vector<std::vector<std::int64_t>> track_ids_;
  std::vector<double> times_;
  std::vector<std::vector<double>> track_u_, track_v_;  // per record, per track
  std::vector<double> profile_times_;
  std::vector<std::vector<double>> profile_u_;
  double profile_lo_ = 0, profile_hi_ = 0;
};

}  // namespace mpmx::app
