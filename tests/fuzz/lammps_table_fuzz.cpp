// The LAMMPS slab stress table (fix ave/time output of the bar's in.bar) that
// `mpmx md --lammps` reads back; the first byte sets the slab count.
#include <cstdint>

#include "fuzz_util.hpp"
#include "mpmx/app/md/lammps_bar.hpp"
#include "mpmx/core/error.hpp"

namespace mpmx::fuzz {

inline int lammps_table(const std::uint8_t* data, std::size_t size) {
  using namespace mpmx;
  if (size < 1) return 0;
  const int bins = 1 + data[0] % 8;
  const std::string path = fuzz::as_file("bar_stress.lammps", fuzz::view(data + 1, size - 1));
  try {
    (void)app::md::read_lammps_bar_stress(path, 0.001, bins);
  } catch (const InputError&) {
  }
  return 0;
}

}  // namespace mpmx::fuzz

// tests/fuzz/fuzz_replay_test.cpp includes every target with MPMX_FUZZ_REPLAY.
#ifndef MPMX_FUZZ_REPLAY
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return mpmx::fuzz::lammps_table(data, size);
}
#endif
