#include "mpmx/app/mpm/vtk_output.hpp"

#include <filesystem>

#include <fmt/format.h>

#include "mpmx/mpm/points.hpp"

namespace mpmx::app {

using namespace mpm;

namespace {

// A Dim x Dim tensor field as VTK's 3 x 3 (zeros outside the run's dimensions, but for
// `zz` where given: plane strain's sigma_zz).
template <int Dim>
io::vtk::Field tensor(const std::string& name, const std::array<std::vector<double>, Dim * Dim>& t, std::size_t n,
                      const std::vector<double>* zz = nullptr) {
  io::vtk::Field f{name, 9, std::vector<double>(9 * n, 0.0)};
  for (std::size_t q = 0; q < n; ++q) {
    for (int a = 0; a < Dim; ++a)
      for (int b = 0; b < Dim; ++b) f.values[9 * q + 3 * a + b] = t[a * Dim + b][q];
    if (zz && !zz->empty()) f.values[9 * q + 8] = (*zz)[q];
  }
  return f;
}

template <int Dim>
io::vtk::Field vector(const std::string& name, const std::array<std::vector<double>, Dim>& v, std::size_t n) {
  io::vtk::Field f{name, 3, std::vector<double>(3 * n, 0.0)};
  for (std::size_t q = 0; q < n; ++q)
    for (int a = 0; a < Dim; ++a) f.values[3 * q + a] = v[a][q];
  return f;
}

}  // namespace

template <int Dim>
VtkOutput<Dim>::VtkOutput(const std::string& dir, double resume_time)
    : dir_(dir), particles_(dir + "/particles.pvd"), grid_(dir + "/grid.pvd") {
  std::filesystem::create_directories(dir + "/vtk");
  if (resume_time >= 0.0) {
    // A final record of a stopped run goes: the resumed run writes the state from here on.
    for (auto* s : {&particles_, &grid_}) {
      s->restore_up_to(resume_time);
      s->drop_files_containing("_final_");
    }
    for (const auto& f : std::filesystem::directory_iterator(dir + "/vtk"))
      if (f.path().filename().string().find("_final_") != std::string::npos) std::filesystem::remove(f.path());
  }
}

template <int Dim>
void VtkOutput<Dim>::record(const State<Dim>& s, bool final) {
  const auto& p = s.particles;
  const std::size_t n = p.size();
  std::vector<double> xyz(3 * n, 0.0);
  for (std::size_t q = 0; q < n; ++q)
    for (int a = 0; a < Dim; ++a) xyz[3 * q + a] = p.x[a][q];
  std::vector<io::vtk::Field> f;
  f.push_back(vector<Dim>("velocity", p.v, n));
  f.push_back(tensor<Dim>("stress", p.stress, n, &p.stress_zz));
  f.push_back(tensor<Dim>("strain", p.strain, n));
  f.push_back(tensor<Dim>("velocity_gradient", p.grad_v, n));
  io::vtk::Field mass{"mass", 1, p.mass}, volume{"volume", 1, p.volume}, density{"density", 1, {}},
      pressure{"pressure", 1, {}};
  for (std::size_t q = 0; q < n; ++q) {
    density.values.push_back(p.mass[q] / p.volume[q]);
    // -tr(sigma)/3 with plane strain's sigma_zz in 2-D.
    double tr = Dim == 2 ? p.stress_zz[q] : 0.0;
    for (int a = 0; a < Dim; ++a) tr += p.stress[a * Dim + a][q];
    pressure.values.push_back(-tr / (Dim == 2 ? 3 : Dim));
  }
  for (auto* x : {&mass, &volume, &density, &pressure}) f.push_back(std::move(*x));
  // Labels, so that bodies and laws can be told apart (ParaView's Threshold on `body`), and
  // the index the deck's md_dump and the 1-D tables name a point by.
  io::vtk::Field id{"id", 1, {}}, body{"body", 1, {}}, law{"material", 1, {}};
  for (std::size_t q = 0; q < n; ++q) {
    id.values.push_back(static_cast<double>(q));
    body.values.push_back(p.body.empty() ? 0.0 : p.body[q]);
    law.values.push_back(p.law.empty() ? 0.0 : p.law[q]);
  }
  for (auto* x : {&id, &body, &law}) f.push_back(std::move(*x));
  // What the law carries beyond the points (temperature, internal energy, plastic strain,
  // 1-D's lateral stresses).
  if (s.material)
    for (auto& lf : s.material->point_fields(points(p))) f.push_back({lf.name, 1, std::move(lf.values)});
  const std::string pname = fmt::format("vtk/particles_{}{:06d}.vtu", final ? "final_" : "", s.step);
  io::vtk::write_points(dir_ + "/" + pname, xyz, f);
  particles_.add(s.time, pname);

  // Nodes without ghosts, x fastest.
  const auto& g = s.grid;
  std::array<int, 3> nodes{1, 1, 1};
  std::array<double, 3> origin{}, spacing{1.0, 1.0, 1.0};
  for (int d = 0; d < Dim; ++d) nodes[d] = g.cells[d] + 1, origin[d] = g.lower[d], spacing[d] = g.dx[d];
  io::vtk::Field gm{"mass", 1, {}}, gv{"velocity", 3, {}};
  // A node without mass has no velocity of its own: written as zero (the step does not
  // visit nodes far from the points, active_lines.hpp, so a face's prescribed value there
  // would be that of the last step that reached them).
  g.for_each_node([&](std::size_t i, const std::array<int, Dim>&) {
    gm.values.push_back(g.mass[i]);
    for (int a = 0; a < 3; ++a) gv.values.push_back(a < Dim && g.mass[i] > 0.0 ? g.velocity_L[a][i] : 0.0);
  });
  const std::string gname = fmt::format("vtk/grid_{}{:06d}.vti", final ? "final_" : "", s.step);
  io::vtk::write_image(dir_ + "/" + gname, nodes, origin, spacing, {gm, gv});
  grid_.add(s.time, gname);
}

template class VtkOutput<1>;
template class VtkOutput<2>;
template class VtkOutput<3>;

}  // namespace mpmx::app
