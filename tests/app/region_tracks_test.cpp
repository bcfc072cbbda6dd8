// Region tracks (app/region_tracks.hpp), the one implementation of the DPD run and its
// all-atom MD reference: a step wave of known speed over a row of particles that also
// drift slowly (a rod's breathing) gives the onsets and the speed; a checkpoint's tracks
// give back every figure; an empty region is refused by name.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <vector>

#include "mpmx/app/region_tracks.hpp"
#include "mpmx/core/error.hpp"

using namespace mpmx;
using namespace mpmx::app;

namespace {

// 200 particles at x = 0, 0.5, ..., 99.5 (ids 1..200; id 0 a rigid one left out); at time
// t each has moved by 1 Angstrom once the front x_f = c t has passed it, less a drift of
// 0.05 t Angstrom.
struct Row {
  std::vector<std::int64_t> id;
  std::vector<double> x0, x, vx;
  Row() {
    id.push_back(0), x0.push_back(-5.0);
    for (int i = 0; i < 200; ++i) id.push_back(i + 1), x0.push_back(0.5 * i);
    x = x0, vx.assign(x0.size(), 0.0);
  }
  TrackFrame at(double t, double c) {
    for (std::size_t i = 1; i < x0.size(); ++i) x[i] = x0[i] + (x0[i] < c * t ? 1.0 : 0.0) - 0.05 * t;
    return TrackFrame{t, id, x, vx};
  }
};

TrackSettings two_regions() {
  TrackSettings s;
  s.tracks = {{"near", 10.0, 16.0}, {"far", 60.0, 66.0}};
  s.every = 1;
  s.onset = 0.3;
  s.wave_speed = {"near", "far"};
  s.profile_bins = 10;
  s.profile_every = 50;
  return s;
}

}  // namespace

TEST(RegionTracks, OnsetsAndSpeedOfAStepWaveThroughADriftingRow) {
  Row row;
  const double c = 25.0;  // Angstrom/ps
  RegionTracks tr(two_regions(), row.at(0.0, c), [](std::size_t i) { return i > 0; });
  for (int k = 1; k <= 400; ++k) tr.record(row.at(0.01 * k, c));
  // A region's mean has risen 0.3 above its (drifting) lowest once 30% of its particles are
  // passed: 10.0 .. 11.0 of near (3 of 12 at 0.5 spacing is 25%, 4 is 33%: the front at 11.5).
  EXPECT_NEAR(tr.onset_time(0), 11.5 / c, 0.011);
  EXPECT_NEAR(tr.onset_time(1), 61.5 / c, 0.011);
  EXPECT_NEAR(tr.wave_speed(), c, 0.02 * c);
  toml::table t;
  tr.summarize(t);
  EXPECT_NEAR(t["wave_speed_m_per_s"].value_or(0.0), 100.0 * tr.wave_speed(), 1e-9);
  EXPECT_EQ(t["tracks"]["near"]["particles"].value_or(0), 12);
}

TEST(RegionTracks, ACheckpointGivesBackEveryFigure) {
  Row row;
  const TrackSettings s = two_regions();
  RegionTracks tr(s, row.at(0.0, 25.0), [](std::size_t i) { return i > 0; });
  for (int k = 1; k <= 300; ++k) tr.record(row.at(0.01 * k, 25.0));
  std::stringstream buf;
  CheckpointOut out(buf);
  tr.save(out);
  CheckpointIn in(buf, "tracks.bin");
  RegionTracks back = RegionTracks::load(s, in, "the tracks");
  EXPECT_EQ(back.times(), tr.times());
  EXPECT_EQ(back.onset_time(0), tr.onset_time(0));
  EXPECT_EQ(back.wave_speed(), tr.wave_speed());
  // Another deck's regions are refused.
  TrackSettings other = s;
  other.tracks.pop_back();
  other.wave_speed = {};
  std::stringstream again;
  CheckpointOut out2(again);
  tr.save(out2);
  CheckpointIn in2(again, "tracks.bin");
  EXPECT_THROW(RegionTracks::load(other, in2, "the tracks"), InputError);
}

TEST(RegionTracks, ARegionWithoutParticlesIsRefusedByName) {
  Row row;
  TrackSettings s = two_regions();
  s.tracks.push_back({"beyond", 150.0, 160.0});
  try {
    RegionTracks tr(s, row.at(0.0, 25.0), [](std::size_t i) { return i > 0; });
    FAIL() << "accepted an empty region";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("track \"beyond\""), std::string::npos) << e.what();
  }
  // The rigid particle (left out) does not make a region non-empty.
  s.tracks.back() = {"rigid", -6.0, -4.0};
  EXPECT_THROW(RegionTracks(s, row.at(0.0, 25.0), [](std::size_t i) { return i > 0; }), InputError);
}
