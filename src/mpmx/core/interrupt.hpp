#pragma once
// Ctrl-C (SIGINT) or SIGTERM asks a run loop to write a checkpoint and stop at its next
// step boundary. A second signal is the same request (GNU `timeout` and batch systems
// send SIGTERM to the process and then to its group), so the checkpoint ends whole; a
// third kills at once (the escape from a run that does not reach its next boundary).
// SIGTERM is what mpirun turns a Ctrl-C into for every rank, what `kill` sends by default
// and what a batch system's time limit sends.
// The guard holds the handlers for the loop's life.
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
  bool active_;
  void (*previous_)(int);
  void (*previous_term_)(int);
};

}  // namespace mpmx
