#pragma once
// Ctrl-C asks a run loop to write a checkpoint and stop; a second one kills. Under MPI,
// SIGTERM does the same: mpirun turns a Ctrl-C into SIGTERM to every rank, and a batch
// system's time limit sends it too. The guard holds the handlers for the loop's life.
namespace mpmx {

class InterruptGuard {
 public:
  explicit InterruptGuard(bool active);
  ~InterruptGuard();
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;

  // Whether a signal came since the guard was made.
  static bool interrupted();

 private:
  bool active_, term_;
  void (*previous_)(int);
  void (*previous_term_)(int);
};

}  // namespace mpmx
