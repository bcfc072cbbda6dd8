#pragma once
// The batch executor of the multiscale closure: one MD box per material point, each
// advanced by its own velocity gradient. Material points never talk to each other
// (dissertation 1.2, 6.4), so the boxes spread over OpenMP threads; each box carries
// its own random stream, so results do not depend on the thread count. MPI ranks (each
// advancing its block of boxes, multiscale/spread) and a GPU belong behind this
// interface; the continuum solver never sees them.
#include <cstddef>
#include <functional>
#include <vector>

#include "mpmx/md/system.hpp"

namespace mpmx::multiscale {

enum class StressSample {
  last,     // eq. 2.25 at the last MD step of the macro step (the seed's choice)
  average,  // the mean of eq. 2.25 over the macro step's MD steps (fig. 6.6)
};

// Advances one box by nsteps MD steps of dt (ps) under the gradient (1/ps) and returns
// its stress (GPa, Cauchy) sampled as asked.
void advance_box(md::System& box, const md::Mat3& gradient, int nsteps, double dt, StressSample sample,
                 md::Mat3& stress_gpa);

class Batch {
 public:
  explicit Batch(int threads = 0);  // 0: OpenMP's default (OMP_NUM_THREADS or all cores)
  int threads() const { return threads_; }

  // Calls task(q) for q in [0, n) on the threads; the first exception is rethrown here.
  void for_each(std::size_t n, const std::function<void(std::size_t)>& task) const;

  // Advances boxes[q] by nsteps MD steps of dt (ps) under gradients[q] (1/ps) and
  // returns its stress (GPa, Cauchy) in stress_gpa[q]. A box that fails stops the
  // batch with a RunError naming the lowest failing point, first_point + q (the same
  // on any thread count). `seconds`, when given, gains each box's wall time (its cost,
  // for balancing the ranks).
  void advance(std::vector<md::System>& boxes, const std::vector<md::Mat3>& gradients, int nsteps,
               double dt, StressSample sample, std::vector<md::Mat3>& stress_gpa,
               std::size_t first_point = 0, std::vector<double>* seconds = nullptr) const;

  // task(q) for each of n boxes on the threads, as advance does it: a failing box stops
  // the batch with a RunError naming the lowest failing point, first_point + q; each
  // box's wall time is added to seconds[q] when given.
  void each_box(std::size_t n, std::size_t first_point, std::vector<double>* seconds,
                const std::function<void(std::size_t)>& task) const;

 private:
  int threads_;
};

}  // namespace mpmx::multiscale
