// OUT/.mpmx-files, the list of what mpmx wrote into a run folder: written and read back
// whole; a list that is not one, or names a file outside the folder (which --overwrite
// would then remove), is refused naming it; a folder without one holds no run.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "mpmx/core/error.hpp"
#include "mpmx/io/run_manifest.hpp"

namespace run_manifest_test {

namespace fs = std::filesystem;
using namespace mpmx;

fs::path folder(const std::string& name) {
  const fs::path p = fs::temp_directory_path() / ("mpmx_manifest_" + std::to_string(getpid())) / name;
  fs::remove_all(p);
  fs::create_directories(p);
  return p;
}

TEST(RunManifest, RoundTripsAndAFolderWithoutOneHoldsNoRun) {
  const fs::path out = folder("round");
  EXPECT_FALSE(io::read_manifest(out.string()));
  const io::RunManifest m{io::run_owner("md", "deck.toml"), {"run.json", "vtk/a.vtu", "thermo.csv"}};
  io::write_manifest(out.string(), m);
  const auto back = io::read_manifest(out.string());
  ASSERT_TRUE(back);
  EXPECT_EQ(back->owner, m.owner);
  EXPECT_EQ(back->files, m.files);
  EXPECT_EQ(m.owner, "md " + (fs::current_path() / "deck.toml").string());
  EXPECT_FALSE(fs::exists(out / ".mpmx-files.tmp"));
  fs::remove_all(out.parent_path());
}

TEST(RunManifest, ANameOutsideTheFolderOrAForeignFileIsRefused) {
  const fs::path out = folder("bad");
  for (const std::string line : {"../elsewhere.csv", "/etc/passwd", "a/../../b"}) {
    std::ofstream(out / ".mpmx-files", std::ios::trunc) << "mpmx-files 1\nrun md /x.toml\n" << line << "\n";
    try {
      (void)io::read_manifest(out.string());
      ADD_FAILURE() << line;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("'" + line + "' is not a file of the folder"), std::string::npos) << e.what();
    }
  }
  std::ofstream(out / ".mpmx-files", std::ios::trunc) << "something else\n";
  try {
    (void)io::read_manifest(out.string());
    ADD_FAILURE() << "a foreign file read as a list";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("not an mpmx file list"), std::string::npos) << e.what();
  }
  fs::remove_all(out.parent_path());
}

}  // namespace run_manifest_test
