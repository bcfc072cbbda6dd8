// DpdGrid::save and load: the grid's place and the continuum points' state. The nodes'
// fields are cleared and refilled every step, so they are not kept.
#include <cmath>
#include <cstring>
#include <istream>
#include <ostream>
#include <type_traits>

#include <fmt/format.h>

#include "mpmx/core/binary.hpp"
#include "mpmx/core/error.hpp"
#include "mpmx/multiscale/dpd_grid.hpp"

namespace mpmx::multiscale {

namespace {

constexpr char kMagic[8] = {'M', 'P', 'M', 'X', 'D', 'G', 'R', '1'};

constexpr const char* kState = "DPD/MPM grid's state";

// A list with its count first.
template <class T>
void put_list(std::ostream& o, const std::vector<T>& v) {
  write_raw<std::uint64_t>(o, v.size());
  write_values(o, v);
}
// A list of exactly n values.
template <class T>
std::vector<T> get_vec(std::istream& i, std::size_t n, const char* what) {
  const std::uint64_t m = read_count(i, sizeof(T), what);
  if (m != n) throw InputError(fmt::format("the DPD/MPM grid's {} hold {} values, the run has {}", what, m, n));
  std::vector<T> v;
  read_values(i, v, n, kState);
  if constexpr (std::is_floating_point_v<T>)
    for (T x : v)
      if (!std::isfinite(x)) throw InputError(fmt::format("the DPD/MPM grid's {} hold a non-finite value", what));
  return v;
}

}  // namespace

void DpdGrid::save(std::ostream& o) const {
  o.write(kMagic, 8);
  write_raw(o, g_.lower);
  write_raw(o, g_.upper);
  write_raw(o, g_.cells);
  write_raw(o, skipped_);
  put_list(o, cont_id_);
  for (const auto* v : {&mass_, &volume_, &volume0_, &length_}) put_list(o, *v);
  for (int c = 0; c < 9; ++c) put_list(o, grad_v_[c]), put_list(o, stress_[c]), put_list(o, strain_[c]);
  const bool law = law_ != nullptr;
  write_raw<std::uint8_t>(o, law);
  if (law) law_->save(o);
}

void DpdGrid::load(std::istream& in) {
  char magic[8] = {};
  in.read(magic, 8);
  if (!in || std::memcmp(magic, kMagic, 8) != 0) throw InputError("not the state of a DPD/MPM grid");
  const auto lower = read_raw<std::array<double, 3>>(in, kState), upper = read_raw<std::array<double, 3>>(in, kState);
  const auto cells = read_raw<std::array<int, 3>>(in, kState);
  for (int d = 0; d < 3; ++d)
    if (!(cells[d] >= 1 && cells[d] <= 4096 && std::isfinite(lower[d]) && std::isfinite(upper[d]) &&
          std::abs((upper[d] - lower[d]) / cells[d] - g_.dx[d]) <= 1e-9 * g_.dx[d]))
      throw InputError(fmt::format("the DPD/MPM grid's axis {} ({} cells over [{}, {}]) is not one of cell {} A", d,
                                   cells[d], lower[d], upper[d], g_.dx[d]));
  const auto skipped = read_raw<std::int64_t>(in, kState);
  const std::size_t m = cont_id_.size();
  if (get_vec<std::int64_t>(in, m, "continuum point ids") != cont_id_)
    throw InputError("the DPD/MPM grid's continuum points are not the run's");
  std::vector<double> mass = get_vec<double>(in, m, "masses"), volume = get_vec<double>(in, m, "volumes"),
                      volume0 = get_vec<double>(in, m, "initial volumes"), length = get_vec<double>(in, m, "lengths");
  std::array<std::vector<double>, 9> grad_v, stress, strain;
  for (int c = 0; c < 9; ++c)
    grad_v[c] = get_vec<double>(in, m, "velocity gradients"), stress[c] = get_vec<double>(in, m, "stresses"),
    strain[c] = get_vec<double>(in, m, "strains");
  const bool law = read_raw<std::uint8_t>(in, kState) != 0;
  if (law != (law_ != nullptr)) throw InputError("the DPD/MPM grid's continuum law is not the run's");
  if (law) law_->load(in);
  make_grid(lower, upper, cells);
  skipped_ = skipped;
  mass_ = std::move(mass), volume_ = std::move(volume), volume0_ = std::move(volume0), length_ = std::move(length);
  grad_v_ = std::move(grad_v), stress_ = std::move(stress), strain_ = std::move(strain);
  active_.clear();
}

}  // namespace mpmx::multiscale
