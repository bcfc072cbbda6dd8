#pragma once
// Particle fields mapped to the nodes at the current positions with the run's own
// shape functions, q_i = sum_p m_p q_p S_ip / m_i (ADMPM eq. 1.39; eq. 3.16 for v),
// and the nodal density m_i / V_i. What ADMPM writes and plots at the nodes.
#include <vector>

#include "mpmx/mpm/state.hpp"

namespace mpmx::mpm {

struct NodalFields {
  std::vector<double> x, mass, volume, velocity, strain, stress, density;
  std::size_t size() const { return x.size(); }
  double field(const std::string& name, std::size_t i) const;
};

NodalFields nodal_fields(const State<1>& s);

}  // namespace mpmx::mpm
