#include "mpmx/app/mpm/output.hpp"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <iterator>
#include <stdexcept>
#include <filesystem>

#include <fmt/format.h>

#include "mpmx/core/error.hpp"
#include "mpmx/app/mpm/reference.hpp"
#include "mpmx/mpm/points.hpp"

namespace mpmx::app {

using namespace mpm;

namespace {

// Appends a CSV field: v as printf's %.{digits}g (std::to_chars gives the same text as
// fmt's {:.Ng} and avoids its slow exact path, a fifth of a record's time).
void put(fmt::memory_buffer& b, double v, int digits = 10) {
  char s[32];
  const auto r = std::to_chars(s, s + sizeof s, v, std::chars_format::general, digits);
  b.append(s, r.ptr);
}
template <class... T>
void put_row(fmt::memory_buffer& b, double t, std::size_t index, double x, int x_digits, T... rest) {
  put(b, t);
  b.push_back(',');
  char s[24];
  b.append(s, std::to_chars(s, s + sizeof s, index).ptr);
  b.push_back(',');
  put(b, x, x_digits);
  ((b.push_back(','), put(b, rest)), ...);
}

}  // namespace

Output::Output(const std::string& dir, bool nodes, bool particles, Marks resume, std::string prefix)
    : dir_(dir), want_nodes_(nodes), want_particles_(particles), resume_(std::move(resume)), prefix_(std::move(prefix)) {}

Output::~Output() {
  for (std::FILE* f : {nodes_, particles_, energy_, front_})
    if (f) std::fclose(f);
  try {  // a run stopped by an error: what its tables hold so far, as closing a file would
    flush_rows();
  } catch (const std::exception&) {
  }
}

std::FILE* Output::open(const std::string& name, const char* header) {
  const std::string path = dir_ + "/" + name;
  if (auto it = resume_.find(name); it != resume_.end()) {
    std::error_code ec;
    std::filesystem::resize_file(path, static_cast<std::uintmax_t>(it->second), ec);
    if (ec) throw SystemError(fmt::format("cannot resume {}: {}", path, ec.message()));
    std::FILE* f = std::fopen(path.c_str(), "a");
    if (!f) throw SystemError(fmt::format("cannot append to {}: {}", path, std::strerror(errno)));
    std::fseek(f, 0, SEEK_END);  // so ftell reports the length from the start
    names_[f] = name;
    return f;
  }
  std::FILE* f = std::fopen(path.c_str(), "w");
  if (!f) throw SystemError(fmt::format("cannot write {}: {}", path, std::strerror(errno)));
  names_[f] = name;
  emit(f, header);
  return f;
}

void Output::emit(std::FILE* f, std::string_view bytes, bool flush) {
  // A full disk or a vanished folder is the machine's failure, said with the file and the
  // system's reason; a table left short would otherwise pass for a whole one.
  if ((!bytes.empty() && std::fwrite(bytes.data(), 1, bytes.size(), f) != bytes.size()) ||
      (flush && std::fflush(f) != 0))
    throw SystemError(fmt::format("writing {}/{}: {}", dir_, names_[f], std::strerror(errno)));
}

void Output::close() {
  flush_rows();
  std::vector<std::FILE**> files = {&nodes_, &particles_, &energy_, &front_};
  for (std::FILE** f : files) {
    if (!*f) continue;
    const std::string name = names_[*f];
    const bool ok = std::fflush(*f) == 0 && !std::ferror(*f);
    const int err = errno;
    const bool closed = std::fclose(*f) == 0;
    *f = nullptr;
    if (!ok || !closed)
      throw SystemError(fmt::format("writing {}/{}: {}", dir_, name, std::strerror(ok ? errno : err)));
  }
}

void Output::record(const State<1>& s, const NodalFields& nf, const Reference* ref) {
  const auto& g = s.grid;
  const auto& p = s.particles;
  const double t = s.time;
  const bool with_ref = ref && ref->valid(t);
  auto ref_columns = [&](double x) {
    if (!ref) return;
    for (const auto& f : ref->fields()) {
      buf_.push_back(',');
      if (with_ref) put(buf_, ref->value(f, x, t));
    }
  };
  auto ref_header = [&](std::string h) {
    if (ref)
      for (const auto& f : ref->fields()) h += ",ref_" + f;
    return h + "\n";
  };
  if (want_nodes_) {
    if (!nodes_)
      nodes_ = open(prefix_ + "nodes.csv",
                    ref_header("time,node,x,mass,density,velocity,strain,stress,pressure,force").c_str());
    buf_.clear();
    for (int i = 0; i <= g.cells[0]; ++i) {
      const std::size_t k = g.index1(i);
      put_row(buf_, t, static_cast<std::size_t>(i), nf.x[i], 10, nf.mass[i], nf.density[i], nf.velocity[i],
              nf.strain[i], nf.stress[i], -nf.stress[i], g.force[0][k]);
      ref_columns(nf.x[i]);
      buf_.push_back('\n');
    }
    emit(nodes_, {buf_.data(), buf_.size()}, true);
  }
  if (want_particles_) {
    // The law's own fields (temperature, the lateral stresses, ...) after ADMPM's columns
    // and the labels; the columns are those of the first record.
    const auto extra = s.material ? s.material->point_fields(points(p)) : std::vector<material::PointField>{};
    if (!particles_) {
      std::string h = "time,particle,x,mass,volume,density,velocity,strain,stress,pressure,body,material";
      for (const auto& f : extra) h += "," + f.name;
      particles_ = open(prefix_ + "particles.csv", ref_header(h).c_str());
      extra_columns_ = extra.size();
    }
    if (extra.size() != extra_columns_)
      throw std::logic_error(fmt::format("particles.csv: {} law fields where its header has {}", extra.size(),
                                         extra_columns_));
    buf_.clear();
    for (std::size_t q = 0; q < p.size(); ++q) {
      put_row(buf_, t, q, p.x[0][q], 12, p.mass[q], p.volume[q], p.density(q), p.v[0][q], p.strain[0][q],
              p.stress[0][q], -p.stress[0][q], p.body.empty() ? 0.0 : p.body[q], p.law.empty() ? 0.0 : p.law[q]);
      for (const auto& f : extra) buf_.push_back(','), put(buf_, f.values[q]);
      ref_columns(p.x[0][q]);
      buf_.push_back('\n');
    }
    emit(particles_, {buf_.data(), buf_.size()}, true);
  }
}

void Output::energy(std::int64_t step, double t, double kinetic, double internal, double momentum,
                    double boundary_impulse, double ref_total) {
  if (!energy_)
    energy_ = open("energy.csv", "step,time,kinetic,internal,total,momentum,boundary_impulse,ref_total\n");
  buf_.clear();
  fmt::format_to(std::back_inserter(buf_), "{},{:.10g},{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},", step, t, kinetic,
                 internal, kinetic + internal, momentum, boundary_impulse);
  if (std::isfinite(ref_total)) fmt::format_to(std::back_inserter(buf_), "{:.12g}", ref_total);
  buf_.push_back('\n');
  emit(energy_, {buf_.data(), buf_.size()});
}

void Output::front(double t, double x, double ref_x) {
  if (!front_) front_ = open("front.csv", "time,front,ref_front\n");
  buf_.clear();
  fmt::format_to(std::back_inserter(buf_), "{:.10g},{:.10g},{:.10g}\n", t, x, ref_x);
  emit(front_, {buf_.data(), buf_.size()}, true);
}

void Output::row(const std::string& table, std::string_view header, const std::vector<double>& values) {
  auto [it, made] = tables_.try_emplace(table);
  RowTable& t = it->second;
  if (made) {
    if (auto r = resume_.find(table); r != resume_.end()) {  // cut back to its checkpoint's length
      const std::string path = dir_ + "/" + table;
      std::error_code ec;
      std::filesystem::resize_file(path, static_cast<std::uintmax_t>(r->second), ec);
      if (ec) throw SystemError(fmt::format("cannot resume {}: {}", path, ec.message()));
      t.written = r->second;
      t.fresh = false;
    } else {
      t.pending.assign(header);
    }
  }
  const std::size_t before = t.pending.size();
  buf_.clear();
  for (std::size_t k = 0; k < values.size(); ++k) {
    if (k) buf_.push_back(',');
    put(buf_, values[k], 12);
  }
  buf_.push_back('\n');
  t.pending.append(buf_.data(), buf_.size());
  pending_bytes_ += t.pending.size() - before;
  if (pending_bytes_ > kPendingBytes) flush_rows();
}

void Output::flush_rows() {
  for (auto& [name, t] : tables_) {
    if (t.pending.empty()) continue;
    const std::string path = dir_ + "/" + name;
    std::FILE* f = std::fopen(path.c_str(), t.fresh ? "w" : "a");
    if (!f) throw SystemError(fmt::format("cannot write {}: {}", path, std::strerror(errno)));
    const bool wrote = std::fwrite(t.pending.data(), 1, t.pending.size(), f) == t.pending.size();
    const int err = errno;
    const bool closed = std::fclose(f) == 0;
    if (!wrote || !closed) throw SystemError(fmt::format("writing {}: {}", path, std::strerror(wrote ? errno : err)));
    t.written += static_cast<std::int64_t>(t.pending.size());
    t.fresh = false;
    pending_bytes_ -= t.pending.size();
    t.pending.clear();
    t.pending.shrink_to_fit();  // thousands of tables: each keeps no buffer between flushes
  }
}

Output::Marks Output::marks() {
  // A table this process has not opened yet (a resumed run stopped again before its next
  // record) keeps the length its checkpoint gave it: left out, the next resume would start
  // it afresh and lose the records before.
  Marks m = resume_;
  const std::pair<const char*, std::FILE*> files[] = {
      {"nodes.csv", nodes_}, {"particles.csv", particles_}, {"energy.csv", energy_}, {"front.csv", front_}};
  for (const auto& [name, f] : files) {
    if (!f) continue;
    emit(f, {}, true);
    m[name] = static_cast<std::int64_t>(std::ftell(f));
  }
  flush_rows();
  for (const auto& [name, t] : tables_) m[name] = t.written;
  return m;
}

}  // namespace mpmx::app
