#include "mpmx/particles/lattice.hpp"

#include <fmt/format.h>

#include "mpmx/core/error.hpp"

namespace mpmx::particles {

Crystal fcc(int nx, int ny, int nz, double a, double strain_x, int type) {
  if (nx < 1 || ny < 1 || nz < 1 || !(a > 0.0) || !(strain_x > -1.0))
    throw InputError(fmt::format("fcc lattice: cells {}x{}x{}, a = {}, strain {}: need cells >= 1, "
                                 "a > 0, strain > -1",
                                 nx, ny, nz, a, strain_x));
  Crystal c;
  const double sx = 1.0 + strain_x;
  c.box.lx = nx * a * sx;
  c.box.ly = ny * a;
  c.box.lz = nz * a;
  std::int64_t id = 1;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
        for (const auto& b : kFccBasis)
          c.atoms.push_back((i + b[0]) * a * sx, (j + b[1]) * a, (k + b[2]) * a, type, id++);
  return c;
}

}  // namespace mpmx::particles
