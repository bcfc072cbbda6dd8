#pragma once
// This process's place among MPI ranks, and the few collective operations the
// multiscale run needs. Built without MPI, or started without an MPI launcher, the
// process is rank 0 of 1 and every operation is the identity: the single-process run
// takes exactly the path it takes without this file.
//
// Failures agree: a rank that fails inside a collective section reports it, every rank
// learns the failure of the lowest failing rank and throws the same error (same kind,
// same message), so all stop together with one message and one exit status.
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace mpmx::ranks {

// MPI_Init when launched by an MPI launcher (mpirun, srun), MPI_Finalize at the end.
class Session {
 public:
  Session(int& argc, char**& argv);
  ~Session();
  Session(const Session&) = delete;
  Session& operator=(const Session&) = delete;
};

int rank();
int size();
bool active();  // MPI initialised (launched by an MPI launcher), even as one rank
inline bool root() { return rank() == 0; }
// "Open MPI 4.1.4", or "none" when built without MPI.
std::string library();

// An error as it travels between ranks.
struct Failure {
  enum Kind : int { input = 1, run = 2, internal = 3, system = 4 } kind = run;
  std::string message;
};
// The exception being handled, as a Failure (call it in a catch block).
Failure current_failure();
// Throws the error a Failure describes (InputError, RunError, SystemError, std::runtime_error).
[[noreturn]] void raise(const Failure& f);

// How long a rank waits for the others in an agreement. `unbounded`: the steps of a run,
// where ranks arrive as their work allows. `input`: the agreements on the command line
// and the deck, which every rank reaches within moments of the others; a rank that does
// not (stuck, or started on another command line) ends the job, exit 2, after
// MPMX_AGREE_SECONDS (default 300) instead of leaving the rest waiting for ever.
enum class Wait { unbounded, input };
double input_wait_seconds();  // MPMX_AGREE_SECONDS, checked

// Collective: the failure of the lowest failing rank, the same on every rank.
std::optional<Failure> first_failure(const std::optional<Failure>& mine, Wait wait = Wait::unbounded);
// Collective: runs f on every rank; if it threw on any, every rank throws the lowest
// failing rank's error (marked agreed).
void together(const std::function<void()>& f, Wait wait = Wait::unbounded);
// Whether the error being handled was agreed by every rank (exit cleanly), or is this
// rank's alone (the others cannot be told: the job must be aborted).
bool failure_agreed();
void mark_agreed();
// Ends every rank of the job after an error only this rank saw (no-op single-process).
[[noreturn]] void abort_job(int code);

// Collective reductions.
std::vector<double> max(std::vector<double> v);
double sum(double v);

// Collective: every rank's `mine` (count[r] values from rank r, in rank order).
std::vector<double> all_gather(const std::vector<double>& mine, const std::vector<int>& counts);
// Collective: every rank's bytes concatenated in rank order, on rank 0 ("" elsewhere).
std::string gather_to_root(const std::string& mine);
// Collective: sends to_rank[r] to rank r; returns what every rank sent this one,
// concatenated in rank order.
std::string exchange(const std::vector<std::string>& to_rank);

}  // namespace mpmx::ranks
