#pragma once
// The one registry idiom of mpmx. A kind of named piece (a shape scheme, a material, an
// MD potential, a DPD potential, a reference solution) is a list of entry types, each
// with
//   static constexpr std::string_view name;   // what a deck calls it
// and what its kind asks of an entry (a reader of its own deck table, a maker). Adding
// one is its own file and one line in its kind's list:
//   using Materials = Registry<LinearElasticModel, ..., MieGruneisenModel>;
// Names are compared here and nowhere else: a caller asks for the entry of a name and is
// handed its type.
#include <array>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

namespace mpmx {

template <class... Entries>
struct Registry {
  static_assert(sizeof...(Entries) > 0, "a registry lists at least one entry");

  static std::vector<std::string> names() { return {std::string(Entries::name)...}; }

  static bool has(std::string_view name) { return ((Entries::name == name) || ...); }

  // The entry's place in the list (the index of its alternative in a variant listed in
  // the same order); sizeof...(Entries) for an unknown name.
  static constexpr std::size_t index(std::string_view name) {
    constexpr std::array<std::string_view, sizeof...(Entries)> all{Entries::name...};
    for (std::size_t k = 0; k < all.size(); ++k)
      if (all[k] == name) return k;
    return all.size();
  }

  // f.template operator()<E>() for the entry E named `name`; `otherwise()` when none is
  // (the caller has already recorded the unknown name, as Table::choice does).
  template <class F, class Otherwise>
  static decltype(auto) with(std::string_view name, F&& f, Otherwise&& otherwise) {
    return with_impl<F, Otherwise, Entries...>(name, std::forward<F>(f), std::forward<Otherwise>(otherwise));
  }

  // f.template operator()<E>() for the k-th entry (k < sizeof...(Entries)).
  template <class F>
  static decltype(auto) at(std::size_t k, F&& f) {
    return at_impl<F, Entries...>(k, std::forward<F>(f));
  }

  // f.template operator()<E>() for every entry, in list order.
  template <class F>
  static void each(F&& f) {
    (f.template operator()<Entries>(), ...);
  }

 private:
  template <class F, class Otherwise, class E, class... Rest>
  static decltype(auto) with_impl(std::string_view name, F&& f, Otherwise&& otherwise) {
    if (E::name == name) return f.template operator()<E>();
    if constexpr (sizeof...(Rest) > 0)
      return with_impl<F, Otherwise, Rest...>(name, std::forward<F>(f), std::forward<Otherwise>(otherwise));
    else
      return otherwise();
  }
  template <class F, class E, class... Rest>
  static decltype(auto) at_impl(std::size_t k, F&& f) {
    if constexpr (sizeof...(Rest) == 0) {
      return f.template operator()<E>();
    } else {
      if (k == 0) return f.template operator()<E>();
      return at_impl<F, Rest...>(k - 1, std::forward<F>(f));
    }
  }
};

// The variant of a registry's entries, alternatives in list order (so Registry::index
// of a name is the index of its entry's alternative): a spec that holds one entry.
template <class R>
struct VariantOfRegistry;
template <class... Entries>
struct VariantOfRegistry<Registry<Entries...>> {
  using type = std::variant<Entries...>;
};
template <class R>
using VariantOf = typename VariantOfRegistry<R>::type;

}  // namespace mpmx
