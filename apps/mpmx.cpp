// mpmx: material point method, molecular dynamics, and their coupling.
// Every command ends with one exit status from core/exit_codes.hpp, and every message is
// printed once, here: CLI11's errors, InputError, RunError, Interrupted, and anything else.
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <filesystem>
#include <new>
#include <string>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "mpmx/app/cli_checks.hpp"
#include "mpmx/app/commands.hpp"
#include "mpmx/core/error.hpp"
#include "mpmx/core/file_text.hpp"
#include "mpmx/core/ranks.hpp"
#include "mpmx/md/potential/eam_one_type.hpp"
#include "mpmx/core/isa.hpp"
#include "mpmx/core/exit_codes.hpp"
#include "mpmx/core/omp_wait.hpp"

namespace {

// The command as typed (for "out of memory while ...").
std::string command_line(int argc, char** argv) {
  std::string s = "mpmx";
  for (int i = 1; i < argc; ++i) s += std::string(" ") + argv[i];
  return s;
}

// The words CLI11 accepts as a command.
std::string command_names(CLI::App& app) {
  std::string s;
  for (const CLI::App* sub : app.get_subcommands({})) s += (s.empty() ? "" : ", ") + sub->get_name();
  return s;
}

// "mpmx frobnicate": CLI11 would say "A subcommand is required"; name the word instead.
// The top level has only flags (--help, --version), so the first word that is not one
// is the command.
const char* unknown_command(CLI::App& app, int argc, char** argv) {
  for (int i = 1; i < argc; ++i) {
    if (argv[i][0] == '-') continue;
    for (const CLI::App* sub : app.get_subcommands({}))
      if (sub->check_name(argv[i])) return nullptr;
    return argv[i];
  }
  return nullptr;
}

// Under MPI: an error every rank agreed on is printed once, by rank 0, and every rank
// exits with its status; an error only this rank saw is printed with the rank's number
// and ends the whole job (the other ranks would wait for it for ever). Control characters
// a message still holds (from a deck, a path, a file) are escaped here, the last step
// before the terminal; its own line breaks stay.
int finish(int code, const std::string& text) {
  namespace ranks = mpmx::ranks;
  const std::string message = mpmx::escape_controls(text, true);
  if (ranks::size() == 1 || ranks::failure_agreed()) {
    if (ranks::root()) fmt::print(stderr, "{}", message);
    return code;
  }
  fmt::print(stderr, "[rank {} of {}] {}", ranks::rank(), ranks::size(), message);
  std::fflush(stderr);
  ranks::abort_job(code);
}

// A command line that fails to parse on this rank need not fail on the others (a deck
// that exists on one node's disk only, a launch with a command line per rank): the
// ranks that parsed meet this one in the run's first collective (`ranks::together`
// around the deck), so the failure is agreed there and every rank stops with the lowest
// failing rank's message, instead of the others waiting for this one for ever.
std::string agreed_parse_failure(const std::string& message) {
  namespace ranks = mpmx::ranks;
  if (ranks::size() == 1) return message;
  using F = ranks::Failure;
  const auto agreed = ranks::first_failure(
      F{F::input, ranks::root() ? message : fmt::format("[rank {} of {}] {}", ranks::rank(), ranks::size(), message)},
      ranks::Wait::input);
  ranks::mark_agreed();
  return agreed->message;
}

int run(int argc, char** argv) {
  namespace code = mpmx::exit_code;
  CLI::App app{"mpmx " MPMX_VERSION ": material point method + molecular dynamics multiscale solver"};
  // With the vector paths of the 1-D and MD kernels (those built in, those this machine
  // runs, the one taken) and the MPI library the ranks use.
  app.set_version_flag("--version", [] {
    const char* wait = std::getenv("OMP_WAIT_POLICY");
    return std::string("mpmx ") + MPMX_VERSION + "\n" + mpmx::isa_summary() + "\n" +
           mpmx::md::eam_isa_summary() + "\nMPI: " + mpmx::ranks::library() +
           "\nOpenMP: idle threads wait " + (wait ? std::string("as OMP_WAIT_POLICY=") + wait + " says" :
                                                   std::string("as GOMP_SPINCOUNT says"));
  });
  app.require_subcommand(1);
  app.footer("Exit status: 0 done, 1 the machine failed (a write refused: disk full, read-only; the earlier results "
             "kept) or an internal error, 2 bad input (also an --out another run holds or owns), 3 run stopped by the "
             "physics (partial result written), 130 interrupted by Ctrl-C or SIGTERM (a checkpoint written: --resume "
             "continues; fit-dpd from its last finished stage; a third signal kills at once).");
  mpmx::app::add_mpm_commands(app);
  mpmx::app::add_md_commands(app);
  mpmx::app::add_dpd_commands(app);
  mpmx::app::apply_shared_checks(app);
  // "mpmx --frob": an option before any command, other than the top level's own.
  for (int i = 1; i < argc && argv[i][0] == '-'; ++i) {
    const std::string w = argv[i];
    if (w != "--help" && w != "-h" && w != "--version") {
      fmt::print(stderr, "mpmx: unknown option '{}' (the top level takes --help and --version; the commands: {})\n",
                 w, command_names(app));
      return code::bad_input;
    }
  }
  if (const char* word = unknown_command(app, argc, argv)) {
    mpmx::ranks::mark_agreed();  // the same command line on every rank
    return finish(code::bad_input, fmt::format("mpmx: unknown command '{}': expected one of {} (mpmx --help)\n",
                                               word, command_names(app)));
  }
  // Only `mpmx run` spreads its work over MPI ranks; any other command on several
  // ranks would run N times over into the same files.
  if (mpmx::ranks::size() > 1)
    for (int i = 1; i < argc; ++i)
      if (argv[i][0] != '-') {
        if (std::strcmp(argv[i], "run") == 0) break;
        mpmx::ranks::mark_agreed();
        return finish(code::bad_input,
                      fmt::format("mpmx: `mpmx {}` runs as one process; under an MPI launcher only `mpmx run` "
                                  "spreads over ranks (start it with -np 1, or without mpirun)\n",
                                  argv[i]));
      }
  try {
    mpmx::isa_chosen();  // a bad MPMX_ISA stops here, before any command writes
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help and --version: CLI11 prints them and says 0.
    if (e.get_exit_code() == static_cast<int>(CLI::ExitCodes::Success))
      return mpmx::ranks::root() ? app.exit(e) : code::done;
    std::string where = "mpmx";
    for (const CLI::App* sub : app.get_subcommands()) where += " " + sub->get_name();
    const std::string message =
        where == "mpmx" && e.get_name() == "RequiredError"
            ? fmt::format("mpmx: a command is required: one of {} (mpmx --help)\n", command_names(app))
            : fmt::format("mpmx: {}\n({} --help lists the options)\n", e.what(), where);
    return finish(code::bad_input, agreed_parse_failure(message));
  } catch (const mpmx::InputError& e) {
    return finish(code::bad_input, fmt::format("mpmx: input error:\n{}\n", e.what()));
  } catch (const mpmx::RunError& e) {
    return finish(code::stopped, fmt::format("mpmx: run stopped: {}\n", e.what()));
  } catch (const mpmx::SystemError& e) {
    // A write the machine refused (disk full, read-only, the folder gone): the earlier
    // results and the last checkpoint are as they were.
    return finish(code::internal, fmt::format("mpmx: the file system failed: {}\n", e.what()));
  } catch (const mpmx::Interrupted& e) {
    return finish(code::interrupted, fmt::format("\nmpmx: interrupted: {}\n", e.what()));
  } catch (const std::bad_alloc&) {
    // The estimates refuse what cannot fit before anything runs; this is the last resort.
    return finish(code::internal, fmt::format("mpmx: out of memory while running `{}`\n", command_line(argc, argv)));
  } catch (const std::filesystem::filesystem_error& e) {
    // The inputs were checked before the work; a file system that fails later is the
    // machine's (exit 1), said in words.
    return finish(code::internal, fmt::format("mpmx: the file system failed: {} {}\n",
                                              mpmx::short_path(e.path1().string()),
                                              mpmx::path_problem(e.path1(), e.code())));
  } catch (const std::exception& e) {
    // Every input and physics failure has its own type above: what lands here is a fault
    // of mpmx itself, said as one (with the library's words as the detail).
    return finish(code::internal, fmt::format("mpmx: internal error while running `{}`: {}. This is a fault in "
                                              "mpmx, not in the input: please report it with the deck.\n",
                                              command_line(argc, argv), e.what()));
  }
  return code::done;
}

}  // namespace

int main(int argc, char** argv) {
  mpmx::wait_passively(argv);  // before MPI or OpenMP start: it may restart the process
  // Past a file size limit (ulimit -f) a write fails with EFBIG and is reported as the
  // machine's failure, instead of the signal killing the run with no word.
  std::signal(SIGXFSZ, SIG_IGN);
  mpmx::ranks::Session mpi(argc, argv);  // MPI only when started by an MPI launcher
  return run(argc, argv);
}
