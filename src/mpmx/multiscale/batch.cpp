#include "mpmx/multiscale/batch.hpp"

#include <chrono>
#include <exception>
#include <limits>
#include <mutex>
#include <string>

#include <fmt/format.h>
#include <omp.h>

#include "mpmx/core/error.hpp"

namespace mpmx::multiscale {

Batch::Batch(int threads) : threads_(threads > 0 ? threads : omp_get_max_threads()) {}

void Batch::for_each(std::size_t n, const std::function<void(std::size_t)>& task) const {
  std::exception_ptr failure;
  std::mutex m;
  const long count = static_cast<long>(n);
  // Dynamic, one box at a time: boxes differ in cost (neighbour rebuilds, compression).
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads_)
  for (long q = 0; q < count; ++q) {
    try {
      task(static_cast<std::size_t>(q));
    } catch (...) {
      std::lock_guard<std::mutex> lock(m);
      if (!failure) failure = std::current_exception();
    }
  }
  if (failure) std::rethrow_exception(failure);
}

void advance_box(md::System& box, const md::Mat3& gradient, int nsteps, double dt, StressSample sample,
                 md::Mat3& stress_gpa) {
  if (sample == StressSample::last) {
    box.advance(nsteps, gradient, dt);
    stress_gpa = box.stress_gpa();
    return;
  }
  md::Mat3 sum{};
  for (int s = 0; s < nsteps; ++s) {
    box.advance(1, gradient, dt);
    const md::Mat3 now = box.stress_gpa();
    for (int c = 0; c < 9; ++c) sum[c] += now[c];
  }
  for (int c = 0; c < 9; ++c) stress_gpa[c] = sum[c] / nsteps;
}

void Batch::advance(std::vector<md::System>& boxes, const std::vector<md::Mat3>& gradients, int nsteps,
                    double dt, StressSample sample, std::vector<md::Mat3>& stress_gpa,
                    std::size_t first_point, std::vector<double>* seconds) const {
  stress_gpa.resize(boxes.size());
  each_box(boxes.size(), first_point, seconds,
           [&](std::size_t q) { advance_box(boxes[q], gradients[q], nsteps, dt, sample, stress_gpa[q]); });
}

void Batch::each_box(std::size_t n, std::size_t first_point, std::vector<double>* seconds,
                     const std::function<void(std::size_t)>& task) const {
  std::mutex m;
  std::size_t failed = std::numeric_limits<std::size_t>::max();
  std::string why;
  for_each(n, [&](std::size_t q) {
    try {
      const auto t0 = std::chrono::steady_clock::now();
      task(q);
      if (seconds) (*seconds)[q] += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    } catch (const std::exception& e) {
      std::lock_guard<std::mutex> lock(m);
      if (q < failed) failed = q, why = e.what();
    }
  });
  if (failed != std::numeric_limits<std::size_t>::max())
    throw RunError(fmt::format("the MD box of material point {} failed: {}", first_point + failed, why));
}

}  // namespace mpmx::multiscale
