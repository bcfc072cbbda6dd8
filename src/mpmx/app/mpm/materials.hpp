#pragma once
// The materials a continuum deck names ([material] model = ...): one line each. An entry
// is a struct with `name` and `read(Table&, const Context&)` returning its Model
// (material/model.hpp); the order is the one error messages list them in.
#include <memory>
#include <string>
#include <vector>

#include "mpmx/core/registry.hpp"
#include "mpmx/material/cubic_elastic.hpp"
#include "mpmx/material/ideal_gas_model.hpp"
#include "mpmx/material/linear_elastic_model.hpp"
#include "mpmx/material/mie_gruneisen.hpp"
#include "mpmx/multiscale/md_closure_model.hpp"

namespace mpmx::app {

using Materials = Registry<material::LinearElasticEntry,       //
                           material::IdealGasIsothermalEntry,  //
                           material::IdealGasAdiabaticEntry,   //
                           multiscale::MdClosureEntry,         //
                           material::CubicElasticEntry,        //
                           material::MieGruneisenEntry>;

// The reader's context for a deck: its dimension, folder and units, and the MD engine's
// crystals for the laws that take their constants from a potential.
material::Context material_context(int dim, const std::string& deck_dir, const std::string& units);

// Reads `model` and the rest of the table by that model's entry; an unknown name is an
// error listing the known ones (recorded in the table; nullptr then).
std::shared_ptr<const material::Model> read_material(Table& table, const material::Context& ctx);

}  // namespace mpmx::app
