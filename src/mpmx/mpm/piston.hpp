#pragma once
// A piston: a rigid wall that starts on a face of the grid and moves into it at a
// prescribed speed v(t) (a constant, or a table of (t, v) points joined by straight
// lines, held at its end values outside them), along the face's inward normal n.
//
// It carries the grid with it (piston_grid.hpp): the grid's corner follows n travel(t),
// so the face stays on the grid's face nodes and the material behind the shock rests on
// the grid, as it does when the bar is sent onto a fixed wall. MPM's steps are Galilean
// (a uniform velocity added to the points and the grid changes no difference, gradient
// or shape function), so in the grid's frame the piston is the wall: the same nodes, the
// same v^n and v^L, the same ringing (docs/validation.md, C1). On a fixed grid the
// shocked material crossed the cells under stress, and the piston's contact took in a
// node every dx / v: 2.6x to 8.6x the wall's ringing with DDMP, and original MPM's
// plateau fell to 57% of the piston's speed.
//
// On its face nodes the piston holds the normal velocity at its own where the material
// would move slower (it pushes, it never pulls): v^n at v(t), v^L at v(t + dt), as a
// velocity face holds them (ADMPM eq. 5.24).
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

// The inward normal of face f along its axis: +1 on a lower face, -1 on an upper one.
inline double inward(int face) { return face % 2 == 0 ? 1.0 : -1.0; }

// Whether a piston on face f at speed `speed` takes a node whose normal velocity (the
// material's, before the piston acts) is v: where the material would fall behind it.
inline bool piston_contact(double v, int face, double speed) { return v * inward(face) < speed; }

}  // namespace mpmx::mpm
