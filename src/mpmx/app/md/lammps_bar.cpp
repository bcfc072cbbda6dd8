#include "mpmx/app/md/lammps_bar.hpp"

#include <cerrno>
#include <cstring>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <deque>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "mpmx/core/error.hpp"
#include "mpmx/core/file_text.hpp"
#include "mpmx/core/units.hpp"

namespace mpmx::app::md {

namespace fs = std::filesystem;

std::string lammps_pair_lines(const PotentialSpec& spec, const Potential& pot) {
  return std::visit(
      [&](const auto& entry) {
        const auto* made = pot.kernel<typename std::decay_t<decltype(entry)>::Kernel>();
        if (!made) throw RunError("the LAMMPS route's potential was not made from its spec");
        return entry.lammps_pair_lines(*made);
      },
      spec);
}

std::string lammps_lattice_line(const particles::LatticeSpec& spec) {
  const particles::Orient& o = spec.orient;
  std::string orient;
  for (int d = 0; d < 3; ++d) orient += fmt::format(" orient {} {} {} {}", "xyz"[d], o[d][0], o[d][1], o[d][2]);
  // LAMMPS's hcp is ideal (c/a = sqrt(8/3)); another c/a is its cell and basis spelled out.
  if (spec.style == particles::LatticeStyle::hcp && std::abs(spec.c_over_a - std::sqrt(8.0 / 3.0)) > 1e-12)
    return fmt::format("lattice custom {:.17g} a1 1 0 0 a2 0 {:.17g} 0 a3 0 0 {:.17g} basis 0 0 0 basis 0.5 0.5 0 "
                       "basis 0.5 {:.17g} 0.5 basis 0 {:.17g} 0.5{}\n",
                       spec.constant, std::sqrt(3.0), spec.c_over_a, 5.0 / 6.0, 1.0 / 3.0, orient);
  if (spec.style == particles::LatticeStyle::b2)  // bcc's sites, the body centres typed by create_atoms' basis
    return fmt::format("lattice bcc {:.17g}{}\n", spec.constant, orient);
  return fmt::format("lattice {} {:.17g}{}\n", particles::lattice_name(spec.style), spec.constant, orient);
}

void write_lammps_data(const System& sys, const std::string& path, const std::string& title) {
  const Box& b = sys.box();
  const Atoms a = sys.snapshot();  // positions in the box, on-step velocities
  const auto& mass = sys.type_mass();
  std::ofstream d(path);
  if (!d) throw SystemError(fmt::format("cannot write {}: {}", path, std::strerror(errno)));
  d << fmt::format("mpmx {} {}, step {} (atom_style atomic, metal units)\n\n", MPMX_VERSION, title, sys.step());
  d << fmt::format("{} atoms\n{} atom types\n\n", a.size(), mass.size());
  d << fmt::format("0 {:.17g} xlo xhi\n0 {:.17g} ylo yhi\n0 {:.17g} zlo zhi\n", b.lx, b.ly, b.lz);
  if (b.xy != 0 || b.xz != 0 || b.yz != 0) d << fmt::format("{:.17g} {:.17g} {:.17g} xy xz yz\n", b.xy, b.xz, b.yz);
  d << "\nMasses\n\n";
  for (std::size_t t = 0; t < mass.size(); ++t) d << fmt::format("{} {:.17g}\n", t + 1, mass[t]);
  d << "\nAtoms # atomic\n\n";
  for (std::size_t i = 0; i < a.size(); ++i)
    d << fmt::format("{} {} {:.17g} {:.17g} {:.17g}\n", a.id[i], a.type[i] + 1, a.x[i], a.y[i], a.z[i]);
  d << "\nVelocities\n\n";
  for (std::size_t i = 0; i < a.size(); ++i)
    d << fmt::format("{} {:.17g} {:.17g} {:.17g}\n", a.id[i], a.vx[i], a.vy[i], a.vz[i]);
  if (!d) throw SystemError(fmt::format("error writing {}: {}", path, std::strerror(errno)));
}

namespace {

std::string shell_quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

bool on_path(const std::string& program) {
  return std::system(fmt::format("command -v {} > /dev/null 2>&1", program).c_str()) == 0;
}

std::string last_lines(const fs::path& p, std::size_t n) {
  std::ifstream in(p);
  if (!in) return fmt::format("({} not written)", p.string());
  std::deque<std::string> tail;
  for (std::string line; std::getline(in, line);) {
    tail.push_back(line);
    if (tail.size() > n) tail.pop_front();
  }
  std::string s;
  for (const auto& l : tail) s += "\n  " + l;
  return s;
}

}  // namespace

void write_lammps_bar(const Bar& bar, const PotentialSpec& spec, double dt, std::int64_t steps, std::int64_t every,
                      const std::string& dir) {
  const System& sys = bar.system();
  const Walls& w = sys.walls();
  const int bins = static_cast<int>(bar.slab_centres().size());
  if (!(dt > 0)) throw InputError(fmt::format("dt = {}: must be positive", dt));
  if (every < 1) throw InputError(fmt::format("[bar] output_every = {}: must be >= 1", every));
  if (steps < 0 || steps % every != 0)
    throw InputError(fmt::format("steps = {}: the LAMMPS route writes the slab stress every output_every = {} "
                                 "steps only, so steps must be a non-negative multiple of it",
                                 steps, every));
  if (sys.step() % every != 0)
    throw InputError(fmt::format("bar at step {}: must be a multiple of output_every = {}", sys.step(), every));
  // fix wall/reflect mirrors v_x -> -v_x; mpmx's moving piston gives 2 v_w - v_x.
  if (!w.enabled || w.v_lo != 0 || w.v_hi != 0)
    throw InputError(fmt::format("[bar] piston_velocity = {}: the LAMMPS route needs fixed walls (LAMMPS's "
                                 "wall/reflect mirrors v_x -> -v_x, a moving piston 2 v_w - v_x)",
                                 w.v_lo));
  const std::string pair = lammps_pair_lines(spec, sys.potential());
  fs::create_directories(dir);
  write_lammps_data(sys, (fs::path(dir) / kLammpsBarData).string(), "direct-MD bar");

  // Slab stress exactly as slab_stress(x0, x1) defines it: bin = floor((x - lo) / width)
  // in the same double arithmetic (an atom-style variable, not bin/1d, whose bound
  // layers come from (hi - lo) / delta and can gain a layer from round-off); atoms
  // outside [lo, hi) count nowhere; kinetic part about each slab's mean velocity
  // (temp/chunk com yes as the bias of stress/atom); volume width * ly * lz.
  const double width = (w.hi - w.lo) / bins;
  const double volume = width * sys.box().ly * sys.box().lz;
  // stress/atom is -(m v v + W) in bar A^3 (LAMMPS's nktv2p); mpmx's GPa use
  // units::eV_per_A3_in_GPa, which differs from nktv2p / 1e4 in the 8th digit.
  const double to_gpa = units::eV_per_A3_in_GPa / (units::lammps_nktv2p * volume);
  std::ofstream in(fs::path(dir) / kLammpsBarInput);
  in << fmt::format(
      "# mpmx {}: direct-MD bar ({} atoms, {} slabs), the LAMMPS route of `mpmx md DECK --lammps`.\n"
      "# Writes {}: every {} steps, {} rows 'slab sxx syy szz sxy sxz syz' (GPa, Cauchy\n"
      "# sign, eq. 2.25 per slab) - the numbers of mpmx's bar_stress.csv.\n"
      "units metal\n"
      "atom_style atomic\n"
      "# mpmx's x is periodic with a vacuum gap wider than 2 (cutoff + skin) beyond the walls,\n"
      "# so no pair crosses it; LAMMPS's wall/reflect needs a non-periodic x: same forces.\n"
      "boundary f p p\n"
      "read_data {}\n",
      MPMX_VERSION, sys.atoms().size(), bins, kLammpsBarStress, every, bins, kLammpsBarData);
  if (sys.step() != 0) in << fmt::format("reset_timestep {}\n", sys.step());
  in << pair;
  in << fmt::format(
      "neighbor {:.17g} bin\n"
      "neigh_modify every 1 delay 0 check yes\n"
      "timestep {:.17g}\n"
      "fix nve all nve\n"
      "# mpmx mirrors after the drift, before the forces: LAMMPS's post_integrate.\n"
      "fix walls all wall/reflect xlo {:.17g} xhi {:.17g} units box\n"
      "variable slab atom floor((x-{:.17g})/{:.17g})+1\n"
      "compute slab all chunk/atom v_slab limit {} exact nchunk once discard yes\n"
      "compute slabcom all temp/chunk slab com yes\n"
      "compute sa all stress/atom slabcom ke pair\n"
      "# bar A^3 per atom -> GPa of the slab: {} / (nktv2p * width * ly * lz)\n"
      "variable sxx atom c_sa[1]*{:.17g}\n"
      "variable syy atom c_sa[2]*{:.17g}\n"
      "variable szz atom c_sa[3]*{:.17g}\n"
      "variable sxy atom c_sa[4]*{:.17g}\n"
      "variable sxz atom c_sa[5]*{:.17g}\n"
      "variable syz atom c_sa[6]*{:.17g}\n"
      "# One reduce/chunk per component: with several inputs, LAMMPS 29Sep2021 (Debian)\n"
      "# zeroes only some slabs' sums each step, and the others accumulate.\n"
      "compute rxx all reduce/chunk slab sum v_sxx\n"
      "compute ryy all reduce/chunk slab sum v_syy\n"
      "compute rzz all reduce/chunk slab sum v_szz\n"
      "compute rxy all reduce/chunk slab sum v_sxy\n"
      "compute rxz all reduce/chunk slab sum v_sxz\n"
      "compute ryz all reduce/chunk slab sum v_syz\n"
      "fix out all ave/time {} 1 {} c_rxx c_ryy c_rzz c_rxy c_rxz c_ryz mode vector file {} format \" %.17g\"\n"
      "thermo_style custom step temp pe ke etotal press\n"
      "thermo_modify norm no\n"
      "thermo {}\n"
      "run {}\n",
      sys.options().skin, dt, w.lo, w.hi, w.lo, width, bins, units::eV_per_A3_in_GPa, to_gpa, to_gpa, to_gpa, to_gpa,
      to_gpa, to_gpa, every, every, kLammpsBarStress, every, steps);
  if (!in)
    throw SystemError(
        fmt::format("error writing {}: {}", (fs::path(dir) / kLammpsBarInput).string(), std::strerror(errno)));
}

LammpsRun run_lammps(const std::string& dir, int ranks, const std::string& input, const std::string& output) {
  if (ranks < 1) throw InputError(fmt::format("--ranks {}: must be >= 1", ranks));
  if (!on_path("lmp"))
    throw RunError("lmp (LAMMPS) is not on PATH: install it (Debian: apt-get install lammps) or run the inputs "
                   "written by --lammps-write-only elsewhere");
  LammpsRun r;
  r.ranks = ranks > 1 && on_path("mpirun") ? ranks : 1;
  std::string launcher;
  if (r.ranks > 1) {
    // Open MPI refuses to start as root unless told; containers often run as root.
    if (geteuid() == 0) launcher = "OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 ";
    launcher += fmt::format("mpirun -np {} ", r.ranks);
  }
  r.command = fmt::format("{}lmp -in {} -log {} -screen none", launcher, input, kLammpsBarLog);
  std::error_code ec;
  fs::remove(fs::path(dir) / output, ec);  // no stale output read back after a failure
  const std::string full = fmt::format("cd {} && {} > lmp.out 2>&1", shell_quote(dir), r.command);
  const int status = std::system(full.c_str());
  const int code = status == -1 ? -1 : WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  if (code != 0)
    throw RunError(fmt::format("`{}` in {} exited with status {}; last lines of {}:{}\nlast lines of lmp.out:{}",
                               r.command, dir, code, kLammpsBarLog, last_lines(fs::path(dir) / kLammpsBarLog, 8),
                               last_lines(fs::path(dir) / "lmp.out", 4)));
  return r;
}

std::vector<BarStressSample> read_lammps_bar_stress(const std::string& path, double dt, int bins) {
  std::ifstream in(path);
  if (!in) throw InputError(fmt::format("{}: cannot open the LAMMPS slab stress file", path));
  std::vector<BarStressSample> out;
  std::string line;
  long ln = 0;
  auto fail = [&](const std::string& what) {
    throw InputError(fmt::format("{}:{}: {} (line {})", path, ln, what, quote_excerpt(line)));
  };
  while (std::getline(in, line)) {
    ++ln;
    if (line.empty() || line[0] == '#') continue;
    std::istringstream head(line);
    BarStressSample s;
    long rows = 0;
    std::string extra;
    if (!(head >> s.step >> rows) || (head >> extra)) fail("expected a block header 'step rows'");
    if (rows != bins) fail(fmt::format("block of {} rows, expected {} slabs", rows, bins));
    s.time_ps = static_cast<double>(s.step) * dt;
    for (long r = 0; r < rows; ++r) {
      if (!std::getline(in, line)) {
        line.clear();
        fail(fmt::format("file ends inside the block of step {}: {} of {} rows", s.step, r, rows));
      }
      ++ln;
      std::istringstream row(line);
      long index = 0;
      double v[6];
      if (!(row >> index >> v[0] >> v[1] >> v[2] >> v[3] >> v[4] >> v[5]) || (row >> extra))
        fail("expected 'slab sxx syy szz sxy sxz syz'");
      if (index != r + 1) fail(fmt::format("slab {}, expected {}", index, r + 1));
      // LAMMPS order xx yy zz xy xz yz -> row-major symmetric tensor.
      s.stress_gpa.push_back({v[0], v[3], v[4], v[3], v[1], v[5], v[4], v[5], v[2]});
    }
    out.push_back(std::move(s));
  }
  if (out.empty()) throw InputError(fmt::format("{}: no slab stress blocks (did the LAMMPS run finish?)", path));
  return out;
}

void write_bar_stress_csv(const std::string& path, const std::vector<BarStressSample>& samples,
                          const std::vector<double>& centres) {
  std::ofstream csv(path);
  if (!csv) throw SystemError(fmt::format("cannot write {}: {}", path, std::strerror(errno)));
  // The header and number formats of run_bar's bar_stress.csv.
  csv << "step,time_ps,bin,x_A,sxx_GPa,syy_GPa,szz_GPa,sxy_GPa,sxz_GPa,syz_GPa\n";
  for (const auto& s : samples) {
    if (s.stress_gpa.size() != centres.size())
      throw RunError(fmt::format("step {}: {} slabs of stress, {} slab centres", s.step, s.stress_gpa.size(),
                                 centres.size()));
    for (std::size_t b = 0; b < centres.size(); ++b) {
      const Mat3& m = s.stress_gpa[b];
      csv << fmt::format("{},{:.6f},{},{:.6g},{:.8g},{:.8g},{:.8g},{:.8g},{:.8g},{:.8g}\n", s.step, s.time_ps, b,
                         centres[b], m[0], m[4], m[8], m[1], m[2], m[5]);
    }
  }
  if (!csv) throw SystemError(fmt::format("error writing {}: {}", path, std::strerror(errno)));
}

}  // namespace mpmx::app::md
