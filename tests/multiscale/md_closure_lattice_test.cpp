// md_closure's crystal (issue 53, item 2): with no `lattice` or `orient`, the boxes take
// the lattice the potential's file declares; a crystal the potential does not hold
// together is refused with its constants (CuTa.eam.alloy names Ta fcc, whose fcc Ta is
// not Born-stable); the boxes' constants are said in `check` and run.json; a deck that
// names another lattice than the file's, where the file's lies lower, is warned of.
#include <gtest/gtest.h>

#include <string>

#include "mpmx/app/mpm/materials.hpp"
#include "mpmx/io/deck.hpp"
#include "mpmx/multiscale/md_closure_model.hpp"

namespace md_closure_lattice {

using namespace mpmx;

std::shared_ptr<const material::Model> read(const std::string& md_keys, const std::string& element,
                                            std::vector<std::string>& errors) {
  auto deck = io::Deck::from_string("[material]\nmodel = \"md_closure\"\n[material.potential]\nstyle = \"eam\"\n"
                                    "file = \"CuTa.eam.alloy\"\nelements = [\"" + element + "\"]\n[material.md]\n" +
                                    md_keys);
  auto m = deck.root().table("material");
  auto model = app::read_material(m, app::material_context(2, "", "nm_ps_GPa"));
  errors = deck.errors();
  return model;
}

TEST(MdClosureLattice, TheFilesLatticeUnlessTheDeckNamesOne) {
  std::vector<std::string> errors;
  read("cells = 3\n", "Ta", errors);  // the file's fcc: unstable
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_NE(errors.front().find("not Born-stable"), std::string::npos) << errors.front();
  EXPECT_NE(errors.front().find("the one the potential's file declares"), std::string::npos) << errors.front();

  const auto ta = read("cells = 3\nlattice = \"bcc\"\n", "Ta", errors);
  ASSERT_TRUE(errors.empty()) << errors.front();
  const auto& m = dynamic_cast<const multiscale::MdClosureModel&>(*ta);
  EXPECT_NEAR(m.c11, 264.39, 0.01);
  EXPECT_NEAR(m.c12, 159.54, 0.01);
  EXPECT_NEAR(m.c44, 80.88, 0.01);
  EXPECT_TRUE(m.warnings.empty());  // bcc Ta lies below the file's fcc
  EXPECT_NE(m.check_notes()[1].find("C11 = 264.39"), std::string::npos) << m.check_notes()[1];
  EXPECT_EQ(m.constants().front().first, "c11");
  EXPECT_NE(m.constants_source().find("bcc"), std::string::npos);

  const auto cu = read("cells = 3\n", "Cu", errors);  // the file's fcc, as before
  ASSERT_TRUE(errors.empty()) << errors.front();
  EXPECT_NE(dynamic_cast<const multiscale::MdClosureModel&>(*cu).lattice_from.find("file"), std::string::npos);

  const auto cu_bcc = read("cells = 3\nlattice = \"bcc\"\n", "Cu", errors);  // bcc Cu holds, but lies above fcc
  if (errors.empty()) {
    const auto& w = dynamic_cast<const multiscale::MdClosureModel&>(*cu_bcc).warnings;
    ASSERT_EQ(w.size(), 1u);
    EXPECT_NE(w.front().find("declares Cu fcc"), std::string::npos) << w.front();
  } else {
    EXPECT_NE(errors.front().find("not Born-stable"), std::string::npos) << errors.front();
  }
}

}  // namespace md_closure_lattice
