#include <cmath>
#include <vector>

#include "mpmx/app/mpm/output.hpp"
#include "mpmx/app/mpm/references.hpp"
#include "mpmx/reference/shock_front.hpp"

namespace mpmx::app {

namespace {

// The front behind the right-going half of the initial strain step (ADMPM sec. 8.3): at
// each record, where the strain crosses from the plateau ahead to the one behind (the
// mean of the two initial states: the step splits into two half-amplitude waves); at
// the end, its speed against the bar's sqrt(E / rho).
class FrontComparison final : public Comparison<1> {
 public:
  explicit FrontComparison(const MpmConfig& c)
      : c_(c),
        ahead_(c.strain.right),
        behind_(0.5 * (c.strain.left + c.strain.right)),
        c0_(std::sqrt(c.material.youngs_modulus / c.material.density)) {}

  void compare(const mpm::State<1>&, ErrorBook&) override {}

  void at_record(const mpm::State<1>& s, ErrorBook& book, Output* out) override {
    if (s.step == 0) return;
    const auto& p = s.particles;
    std::vector<double> xs(p.x[0]), fs(p.strain[0]);
    const auto x = reference::locate_front(xs, fs, behind_, ahead_, reference::ScanFrom::right);
    if (!x) return;
    book.fronts.emplace_back(s.time, *x);
    if (out) out->front(s.time, *x, c_.strain.at + c0_ * s.time);
  }

  void finish(ErrorBook& book) const override {
    if (book.fronts.size() < 2) return;
    std::vector<double> ts, xs;
    for (const auto& [t, x] : book.fronts) ts.push_back(t), xs.push_back(x);
    book.front_speed = reference::front_speed(ts, xs);
    const double rel = std::abs(book.front_speed - c0_) / c0_;
    book.errors["front_speed"] = {rel, rel};
    book.record().set("front_speed", book.front_speed);
    book.record().set("reference_speed", c0_);
  }

 private:
  const MpmConfig& c_;
  double ahead_, behind_, c0_;
};

}  // namespace

template <int Dim>
std::unique_ptr<Comparison<Dim>> ShockFrontEntry::make(const MpmConfig& c) {
  if constexpr (Dim != 1) return nullptr;
  else return std::make_unique<FrontComparison>(c);
}

template std::unique_ptr<Comparison<1>> ShockFrontEntry::make<1>(const MpmConfig&);
template std::unique_ptr<Comparison<2>> ShockFrontEntry::make<2>(const MpmConfig&);
template std::unique_ptr<Comparison<3>> ShockFrontEntry::make<3>(const MpmConfig&);

}  // namespace mpmx::app
