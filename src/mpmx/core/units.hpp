#pragma once
// Every unit conversion of mpmx lives here. MD uses LAMMPS "metal" units
// (Angstrom, ps, eV, amu, K); continuum decks name their own consistent system.

#include <optional>
#include <string>
#include <string_view>

namespace mpmx::units {

inline constexpr double eV_per_A3_in_GPa = 160.21766208;     // 1 eV/A^3 in GPa
inline constexpr double boltzmann_eV_per_K = 8.617343e-5;     // LAMMPS metal k_B
// m v^2 with m in amu and v in A/ps gives energy in eV times this factor inverse:
// 1 amu A^2/ps^2 = 1.0364269e-4 eV (LAMMPS metal mvv2e).
inline constexpr double mvv2e = 1.0364269e-4;
inline constexpr double ftm2v = 1.0 / 1.0364269e-4;           // eV/A/amu -> A/ps^2
inline constexpr double angstrom_in_m = 1e-10;
inline constexpr double ps_in_s = 1e-12;
inline constexpr double A_per_ps_in_m_per_s = 100.0;         // 1 A/ps = 100 m/s
inline constexpr double GPa_in_Pa = 1e9;
// LAMMPS metal pressure factor (eV/A^3 -> bar) as LAMMPS defines it; used when
// comparing with LAMMPS output to round-off.
inline constexpr double lammps_nktv2p = 1.6021765e6;

inline constexpr double amu_in_kg = 1.66053906660e-27;

// A continuum unit system by its size in MD units: one continuum length in Angstrom,
// time in ps, stress in GPa. Mass follows (stress time^2 length), so density,
// velocity and energy are consistent. The multiscale closure converts here only.
struct UnitSystem {
  std::string_view name;
  double length_A, time_ps, stress_GPa;
  double velocity_A_per_ps() const { return length_A / time_ps; }
};

// nm_ps_GPa: nm, ps, GPa, so density is g/cm^3 and velocity km/s (mass unit 1e-24 kg).
// mm_us_GPa: mm, microsecond, GPa, the same density and velocity units.
// metal: Angstrom, ps, amu (LAMMPS); SI: m, s, kg.
inline constexpr UnitSystem kUnitSystems[] = {
    {"nm_ps_GPa", 10.0, 1.0, 1.0},
    {"mm_us_GPa", 1e7, 1e6, 1.0},
    {"metal", 1.0, 1.0, amu_in_kg / (angstrom_in_m * ps_in_s * ps_in_s) / GPa_in_Pa},
    {"SI", 1e10, 1e12, 1.0 / GPa_in_Pa},
};

inline std::optional<UnitSystem> unit_system(std::string_view name) {
  for (const auto& u : kUnitSystems)
    if (u.name == name) return u;
  return std::nullopt;
}

inline std::string unit_system_names() {
  std::string s;
  for (const auto& u : kUnitSystems) s += (s.empty() ? "" : ", ") + std::string(u.name);
  return s;
}

// The one rule for case.units in every deck kind: a known system's name, or, for a
// continuum deck in units of its own, "dimensionless" (alone or followed by what sets the
// scale: "dimensionless (E = rho0 = 1)"). A free description is refused, since a slip
// ("nm_ps_Gpa") would otherwise pass as one. "" when `units` follows the rule, else why not.
inline std::string case_units_problem(std::string_view units) {
  if (unit_system(units)) return {};
  constexpr std::string_view free = "dimensionless";
  if (units.substr(0, free.size()) == free &&
      (units.size() == free.size() || units[free.size()] == ' ' || units[free.size()] == '('))
    return {};
  return "not a known unit system: give one of " + unit_system_names() +
         ", or \"dimensionless\" (followed by what sets the scale, e.g. \"dimensionless (E = rho0 = 1)\")";
}

}  // namespace mpmx::units
