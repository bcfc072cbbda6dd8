#include "mpmx/app/run_control.hpp"

#include <filesystem>
#include <sstream>

#include <fmt/format.h>

#include "mpmx/app/run_folder.hpp"
#include "mpmx/io/checked_file.hpp"

namespace mpmx::app {

namespace {

std::string text_of(const toml::table& deck) {
  std::ostringstream ss;
  ss << deck;
  return ss.str();
}

}  // namespace

RunControl::RunControl(std::string dir, std::string_view kind, const toml::table& deck_echo,
                       const RunControlOptions& o, std::uint32_t version)
    : dir_(std::move(dir)), kind_(kind), deck_text_(text_of(deck_echo)), version_(version), o_(o), guard_(true) {
  if (!o_.resume) tables_.emplace(dir_);
}

void RunControl::resume(std::uint64_t count, const std::function<void(CheckpointIn&)>& read) {
  const std::string path = checkpoint_path(dir_);
  std::istringstream f(io::read_checked(path, {kind_, version_, io::text_hash(deck_text_), count}),
                       std::ios::binary);
  CheckpointIn in(f, path, io::kCheckedHeaderBytes);
  if (in.text() != deck_text_)
    throw InputError(fmt::format("{} was written for another deck (the deck changed since); run afresh "
                                 "without --resume",
                                 path));
  in.check_inputs();
  read(in);
  TableMarks marks = in.marks();
  in.end();
  tables_.emplace(dir_, std::move(marks));
}

bool RunControl::stop_due(std::int64_t step) const {
  return InterruptGuard::interrupted() || (o_.stop_after > 0 && step >= o_.stop_after);
}

void RunControl::checkpoint(std::uint64_t count, const std::function<void(CheckpointOut&)>& write) {
  io::CheckedWriter file(checkpoint_path(dir_), {kind_, version_, io::text_hash(deck_text_), count});
  CheckpointOut w(file.stream());
  w.text(deck_text_);
  w.inputs();
  write(w);
  w.marks(tables_->marks());
  file.commit();
  interrupted_ = true;
}

std::string RunControl::shown_checkpoint() const { return checkpoint_path(o_.out.empty() ? dir_ : o_.out); }

void RunControl::finished() {
  tables_->marks();  // a table the disk cut short fails the run here, not silently
  std::error_code ec;
  std::filesystem::remove(checkpoint_path(dir_), ec);
}

}  // namespace mpmx::app
