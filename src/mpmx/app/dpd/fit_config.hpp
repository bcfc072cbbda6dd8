#pragma once
// The MD-to-DPD fit deck (`mpmx fit-dpd DECK`, D0): the MD potential and crystal, the
// densities of the isotherm, the DPD side (mesoparticle size, cutoff, start
// parameters, DPDE runs) and the potential file to write; every key checked (key, value,
// reason) like the other decks.
#include <string>
#include <vector>

#include "mpmx/io/deck.hpp"
#include "mpmx/md/potential/potential.hpp"
#include "mpmx/multiscale/md_to_dpd_fit.hpp"

namespace mpmx::app::dpd {

using namespace mpmx::dpd;  // the DPD driver speaks the engine's names

struct FitConfig {
  std::string id, title, seed_ref, deck_file;
  md::PotentialSpec md_potential;
  double lattice_constant = 0;          // Angstrom: the reference density rho0
  std::vector<double> density_ratios;   // rho / rho0 of the samples
  multiscale::MdIsothermOptions md;
  multiscale::FitOptions fit;
  // [elastic]: the MD crystal's strained boxes (their constants become fit.elastic's
  // targets once measured, at the isotherm's zero-pressure density).
  multiscale::StrainedBoxOptions md_elastic;
  std::string potential_file;           // written into the output folder
};

FitConfig read_fit_config(io::Deck& deck);

// Writes a DPD potential file: a TOML [potential] table that DPD decks name with
// `[potential] file = "..."`, with a comment naming its origin.
void write_potential_file(const std::string& path, const MorsePotential& m, const std::string& comment);

}  // namespace mpmx::app::dpd
