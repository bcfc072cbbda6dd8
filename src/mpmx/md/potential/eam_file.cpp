#include "mpmx/core/input_files.hpp"
#include "mpmx/md/potential/eam_file.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "mpmx/core/error.hpp"
#include "mpmx/core/file_text.hpp"
#include "mpmx/md/physical_bounds.hpp"

namespace mpmx::md {

namespace {

// Limits of what a file may claim, checked before anything is sized by it: grid points
// per table (LAMMPS's files have 500 to 10,000; 10^7 is 80 MB a table) and elements.
constexpr std::int64_t kMaxGridPoints = 10'000'000;
constexpr std::int64_t kMaxElements = 100;
constexpr std::size_t kMaxElementName = 16;

// Reads a potential file line by line and value by value, keeping the line number
// for messages.
class Cursor {
 public:
  explicit Cursor(std::string path) : path_(std::move(path)) {
    std::error_code ec;
    if (std::filesystem::is_directory(path_, ec))
      throw InputError(fmt::format("{}: is a directory, not an EAM potential file", path_));
    std::ifstream in(path_);
    if (!in) throw InputError(fmt::format("{}: cannot open EAM potential file", path_));
    note_input_file(path_);  // pinned by a checkpoint
    std::string line;
    while (std::getline(in, line)) lines_.push_back(line);
    if (lines_.empty()) throw InputError(fmt::format("{}: the EAM potential file is empty", path_));
  }

  // How many values (words) the file holds from the next line on: a header's counts
  // must fit in them before anything is sized by the counts.
  std::int64_t values_left() const {
    std::int64_t n = 0;
    for (std::size_t k = next_; k < lines_.size(); ++k) {
      std::istringstream words(lines_[k]);
      std::string w;
      while (words >> w) ++n;
    }
    return n;
  }

  [[noreturn]] void fail(int line, const std::string& what) const {
    throw InputError(fmt::format("{}:{}: {}", path_, line, what));
  }

  // The next whole line (1-based line number in `line_no`).
  std::string line(const std::string& expected) {
    if (next_ >= lines_.size())
      fail(static_cast<int>(lines_.size()),
           fmt::format("file ends early: expected {} on line {}", expected, next_ + 1));
    line_no_ = static_cast<int>(next_ + 1);
    return lines_[next_++];
  }
  int line_no() const { return line_no_; }

  // n numbers, several to a line, starting on the next line (LAMMPS's grab()).
  void grab(int n, double* out, const std::string& what) {
    int i = 0;
    while (i < n) {
      if (next_ >= lines_.size())
        fail(static_cast<int>(lines_.size()),
             fmt::format("file ends early: expected {} values of {}, found {}", n, what, i));
      line_no_ = static_cast<int>(next_ + 1);
      std::istringstream words(lines_[next_++]);
      std::string w;
      while (words >> w) {
        if (i == n)
          fail(line_no_, fmt::format("more values than expected: {} values of {} end inside this "
                                     "line",
                                     n, what));
        out[i++] = to_number(w, what, line_no_);
      }
    }
  }

  double to_number(const std::string& w, const std::string& what, int line) const {
    char* end = nullptr;
    errno = 0;
    const double v = std::strtod(w.c_str(), &end);
    if (end == w.c_str() || *end != '\0')
      fail(line, fmt::format("expected a number ({}), found {}", what, quote_excerpt(w)));
    if (!std::isfinite(v))
      fail(line, fmt::format("expected a finite number ({}), found {} (nan and inf are not accepted)", what,
                             quote_excerpt(w)));
    return v;
  }
  // A whole number from lo to hi `unit`: out of range, the message names it, the value
  // and the range.
  std::int64_t to_integer(const std::string& w, const std::string& what, int line, std::int64_t lo,
                          std::int64_t hi, const std::string& unit) const {
    char* end = nullptr;
    errno = 0;
    const long long v = std::strtoll(w.c_str(), &end, 10);
    if (end == w.c_str() || *end != '\0')
      fail(line, fmt::format("expected an integer ({}), found {}", what, quote_excerpt(w)));
    if (errno == ERANGE || v < lo || v > hi)
      fail(line, fmt::format("{} = {}: out of range: expected from {} to {} {}", what,
                             w.size() <= 40 ? w : quote_excerpt(w), lo, hi, unit));  // all digits: printable
    return v;
  }
  std::vector<std::string> words(const std::string& text) const {
    std::istringstream in(text);
    std::vector<std::string> out;
    std::string w;
    while (in >> w) out.push_back(w);
    return out;
  }

 private:
  std::string path_;
  std::vector<std::string> lines_;
  std::size_t next_ = 0;
  int line_no_ = 0;
};

// "nrho drho nr dr cut" header line of all three formats; returns its line number.
int read_grid(Cursor& c, EamTables& t) {
  const auto text = c.line("'nrho drho nr dr cutoff'");
  const auto w = c.words(text);
  const int ln = c.line_no();
  if (w.size() < 5)
    c.fail(ln, fmt::format("expected 5 values 'nrho drho nr dr cutoff', found {}", w.size()));
  // Checked before anything is sized by them: at least 5 points (the splines), at most
  // kMaxGridPoints.
  t.nrho = static_cast<int>(c.to_integer(w[0], "nrho", ln, 5, kMaxGridPoints, "grid points"));
  t.drho = c.to_number(w[1], "drho", ln);
  t.nr = static_cast<int>(c.to_integer(w[2], "nr", ln, 5, kMaxGridPoints, "grid points"));
  t.dr = c.to_number(w[3], "dr", ln);
  t.cut = c.to_number(w[4], "cutoff", ln);
  if (!(t.drho > 0)) c.fail(ln, fmt::format("drho = {}: expected a positive spacing", t.drho));
  if (!(t.dr > 0)) c.fail(ln, fmt::format("dr = {}: expected a positive spacing", t.dr));
  if (!(t.cut > 0)) c.fail(ln, fmt::format("cutoff = {}: expected a positive cutoff", t.cut));
  return ln;
}

// Tables that parse can still describe no potential: a grid that ends before the cutoff
// (pairs beyond it would read the last entry: dr = 1e-300 ran with no interaction at
// all), too few points below the cutoff to tabulate anything, or a density grid so coarse
// that every density a crystal has falls in its first interval (drho = 1e300 gave -1.20
// eV/atom for copper's -3.54). `rho` are the density tables on the r grid (1-based).
// Debian's lammps-data files have nr * dr from 1.0 to 1.9 times the cutoff (many exactly
// equal), at least 400 points below it, and drho at most 0.026 of the largest density
// one neighbour brings beyond 1 A: the limits below leave them far inside.
constexpr double kMinIntervalsBelowCutoff = 10;

void check_tables_reach(const Cursor& c, int ln, const EamTables& grid, const std::vector<std::vector<double>>& rho) {
  const double reach = grid.nr * grid.dr;
  if (!(reach >= grid.cut * (1.0 - 1e-9)))
    c.fail(ln, fmt::format("nr * dr = {} * {} = {:.6g} A ends before the cutoff {:.6g} A: the tables do not cover the "
                           "distances the potential acts over",
                           grid.nr, grid.dr, reach, grid.cut));
  if (!(grid.cut / grid.dr >= kMinIntervalsBelowCutoff))
    c.fail(ln, fmt::format("dr = {} A leaves {:.3g} grid intervals below the cutoff {:.6g} A: at least {} are "
                           "needed to tabulate the functions",
                           grid.dr, grid.cut / grid.dr, grid.cut, kMinIntervalsBelowCutoff));
  double peak = 0;  // the largest density one neighbour brings at a bond's length or more
  for (const auto& f : rho)
    for (int m = 1; m <= grid.nr && m < static_cast<int>(f.size()); ++m) {
      const double r = (m - 1) * grid.dr;
      if (r >= kMinBondLength && r <= grid.cut) peak = std::max(peak, std::abs(f[m]));
    }
  if (peak > 0 && !(grid.drho <= peak))
    c.fail(ln, fmt::format("drho = {} is coarser than the largest density one neighbour brings beyond {} A ({:.6g}): "
                           "every density a crystal has would fall in the first intervals of F(rho)",
                           grid.drho, kMinBondLength, peak));
  if (!std::isfinite((grid.nrho - 1) * grid.drho))
    c.fail(ln, fmt::format("nrho * drho = {} * {} is not a finite density", grid.nrho, grid.drho));
}

// The values a header promises must be in the file before big tables are sized by them:
// a header claiming 10^7 points in a file of a few lines is refused here, not by the
// allocator. A smaller shortfall is left to the reading, which names the line where the
// file ends and what it expected there.
constexpr double kValuesReadOptimistically = 1e6;  // 8 MB

void check_values_left(Cursor& c, int header_line, double needed, const std::string& what) {
  if (needed <= kValuesReadOptimistically) return;
  const std::int64_t left = c.values_left();
  if (needed > static_cast<double>(left))
    c.fail(header_line, fmt::format("{} promise {:.0f} values, but the rest of the file holds {}", what, needed,
                                    left));
}

// "Z mass [a lattice]" line of one element; `z`, when given, gets Z.
// The element line "Z mass [a lattice]": the mass, and what the file says of the
// element's crystal where it says it (LAMMPS ignores the last two; they are the
// potential's own ground state by the convention of setfl and funcfl files).
double read_mass(Cursor& c, const std::string& element, int* z = nullptr, DeclaredLattice* lattice = nullptr) {
  const auto text = c.line(fmt::format("'Z mass' of element {}", element));
  const auto w = c.words(text);
  const int ln = c.line_no();
  if (lattice && w.size() >= 4) {
    char* end = nullptr;
    const std::string a(w[2]);
    const double v = std::strtod(a.c_str(), &end);
    std::string name(w[3]);
    for (char& ch : name) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
    if (end && *end == '\0' && std::isfinite(v) && v > 0 && name.size() <= 8) *lattice = {name, v};
  }
  if (w.size() < 2)
    c.fail(ln, fmt::format("expected 'atomic-number mass ...' for element {}", element));
  const double number = c.to_number(w[0], "atomic number", ln);
  if (z) *z = number >= 1 && number <= 200 ? static_cast<int>(number) : 0;
  const double m = c.to_number(w[1], "mass", ln);
  if (const std::string why = atom_mass_problem(m); !why.empty())
    c.fail(ln, fmt::format("mass = {} amu{}: {}", m, element.starts_with("of ") ? "" : " of element " + element, why));
  return m;
}

std::vector<double> one_based(int n) { return std::vector<double>(static_cast<std::size_t>(n) + 1, 0.0); }

void lower_triangle_maps(EamTables& t) {
  const int n = static_cast<int>(t.elements.size());
  t.z2r_index.assign(n * n, 0);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      int row = i, col = j;
      if (row < col) std::swap(row, col);
      t.z2r_index[i * n + j] = row * (row + 1) / 2 + col;
    }
}

EamTables read_funcfl(const std::string& path) {
  Cursor c(path);
  EamTables t;
  t.file = path;
  t.format = "funcfl";
  c.line("a comment line");
  DeclaredLattice declared;
  const double mass = read_mass(c, "of the funcfl file", &t.atomic_number, &declared);
  EamTables file;  // the file's own grid
  const int grid_line = read_grid(c, file);
  check_values_left(c, c.line_no(), static_cast<double>(file.nrho) + 2.0 * file.nr,
                    fmt::format("nrho = {} and nr = {}", file.nrho, file.nr));
  std::vector<double> frho = one_based(file.nrho), zr = one_based(file.nr), rhor = one_based(file.nr);
  c.grab(file.nrho, &frho[1], "F(rho)");
  c.grab(file.nr, &zr[1], "Z(r)");
  c.grab(file.nr, &rhor[1], "rho(r)");
  check_tables_reach(c, grid_line, file, {rhor});

  // LAMMPS file2array for funcfl: the common grid (here one file) and 4-point
  // Lagrange interpolation onto it.
  t.elements = {"funcfl"};
  t.masses = {mass};
  t.lattices = {declared};
  t.dr = file.dr;
  t.drho = file.drho;
  const double rmax = (file.nr - 1) * file.dr;
  t.rhomax = (file.nrho - 1) * file.drho;
  t.nr = static_cast<int>(rmax / t.dr + 0.5);
  t.nrho = static_cast<int>(t.rhomax / t.drho + 0.5);
  t.cut = file.cut;
  const double sixth = 1.0 / 6.0;
  auto lagrange = [&](const std::vector<double>& f, int fn, double fdelta, double r) {
    double p = r / fdelta + 1.0;
    int k = static_cast<int>(p);
    k = std::min(k, fn - 2);
    k = std::max(k, 2);
    p -= k;
    p = std::min(p, 2.0);
    const double cof1 = -sixth * p * (p - 1.0) * (p - 2.0);
    const double cof2 = 0.5 * (p * p - 1.0) * (p - 2.0);
    const double cof3 = -0.5 * p * (p + 1.0) * (p - 2.0);
    const double cof4 = sixth * p * (p * p - 1.0);
    return cof1 * f[k - 1] + cof2 * f[k] + cof3 * f[k + 1] + cof4 * f[k + 2];
  };
  t.frho.assign(1, one_based(t.nrho));
  for (int m = 1; m <= t.nrho; ++m) t.frho[0][m] = lagrange(frho, file.nrho, file.drho, (m - 1) * t.drho);
  t.rhor.assign(1, one_based(t.nr));
  t.z2r.assign(1, one_based(t.nr));
  for (int m = 1; m <= t.nr; ++m) {
    const double r = (m - 1) * t.dr;
    t.rhor[0][m] = lagrange(rhor, file.nr, file.dr, r);
    const double z = lagrange(zr, file.nr, file.dr, r);
    t.z2r[0][m] = 27.2 * 0.529 * z * z;  // Hartree*Bohr: Z_i Z_j e^2 in eV*Angstrom
  }
  t.rhor_index = {0};
  lower_triangle_maps(t);
  return t;
}

EamTables read_setfl_or_fs(const std::string& path, bool fs) {
  Cursor c(path);
  EamTables t;
  t.file = path;
  t.format = fs ? "fs" : "setfl";
  for (int i = 0; i < 3; ++i) c.line("a comment line (3 at the top)");
  {
    const auto text = c.line("'N element1 ... elementN'");
    const auto w = c.words(text);
    const int ln = c.line_no();
    if (w.empty()) c.fail(ln, "expected 'N element1 ... elementN', found an empty line");
    const std::int64_t n = c.to_integer(w[0], "number of elements", ln, 1, kMaxElements, "elements");
    if (static_cast<std::int64_t>(w.size()) - 1 != n)
      c.fail(ln, fmt::format("expected {} element names after N, found {}", n, w.size() - 1));
    t.elements.assign(w.begin() + 1, w.end());
    for (const auto& e : t.elements)  // names go into messages and the deck's elements are matched to them
      if (e.size() > kMaxElementName || quote_excerpt(e, e.size()) != "'" + e + "'")
        c.fail(ln, fmt::format("element name {} is not a name: at most {} printable characters",
                               quote_excerpt(e), kMaxElementName));
  }
  const int grid_line = read_grid(c, t);
  t.rhomax = (t.nrho - 1) * t.drho;
  const int n = static_cast<int>(t.elements.size());
  {
    // Per element: a mass line (2+ words), F(rho), rho(r) (n of them in fs); per pair: r*phi.
    const double dn = n;
    const double needed = dn * (2.0 + t.nrho + (fs ? dn : 1.0) * t.nr) + dn * (dn + 1) / 2 * t.nr;
    check_values_left(c, c.line_no(), needed,
                      fmt::format("{} element(s) with nrho = {} and nr = {}", n, t.nrho, t.nr));
  }
  t.frho.assign(n, one_based(t.nrho));
  t.rhor.assign(fs ? n * n : n, one_based(t.nr));
  for (int i = 0; i < n; ++i) {
    const auto& el = t.elements[i];
    DeclaredLattice declared;
    t.masses.push_back(read_mass(c, el, nullptr, &declared));
    t.lattices.push_back(declared);
    c.grab(t.nrho, &t.frho[i][1], fmt::format("F(rho) of {}", el));
    if (fs) {
      for (int j = 0; j < n; ++j)
        c.grab(t.nr, &t.rhor[i * n + j][1], fmt::format("rho_{}{}(r)", el, t.elements[j]));
    } else {
      c.grab(t.nr, &t.rhor[i][1], fmt::format("rho(r) of {}", el));
    }
  }
  for (int i = 0; i < n; ++i)
    for (int j = 0; j <= i; ++j) {
      t.z2r.push_back(one_based(t.nr));
      c.grab(t.nr, &t.z2r.back()[1], fmt::format("r*phi(r) of {}-{}", t.elements[i], t.elements[j]));
    }
  check_tables_reach(c, grid_line, t, t.rhor);
  // Density at an atom of element i due to a neighbour of element j (LAMMPS
  // type2rhor[j][i]): setfl uses j's function, fs the function listed under j for i.
  t.rhor_index.assign(n * n, 0);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) t.rhor_index[j * n + i] = fs ? j * n + i : j;
  lower_triangle_maps(t);
  return t;
}

bool ends_with(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

}  // namespace

int EamTables::element_index(const std::string& name) const {
  for (std::size_t i = 0; i < elements.size(); ++i)
    if (elements[i] == name) return static_cast<int>(i);
  return -1;
}

EamFormat eam_format_from_name(const std::string& path) {
  if (ends_with(path, ".eam.alloy") || ends_with(path, ".alloy")) return EamFormat::setfl;
  if (ends_with(path, ".eam.fs") || ends_with(path, ".fs")) return EamFormat::fs;
  if (ends_with(path, ".eam")) return EamFormat::funcfl;
  throw InputError(fmt::format("{}: cannot tell the EAM format from the name: expected a name "
                               "ending in .eam (funcfl), .eam.alloy (setfl) or .eam.fs (fs)",
                               path));
}

EamTables read_eam(const std::string& path, EamFormat format) {
  switch (format) {
    case EamFormat::funcfl: return read_funcfl(path);
    case EamFormat::setfl: return read_setfl_or_fs(path, false);
    case EamFormat::fs: return read_setfl_or_fs(path, true);
  }
  return {};
}

EamTables read_eam(const std::string& path) { return read_eam(path, eam_format_from_name(path)); }

namespace fs = std::filesystem;

std::string resolve_potential_file(const std::string& name, const std::string& deck_dir) {
  std::vector<fs::path> tried;
  fs::path p(name);
  if (p.is_absolute()) {
    tried.push_back(p);
  } else {
    tried.push_back(deck_dir.empty() ? p : fs::path(deck_dir) / p);
    tried.push_back(fs::path("/usr/share/lammps/potentials") / p);
  }
  // The error_code form: a name the system cannot even look up (too long, bad bytes) is
  // a file not found, not an exception from the filesystem.
  for (const auto& t : tried)
    if (std::error_code ec; fs::is_regular_file(t, ec)) return t.string();
  std::vector<std::string> names;
  for (const auto& t : tried) {
    names.push_back(short_path(t.string()));
    // Found, but not a file: say what it is rather than "not found".
    if (std::error_code ec; fs::exists(t, ec))
      throw InputError(fmt::format("potential file '{}': {} {}", short_path(name), names.back(),
                                   file_problem(t, "potential file")));
  }
  throw InputError(fmt::format("potential file '{}' not found (tried: {})", short_path(name), fmt::join(names, ", ")));
}

}  // namespace mpmx::md
