#include "mpmx/app/mpm/convergence.hpp"

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>

#include <fmt/format.h>

#include "mpmx/app/mpm/prepare.hpp"
#include "mpmx/core/error.hpp"
#include "mpmx/io/plot.hpp"
#include "mpmx/io/run_record.hpp"

namespace mpmx::app {

using namespace mpm;

MpmConfig refined(const MpmConfig& c, int k) {
  MpmConfig r = c;
  const int f = 1 << k;
  for (int d = 0; d < c.dim; ++d) r.cells_all[d] = c.cells_all[d] * f;
  r.cells = r.cells_all[0];
  r.dt = c.dt / f;
  r.output_every = c.output_every * f;
  r.convergence_levels = 1;
  return r;
}

double observed_order(const std::vector<double>& h, const std::vector<double>& e) {
  double n = 0.0, sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0;
  for (std::size_t k = 0; k < h.size() && k < e.size(); ++k) {
    if (!(e[k] > 0.0) || !(h[k] > 0.0)) continue;
    const double x = std::log(h[k]), y = std::log(e[k]);
    n += 1.0, sx += x, sy += y, sxx += x * x, sxy += x * y;
  }
  const double den = n * sxx - sx * sx;
  return n >= 2.0 && den > 0.0 ? (n * sxy - sx * sy) / den : std::nan("");
}

ConvergenceStudy run_convergence(const MpmConfig& c, const RunOptions& o) {
  if (o.resume) throw InputError("a convergence study (convergence.levels > 1) does not resume: run it afresh");
  ConvergenceStudy study;
  const auto start = std::chrono::steady_clock::now();
  const MpmConfig prepared = prepared_for_run(c);  // once for every level (prepare.hpp)
  for (int k = 0; k < c.convergence_levels; ++k) {
    ConvergenceLevel level;
    const MpmConfig ck = refined(prepared, k);
    RunOptions ok = o;
    if (!o.out_dir.empty()) ok.out_dir = fmt::format("{}/level_{}", o.out_dir, k);
    ok.checkpoint_every = 0;
    ok.checkpoint_seconds = 0.0;
    ok.plot = false;  // the study's figure is convergence.png; each level keeps its VTK files
    if (!o.quiet)
      fmt::print(stderr, "{}: level {} of {}: {} cells along x, dt = {}\n", c.id, k + 1, c.convergence_levels,
                 ck.cells_all[0], ck.dt);
    level.cells = ck.cells_all;
    level.dx = (ck.upper_all[0] - ck.lower_all[0]) / ck.cells_all[0];
    level.dt = ck.dt;
    level.run = run_any(ck, ok);
    if (level.run.interrupted) {
      study.levels.push_back(std::move(level));
      return study;
    }
    study.levels.push_back(std::move(level));
  }
  std::vector<double> h;
  for (const auto& l : study.levels) h.push_back(l.dx);
  for (const auto& [f, e] : study.levels.back().run.errors) {
    std::vector<double> l1, l2;
    for (const auto& l : study.levels) {
      const auto it = l.run.errors.find(f);
      l1.push_back(it == l.run.errors.end() ? 0.0 : it->second.l1);
      l2.push_back(it == l.run.errors.end() ? 0.0 : it->second.l2);
    }
    study.order_l1[f] = observed_order(h, l1);
    study.order_l2[f] = observed_order(h, l2);
  }
  if (o.out_dir.empty()) return study;

  io::RunRecord rec;
  rec.set("version", MPMX_VERSION);
  rec.set("deck", c.deck);
  rec.set("deck_path", c.deck_path);
  rec.set("dim", c.dim);
  const auto& finest = study.levels.back().run;
  rec.set("particles", static_cast<std::int64_t>(finest.particles));
  rec.set("steps", finest.steps);
  rec.set("wall_seconds", std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  for (const auto& [f, e] : finest.errors) {
    rec.set(fmt::format("errors.{}.l1", f), e.l1);
    rec.set(fmt::format("errors.{}.l2", f), e.l2);
  }
  for (const auto& [f, p] : study.order_l2) rec.set(fmt::format("convergence.order.{}", f), p);
  for (const auto& [f, p] : study.order_l1) rec.set(fmt::format("convergence.order_l1.{}", f), p);
  for (std::size_t k = 0; k < study.levels.size(); ++k) {
    const auto& l = study.levels[k];
    toml::table t;
    toml::array cells;
    for (int d = 0; d < c.dim; ++d) cells.push_back(l.cells[d]);
    t.insert("cells", std::move(cells));
    t.insert("dx", l.dx);
    t.insert("dt", l.dt);
    t.insert("particles", static_cast<std::int64_t>(l.run.particles));
    t.insert("steps", l.run.steps);
    t.insert("wall_seconds", l.run.wall_seconds);
    t.insert("out", fmt::format("level_{}", k));
    toml::table errors;
    for (const auto& [f, e] : l.run.errors) errors.insert(f, toml::table{{"l1", e.l1}, {"l2", e.l2}});
    t.insert("errors", std::move(errors));
    rec.append("convergence.levels", std::move(t));
  }
  rec.write(o.out_dir + "/run.json");
  if (o.plot && c.plot) {
    if (io::matplotlib_present()) io::run_plot_script("convergence.py", fmt::format("'{}' >/dev/null", o.out_dir));
    else if (!o.quiet)
      fmt::print(stderr, "{}: no convergence figure (tools/plot/convergence.py needs matplotlib)\n", c.id);
  }
  return study;
}

}  // namespace mpmx::app
