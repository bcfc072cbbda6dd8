#include "mpmx/app/mpm/prepare.hpp"

#include <map>

#include "mpmx/app/mpm/signal_speed.hpp"

namespace mpmx::app {

MpmConfig prepared_for_run(const MpmConfig& c) {
  // Each law prepared once: a body sharing the deck's [material] keeps sharing it (the
  // points' laws are told apart by identity, setup.cpp).
  std::map<const material::Model*, std::shared_ptr<const material::Model>> done;
  auto prepare = [&](std::shared_ptr<const material::Model>& law) {
    if (!law) return false;
    auto [it, first] = done.try_emplace(law.get());
    if (first) it->second = law->prepared();
    if (!it->second) return false;
    law = it->second;
    return true;
  };
  MpmConfig p = c;
  bool any = false;
  if (prepare(p.material.spec)) {
    p.material.density = p.material.spec->density();  // as the deck's reading takes it (deck.cpp)
    any = true;
  }
  for (auto& body : p.bodies) any = prepare(body.material) || any;
  if (!any) return c;
  if (p.cfl_dt) p.dt = first_cfl_step(p);
  return p;
}

}  // namespace mpmx::app
