// The MD deck reader and validator (with the potential file it names, parsed as `mpmx md
// --check` parses it) and the MD memory and work estimate. A deck that passes is one whose
// check is cheap (issue 45): atoms no closer than a bond, a reach over few box lengths;
// anything else aborts.
#include <cmath>
#include <cstdint>
#include <cstdlib>

#include "fuzz_util.hpp"
#include "mpmx/app/md/budget.hpp"
#include "mpmx/app/md/config.hpp"
#include "mpmx/core/error.hpp"
#include "mpmx/io/deck.hpp"
#include "mpmx/md/physical_bounds.hpp"
#include "mpmx/md/potential/potential.hpp"

namespace mpmx::fuzz {

inline int md_deck(const std::uint8_t* data, std::size_t size) {
  using namespace mpmx;
  const std::string path = fuzz::as_file("md.toml", fuzz::view(data, size));
  try {
    auto deck = io::Deck::from_file(path);
    const app::md::MdConfig c = app::md::read_md_config(deck);
    const md::Potential pot(c.potential);
    const auto budget = app::md::estimate_md(c, pot.cutoff());
    app::md::check_md_budget(budget, std::uint64_t{1} << 34, false);
    if (!(c.lattice_constant / std::sqrt(2.0) >= md::kMinBondLength && budget.images <= app::md::kMaxImages))
      std::abort();
  } catch (const InputError&) {
  }
  return 0;
}

}  // namespace mpmx::fuzz

// tests/fuzz/fuzz_replay_test.cpp includes every target with MPMX_FUZZ_REPLAY.
#ifndef MPMX_FUZZ_REPLAY
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return mpmx::fuzz::md_deck(data, size);
}
#endif
