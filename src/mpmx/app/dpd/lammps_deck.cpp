#include "mpmx/app/dpd/lammps_deck.hpp"

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include <fmt/format.h>

#include "mpmx/core/error.hpp"
#include "mpmx/core/units.hpp"

namespace mpmx::app::dpd {

namespace fs = std::filesystem;

namespace {

// The pair_style lines of each potential (one overload per registered potential).
std::string pair_lines(const SoftPotential& p, int types, const std::string& dir) {
  // pair python evaluates these per pair, in double, exactly as soft.hpp does.
  std::ofstream py(fs::path(dir) / "mpmx_soft_dpd.py");
  py << "import math\n"
        "class SoftDPD(object):\n"
        "    def __init__(self):\n"
        "        self.units = 'metal'\n"
        "        self.pmap = dict()\n"
     << fmt::format("        self.a = {:.17g}\n        self.rc = {:.17g}\n", p.a, p.rc)
     << "    def map_coeff(self, name, ltype):\n"
        "        self.pmap[ltype] = name\n"
        "    def check_units(self, units):\n"
        "        if units != self.units:\n"
        "            raise Exception('units %s, expected metal' % units)\n"
        "    def compute_force(self, rsq, itype, jtype):\n"
        "        r = math.sqrt(rsq)\n"
        "        w = 1.0 - r / self.rc\n"
        "        return self.a * w / r\n"
        "    def compute_energy(self, rsq, itype, jtype):\n"
        "        r = math.sqrt(rsq)\n"
        "        w = 1.0 - r / self.rc\n"
        "        return 0.5 * self.a * self.rc * w * w\n";
  std::string names;
  for (int t = 0; t < types; ++t) names += " DPD";
  return fmt::format("pair_style python {:.17g}\npair_coeff * * mpmx_soft_dpd.SoftDPD{}\n", p.rc, names);
}

std::string pair_lines(const MorsePotential& p, int, const std::string&) {
  return fmt::format("pair_style morse {:.17g}\npair_coeff * * {:.17g} {:.17g} {:.17g}\npair_modify shift {}\n",
                     p.rc, p.d0, p.alpha, p.r0, p.shift ? "yes" : "no");
}

std::string pair_lines(const NmPotential& p, int, const std::string&) {
  return fmt::format("pair_style nm/cut {:.17g}\npair_coeff * * {:.17g} {:.17g} {:.17g} {:.17g}\npair_modify shift {}\n",
                     p.rc, p.e0, p.r0, p.n, p.m, p.shift ? "yes" : "no");
}

std::string shell_quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

std::string tail(const fs::path& p, int n) {
  std::ifstream in(p);
  std::vector<std::string> lines;
  std::string l;
  while (std::getline(in, l)) lines.push_back(l);
  std::string out;
  for (std::size_t k = lines.size() > static_cast<std::size_t>(n) ? lines.size() - n : 0; k < lines.size(); ++k)
    out += "\n  " + lines[k];
  return out;
}

}  // namespace

bool lammps_available() { return std::system("command -v lmp > /dev/null 2>&1") == 0; }

void write_lammps_dpd(const System& s, const LammpsDpdOptions& o, const std::string& dir) {
  fs::create_directories(dir);
  const Particles& p = s.particles();
  const Domain& d = s.domain();
  if (!s.groups().empty()) throw InputError("LAMMPS deck: rigid groups are not written (use a system without)");
  // One LAMMPS type per distinct mass.
  std::map<double, int> type_of;
  for (double m : p.mass) type_of.emplace(m, 0);
  int t = 1;
  for (auto& [m, k] : type_of) k = t++;
  const int types = static_cast<int>(type_of.size());

  std::ofstream data(fs::path(dir) / "dpd.data");
  data << fmt::format("mpmx DPD configuration\n\n{} atoms\n{} atom types\n\n", p.size(), types);
  static const char* axis[3] = {"x", "y", "z"};
  const std::vector<double>* c[3] = {&p.x, &p.y, &p.z};
  for (int k = 0; k < 3; ++k) {
    double lo = 0, hi = d.length(k);
    if (!d.periodic[k])
      for (double v : *c[k]) lo = std::min(lo, v - 1.0), hi = std::max(hi, v + 1.0);
    data << fmt::format("{:.17g} {:.17g} {}lo {}hi\n", lo, hi, axis[k], axis[k]);
  }
  data << "\nMasses\n\n";
  for (auto& [m, k] : type_of) data << fmt::format("{} {:.17g}\n", k, m);
  data << "\nAtoms # atomic\n\n";
  for (std::size_t i = 0; i < p.size(); ++i)
    data << fmt::format("{} {} {:.17g} {:.17g} {:.17g}\n", p.id[i], type_of[p.mass[i]], d.wrap(0, p.x[i]),
                        d.wrap(1, p.y[i]), d.wrap(2, p.z[i]));
  data << "\nVelocities\n\n";
  for (std::size_t i = 0; i < p.size(); ++i)
    data << fmt::format("{} {:.17g} {:.17g} {:.17g}\n", p.id[i], p.vx[i], p.vy[i], p.vz[i]);
  data.close();

  const std::string pair = std::visit([&](const auto& pp) { return pair_lines(pp, types, dir); }, s.potential());
  std::ofstream in(fs::path(dir) / "in.dpd");
  in << "# Written by mpmx (dpd/lammps_deck.cpp): the conservative part of a DPD configuration.\n"
        "units metal\natom_style atomic\natom_modify map array\n"
     << fmt::format("boundary {} {} {}\n", d.periodic[0] ? "p" : "s", d.periodic[1] ? "p" : "s",
                    d.periodic[2] ? "p" : "s")
     << "read_data dpd.data\n"
     << pair
     << fmt::format("neighbor {:.17g} bin\nneigh_modify every 1 delay 0 check yes\n", s.options().skin)
     << "compute pv all pressure NULL virial\n"
        "thermo_style custom step pe c_pv[1] c_pv[2] c_pv[3] c_pv[4] c_pv[5] c_pv[6]\n"
        "thermo_modify format float %.17g\n";
  if (o.dump_forces)
    in << "dump f all custom 1 forces.dump id fx fy fz\ndump_modify f format float %.17g sort id\n";
  in << "run 0\n";
  if (o.dump_forces) in << "undump f\n";
  if (o.steps > 0)
    in << fmt::format("fix nve all nve\ntimestep {:.17g}\nthermo {}\nrun {}\n", o.dt, o.steps, o.steps);
  if (o.dump_final)
    in << "write_dump all custom final.dump id x y z vx vy vz modify format float %.17g sort id\n";
}

LammpsDpdResult run_lammps_dpd(const std::string& dir) {
  if (!lammps_available()) throw RunError("lmp (LAMMPS) is not on PATH (Debian: apt-get install lammps)");
  std::error_code ec;
  fs::remove(fs::path(dir) / "forces.dump", ec);
  fs::remove(fs::path(dir) / "log.lammps", ec);
  fs::remove(fs::path(dir) / "final.dump", ec);
  const std::string cmd = "lmp -in in.dpd -log log.lammps -screen none";
  const std::string full = fmt::format("cd {} && PYTHONPATH=. {} > lmp.out 2>&1", shell_quote(dir), cmd);
  const int status = std::system(full.c_str());
  const int code = status == -1 ? -1 : WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  if (code != 0)
    throw RunError(fmt::format("`{}` in {} exited with status {}; last lines of log.lammps:{}", cmd, dir, code,
                               tail(fs::path(dir) / "log.lammps", 8)));
  LammpsDpdResult r;
  // The first thermo row after the "Step PotEng c_pv[1] ..." header is step 0.
  std::ifstream log(fs::path(dir) / "log.lammps");
  std::string line;
  bool header = false, got = false;
  double volume = 0;
  while (std::getline(log, line)) {
    if (!got && header) {
      std::istringstream ss(line);
      long step;
      double pv[6];
      if (ss >> step >> r.energy >> pv[0] >> pv[1] >> pv[2] >> pv[3] >> pv[4] >> pv[5]) {
        for (int k = 0; k < 6; ++k) r.virial[k] = pv[k];
        got = true;
      }
      header = false;
    }
    if (line.rfind("   Step", 0) == 0 || line.rfind("Step", 0) == 0) header = true;
    if (line.rfind("Loop time of ", 0) == 0 && got) r.loop_seconds = std::stod(line.substr(13));
  }
  if (!got) throw RunError(fmt::format("{}/log.lammps: no thermo row at step 0", dir));
  // The pressure tensor is W/V in bar (nktv2p); the volume is the data file's box.
  {
    std::ifstream data(fs::path(dir) / "dpd.data");
    double ext[3] = {0, 0, 0};
    int k = 0;
    while (std::getline(data, line) && k < 3) {
      std::istringstream ss(line);
      double lo, hi;
      std::string a, b;
      if (ss >> lo >> hi >> a >> b && a.size() == 3 && a.substr(1) == "lo") ext[k++] = hi - lo;
    }
    volume = ext[0] * ext[1] * ext[2];
  }
  for (auto& w : r.virial) w *= volume / units::lammps_nktv2p;
  std::ifstream dump(fs::path(dir) / "forces.dump");
  bool atoms = false;
  while (std::getline(dump, line)) {
    if (line.rfind("ITEM: ATOMS", 0) == 0) {
      atoms = true;
      continue;
    }
    if (line.rfind("ITEM:", 0) == 0) {
      if (atoms) break;  // one frame
      continue;
    }
    if (!atoms) continue;
    std::istringstream ss(line);
    long id;
    double fx, fy, fz;
    if (ss >> id >> fx >> fy >> fz) r.id.push_back(id), r.fx.push_back(fx), r.fy.push_back(fy), r.fz.push_back(fz);
  }
  std::ifstream fin(fs::path(dir) / "final.dump");
  atoms = false;
  while (std::getline(fin, line)) {
    if (line.rfind("ITEM: ATOMS", 0) == 0) {
      atoms = true;
      continue;
    }
    if (!atoms || line.rfind("ITEM:", 0) == 0) continue;
    std::istringstream ss(line);
    long id;
    double v[6];
    if (ss >> id >> v[0] >> v[1] >> v[2] >> v[3] >> v[4] >> v[5]) {
      r.final_id.push_back(id);
      r.x.push_back(v[0]), r.y.push_back(v[1]), r.z.push_back(v[2]);
      r.vx.push_back(v[3]), r.vy.push_back(v[4]), r.vz.push_back(v[5]);
    }
  }
  return r;
}

}  // namespace mpmx::app::dpd
