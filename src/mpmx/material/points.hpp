#pragma once
// The view of a batch of material points that a constitutive law sees: the fields it
// reads (velocity gradient, mass, volumes, domain lengths) and writes (stress, strain),
// never the solver's particle container. A closure built on this view (an MD box per
// point, DPD) needs nothing of the continuum solver.
#include <array>
#include <cstddef>

namespace mpmx::material {

template <int Dim>
struct Points {
  static constexpr int tensor = Dim * Dim;  // components stored row-major: [a * Dim + b]

  std::size_t n = 0;
  std::array<const double*, tensor> grad_v{};  // L_ab = dv_a / dx_b at v^{n+1/2} (eq. 4.10)
  std::array<double*, tensor> stress{};        // Cauchy stress, tension positive
  // 2-D (plane strain, D_zz = 0): the out-of-plane normal stress sigma_zz, which the
  // in-plane forces do not use but the mean stress, the deviator and the output do;
  // null in 1-D and 3-D.
  double* stress_zz = nullptr;
  std::array<double*, tensor> strain{};        // integrated strain (small-strain measure)
  const double* mass = nullptr;
  const double* volume = nullptr;              // current volume (after this step's update)
  const double* volume0 = nullptr;             // initial volume
  std::array<const double*, Dim> length{};     // domain edge per axis (viscosity's length)
  // The tensor artificial viscous stress the forces used this step (eqs. 7.8-7.10),
  // null when off: a law that keeps an energy account sees the continuum's whole work.
  std::array<const double*, tensor> viscous{};
  // The linear artificial viscosity q (>= 0, ch. 6) the forces took off every normal
  // stress this step: null when the deck has none.
  const double* viscous_pressure = nullptr;

  std::size_t size() const { return n; }
  double density(std::size_t q) const { return mass[q] / volume[q]; }
  double L(std::size_t q, int a, int b) const { return grad_v[a * Dim + b][q]; }
  double& sigma(std::size_t q, int a, int b) const { return stress[a * Dim + b][q]; }
  double& eps(std::size_t q, int a, int b) const { return strain[a * Dim + b][q]; }
  // sigma_zz where the view carries it (2-D), for a law to set.
  void set_sigma_zz(std::size_t q, double value) const {
    if (stress_zz) stress_zz[q] = value;
  }
};

}  // namespace mpmx::material
