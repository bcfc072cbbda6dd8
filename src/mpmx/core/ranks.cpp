#include "mpmx/core/ranks.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <limits>
#include <new>
#include <stdexcept>
#include <thread>

#include <fmt/format.h>

#include "mpmx/core/error.hpp"

#ifdef MPMX_HAVE_MPI
#include <mpi.h>
#endif

namespace mpmx::ranks {

namespace {
int g_rank = 0, g_size = 1;
bool g_active = false;  // MPI_Init was called
bool g_agreed = false;

#ifdef MPMX_HAVE_MPI
// Started by a launcher (Open MPI's mpirun, or a PMI/PMIx launcher such as srun)?
// A binary started by hand stays single-process and never touches MPI.
bool launched() {
  for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK", "PMI_SIZE"})
    if (std::getenv(v)) return true;
  return false;
}

void check(int rc, const char* what) {
  if (rc != MPI_SUCCESS) throw std::runtime_error(fmt::format("MPI: {} failed (error {})", what, rc));
}

// Waits for r. With a bound (seconds), by testing it every millisecond: a rank waiting
// for a late one sleeps in between rather than spinning in MPI's progress loop, and past
// the bound the job ends (exit 2) with a sentence from this rank. Without one (the
// agreements between a run's steps, where every rank has just met in a collective), MPI's
// own wait.
void wait_for(MPI_Request& r, double bound) {
  if (bound <= 0) return check(MPI_Wait(&r, MPI_STATUS_IGNORE), "Wait");
  using clock = std::chrono::steady_clock;
  const auto start = clock::now();
  for (int done = 0;;) {
    check(MPI_Test(&r, &done, MPI_STATUS_IGNORE), "Test");
    if (done) return;
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
    if (std::chrono::duration<double>(clock::now() - start).count() > bound) {
      fmt::print(stderr,
                 "[rank {} of {}] mpmx: the other ranks did not reach the reading of the command line and deck "
                 "within {:g} s (MPMX_AGREE_SECONDS): a rank is stuck or was started on another command line; "
                 "the job is stopped\n",
                 g_rank, g_size, bound);
      std::fflush(stderr);
      MPI_Abort(MPI_COMM_WORLD, 2);
    }
  }
}

int checked_count(std::size_t n) {
  if (n > static_cast<std::size_t>(std::numeric_limits<int>::max()))
    throw std::runtime_error(fmt::format("MPI: {} items in one message exceed the 2^31 limit; use more ranks", n));
  return static_cast<int>(n);
}
#endif
}  // namespace

Session::Session([[maybe_unused]] int& argc, [[maybe_unused]] char**& argv) {
#ifdef MPMX_HAVE_MPI
  if (!launched()) return;
  int provided = 0;
  // Only the main thread calls MPI; OpenMP threads work between the calls.
  if (MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided) != MPI_SUCCESS) return;
  g_active = true;
  MPI_Comm_rank(MPI_COMM_WORLD, &g_rank);
  MPI_Comm_size(MPI_COMM_WORLD, &g_size);
#endif
}

Session::~Session() {
#ifdef MPMX_HAVE_MPI
  int finalized = 0;
  if (g_active && MPI_Finalized(&finalized) == MPI_SUCCESS && !finalized) MPI_Finalize();
#endif
}

int rank() { return g_rank; }
int size() { return g_size; }
bool active() { return g_active; }

std::string library() {
#ifdef MPMX_HAVE_MPI
  char text[MPI_MAX_LIBRARY_VERSION_STRING] = {};
  int len = 0;
  MPI_Get_library_version(text, &len);
  std::string s(text, static_cast<std::size_t>(std::max(len, 0)));
  // "Open MPI v4.1.4, package: ..." -> "Open MPI 4.1.4"; others: the first line.
  s = s.substr(0, std::min(s.find(','), s.find('\n')));
  if (const auto v = s.find(" v"); v != std::string::npos) s.erase(v + 1, 1);
  return s;
#else
  return "none";
#endif
}

Failure current_failure() {
  try {
    throw;
  } catch (const InputError& e) {
    return {Failure::input, e.what()};
  } catch (const RunError& e) {
    return {Failure::run, e.what()};
  } catch (const SystemError& e) {
    return {Failure::system, e.what()};
  } catch (const std::exception& e) {
    return {Failure::internal, e.what()};
  }
}

void raise(const Failure& f) {
  switch (f.kind) {
    case Failure::input: throw InputError(f.message);
    case Failure::run: throw RunError(f.message);
    case Failure::system: throw SystemError(f.message);
    case Failure::internal: break;
  }
  throw std::runtime_error(f.message);
}

double input_wait_seconds() {
  const char* text = std::getenv("MPMX_AGREE_SECONDS");
  if (!text || !*text) return 300.0;
  char* end = nullptr;
  const double s = std::strtod(text, &end);
  if (*end != '\0' || !std::isfinite(s) || s <= 0 || s > 1e6)
    throw InputError(fmt::format("MPMX_AGREE_SECONDS = '{}': expected seconds, a number above 0 and at most 1e6",
                                 std::string(text).substr(0, 40)));
  return s;
}

std::optional<Failure> first_failure(const std::optional<Failure>& mine, [[maybe_unused]] Wait wait) {
  if (g_size == 1) return mine;
#ifdef MPMX_HAVE_MPI
  const double bound = wait == Wait::input ? input_wait_seconds() : 0.0;  // 0: none
  int first = mine ? g_rank : g_size;
  MPI_Request request;
  check(MPI_Iallreduce(MPI_IN_PLACE, &first, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD, &request), "Iallreduce");
  wait_for(request, bound);
  if (first == g_size) return std::nullopt;
  Failure f = first == g_rank ? *mine : Failure{};
  int head[2] = {static_cast<int>(f.kind), checked_count(f.message.size())};
  check(MPI_Bcast(head, 2, MPI_INT, first, MPI_COMM_WORLD), "Bcast");
  f.kind = static_cast<Failure::Kind>(head[0]);
  f.message.resize(static_cast<std::size_t>(head[1]));
  check(MPI_Bcast(f.message.data(), head[1], MPI_CHAR, first, MPI_COMM_WORLD), "Bcast");
  // Bad input of a rank other than the first is said with its rank (a deck only rank 1
  // cannot read, say); the same text on every rank. A run's failures name their point.
  if (first != 0 && f.kind == Failure::input && f.message.rfind("[rank ", 0) != 0)
    f.message = fmt::format("[rank {} of {}] {}", first, g_size, f.message);
  return f;
#else
  return mine;
#endif
}

void together(const std::function<void()>& f, Wait wait) {
  std::optional<Failure> mine;
  try {
    f();
  } catch (const std::bad_alloc&) {
    mine = Failure{Failure::internal, fmt::format("out of memory on rank {}", g_rank)};
  } catch (const std::exception&) {
    mine = current_failure();
  }
  if (const auto agreed = first_failure(mine, wait)) {
    mark_agreed();
    raise(*agreed);
  }
}

bool failure_agreed() { return g_size == 1 || g_agreed; }
void mark_agreed() { g_agreed = true; }

void abort_job(int code) {
#ifdef MPMX_HAVE_MPI
  if (g_active) MPI_Abort(MPI_COMM_WORLD, code);
#endif
  std::exit(code);
}

std::vector<double> max(std::vector<double> v) {
#ifdef MPMX_HAVE_MPI
  if (g_size > 1)
    check(MPI_Allreduce(MPI_IN_PLACE, v.data(), checked_count(v.size()), MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD),
          "Allreduce");
#endif
  return v;
}

double sum(double v) {
#ifdef MPMX_HAVE_MPI
  if (g_size > 1) check(MPI_Allreduce(MPI_IN_PLACE, &v, 1, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD), "Allreduce");
#endif
  return v;
}

std::vector<double> all_gather(const std::vector<double>& mine, [[maybe_unused]] const std::vector<int>& counts) {
  if (g_size == 1) return mine;
#ifdef MPMX_HAVE_MPI
  std::vector<int> offsets(counts.size(), 0);
  std::size_t total = 0;
  for (std::size_t r = 0; r < counts.size(); ++r) offsets[r] = checked_count(total), total += counts[r];
  std::vector<double> all(total);
  check(MPI_Allgatherv(mine.data(), checked_count(mine.size()), MPI_DOUBLE, all.data(), counts.data(),
                       offsets.data(), MPI_DOUBLE, MPI_COMM_WORLD),
        "Allgatherv");
  return all;
#else
  return mine;
#endif
}

std::string gather_to_root(const std::string& mine) {
  if (g_size == 1) return mine;
#ifdef MPMX_HAVE_MPI
  const int n = checked_count(mine.size());
  std::vector<int> counts(static_cast<std::size_t>(g_size)), offsets(counts.size(), 0);
  check(MPI_Gather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, MPI_COMM_WORLD), "Gather");
  std::string all;
  if (g_rank == 0) {
    std::size_t total = 0;
    for (std::size_t r = 0; r < counts.size(); ++r) offsets[r] = checked_count(total), total += counts[r];
    all.resize(total);
  }
  check(MPI_Gatherv(mine.data(), n, MPI_CHAR, all.data(), counts.data(), offsets.data(), MPI_CHAR, 0,
                    MPI_COMM_WORLD),
        "Gatherv");
  return all;
#else
  return mine;
#endif
}

std::string exchange(const std::vector<std::string>& to_rank) {
  if (g_size == 1) return to_rank.at(0);
#ifdef MPMX_HAVE_MPI
  const auto n = static_cast<std::size_t>(g_size);
  std::vector<int> send_counts(n), send_offsets(n), recv_counts(n), recv_offsets(n);
  std::string out;
  for (std::size_t r = 0; r < n; ++r) {
    send_counts[r] = checked_count(to_rank[r].size());
    send_offsets[r] = checked_count(out.size());
    out += to_rank[r];
  }
  check(MPI_Alltoall(send_counts.data(), 1, MPI_INT, recv_counts.data(), 1, MPI_INT, MPI_COMM_WORLD), "Alltoall");
  std::size_t total = 0;
  for (std::size_t r = 0; r < n; ++r) recv_offsets[r] = checked_count(total), total += recv_counts[r];
  std::string in(total, '\0');
  check(MPI_Alltoallv(out.data(), send_counts.data(), send_offsets.data(), MPI_CHAR, in.data(), recv_counts.data(),
                      recv_offsets.data(), MPI_CHAR, MPI_COMM_WORLD),
        "Alltoallv");
  return in;
#else
  return to_rank.at(0);
#endif
}

}  // namespace mpmx::ranks
