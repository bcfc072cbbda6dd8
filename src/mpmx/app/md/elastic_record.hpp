#pragma once
// run.json's "elastic" of a deck with [elastic]: the 0 K tensor of its crystal
// (md/elastic_constants.hpp) in the box frame and the crystal's axes, its stability, and
// the named constants of its symmetry, with a line for the terminal.
#include <string>

#include <toml++/toml.h>

#include "mpmx/app/md/config.hpp"

namespace mpmx::app::md {

struct ElasticRecord {
  toml::table table;
  std::string summary;  // one line: the constants a user reads first
};

ElasticRecord elastic_record(const MdConfig& c, const Potential& pot);

}  // namespace mpmx::app::md
