#pragma once
// A potential picked by name ("eam", "lj", "sutton_chen"); the variant is dispatched once
// per force evaluation, never per pair.
#include <memory>
#include <string>
#include <variant>
#include <vector>

#include "mpmx/md/forces.hpp"
#include "mpmx/md/neighbor.hpp"
#include "mpmx/md/potential/eam.hpp"
#include "mpmx/md/potential/lj.hpp"
#include "mpmx/md/potential/sutton_chen.hpp"

namespace mpmx::md {

struct PotentialSpec {
  std::string style = "eam";            // eam | lj | sutton_chen
  std::string file;                     // eam: potential file (format from its name)
  std::vector<std::string> elements;    // eam: file element of each atom type
  double epsilon = 0, sigma = 0, a = 0, c = 0, cutoff = 0, mass = 0;  // lj, sutton_chen
  int n = 0, m = 0;                     // sutton_chen exponents
  bool shift = false;                   // lj: shift energy to zero at the cutoff
};

// Finds a potential file: an absolute path as given; a relative one against `deck_dir`
// (the working directory when empty), then in /usr/share/lammps/potentials. Throws InputError listing the places tried.
std::string resolve_potential_file(const std::string& name, const std::string& deck_dir);

class Potential {
 public:
  explicit Potential(const PotentialSpec& spec);
  explicit Potential(Eam eam) : impl_(std::make_shared<const Impl>(Impl{std::move(eam)})) {}

  double cutoff() const;
  int types() const;
  double mass(int type) const;
  std::string describe() const;
  // Forces on locals and ghosts into w (zeroed by the caller), energy and virial.
  ForceSums compute(const Neighbors& nb, ForceWork& w, bool mixed_precision = false) const;
  const Eam* eam() const { return std::get_if<Eam>(&impl_->v); }

 private:
  struct Impl {
    std::variant<Eam, LennardJones, SuttonChen> v;
  };
  std::shared_ptr<const Impl> impl_;  // immutable, shared by copies of a System
};

}  // namespace mpmx::md
