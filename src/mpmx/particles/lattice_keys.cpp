#include "mpmx/particles/lattice_keys.hpp"

#include <string>

namespace mpmx::particles {

namespace {

void read_orient(Table& t, LatticeSpec& spec) {
  if (!t.has("orient")) return;
  const auto rows = t.integer_rows("orient", -1000, 1000);
  if (rows.empty()) return;  // the reader said why
  const bool shaped = rows.size() == 3 && rows[0].size() == 3 && rows[1].size() == 3 && rows[2].size() == 3;
  t.check(shaped, "orient", "expected three directions [[u,v,w], [u,v,w], [u,v,w]] for x, y and z");
  if (!shaped) return;
  for (int d = 0; d < 3; ++d)
    for (int k = 0; k < 3; ++k) spec.orient[d][k] = static_cast<int>(rows[d][k]);
  if (const std::string why = orient_problem(spec); !why.empty()) t.check(false, "orient", why);
}

}  // namespace

void read_crystal_keys(Table& t, std::string_view style_key, LatticeSpec& spec) {
  spec.style = lattice_style(t.choice(style_key, {"fcc", "bcc", "hcp", "b2"}, "fcc"));
  if (t.has("c_over_a")) {
    spec.c_over_a = t.number("c_over_a");
    t.check(spec.style == LatticeStyle::hcp, "c_over_a", "applies to an hcp lattice only");
    t.check(spec.c_over_a >= 0.5 && spec.c_over_a <= 5, "c_over_a",
            "must lie in [0.5, 5] (the ideal sqrt(8/3) = 1.633; Zn's 1.86 is the largest of the elements)");
  }
  read_orient(t, spec);
}

}  // namespace mpmx::particles
