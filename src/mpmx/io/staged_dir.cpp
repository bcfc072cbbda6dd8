#include "mpmx/io/staged_dir.hpp"

#include <filesystem>

#include <fmt/format.h>

#include "mpmx/core/error.hpp"
#include "mpmx/core/file_text.hpp"
#include "mpmx/io/run_manifest.hpp"

namespace mpmx::io {

namespace fs = std::filesystem;

namespace {

// The regular files under `dir`, relative, the staging folder, the list and the lock aside.
std::set<std::string> files_under(const fs::path& dir) {
  std::set<std::string> files;
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) return files;
  for (auto it = fs::recursive_directory_iterator(dir, ec); !ec && it != fs::recursive_directory_iterator();
       it.increment(ec)) {
    const std::string rel = fs::relative(it->path(), dir, ec).generic_string();
    if (rel == ".staging" || rel == kManifestName || rel == FolderLock::kName) {
      if (it->is_directory()) it.disable_recursion_pending();
      continue;
    }
    if (it->is_regular_file()) files.insert(rel);
  }
  return files;
}

// A half-written file (AtomicWriter's .tmp) of a killed run: never a result.
bool temporary(const std::string& rel) { return rel.size() > 4 && rel.compare(rel.size() - 4, 4, ".tmp") == 0; }

[[noreturn]] void machine_failed(const std::string& what, const fs::path& path, const std::error_code& ec) {
  throw SystemError(fmt::format("{} {}: {}", what, path.string(), ec.message()));
}

// Removes `rel` under `out` and the folders above it that it leaves empty.
void remove_file(const fs::path& out, const std::string& rel) {
  std::error_code ec;
  const fs::path p = out / rel;
  if (!fs::is_regular_file(fs::symlink_status(p, ec))) return;
  if (!fs::remove(p, ec) && ec) machine_failed("cannot remove", p, ec);
  for (fs::path up = p.parent_path(); up != out && fs::is_empty(up, ec) && !ec; up = up.parent_path())
    fs::remove(up, ec);
}

}  // namespace

std::string StagedDir::staging_of(const std::string& out) { return (fs::path(out) / ".staging").string(); }

StagedDir::StagedDir(std::string out, Mode mode, FolderOwner owner)
    : out_(std::move(out)), staging_(mode == Mode::in_place ? out_ : staging_of(out_)), mode_(mode),
      owner_(std::move(owner)) {
  std::error_code ec;
  out_existed_ = fs::exists(out_, ec);
  // Every command's --out: a file there is the user's, never a folder to write into.
  if (out_existed_ && !fs::is_directory(out_, ec))
    throw InputError(fmt::format("--out {}: exists and is not a directory", out_));
  // Made now, before the run's work: a folder that cannot be (read-only, a name too long)
  // is bad input, said in words; a run that never writes removes it again.
  if (fs::create_directories(out_, ec); ec || !fs::is_directory(out_, ec)) {
    const auto e = static_cast<std::errc>(ec.value());
    const std::string why =
        e == std::errc::no_such_file_or_directory ? "a folder on its path cannot be made there"
        : e == std::errc::permission_denied || e == std::errc::operation_not_permitted
            ? "permission denied: the folder it goes in cannot be written"
            : path_problem(out_, ec);
    throw InputError(fmt::format("--out {}: cannot make the output folder: {}", short_path(out_), why));
  }
  try {
    // The lock first: until it is held, the folder may be another run's to write.
    lock_.emplace(out_);
    const auto held = read_manifest(out_);
    // An owner not said (a caller of the library) is no one's: it neither refuses nor is refused.
    if (held && !held->owner.empty() && !owner_.run.empty() && held->owner != owner_.run && !owner_.overwrite)
      throw InputError(fmt::format("--out {} holds the results of another run (another deck or command: {}); this "
                                   "is {}: give another --out, or --overwrite to replace that run's files (only "
                                   "the files mpmx wrote there go)",
                                   short_path(out_), held->owner, owner_.run));
    if (mode_ == Mode::in_place) {
      // A file a killed run was writing whole (NAME.tmp of a file of its own): never a result.
      for (const auto& f : files_under(out_)) {
        const std::string name = f.substr(0, f.size() - 4);
        if (temporary(f) && ((held && held->files.count(name)) || name == "checkpoint.bin" || name == "run.json"))
          fs::remove(fs::path(out_) / f, ec);
      }
      before_ = files_under(out_);
      return;
    }
    if (mode_ == Mode::fresh) fs::remove_all(staging_, ec);
    if (fs::create_directories(staging_, ec); ec || !fs::is_directory(staging_, ec))
      throw InputError(fmt::format("--out {}: cannot make the staging folder {}: {}", short_path(out_),
                                   short_path(staging_), path_problem(staging_, ec)));
  } catch (...) {
    lock_.reset();
    if (!out_existed_ && fs::is_empty(out_, ec) && !ec) fs::remove(out_, ec);
    throw;
  }
}

void StagedDir::publish() {
  const fs::path out(out_);
  const auto held = read_manifest(out_);
  RunManifest m{owner_.run.empty() && held ? held->owner : owner_.run, held ? held->files : std::set<std::string>{}};
  if (mode_ == Mode::in_place) {
    // The files the resumed run added (a checkpoint it removed drops out).
    for (const auto& f : files_under(out))
      if (!before_.count(f) && !temporary(f)) m.files.insert(f);
    std::erase_if(m.files, [&](const std::string& f) { return !fs::exists(out / f); });
    write_manifest(out_, m);
    published_ = true;
    return;
  }
  std::set<std::string> fresh;
  for (const auto& f : files_under(staging_))
    if (!temporary(f)) fresh.insert(f);
  // What goes: another run's files all; of the folder's own, those in a folder this run
  // writes again (vtk/ whole, as the run made it).
  std::set<std::string> replaced;
  const bool other = held && !held->owner.empty() && held->owner != m.owner;
  for (const auto& f : m.files) {
    const auto slash = f.find('/');
    if (other || (slash != std::string::npos && fs::is_directory(fs::path(staging_) / f.substr(0, slash))))
      replaced.insert(f);
  }
  // Claimed before anything moves: a publish cut short leaves every file it touched named.
  m.files.insert(fresh.begin(), fresh.end());
  write_manifest(out_, m);
  for (const auto& f : replaced)
    if (!fresh.count(f)) remove_file(out, f);
  std::error_code ec;
  for (const auto& f : fresh) {
    const fs::path from = fs::path(staging_) / f, to = out / f;
    fs::create_directories(to.parent_path(), ec);
    if (ec) machine_failed("cannot make the folder", to.parent_path(), ec);
    fs::rename(from, to, ec);
    if (ec) throw SystemError(fmt::format("cannot move {} to {}: {}", from.string(), to.string(), ec.message()));
  }
  for (const auto& f : replaced)
    if (!fresh.count(f)) m.files.erase(f);
  std::erase_if(m.files, [&](const std::string& f) { return !fs::exists(out / f); });
  write_manifest(out_, m);
  fs::remove_all(staging_, ec);
  published_ = true;
}

void record_written(const std::string& out, const std::string& owner, const std::set<std::string>& files) {
  const auto held = read_manifest(out);
  const bool other = held && !held->owner.empty() && held->owner != owner;
  RunManifest m{owner, {}};
  if (held && !other) m.files = held->files;
  m.files.insert(files.begin(), files.end());
  write_manifest(out, m);
  if (other)
    for (const auto& f : held->files)
      if (!files.count(f)) remove_file(out, f);
}

StagedDir::~StagedDir() {
  if (published_ || mode_ == Mode::in_place) return;
  std::error_code ec;
  // A staging folder with a checkpoint is a run --resume continues (a run the disk
  // failed after a checkpoint); any other is only half a run.
  if (!fs::exists(fs::path(staging_) / "checkpoint.bin", ec)) fs::remove_all(staging_, ec);
  lock_.reset();
  if (!out_existed_ && fs::is_empty(out_, ec) && !ec) fs::remove(out_, ec);
}

}  // namespace mpmx::io
