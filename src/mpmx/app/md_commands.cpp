#include "mpmx/app/commands.hpp"

namespace mpmx::app {
void add_md_commands(CLI::App&) {}
}  // namespace mpmx::app
