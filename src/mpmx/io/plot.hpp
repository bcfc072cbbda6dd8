#pragma once
// The figures of a run: tools/plot scripts through the system interpreter (Debian's
// python3-matplotlib serves /usr/bin/python3), skipped when matplotlib is missing.
#include <string>

namespace mpmx::io {

bool matplotlib_present();
// Runs tools/plot/<script> with `args` (already quoted); false (and a line on stderr,
// the tables being complete) when it fails.
bool run_plot_script(const std::string& script, const std::string& args);

}  // namespace mpmx::io
