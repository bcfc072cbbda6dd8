#include "mpmx/md/lammps_dump.hpp"

#include <algorithm>

#include <fmt/format.h>

namespace mpmx::md {

void write_lammps_dump(std::ostream& out, std::int64_t step, const Atoms& a, const Box& b) {
  out << fmt::format("ITEM: TIMESTEP\n{}\nITEM: NUMBER OF ATOMS\n{}\n", step, a.size());
  if (b.xy == 0 && b.xz == 0 && b.yz == 0) {
    out << fmt::format("ITEM: BOX BOUNDS pp pp pp\n0 {:.16g}\n0 {:.16g}\n0 {:.16g}\n", b.lx, b.ly, b.lz);
  } else {
    const double xlo = std::min({0.0, b.xy, b.xz, b.xy + b.xz});
    const double xhi = b.lx + std::max({0.0, b.xy, b.xz, b.xy + b.xz});
    const double ylo = std::min(0.0, b.yz), yhi = b.ly + std::max(0.0, b.yz);
    out << fmt::format("ITEM: BOX BOUNDS xy xz yz pp pp pp\n{:.16g} {:.16g} {:.16g}\n{:.16g} {:.16g} {:.16g}\n"
                       "0 {:.16g} {:.16g}\n",
                       xlo, xhi, b.xy, ylo, yhi, b.xz, b.lz, b.yz);
  }
  out << "ITEM: ATOMS id type x y z vx vy vz\n";
  for (std::size_t i = 0; i < a.size(); ++i)
    out << fmt::format("{} {} {:.10g} {:.10g} {:.10g} {:.8g} {:.8g} {:.8g}\n", a.id[i], a.type[i] + 1, a.x[i], a.y[i],
                       a.z[i], a.vx[i], a.vy[i], a.vz[i]);
}

}  // namespace mpmx::md
