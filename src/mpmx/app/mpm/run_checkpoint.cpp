#include "mpmx/app/mpm/run_checkpoint.hpp"

#include <optional>
#include <ostream>
#include <sstream>

#include <fmt/format.h>

#include "mpmx/app/mpm/checkpoint.hpp"
#include "mpmx/core/error.hpp"
#include "mpmx/core/ranks.hpp"
#include "mpmx/io/checked_file.hpp"

namespace mpmx::app {

namespace {

std::string deck_text(const MpmConfig& c) {
  std::ostringstream ss;
  ss << c.deck;
  return ss.str();
}

// The carried figures in their order in the file.
template <class Carry, class Book>
auto carried(Carry& k, Book& book) {
  return std::array{&k.momentum_initial[0], &k.momentum_initial[1], &k.momentum_initial[2], &k.kinetic_initial,
                    &k.mass_particles,      &k.momentum_scale,      &k.max_kinetic,         &book.eq712.squared_difference,
                    &book.eq712.squared_reference, &k.wall_before,  &k.stored_initial};
}

}  // namespace

template <int Dim>
void save_run_checkpoint(const std::string& path, const MpmConfig& c, const mpm::State<Dim>& s,
                         const RunCarry& carry, const ErrorBook& book, const io::RunRecord& rec,
                         const Output::Marks& marks) {
  // Every rank fills the stream (the laws gather their state to rank 0): rank 0's goes to
  // the file as it comes, the others' nowhere.
  std::optional<io::CheckedWriter> file;
  if (ranks::root()) file.emplace(path, run_checkpoint_kind(deck_text(c), s.particles.size()));
  std::ostream nowhere(nullptr);
  std::ostream& f = file ? file->stream() : nowhere;
  CheckpointOut w(f);
  w.text(deck_text(c));
  w.inputs();
  save_state(w, s);
  for (const double* v : carried(carry, book)) w.number(*v);
  w.integer(static_cast<std::int64_t>(book.errors.size()));
  for (const auto& [name, e] : book.errors) {
    w.text(name);
    w.numbers({e.l1, e.l2, e.peak});
  }
  std::vector<double> fr;
  for (const auto& [t, x] : book.fronts) fr.push_back(t), fr.push_back(x);
  w.numbers(fr);
  std::ostringstream table;
  table << rec.table();
  w.text(table.str());
  w.marks(marks);
  carry.steps.save(w);
  if (file) file->commit();
}

template <int Dim>
Output::Marks load_run_checkpoint(const std::string& path, const MpmConfig& c, mpm::State<Dim>& s, RunCarry& carry,
                                  ErrorBook& book, io::RunRecord& rec) {
  std::istringstream f(io::read_checked(path, run_checkpoint_kind(deck_text(c), s.particles.size())),
                       std::ios::binary);
  CheckpointIn in(f, path, io::kCheckedHeaderBytes);
  if (in.text() != deck_text(c))
    throw InputError(fmt::format("{} was written for another deck (the deck changed since); run afresh "
                                 "without --resume",
                                 path));
  in.check_inputs();
  load_state(in, s);
  // A checkpoint is written before the last step, never at or past it.
  if (!c.cfl_dt && s.step >= c.steps())
    throw in.refuse(io::kCheckedHeaderBytes,
                    fmt::format("step {} is at or past the deck's last step {}", s.step, c.steps()));
  if (!(s.time < c.end))
    throw in.refuse(io::kCheckedHeaderBytes, fmt::format("time {} is at or past the deck's end {}", s.time, c.end));
  for (double* v : carried(carry, book)) *v = in.number();
  for (std::int64_t k = in.integer(); k > 0; --k) {
    const long long at = in.offset();
    const std::string name = in.text();
    const auto e = in.numbers();
    if (e.size() != 3) throw in.refuse(at, "an error norm of other than 3 numbers");
    book.errors[name] = {e[0], e[1], e[2]};
  }
  const auto fr = in.numbers();
  for (std::size_t k = 0; k + 1 < fr.size(); k += 2) book.fronts.emplace_back(fr[k], fr[k + 1]);
  const long long at_rec = in.offset();
  try {
    rec.assign(toml::parse(in.text()));
  } catch (const toml::parse_error& e) {
    throw in.refuse(at_rec, fmt::format("its run record does not parse: {}", e.what()));
  }
  const Output::Marks marks = in.marks();
  carry.steps.load(in);
  in.end();
  return marks;
}

#define MPMX_RUN_CHECKPOINT(D)                                                                                     \
  template void save_run_checkpoint<D>(const std::string&, const MpmConfig&, const mpm::State<D>&, const RunCarry&, \
                                       const ErrorBook&, const io::RunRecord&, const Output::Marks&);              \
  template Output::Marks load_run_checkpoint<D>(const std::string&, const MpmConfig&, mpm::State<D>&, RunCarry&,   \
                                                ErrorBook&, io::RunRecord&);
MPMX_RUN_CHECKPOINT(1)
MPMX_RUN_CHECKPOINT(2)
MPMX_RUN_CHECKPOINT(3)
#undef MPMX_RUN_CHECKPOINT

}  // namespace mpmx::app
