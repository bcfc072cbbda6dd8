#include "mpmx/io/plot.hpp"

#include <cstdlib>

#include <fmt/format.h>

namespace mpmx::io {

bool matplotlib_present() {
  return std::system(MPMX_PYTHON " -c 'import matplotlib, numpy' >/dev/null 2>&1") == 0;
}

bool run_plot_script(const std::string& script, const std::string& args) {
  const std::string cmd = fmt::format("{} {}/tools/plot/{} {}", MPMX_PYTHON, MPMX_SOURCE_DIR, script, args);
  if (std::system(cmd.c_str()) == 0) return true;
  fmt::print(stderr, "mpmx: plotting failed (the run's tables are complete): {}\n", cmd);
  return false;
}

}  // namespace mpmx::io
