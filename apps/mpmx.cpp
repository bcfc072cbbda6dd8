// mpmx: material point method, molecular dynamics, and their coupling.
#include <cstdio>
#include <exception>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "mpmx/app/commands.hpp"
#include "mpmx/core/error.hpp"

int main(int argc, char** argv) {
  CLI::App app{"mpmx " MPMX_VERSION ": material point method + molecular dynamics multiscale solver"};
  app.set_version_flag("--version", std::string("mpmx ") + MPMX_VERSION);
  app.require_subcommand(1);
  mpmx::app::add_mpm_commands(app);
  mpmx::app::add_md_commands(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  } catch (const mpmx::InputError& e) {
    fmt::print(stderr, "mpmx: input error:\n{}\n", e.what());
    return 2;
  } catch (const mpmx::RunError& e) {
    fmt::print(stderr, "mpmx: run stopped: {}\n", e.what());
    return 3;
  } catch (const mpmx::Interrupted& e) {
    fmt::print(stderr, "\nmpmx: interrupted: {}\n", e.what());
    return 130;
  } catch (const std::exception& e) {
    fmt::print(stderr, "mpmx: {}\n", e.what());
    return 1;
  }
  return 0;
}
