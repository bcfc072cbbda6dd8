#include "mpmx/md/potential/eam_file.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "mpmx/core/error.hpp"

namespace mpmx::md {

namespace {

// Reads a potential file line by line and value by value, keeping the line number
// for messages.
class Cursor {
 public:
  explicit Cursor(std::string path) : path_(std::move(path)) {
    std::ifstream in(path_);
    if (!in) throw InputError(fmt::format("{}: cannot open EAM potential file", path_));
    std::string line;
    while (std::getline(in, line)) lines_.push_back(line);
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
    if (end == w.c_str() || *end != '\0' || !std::isfinite(v))
      fail(line, fmt::format("expected a number ({}), found '{}'", what, w));
    return v;
  }
  long to_integer(const std::string& w, const std::string& what, int line) const {
    char* end = nullptr;
    const long v = std::strtol(w.c_str(), &end, 10);
    if (end == w.c_str() || *end != '\0')
      fail(line, fmt::format("expected an integer ({}), found '{}'", what, w));
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

// "nrho drho nr dr cut" header line of all three formats.
void read_grid(Cursor& c, EamTables& t) {
  const auto text = c.line("'nrho drho nr dr cutoff'");
  const auto w = c.words(text);
  const int ln = c.line_no();
  if (w.size() < 5)
    c.fail(ln, fmt::format("expected 5 values 'nrho drho nr dr cutoff', found {}", w.size()));
  t.nrho = static_cast<int>(c.to_integer(w[0], "nrho", ln));
  t.drho = c.to_number(w[1], "drho", ln);
  t.nr = static_cast<int>(c.to_integer(w[2], "nr", ln));
  t.dr = c.to_number(w[3], "dr", ln);
  t.cut = c.to_number(w[4], "cutoff", ln);
  if (t.nrho < 5) c.fail(ln, fmt::format("nrho = {}: expected at least 5 grid points", t.nrho));
  if (t.nr < 5) c.fail(ln, fmt::format("nr = {}: expected at least 5 grid points", t.nr));
  if (!(t.drho > 0)) c.fail(ln, fmt::format("drho = {}: expected a positive spacing", t.drho));
  if (!(t.dr > 0)) c.fail(ln, fmt::format("dr = {}: expected a positive spacing", t.dr));
  if (!(t.cut > 0)) c.fail(ln, fmt::format("cutoff = {}: expected a positive cutoff", t.cut));
}

// "Z mass [a lattice]" line of one element.
double read_mass(Cursor& c, const std::string& element) {
  const auto text = c.line(fmt::format("'Z mass' of element {}", element));
  const auto w = c.words(text);
  const int ln = c.line_no();
  if (w.size() < 2)
    c.fail(ln, fmt::format("expected 'atomic-number mass ...' for element {}", element));
  c.to_number(w[0], "atomic number", ln);
  const double m = c.to_number(w[1], "mass", ln);
  if (!(m > 0)) c.fail(ln, fmt::format("mass = {}: expected a positive mass", m));
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
  const double mass = read_mass(c, "of the funcfl file");
  EamTables file;  // the file's own grid
  read_grid(c, file);
  std::vector<double> frho = one_based(file.nrho), zr = one_based(file.nr), rhor = one_based(file.nr);
  c.grab(file.nrho, &frho[1], "F(rho)");
  c.grab(file.nr, &zr[1], "Z(r)");
  c.grab(file.nr, &rhor[1], "rho(r)");

  // LAMMPS file2array for funcfl: the common grid (here one file) and 4-point
  // Lagrange interpolation onto it.
  t.elements = {"funcfl"};
  t.masses = {mass};
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
    const long n = c.to_integer(w[0], "number of elements", ln);
    if (n < 1) c.fail(ln, fmt::format("number of elements = {}: expected at least 1", n));
    if (static_cast<long>(w.size()) - 1 != n)
      c.fail(ln, fmt::format("expected {} element names after N, found {}", n, w.size() - 1));
    t.elements.assign(w.begin() + 1, w.end());
  }
  read_grid(c, t);
  t.rhomax = (t.nrho - 1) * t.drho;
  const int n = static_cast<int>(t.elements.size());
  t.frho.assign(n, one_based(t.nrho));
  t.rhor.assign(fs ? n * n : n, one_based(t.nr));
  for (int i = 0; i < n; ++i) {
    const auto& el = t.elements[i];
    t.masses.push_back(read_mass(c, el));
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

}  // namespace mpmx::md
