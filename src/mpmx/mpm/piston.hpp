#pragma once
// A piston: a rigid wall that starts on a face of the grid and moves into it at a
// prescribed speed v(t) (a constant, or a table of (t, v) points joined by straight
// lines, held at its end values outside them). Its face lies at x0 + n travel(t), n the
// face's inward normal. The nodes whose support reaches behind the face (those behind
// it and the first node ahead of it, less than a cell away) are in its contact: their
// normal velocity v^L is raised to the piston's where the material would move slower (it
// pushes, it never pulls). So the drive follows the material it compresses, where a
// velocity boundary holds only the face's own nodes, which the material leaves. Holding
// only the nodes behind the face let the points of the face's cell lag it (a plateau 5%
// under u_p at 0.05 km/s, VALIDATION.md C1); with the node ahead held it is within 0.5%.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace mpmx::mpm {

struct Piston {
  std::vector<double> times{0.0};   // increasing
  std::vector<double> speeds{0.0};  // along the inward normal

  double speed(double t) const {
    if (t <= times.front()) return speeds.front();
    if (t >= times.back()) return speeds.back();
    const std::size_t k = static_cast<std::size_t>(std::upper_bound(times.begin(), times.end(), t) - times.begin());
    const double f = (t - times[k - 1]) / (times[k] - times[k - 1]);
    return speeds[k - 1] + f * (speeds[k] - speeds[k - 1]);
  }
  // Distance moved since t = 0: the integral of speed, exact for the piecewise-linear table.
  double travel(double t) const {
    if (!(t > 0.0)) return 0.0;
    double d = 0.0, a = 0.0;  // a: the start of the piece summed next
    auto piece = [&](double b) {  // the trapezoid from a to b (both within one segment)
      if (b <= a) return;
      d += 0.5 * (speed(a) + speed(b)) * (b - a);
      a = b;
    };
    for (double tk : times) piece(std::min(std::max(tk, 0.0), t));
    piece(t);
    return d;
  }
};

// The nodes a piston on face f holds at time t, as a range of grid indices along its
// axis: lower faces [0, reach], upper faces [reach, cells]: those less than a cell ahead
// of the face (within a millionth of a cell: at t = 0 the face's own node only). `dx`,
// `cells`: the grid along that axis.
inline int piston_reach(const Piston& p, int face, double dx, int cells, double t) {
  const double cells_moved = p.travel(t) / dx + 1.0 - 1e-6;
  const int k = static_cast<int>(std::floor(std::clamp(cells_moved, -1.0, cells + 1.0)));
  return face % 2 == 0 ? k : cells - k;
}
inline bool piston_holds(int face, int index, int reach) { return face % 2 == 0 ? index <= reach : index >= reach; }

// The normal velocity component of a node in the piston's contact: raised to the
// piston's velocity n v where the material moves slower along n (unilateral contact).
inline double piston_velocity(double v, int face, double speed) {
  const double n = face % 2 == 0 ? 1.0 : -1.0;
  return v * n < speed ? n * speed : v;
}

}  // namespace mpmx::mpm
