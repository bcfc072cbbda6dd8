#include "mpmx/material/registry.hpp"

#include <fmt/format.h>

#include "mpmx/material/cubic_elastic.hpp"
#include "mpmx/material/ideal_gas_model.hpp"
#include "mpmx/material/linear_elastic_model.hpp"
#include "mpmx/material/md_closure_model.hpp"
#include "mpmx/material/mie_gruneisen.hpp"

namespace mpmx::material {

const std::vector<Entry>& registry() {
  static const std::vector<Entry> entries{
      {"linear_elastic", read_linear_elastic},
      {"ideal_gas_isothermal", read_ideal_gas_isothermal},
      {"ideal_gas_adiabatic", read_ideal_gas_adiabatic},
      {"md_closure", read_md_closure},
      {"cubic_elastic", read_cubic_elastic},
      {"mie_gruneisen", read_mie_gruneisen},
  };
  return entries;
}

std::vector<std::string> names() {
  std::vector<std::string> n;
  for (const auto& e : registry()) n.push_back(e.name);
  return n;
}

std::shared_ptr<const Model> read(io::Section& table, const Context& ctx) {
  const std::string model = table.choice("model", names());
  for (const auto& e : registry())
    if (e.name == model) return e.read(table, ctx);
  return nullptr;  // the choice above recorded the error
}

}  // namespace mpmx::material
