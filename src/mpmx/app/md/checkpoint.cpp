#include "mpmx/app/md/checkpoint.hpp"

#include <optional>

#include <fmt/format.h>

namespace mpmx::app::md {

using mpmx::md::System;

Tracked resume_md(RunControl& control, System& sys, std::int64_t last_step) {
  Tracked tracked;
  resume_md_with(control, sys, last_step, [&](CheckpointIn& in) { tracked = in.rows(); });
  return tracked;
}

bool stop_md_at(RunControl& control, const System& sys, const Tracked& tracked) {
  return stop_md_with(control, sys, [&](CheckpointOut& w) { w.rows(tracked); });
}

void resume_md_with(RunControl& control, System& sys, std::int64_t last_step,
                    const std::function<void(CheckpointIn&)>& read_rest) {
  control.resume(sys.atoms().size(), [&](CheckpointIn& in) {
    const long long at = in.offset();
    std::optional<System> saved;
    try {
      saved.emplace(System::load(in.stream(), sys.potential(), sys.options()));
    } catch (const InputError& e) {
      throw in.refuse(at, fmt::format("the MD system: {}", e.what()));
    }
    if (saved->atoms().size() != sys.atoms().size())
      throw in.refuse(at, fmt::format("{} atoms, the deck makes {}", saved->atoms().size(), sys.atoms().size()));
    // A checkpoint is written at a record before the last step, never at or past it.
    if (saved->step() < 0 || saved->step() >= last_step)
      throw in.refuse(at, fmt::format("step {} is outside the deck's run of {} steps", saved->step(), last_step));
    saved->set_rigid(sys.frozen_ids(), sys.rigid_free());  // the piston or flyer is the deck's
    read_rest(in);
    sys = std::move(*saved);
  });
}

bool stop_md_with(RunControl& control, const System& sys, const std::function<void(CheckpointOut&)>& write_rest) {
  if (!control.stop_due(sys.step())) return false;
  control.checkpoint(sys.atoms().size(), [&](CheckpointOut& w) {
    sys.save(w.stream());
    write_rest(w);
  });
  return true;
}

}  // namespace mpmx::app::md
