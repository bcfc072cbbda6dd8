#pragma once
// Every check a DPD run makes before its work, in one place: `mpmx dpd --check` and the
// run both call it (after the deck reader's own checks), so what one passes the other
// does not refuse.
#include <cstddef>
#include <cstdint>

#include "mpmx/app/dpd/budget.hpp"
#include "mpmx/app/dpd/config.hpp"
#include "mpmx/dpd/setup.hpp"

namespace mpmx::app::dpd {

// The random stream of block b (a random fill): build_system's and the checks' alike.
std::uint64_t block_seed(const DpdConfig& c, std::size_t b);

// site(x, y, z, block) for every particle of the blocks, in build_system's order.
template <class Site>
void for_each_block_site(const DpdConfig& c, Site&& site) {
  for (std::size_t b = 0; b < c.blocks.size(); ++b) {
    const BlockSpec& s = c.blocks[b];
    auto at = [&](double x, double y, double z) { site(x, y, z, b); };
    if (s.fcc) fcc_sites(s.cells, s.constant, s.origin, at);
    else random_sites(s.count, s.size, s.origin, block_seed(c, b), at);
  }
}

// The work estimate (refused past a day unless `force`), then the particles as the run
// places them: every [[rigid]] region holds particles of its own (none of another rigid
// group's), and every [[track]] and the [continuum] region mobile particles. Throws
// InputError naming the table.
DpdBudget preflight_dpd(const DpdConfig& c, bool force);

}  // namespace mpmx::app::dpd
