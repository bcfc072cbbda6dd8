#include "mpmx/app/dpd/dump.hpp"

#include <algorithm>

#include <fmt/format.h>

namespace mpmx::app::dpd {

void write_lammps_dump(std::ostream& out, std::int64_t step, const Particles& p, const Domain& d,
                       const std::vector<std::uint8_t>* structure) {
  out << fmt::format("ITEM: TIMESTEP\n{}\nITEM: NUMBER OF ATOMS\n{}\n", step, p.size());
  out << fmt::format("ITEM: BOX BOUNDS {} {} {}\n", d.periodic[0] ? "pp" : "ss", d.periodic[1] ? "pp" : "ss",
                     d.periodic[2] ? "pp" : "ss");
  const std::vector<double>* c[3] = {&p.x, &p.y, &p.z};
  for (int k = 0; k < 3; ++k) {
    double lo = 0, hi = d.length(k);
    if (!d.periodic[k] && p.size() > 0) {
      const auto [mn, mx] = std::minmax_element(c[k]->begin(), c[k]->end());
      lo = std::min(lo, *mn);
      hi = std::max(hi, *mx);
    }
    out << fmt::format("{:.16g} {:.16g}\n", lo, hi);
  }
  out << (structure ? "ITEM: ATOMS id type mass x y z vx vy vz u structure\n" : "ITEM: ATOMS id type mass x y z vx vy vz u\n");
  for (std::size_t i = 0; i < p.size(); ++i) {
    out << fmt::format("{} {} {:.10g} {:.10g} {:.10g} {:.10g} {:.8g} {:.8g} {:.8g} {:.10g}", p.id[i], p.type[i] + 1,
                       p.mass[i], d.wrap(0, p.x[i]), d.wrap(1, p.y[i]), d.wrap(2, p.z[i]), p.vx[i], p.vy[i], p.vz[i],
                       p.u[i]);
    if (structure) out << ' ' << static_cast<int>((*structure)[i]);
    out << '\n';
  }
}

}  // namespace mpmx::app::dpd
