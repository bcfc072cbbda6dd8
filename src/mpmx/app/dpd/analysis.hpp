#pragma once
// What the seed's figures read off a DPD run (seed 004 sec. 4), recorded during the run:
//  - region tracks (fig. 3) and displacement profiles (fig. 8): app/region_tracks.hpp,
//    shared with the all-atom MD reference of the rod;
//  - the tensile test (fig. 6): engineering strain from the grips' separation over the
//    domain's length, stress from the grips' pair forces over the cross-section.
// The rigid particles are left out of tracks and profiles.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <toml++/toml.h>

#include "mpmx/app/checkpoint_fields.hpp"
#include "mpmx/app/region_tracks.hpp"
#include "mpmx/dpd/system.hpp"

namespace mpmx::app::dpd {

using namespace mpmx::dpd;  // the DPD driver speaks the engine's names

struct AnalysisSpec : TrackSettings {
  std::array<std::string, 2> grips;  // tensile: left and right rigid groups, or empty
  std::array<double, 2> slope_strain{0.0, 0.05};
  double cna_lattice = 0;  // > 0: CNA with this lattice constant in the dump and run.json

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
  Recorder(const AnalysisSpec& spec, RegionTracks tracks) : spec_(spec), tracks_(std::move(tracks)) {}
  void record_grips(const System& s);

  AnalysisSpec spec_;
  RegionTracks tracks_;
  double length_ = 0, area_ = 0;
  int grip_[2] = {-1, -1};
  double sep0_ = 0;
  std::vector<double> strain_, stress_;  // GPa, by record
};

}  // namespace mpmx::app::dpd
