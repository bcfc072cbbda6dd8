#include "mpmx/app/commands.hpp"

namespace mpmx::app {
void add_mpm_commands(CLI::App&) {}
}  // namespace mpmx::app
