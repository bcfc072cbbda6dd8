// Every input kept for the fuzz targets, replayed through them in the ordinary builds
// (Release, and ASan/UBSan in `make test`): the seed and grown corpus in
// tests/fuzz/corpus/<target>/, and each input that once crashed a target in
// tests/fuzz/regressions/<target>/ (named after what it found). Each must end in a value
// or an InputError, never a crash, a sanitizer report or another exception.
#define MPMX_FUZZ_REPLAY
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "bodies_fuzz.cpp"
#include "checkpoint_fuzz.cpp"
#include "dpd_deck_fuzz.cpp"
#include "eam_fuzz.cpp"
#include "fit_deck_fuzz.cpp"
#include "lammps_table_fuzz.cpp"
#include "md_deck_fuzz.cpp"
#include "mpm_deck_fuzz.cpp"

namespace {

namespace fs = std::filesystem;
using Target = int (*)(const std::uint8_t*, std::size_t);

std::size_t replay(const std::string& name, Target target) {
  std::size_t n = 0;
  for (const char* kind : {"corpus", "regressions"}) {
    const fs::path dir = fs::path(MPMX_SOURCE_DIR) / "tests/fuzz" / kind / name;
    if (!fs::is_directory(dir)) continue;
    std::vector<fs::path> files;
    for (const auto& e : fs::directory_iterator(dir))
      if (e.is_regular_file()) files.push_back(e.path());
    std::sort(files.begin(), files.end());
    for (const auto& f : files) {
      std::ifstream in(f, std::ios::binary);
      const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
      SCOPED_TRACE(f.string());
      EXPECT_NO_THROW(target(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()));
      ++n;
    }
  }
  return n;
}

TEST(FuzzReplay, MpmDeck) { EXPECT_GT(replay("mpm_deck", mpmx::fuzz::mpm_deck), 10u); }
TEST(FuzzReplay, MdDeck) { EXPECT_GT(replay("md_deck", mpmx::fuzz::md_deck), 5u); }
TEST(FuzzReplay, Eam) { EXPECT_GT(replay("eam", mpmx::fuzz::eam), 3u); }
TEST(FuzzReplay, LammpsTable) { EXPECT_GT(replay("lammps_table", mpmx::fuzz::lammps_table), 1u); }
TEST(FuzzReplay, DpdDeck) { EXPECT_GT(replay("dpd_deck", mpmx::fuzz::dpd_deck), 5u); }
TEST(FuzzReplay, FitDeck) { EXPECT_GT(replay("fit_deck", mpmx::fuzz::fit_deck), 3u); }
TEST(FuzzReplay, Bodies) { EXPECT_GT(replay("bodies", mpmx::fuzz::bodies), 3u); }
TEST(FuzzReplay, Checkpoint) { EXPECT_GT(replay("checkpoint", mpmx::fuzz::checkpoint), 7u); }

}  // namespace
