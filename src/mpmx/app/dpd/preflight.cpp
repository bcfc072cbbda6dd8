#include "mpmx/app/dpd/preflight.hpp"

#include <string>
#include <vector>

#include <fmt/format.h>

#include "mpmx/core/error.hpp"

namespace mpmx::app::dpd {

std::uint64_t block_seed(const DpdConfig& c, std::size_t b) { return c.params.seed + 7919 * b; }

DpdBudget preflight_dpd(const DpdConfig& c, bool force) {
  const DpdBudget budget = estimate_dpd(c);
  check_dpd_work(budget, force);

  // Counted over the particles at their built places, the run's own rules: a region takes
  // the particles of no rigid block and of no earlier region; a track and the continuum
  // the particles of no rigid group.
  const std::size_t nr = c.regions.size(), nt = c.analysis.tracks.size();
  std::vector<long> region_holds(nr, 0);
  std::vector<std::vector<long>> shared(nr, std::vector<long>(nr + c.blocks.size(), 0));
  std::vector<long> track_holds(nt, 0);
  long continuum_holds = 0;
  for_each_block_site(c, [&](double x, double y, double z, std::size_t b) {
    const double p[3] = {x, y, z};
    const bool block_rigid = !c.blocks[b].group.empty();
    int owner = -1;  // the region that takes it
    for (std::size_t r = 0; r < nr; ++r) {
      bool in = true;
      for (int d = 0; d < 3; ++d) in = in && p[d] >= c.regions[r].lo[d] && p[d] < c.regions[r].hi[d];
      if (!in) continue;
      if (block_rigid) ++shared[r][nr + b];
      else if (owner >= 0) ++shared[r][static_cast<std::size_t>(owner)];
      else owner = static_cast<int>(r), ++region_holds[r];
    }
    if (block_rigid || owner >= 0) return;
    for (std::size_t t = 0; t < nt; ++t)
      if (x >= c.analysis.tracks[t].lo && x < c.analysis.tracks[t].hi) ++track_holds[t];
    if (c.continuum.on && x >= c.continuum.lo && x < c.continuum.hi) ++continuum_holds;
  });

  std::vector<std::string> errors;
  for (std::size_t r = 0; r < nr; ++r) {
    bool overlaps = false;
    for (std::size_t o = 0; o < nr + c.blocks.size(); ++o)
      if (shared[r][o] > 0)
        overlaps = true, errors.push_back(fmt::format(
            "rigid group \"{}\": its region overlaps rigid group \"{}\" ({} particles lie in both): a particle "
            "belongs to one group; make the regions disjoint",
            c.regions[r].name, o < nr ? c.regions[o].name : c.blocks[o - nr].group, shared[r][o]));
    if (region_holds[r] == 0 && !overlaps)
      errors.push_back(fmt::format("rigid group \"{}\": its region holds no particle", c.regions[r].name));
  }
  for (std::size_t t = 0; t < nt; ++t)
    if (track_holds[t] == 0)
      errors.push_back(fmt::format("track \"{}\": no mobile particle has x in [{}, {}) A", c.analysis.tracks[t].name,
                                   c.analysis.tracks[t].lo, c.analysis.tracks[t].hi));
  if (c.continuum.on && continuum_holds == 0)
    errors.push_back(
        fmt::format("continuum.x = [{}, {}]: no mobile particle lies there", c.continuum.lo, c.continuum.hi));
  if (errors.empty()) return budget;
  std::string all = c.deck_file + ":";
  for (const auto& e : errors) all += "\n" + e;
  throw InputError(all);
}

}  // namespace mpmx::app::dpd
