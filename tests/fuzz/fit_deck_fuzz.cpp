// The fit-dpd deck reader and validator (the MD potential it names, parsed as `mpmx
// fit-dpd --check` parses it; the densities, the DPD start, [elastic], the output name):
// any text is either a valid fit deck or an InputError, never a crash or a hang.
#include <cstdint>

#include "fuzz_util.hpp"
#include "mpmx/app/dpd/fit_config.hpp"
#include "mpmx/core/error.hpp"
#include "mpmx/io/deck.hpp"

namespace mpmx::fuzz {

inline int fit_deck(const std::uint8_t* data, std::size_t size) {
  using namespace mpmx;
  const std::string path = fuzz::as_file("fit.toml", fuzz::view(data, size));
  try {
    auto deck = io::Deck::from_file(path);
    (void)app::dpd::read_fit_config(deck);
  } catch (const InputError&) {
  }
  return 0;
}

}  // namespace mpmx::fuzz

// tests/fuzz/fuzz_replay_test.cpp includes every target with MPMX_FUZZ_REPLAY.
#ifndef MPMX_FUZZ_REPLAY
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return mpmx::fuzz::fit_deck(data, size);
}
#endif
