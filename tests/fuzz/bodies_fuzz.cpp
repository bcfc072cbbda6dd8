// The bodies of a 2-D or 3-D continuum deck: their shapes (boxes, circles, spheres,
// polygons) checked, their points placed and the placement checked as `mpmx check` and
// `mpmx run` do (app/mpm/preflight.hpp). The input is the [[body]] tables; its first
// byte picks the dimension and the grid they sit on, so the fuzzer spends its time on the
// geometry rather than on the rest of a deck.
#include <cstdint>
#include <string>

#include <fmt/format.h>

#include "fuzz_util.hpp"
#include "mpmx/app/mpm/deck.hpp"
#include "mpmx/app/mpm/preflight.hpp"
#include "mpmx/core/error.hpp"

namespace mpmx::fuzz {

inline int bodies(const std::uint8_t* data, std::size_t size) {
  using namespace mpmx;
  if (size < 1) return 0;
  const int dim = data[0] & 1 ? 3 : 2;
  const int cells = 1 + (data[0] >> 1) % 24, per = 1 + (data[0] >> 6);  // up to 24 cells of 4 points an axis
  const std::string grid =
      dim == 2 ? fmt::format("lower = [0.0, 0.0]\nupper = [1.0, 1.0]\ncells = [{0}, {0}]\n", cells)
               : fmt::format("lower = [0.0, 0.0, 0.0]\nupper = [1.0, 1.0, 1.0]\ncells = [{0}, {0}, {0}]\n", cells);
  const std::string per_cell = dim == 2 ? fmt::format("[{0}, {0}]", per) : fmt::format("[{0}, {0}, {0}]", per);
  const std::string deck = fmt::format(
      "[case]\nid = \"B\"\n[grid]\ndim = {}\n{}[particles]\nper_cell = {}\n[scheme]\nname = \"mpm\"\n"
      "[material]\nmodel = \"linear_elastic\"\ndensity = 1.0\nyoungs_modulus = 1.0\n[time]\ndt = \"cfl\"\n"
      "end = 1e-3\n[output]\nplot = false\nvtk = false\n{}\n",
      dim, grid, per_cell, fuzz::view(data + 1, size - 1));
  const std::string path = fuzz::as_file("bodies.toml", deck);
  try {
    const auto c = app::read_mpm_deck(path);
    app::preflight_mpm_run(c, 1, std::uint64_t{1} << 30, false);
  } catch (const InputError&) {
  }
  return 0;
}

}  // namespace mpmx::fuzz

// tests/fuzz/fuzz_replay_test.cpp includes every target with MPMX_FUZZ_REPLAY.
#ifndef MPMX_FUZZ_REPLAY
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return mpmx::fuzz::bodies(data, size);
}
#endif
