#pragma once
// Several materials in one run (a flyer of one metal on a target of another): the
// points are ordered by material, so each law sees a contiguous block of the batch
// through a view shifted to its first point, as if it were alone.
#include <cstddef>
#include <memory>
#include <vector>

#include "mpmx/material/material.hpp"

namespace mpmx::material {

// The view of points [begin, begin + n) of p, indexed from zero.
template <int Dim>
Points<Dim> block(const Points<Dim>& p, std::size_t begin, std::size_t n);

template <int Dim>
class Composite final : public Material<Dim> {
 public:
  struct Part {
    std::unique_ptr<Material<Dim>> law;
    std::size_t begin = 0, count = 0;
  };
  // Parts in point order, covering the batch without gaps.
  explicit Composite(std::vector<Part> parts);

  std::string name() const override;
  void initialize(const Points<Dim>& p) override;
  void update_stress(const Points<Dim>& p, double dt) override;
  double sound_speed(const Points<Dim>& p, std::size_t q) const override;
  double signal_speed(const Points<Dim>& p, std::size_t q) const override;
  double stored_energy(const Points<Dim>& p, std::size_t q) const override;
  bool keeps_energy_account() const override {
    for (const auto& part : parts_)
      if (!part.law->keeps_energy_account()) return false;
    return true;
  }
  void add_viscous_heat(const Points<Dim>& p, const std::array<double*, Dim * Dim>& q, double dt) override;
  void set_threads(int threads) override;
  std::vector<PointField> point_fields(const Points<Dim>& p) const override;
  std::string point_model_dump(std::size_t q, std::int64_t step, const std::vector<std::string>& fields) const override;
  bool runs_point_model(std::size_t q) const override;
  void save(std::ostream& out) const override;
  void load(std::istream& in) override;

  const std::vector<Part>& parts() const { return parts_; }

 private:
  const Part& part_of(std::size_t q) const;
  std::vector<Part> parts_;
};

}  // namespace mpmx::material
