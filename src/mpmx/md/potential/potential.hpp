#pragma once
// A potential made from its spec (registry.hpp): the force kernel of its entry, held in
// a variant dispatched once per force evaluation, never per pair.
#include <memory>
#include <string>
#include <variant>

#include "mpmx/md/forces.hpp"
#include "mpmx/md/particles.hpp"
#include "mpmx/md/potential/registry.hpp"

namespace mpmx::md {

// The force kernels of a registry's entries (Entry::Kernel), in list order.
template <class R>
struct KernelsOf;
template <class... Entries>
struct KernelsOf<Registry<Entries...>> {
  using type = std::variant<typename Entries::Kernel...>;
};

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
  // The kernel when it is a K (null otherwise).
  template <class K>
  const K* kernel() const {
    return std::get_if<K>(&impl_->v);
  }
  const Eam* eam() const { return kernel<Eam>(); }

 private:
  struct Impl {
    KernelsOf<Potentials>::type v;
  };
  std::shared_ptr<const Impl> impl_;  // immutable, shared by copies of a System
};

}  // namespace mpmx::md
