// docs/guide.md gives every key of a continuum deck a row: each key of every continuum
// deck in examples/ (a [grid] table and no [dpd], [jet] or [bar]), and each key the reader
// reads with a default that no example sets, must appear in backquotes in a table row.
// A [[body]] key is `body.KEY`, a body's own law `material.KEY` (any [material] key), a
// face's `boundary.<face>.KEY` and a profile's `initial.<field>.KEY`, as the guide
// writes them.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <toml++/toml.h>

namespace fs = std::filesystem;

namespace {

// The backquoted words of the guide's table rows.
std::set<std::string> guide_rows_keys() {
  std::ifstream in(fs::path(MPMX_SOURCE_DIR) / "docs/guide.md");
  std::set<std::string> keys;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] != '|') continue;
    for (std::size_t a = line.find('`'); a != std::string::npos; a = line.find('`', a + 1)) {
      const std::size_t b = line.find('`', a + 1);
      if (b == std::string::npos) break;
      keys.insert(line.substr(a + 1, b - a - 1));
      a = b;
    }
  }
  return keys;
}

// The guide's spelling of a deck's dotted key.
std::string guide_spelling(std::vector<std::string> path) {
  if (path.size() > 2 && path[0] == "body" && path[1] == "material") path.erase(path.begin());
  if (path.size() == 3 && path[0] == "boundary") path[1] = "<face>";
  if (path.size() == 3 && path[0] == "initial") path[1] = "<field>";
  std::string s;
  for (const auto& p : path) s += (s.empty() ? "" : ".") + p;
  return s;
}

void collect(const toml::table& t, std::vector<std::string> path, std::set<std::string>& out) {
  for (const auto& [k, v] : t) {
    path.emplace_back(k.str());
    if (const auto* sub = v.as_table()) {
      collect(*sub, path, out);
    } else if (const auto* arr = v.as_array(); arr && !arr->empty() && arr->is_array_of_tables()) {
      for (const auto& e : *arr) collect(*e.as_table(), path, out);
    } else {
      out.insert(guide_spelling(path));
    }
    path.pop_back();
  }
}

}  // namespace

TEST(GuideKeys, EveryContinuumKeyHasARow) {
  const auto rows = guide_rows_keys();
  ASSERT_GT(rows.size(), 50u) << "docs/guide.md not found or without its key tables";

  std::set<std::string> keys;
  int decks = 0;
  for (const auto& e : fs::directory_iterator(fs::path(MPMX_SOURCE_DIR) / "examples")) {
    if (e.path().extension() != ".toml") continue;
    const toml::table deck = toml::parse_file(e.path().string());
    if (!deck.contains("grid") || deck.contains("dpd") || deck.contains("jet") || deck.contains("bar")) continue;
    ++decks;
    collect(deck, {}, keys);
  }
  EXPECT_GT(decks, 50);

  // Read by the continuum reader (app/mpm/deck.cpp, the material and potential readers)
  // with a default, or for a law no example uses.
  for (const char* k :
       {"time.cfl", "time.cfl_limit", "time.energy_growth", "time.energy_growth_stop", "output.particles",
        "output.vtk", "output.every", "output.plot", "mass_distribution.on", "mass_distribution.fraction",
        "viscosity.c_L", "viscosity.c_q", "initial.<field>.value", "initial.<field>.offset",
        "initial.<field>.normal", "boundary.<face>.value", "boundary.<face>.amplitude", "boundary.<face>.omega",
        "particles.move", "scheme.alpha", "reference.at", "convergence.levels", "material.small_strain",
        "material.c11", "material.c12", "material.c44", "material.gamma", "material.poisson_ratio",
        "material.density_of", "material.md.skin", "material.md.precision", "material.md.energy_consistency",
        "material.md.share.enabled", "material.md.share.tolerance", "material.md.share.audit",
        "material.potential.epsilon", "material.potential.cutoff", "material.potential.mass",
        "material.potential.sigma", "material.potential.shift", "material.potential.a", "material.potential.c",
        "material.potential.n", "material.potential.m", "body.remove", "body.angular_velocity", "boundary.<face>.times",
        "output.xt", "output.xt_every", "gauge.every"})
    keys.insert(k);

  std::ostringstream missing;
  for (const auto& k : keys)
    if (!rows.count(k)) missing << " " << k;
  EXPECT_TRUE(missing.str().empty()) << "keys without a row in docs/guide.md:" << missing.str();
}
