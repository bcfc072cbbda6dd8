#include "mpmx/app/mpm/references.hpp"

namespace mpmx::app {

namespace {

// Each point's displacement x_p - X_p against the manufactured u(X_p, t), where the
// state's forcing (mpm/manufactured.hpp) drives the run.
template <int Dim>
class ManufacturedComparison final : public Comparison<Dim> {
 public:
  explicit ManufacturedComparison(const MpmConfig& c) : c_(c) {}
  void compare(const mpm::State<Dim>& s, ErrorBook& book) override {
    if (!s.manufactured) return;
    for (const auto& f : c_.reference.fields) book.add(f, s.manufactured->displacement_error(s.particles, s.time), 0.0, s.time);
  }

 private:
  const MpmConfig& c_;
};

}  // namespace

void ManufacturedEntry::read_keys(Table& r, MpmConfig& c, const std::string& deck_dir) {
  if (!c.manufactured.on) r.check(false, "name", "reference manufactured needs a [manufactured] table");
  if (c.reference.fields.empty()) c.reference.fields = {"displacement"};
  ReferenceEntry::read_keys(r, c, deck_dir);
}

template <int Dim>
std::unique_ptr<Comparison<Dim>> ManufacturedEntry::make(const MpmConfig& c) {
  if constexpr (Dim == 1) return nullptr;
  else return std::make_unique<ManufacturedComparison<Dim>>(c);
}

template std::unique_ptr<Comparison<1>> ManufacturedEntry::make<1>(const MpmConfig&);
template std::unique_ptr<Comparison<2>> ManufacturedEntry::make<2>(const MpmConfig&);
template std::unique_ptr<Comparison<3>> ManufacturedEntry::make<3>(const MpmConfig&);

}  // namespace mpmx::app
