#include "mpmx/app/mpm/box_dumps.hpp"

#include <filesystem>

#include <fmt/format.h>

#include "mpmx/core/error.hpp"
#include "mpmx/core/ranks.hpp"
#include "mpmx/io/atomic_file.hpp"

namespace mpmx::app {

template <int Dim>
BoxDumps<Dim>::BoxDumps(const std::string& dir, std::vector<std::int64_t> points, std::vector<std::string> fields,
                        const material::Material<Dim>& law)
    : dir_(dir + "/md_dump"), points_(std::move(points)), fields_(std::move(fields)) {
  for (const std::int64_t q : points_)
    if (!law.runs_point_model(static_cast<std::size_t>(q)))
      throw InputError(fmt::format("output.md_dump: point {} runs no MD box (its law is {})", q, law.name()));
  if (ranks::root()) std::filesystem::create_directories(dir_);
}

template <int Dim>
void BoxDumps<Dim>::write(const mpm::State<Dim>& s) const {
  for (const std::int64_t q : points_) {
    const std::string text = s.material->point_model_dump(static_cast<std::size_t>(q), s.step, fields_);
    if (!ranks::root()) continue;
    io::write_file_atomic(fmt::format("{}/point_{:06d}_{:09d}.dump", dir_, q, s.step), text);
  }
}

template class BoxDumps<1>;
template class BoxDumps<2>;
template class BoxDumps<3>;

}  // namespace mpmx::app
