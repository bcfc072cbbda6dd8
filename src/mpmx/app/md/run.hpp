#pragma once
// Runs an MD-only deck: builds the crystal, thermalises it, advances it (optionally
// under a velocity gradient) and writes DIR/run.json and DIR/thermo.csv.
#include <string>

#include <toml++/toml.h>

#include "mpmx/app/md/config.hpp"

namespace mpmx::app::md {

using namespace mpmx::md;  // the MD driver speaks the engine's names

struct MdRunSummary {
  long atoms = 0;
  long steps = 0;
  double wall_seconds = 0;
  double atom_steps_per_second = 0;
  double potential_energy_per_atom = 0;
  Mat3 stress_gpa{};
};

MdRunSummary run_md(const MdConfig& config, const std::string& out_dir, const toml::table& deck_echo,
                    bool quiet = false);

}  // namespace mpmx::app::md
