#pragma once
// What mpmx wrote into an output folder: OUT/.mpmx-files names the run that owns the
// folder (its command and deck) and every file it put there, relative to OUT. A later run
// reads it to tell its own earlier results (replaced as they always were) from another
// run's (refused unless --overwrite, then removed whole), and to delete only files mpmx
// wrote: a user's own files in the folder are never touched.
#include <optional>
#include <set>
#include <string>

namespace mpmx::io {

struct RunManifest {
  std::string owner;            // "run /abs/deck.toml": the command and the deck's absolute path
  std::set<std::string> files;  // relative to the folder
};

// The manifest's name in a run folder.
inline constexpr const char* kManifestName = ".mpmx-files";

// OUT's manifest; none when OUT has none (a folder no mpmx run has finished in, or one
// written by an mpmx before manifests). A damaged one is InputError naming it.
std::optional<RunManifest> read_manifest(const std::string& out);

// Writes OUT's manifest whole or not at all.
void write_manifest(const std::string& out, const RunManifest& m);

// The owner text of a command's run of `deck`.
std::string run_owner(const std::string& command, const std::string& deck);

}  // namespace mpmx::io
