#pragma once
// Every unit conversion of mpmx lives here. MD uses LAMMPS "metal" units
// (Angstrom, ps, eV, amu, K); continuum decks name their own consistent system.

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

}  // namespace mpmx::units
