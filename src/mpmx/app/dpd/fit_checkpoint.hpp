#pragma once
// A stopped fit's checkpoint (OUT/checkpoint.bin, framed as every run's: io/checked_file):
// the stages it finished, so that `fit-dpd --resume` continues from the last of them with
// the bits of a fit never stopped. The stages: the MD isotherm, the MD crystal's elastic
// constants ([elastic]), then each fit round (multiscale::FitRound). A stage stopped
// half-way is run again whole.
#include <optional>
#include <string>
#include <vector>

#include "mpmx/multiscale/isotherm.hpp"
#include "mpmx/multiscale/md_to_dpd_fit.hpp"
#include "mpmx/multiscale/strained_box.hpp"

namespace mpmx::app::dpd {

struct FitProgress {
  std::optional<std::vector<multiscale::IsothermPoint>> md;  // the MD isotherm, once measured
  std::optional<multiscale::CubicConstants> md_elastic;      // the MD crystal's constants, once measured
  std::optional<multiscale::FitRound> round;                 // the last finished round's state
  bool empty() const { return !md; }
  // The stages finished: the isotherm, the constants, each round.
  int stages() const { return md ? 1 + (md_elastic ? 1 : 0) + (round ? round->next : 0) : 0; }
  std::string stage() const;  // what it holds, in words
};

// `deck_text`: the deck's canonical text (a checkpoint resumes only its own deck);
// `densities`: the deck's count of densities, kept in the frame.
void write_fit_checkpoint(const std::string& path, const std::string& deck_text, std::size_t densities,
                          const FitProgress& p);
// Refuses (InputError, the byte and the reason) a damaged file, another deck's or kind's.
FitProgress read_fit_checkpoint(const std::string& path, const std::string& deck_text, std::size_t densities);

}  // namespace mpmx::app::dpd
