// The EAM potential files (funcfl .eam, setfl .eam.alloy, Finnis-Sinclair .eam.fs; the
// first byte picks the format), read and, when they read, made into the potential the MD
// uses for their first element (the splines of every table). A file that reads describes
// a potential (issue 45): masses an atom's, spacings finite and positive, the density grid
// finite; anything else is a reader that let a damaged file through, and aborts.
#include <cmath>
#include <cstdint>
#include <cstdlib>

#include "fuzz_util.hpp"
#include "mpmx/core/error.hpp"
#include "mpmx/md/potential/eam_file.hpp"
#include "mpmx/md/physical_bounds.hpp"
#include "mpmx/md/potential/potential.hpp"

namespace mpmx::fuzz {

inline int eam(const std::uint8_t* data, std::size_t size) {
  using namespace mpmx;
  if (size < 1) return 0;
  static const char* names[3] = {"p.eam", "p.eam.alloy", "p.eam.fs"};
  const std::string path = fuzz::as_file(names[data[0] % 3], fuzz::view(data + 1, size - 1));
  try {
    const md::EamTables t = md::read_eam(path);
    for (const double m : t.masses)
      if (!(m >= md::kMinAtomMass && m <= md::kMaxAtomMass)) std::abort();
    if (!(t.dr > 0 && t.drho > 0 && std::isfinite(t.rhomax) && t.cut / t.dr >= 10)) std::abort();
    if (t.elements.empty()) return 0;
    md::EamSpec spec;
    spec.file = path;
    spec.elements = {t.elements.front()};
    const md::Potential pot(spec);
    (void)pot.cutoff();
  } catch (const InputError&) {
  }
  return 0;
}

}  // namespace mpmx::fuzz

// tests/fuzz/fuzz_replay_test.cpp includes every target with MPMX_FUZZ_REPLAY.
#ifndef MPMX_FUZZ_REPLAY
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return mpmx::fuzz::eam(data, size);
}
#endif
