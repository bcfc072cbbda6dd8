#pragma once
// The atomic number of an element symbol, to match a deck's `elements` against a funcfl
// file, which names no element but gives its atomic number on line 2.
#include <array>
#include <string_view>

namespace mpmx::md {

// Element symbols by atomic number - 1.
inline constexpr std::array<std::string_view, 118> kElementSymbols = {
    "H",  "He", "Li", "Be", "B",  "C",  "N",  "O",  "F",  "Ne", "Na", "Mg", "Al", "Si", "P",  "S",  "Cl", "Ar",
    "K",  "Ca", "Sc", "Ti", "V",  "Cr", "Mn", "Fe", "Co", "Ni", "Cu", "Zn", "Ga", "Ge", "As", "Se", "Br", "Kr",
    "Rb", "Sr", "Y",  "Zr", "Nb", "Mo", "Tc", "Ru", "Rh", "Pd", "Ag", "Cd", "In", "Sn", "Sb", "Te", "I",  "Xe",
    "Cs", "Ba", "La", "Ce", "Pr", "Nd", "Pm", "Sm", "Eu", "Gd", "Tb", "Dy", "Ho", "Er", "Tm", "Yb", "Lu", "Hf",
    "Ta", "W",  "Re", "Os", "Ir", "Pt", "Au", "Hg", "Tl", "Pb", "Bi", "Po", "At", "Rn", "Fr", "Ra", "Ac", "Th",
    "Pa", "U",  "Np", "Pu", "Am", "Cm", "Bk", "Cf", "Es", "Fm", "Md", "No", "Lr", "Rf", "Db", "Sg", "Bh", "Hs",
    "Mt", "Ds", "Rg", "Cn", "Nh", "Fl", "Mc", "Lv", "Ts", "Og"};

// 0 when `symbol` is no element's ("cu" and "CU" are not: symbols are as written).
inline int atomic_number(std::string_view symbol) {
  for (std::size_t z = 0; z < kElementSymbols.size(); ++z)
    if (kElementSymbols[z] == symbol) return static_cast<int>(z) + 1;
  return 0;
}

// The symbol of atomic number z ("" outside 1..118).
inline std::string_view element_symbol(int z) {
  return z >= 1 && z <= static_cast<int>(kElementSymbols.size()) ? kElementSymbols[z - 1] : std::string_view();
}

}  // namespace mpmx::md
