// The DPD deck reader and validator (potential by style or file, blocks, rigid groups,
// the DPD/MPM grid and continuum, the analysis tables, the memory estimate), the
// pre-flight `mpmx dpd --check` and the run make (the regions over the particles), and the
// Born constants a concurrent deck's continuum would take.
#include <cstdint>

#include "fuzz_util.hpp"
#include "mpmx/app/dpd/config.hpp"
#include "mpmx/app/dpd/preflight.hpp"
#include "mpmx/core/error.hpp"
#include "mpmx/dpd/elastic.hpp"
#include "mpmx/io/deck.hpp"

namespace mpmx::fuzz {

inline int dpd_deck(const std::uint8_t* data, std::size_t size) {
  using namespace mpmx;
  const std::string path = fuzz::as_file("dpd.toml", fuzz::view(data, size));
  try {
    auto deck = io::Deck::from_file(path);
    const app::dpd::DpdConfig c = app::dpd::read_dpd_config(deck);
    (void)app::dpd::preflight_dpd(c, false);
    if (c.continuum.on && c.continuum.from_potential)
      (void)dpd::fcc_born_constants(c.potential, c.continuum.lattice_constant);
  } catch (const InputError&) {
  }
  return 0;
}

}  // namespace mpmx::fuzz

// tests/fuzz/fuzz_replay_test.cpp includes every target with MPMX_FUZZ_REPLAY.
#ifndef MPMX_FUZZ_REPLAY
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return mpmx::fuzz::dpd_deck(data, size);
}
#endif
