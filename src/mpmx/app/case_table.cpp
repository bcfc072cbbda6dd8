#include "mpmx/app/case_table.hpp"

#include <filesystem>

#include <fmt/format.h>

#include "mpmx/core/file_text.hpp"
#include "mpmx/core/units.hpp"

namespace mpmx::app {

CaseTable read_case_table(io::Section& root, const std::string& deck_name, bool required,
                          std::string_view fixed_units) {
  CaseTable c;
  if (!required && !root.has("case")) {
    c.id = escape_controls(std::filesystem::path(deck_name).stem().string());
    c.units = fixed_units;
    return c;
  }
  io::Section cs = root.table("case");
  c.id = escape_controls(required ? cs.string("id") : cs.string("id", std::filesystem::path(deck_name).stem().string()));
  c.title = cs.string("title", "");
  c.seed = cs.string("seed", "");
  c.units = cs.string("units", fixed_units.empty() ? "dimensionless" : std::string(fixed_units));
  if (const std::string why = units::case_units_problem(c.units); !why.empty()) cs.check(false, "units", why);
  else if (!fixed_units.empty() && c.units != fixed_units)
    cs.check(false, "units",
             fmt::format("this kind of deck is in {} units (Angstrom, ps, eV, amu, K, GPa): give \"{}\" or leave "
                         "case.units out",
                         fixed_units, fixed_units));
  return c;
}

}  // namespace mpmx::app
