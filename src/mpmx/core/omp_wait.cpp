#include "mpmx/core/omp_wait.hpp"

#include <unistd.h>

#include <cstdlib>

namespace mpmx {

void wait_passively(char** argv) {
  if (std::getenv("OMP_WAIT_POLICY") || std::getenv("GOMP_SPINCOUNT")) return;
  if (setenv("OMP_WAIT_POLICY", "passive", 0) != 0) return;
  // The same program, arguments and (now) environment; exec keeps the process id, so an
  // MPI launcher or a shell's job control sees the one process.
  execv("/proc/self/exe", argv);
}

}  // namespace mpmx
