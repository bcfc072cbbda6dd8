#pragma once
// The references a continuum deck names ([reference] name = ...): one line each. An
// entry is a struct with
//   name       what the deck calls it
//   material   the law it needs ("" for any): the deck's material.model must be it
//   dims       the dimensions it runs in (bit d - 1 for d-D)
//   make<Dim>  the run's Comparison (comparison.hpp), from the deck; InputError when the
//              deck does not suit it
//   read_keys  its own keys of the [reference] table beyond the common ones (name,
//              fields, times, at), and its fields' defaults (ReferenceEntry: none)
// Its solution lives in reference/, the entry in references/<name>.cpp. The order is the
// one error messages list them in.
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "mpmx/app/mpm/comparison.hpp"
#include "mpmx/core/registry.hpp"

namespace mpmx::app {

// What an entry does unless it says otherwise.
struct ReferenceEntry {
  // The fields a deck may compare.
  static std::vector<std::string> known_fields() { return {"velocity", "strain", "stress", "pressure", "density"}; }
  // Its own keys (none: a `file` is refused) and the fields compared when the deck lists none.
  static void read_keys(Table& r, MpmConfig& c, const std::string& deck_dir);
};

#define MPMX_REFERENCE_ENTRY(Type, Name, Material, Dims)                 \
  struct Type : ReferenceEntry {                                         \
    static constexpr std::string_view name = Name;                       \
    static constexpr std::string_view material = Material;               \
    static constexpr unsigned dims = Dims;                               \
    template <int Dim>                                                   \
    static std::unique_ptr<Comparison<Dim>> make(const MpmConfig& c);    \
  };

// ADMPM sec. 8.1 (figs. 6-8): a standing wave in an elastic bar.
MPMX_REFERENCE_ENTRY(StandingWaveEntry, "standing_wave", "linear_elastic", 0b001)
// ADMPM sec. 8.2: a wave driven into a bar from its right end, reflected at the left.
MPMX_REFERENCE_ENTRY(WaveReflectionEntry, "wave_reflection", "linear_elastic", 0b001)
// A wave driven into an adiabatic gas (VALIDATION.md A4).
MPMX_REFERENCE_ENTRY(GasWaveEntry, "gas_wave", "ideal_gas_adiabatic", 0b001)
// The isothermal gas's Riemann problem, along the pressure step's normal in 2-D and 3-D.
MPMX_REFERENCE_ENTRY(RiemannIsothermalEntry, "riemann_isothermal", "ideal_gas_isothermal", 0b111)
// The speed of a shock front (ADMPM sec. 8.3), against the bar's sqrt(E / rho).
MPMX_REFERENCE_ENTRY(ShockFrontEntry, "shock_front", "", 0b001)
// The manufactured solution of [manufactured] (VALIDATION.md N4): displacement errors.
struct ManufacturedEntry : ReferenceEntry {
  static constexpr std::string_view name = "manufactured";
  static constexpr std::string_view material = "linear_elastic";
  static constexpr unsigned dims = 0b110;
  template <int Dim>
  static std::unique_ptr<Comparison<Dim>> make(const MpmConfig& c);
  static std::vector<std::string> known_fields() { return {"displacement"}; }
  // Needs the [manufactured] table; compares the displacement by default.
  static void read_keys(Table& r, MpmConfig& c, const std::string& deck_dir);
};
// Direct MD of the same sample, eq. 7.12: a bar's binned stress (1-D), a jet's maps.
struct DirectMdEntry : ReferenceEntry {
  static constexpr std::string_view name = "direct_md";
  static constexpr std::string_view material = "";
  static constexpr unsigned dims = 0b111;
  template <int Dim>
  static std::unique_ptr<Comparison<Dim>> make(const MpmConfig& c);
  // `file`: the direct-MD run's table (1-D) or folder (2-D, 3-D); case.units; in 2-D and
  // 3-D the times and no fields (eq. 7.12 on sigma_xx), in 1-D the stress by default.
  static void read_keys(Table& r, MpmConfig& c, const std::string& deck_dir);
};

#undef MPMX_REFERENCE_ENTRY

using References = Registry<StandingWaveEntry, WaveReflectionEntry, GasWaveEntry, RiemannIsothermalEntry,
                            ShockFrontEntry, ManufacturedEntry, DirectMdEntry>;

// An InputError "reference 'name': what" unless ok (the deck does not suit the reference).
void need(bool ok, std::string_view reference, std::string_view what);

// The names that run in `dim` dimensions, in list order.
std::vector<std::string> reference_names(int dim);

}  // namespace mpmx::app
