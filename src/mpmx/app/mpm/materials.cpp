#include "mpmx/app/mpm/materials.hpp"

namespace mpmx::app {

material::Context material_context(int dim, const std::string& deck_dir, const std::string& units) {
  material::Context ctx{dim, deck_dir, units, {}};
  ctx.crystal_of = [deck_dir, units](Table& table, std::string_view key) {
    return multiscale::potential_crystal(table, key, deck_dir, units);
  };
  return ctx;
}

std::shared_ptr<const material::Model> read_material(Table& table, const material::Context& ctx) {
  const std::string model = table.choice("model", Materials::names());
  return Materials::with(
      model, [&]<class E>() { return E::read(table, ctx); },
      [] { return std::shared_ptr<const material::Model>(); });
}

}  // namespace mpmx::app
