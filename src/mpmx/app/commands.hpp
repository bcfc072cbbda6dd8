#pragma once
// The CLI's subcommands, one registration function per module, so that apps/mpmx.cpp
// stays a dispatcher and each module owns its commands.
#include <CLI/CLI.hpp>

namespace mpmx::app {

void add_mpm_commands(CLI::App& app);  // run, check
void add_md_commands(CLI::App& app);   // md
void add_dpd_commands(CLI::App& app);  // dpd, fit-dpd

}  // namespace mpmx::app
