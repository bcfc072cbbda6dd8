// The continuum deck reader and validator, and the pre-flight `mpmx check` and `mpmx run`
// make (the bodies' placement, the memory and work estimate, the reference): any text is
// either a valid deck or an InputError, never a crash or a hang.
#include <cstdint>

#include "fuzz_util.hpp"
#include "mpmx/core/error.hpp"
#include "mpmx/app/mpm/deck.hpp"
#include "mpmx/app/mpm/preflight.hpp"

namespace mpmx::fuzz {

inline int mpm_deck(const std::uint8_t* data, std::size_t size) {
  using namespace mpmx;
  // A path given in the deck (reference.file, a potential) resolves against this folder.
  const std::string path = fuzz::as_file("deck.toml", fuzz::view(data, size));
  try {
    const auto c = app::read_mpm_deck(path);
    // 1 GiB: the points a deck may place stay few enough to count in a moment.
    app::preflight_mpm_run(c, 1, std::uint64_t{1} << 30, false);
  } catch (const InputError&) {
  }
  return 0;
}

}  // namespace mpmx::fuzz

// tests/fuzz/fuzz_replay_test.cpp includes every target with MPMX_FUZZ_REPLAY.
#ifndef MPMX_FUZZ_REPLAY
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return mpmx::fuzz::mpm_deck(data, size);
}
#endif
