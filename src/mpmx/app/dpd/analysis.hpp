#pragma once
// What the seed's figures read off a DPD run (seed 004 sec. 4), recorded during the run:
//  - region tracks (fig. 3): the mean x displacement and velocity of the particles whose
//    x at the run's start lies in [lo, hi); the onset is the first time the displacement
//    along the wave's direction s (+1 or -1) has risen by `onset` above its lowest value
//    so far, s u(t) - min_{t' <= t} s u(t') >= onset (interpolated between records). The
//    rise above the running minimum, not above the start, because the rod keeps a slow
//    breathing after a short equilibration (the regions drift by a tenth of an Angstrom
//    per ps before the wave comes); a velocity threshold would meet the mean velocity's
//    thermal scatter (0.1-0.2 Angstrom/ps over a few hundred particles). The wave speed is
//    the regions' centre distance over their onsets' difference;
//  - the tensile test (fig. 6): engineering strain from the grips' separation over the
//    domain's length, stress from the grips' pair forces over the cross-section;
//  - displacement profiles (fig. 8): mean x displacement in bins of the start's x.
// The rigid particles are left out of tracks and profiles.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <toml++/toml.h>

#include "mpmx/app/checkpoint_fields.hpp"
#include "mpmx/dpd/system.hpp"

namespace mpmx::app::dpd {

using namespace mpmx::dpd;  // the DPD driver speaks the engine's names

struct TrackSpec {
  std::string name;
  double lo = 0, hi = 0;  // Angstrom, x at the run's start
};

struct AnalysisSpec {
  std::vector<TrackSpec> tracks;
  std::int64_t every = 5;                 // steps between records
  double onset = 0.3;                     // Angstrom of rise
  int onset_direction = 1;                // +1: the wave pushes along +x; -1: along -x
  std::array<std::string, 2> wave_speed;  // two track names, or empty
  std::array<std::string, 2> grips;       // tensile: left and right rigid groups, or empty
  std::array<double, 2> slope_strain{0.0, 0.05};
  int profile_bins = 0;
  std::int64_t profile_every = 0;  // steps
  double cna_lattice = 0;          // > 0: CNA with this lattice constant in the dump and run.json

  bool records() const { return !tracks.empty() || !grips[0].empty() || profile_bins > 0; }
};

class Recorder {
 public:
  // At the run's start (after the equilibration): the reference positions.
  Recorder(const AnalysisSpec& spec, const System& s);
  // One record at the system's current state (time since the start).
  void record(const System& s);
  // tracks.csv, stress_strain.csv, profile.csv as asked (into dir).
  void write(const std::string& dir) const;
  // Figures for run.json: onsets, wave speed, initial slope, peak stress.
  toml::table summary() const;
  double wave_speed() const;  // Angstrom/ps, NaN without the pair or an onset
  // Tensile: least-squares slope of stress on strain over slope_strain, and the peak (GPa).
  double initial_slope() const;
  double peak_stress() const;
  double peak_strain() const;  // the strain at the peak

  // Checkpoint: the run's start it measures from and every record so far. load() gives
  // the recorder of a resumed run (of the deck's spec, on the system `s`), InputError
  // for a state that does not fit them.
  void save(CheckpointOut& out) const;
  static Recorder load(const AnalysisSpec& spec, const System& s, CheckpointIn& in);

 private:
  explicit Recorder(const AnalysisSpec& spec) : spec_(spec) {}
  double onset_time(std::size_t track) const;
  std::vector<double> displacement(const System& s) const;  // x - x0 by particle, NaN rigid

  AnalysisSpec spec_;
  double t0_ = 0, length_ = 0, area_ = 0;
  std::vector<double> x0_;                // by particle id
  std::vector<std::vector<std::int64_t>> track_ids_;
  std::vector<double> times_;
  std::vector<std::vector<double>> track_u_, track_v_;  // per record, per track
  int grip_[2] = {-1, -1};
  double sep0_ = 0;
  std::vector<double> strain_, stress_;  // GPa
  std::vector<double> profile_times_;
  std::vector<std::vector<double>> profile_u_;
  double profile_lo_ = 0, profile_hi_ = 0;
};

}  // namespace mpmx::app::dpd
