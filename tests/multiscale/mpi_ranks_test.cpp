// ctest-label: mpi
// `mpirun -np K mpmx run` on a DDMP-MD bar (VALIDATION.md P1): the material points'
// boxes spread over K ranks give the single-process run's bytes for every K and thread
// count; a checkpoint taken under one rank count resumes under another bit-for-bit;
// Ctrl-C to mpirun leaves a checkpoint; a box failing on one rank stops every rank with
// its message. The bar is a scaled-down H2 (7 points of 32 atoms at 300 K, so random
// streams and relaxation are exercised, and 7 points split unevenly over 2 and 3 ranks).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <tuple>

#include <fmt/format.h>

#include "ms_test_util.hpp"
#include "mpmx/multiscale/md_closure.hpp"

namespace {

using namespace mpmx;

// One machine, loopback only; root in the test containers. `extra`: mpirun options.
std::string mpirun(int ranks, const std::string& extra = "") {
  return fmt::format("'{}' --oversubscribe --allow-run-as-root {} -np {}", MPMX_MPIEXEC, extra, ranks);
}

std::string deck_file(const std::string& name, int steps) {
  auto c = test::tiny_bar(7, 2, steps, 300.0);
  // The boxes of the first and last points dumped (they run on rank 0 and the last rank).
  c.deck["output"].as_table()->insert_or_assign("md_dump", toml::table{{"points", toml::array{0, 6}}, {"every", 4}});
  const std::string deck = test::scratch_dir(name) + "/bar.toml";
  std::ofstream(deck) << c.deck;
  return deck;
}

// `mpmx run DECK --out DIR` with the rest of the command line, under K ranks (0: no
// mpirun); the exit status.
int run(int ranks, const std::string& deck, const std::string& out, const std::string& rest = "") {
  const std::string launch = ranks > 0 ? mpirun(ranks) + " " : "";
  const std::string cmd = fmt::format("{}'{}' run '{}' --out '{}' --quiet --no-plot {} > '{}.log' 2>&1", launch,
                                      MPMX_BINARY, deck, out, rest, out);
  const int status = std::system(cmd.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// run.json less the lines that say how the run was spread and timed.
std::string physics(const std::string& dir) {
  std::istringstream in(test::read_file(dir + "/run.json"));
  std::string line, kept;
  while (std::getline(in, line)) {
    if (line.find("\"phases\" : {") != std::string::npos) {  // the step's seconds by phase: the block
      while (std::getline(in, line) && line.find('}') == std::string::npos) {
      }
      continue;
    }
    bool drop = false;
    for (const char* key :
       {"\"wall_seconds\"", "_per_second\"", "\"threads\"", "\"ranks\"", "\"rank_imbalance\"", "\"rebalances\"",
        "\"peak_memory_bytes\""})
      drop = drop || line.find(key) != std::string::npos;
    if (!drop) kept += line + "\n";
  }
  return kept;
}

void expect_same_outputs(const std::string& a, const std::string& b) {
  for (const char* f : {"particles.csv", "nodes.csv", "energy.csv", "md_dump/point_000000_000000004.dump",
                        "md_dump/point_000006_000000004.dump", "md_dump/point_000006_000000000.dump"}) {
    const std::string x = test::read_file(a + "/" + f);
    EXPECT_FALSE(x.empty()) << a << "/" << f;
    EXPECT_EQ(x, test::read_file(b + "/" + f)) << b << "/" << f;
  }
  EXPECT_EQ(physics(a), physics(b)) << b;
}

TEST(MpiRanks, SameBytesOnEveryRankAndThreadCount) {
  const std::string deck = deck_file("mpi_p1", 8);
  const std::string single = test::scratch_dir("mpi_p1_single");
  ASSERT_EQ(run(0, deck, single, "--threads 1"), 0) << test::read_file(single + ".log");
  const std::string record = test::read_file(single + "/run.json");
  EXPECT_NE(record.find("\"ranks\" : 1,"), std::string::npos);
  EXPECT_NE(record.find("\"rank_imbalance\" : 1.0,"), std::string::npos);
  EXPECT_NE(record.find("\"md_atom_steps_per_second\""), std::string::npos);
  for (int ranks : {1, 2, 3})
    for (int threads : {1, 2}) {
      const std::string out = test::scratch_dir(fmt::format("mpi_p1_{}x{}", ranks, threads));
      ASSERT_EQ(run(ranks, deck, out, fmt::format("--threads {}", threads)), 0) << test::read_file(out + ".log");
      expect_same_outputs(single, out);
      const std::string rec = test::read_file(out + "/run.json");
      EXPECT_NE(rec.find(fmt::format("\"ranks\" : {},", ranks)), std::string::npos) << out;
      EXPECT_NE(rec.find(fmt::format("\"threads\" : {},", threads)), std::string::npos) << out;
      EXPECT_NE(rec.find("\"rank_imbalance\""), std::string::npos) << out;
      // Output from rank 0 alone: one summary line, not one per rank.
      const std::string log = test::read_file(out + ".log");
      EXPECT_EQ(log.find("steps in"), log.rfind("steps in")) << log;
    }
}

TEST(MpiRanks, CheckpointResumesUnderAnotherRankCount) {
  const std::string deck = deck_file("mpi_resume", 8);
  const std::string whole = test::scratch_dir("mpi_resume_whole");
  ASSERT_EQ(run(0, deck, whole, "--threads 2"), 0);
  // Two ranks stop after step 3; three ranks finish.
  const std::string cut = test::scratch_dir("mpi_resume_2to3");
  EXPECT_EQ(run(2, deck, cut, "--threads 1 --stop-after 3"), 130) << test::read_file(cut + ".log");
  ASSERT_TRUE(std::filesystem::exists(cut + "/checkpoint.bin"));
  ASSERT_EQ(run(3, deck, cut, "--threads 1 --resume"), 0) << test::read_file(cut + ".log");
  expect_same_outputs(whole, cut);
  EXPECT_FALSE(std::filesystem::exists(cut + "/checkpoint.bin"));
  // Three ranks stop after step 5; the plain binary finishes.
  const std::string cut1 = test::scratch_dir("mpi_resume_3to1");
  EXPECT_EQ(run(3, deck, cut1, "--threads 1 --stop-after 5"), 130) << test::read_file(cut1 + ".log");
  ASSERT_EQ(run(0, deck, cut1, "--threads 2 --resume"), 0) << test::read_file(cut1 + ".log");
  expect_same_outputs(whole, cut1);
}

// A rebalance at every checkpoint (threshold 0) moves boxes between the ranks by their
// measured cost; the results stay those of the single-process run.
TEST(MpiRanks, RebalanceKeepsTheBytes) {
  const std::string deck = deck_file("mpi_rebalance", 8);
  const std::string single = test::scratch_dir("mpi_rebalance_single"), out = test::scratch_dir("mpi_rebalance_3");
  ASSERT_EQ(run(0, deck, single, "--threads 1"), 0);
  ASSERT_EQ(run(3, deck, out, "--threads 1 --checkpoint-every 2 --rebalance-above 0"), 0)
      << test::read_file(out + ".log");
  expect_same_outputs(single, out);
  EXPECT_NE(test::read_file(out + "/run.json").find("\"rebalances\""), std::string::npos);
}

// (That the checkpoint resumes bit for bit under any rank count is the test above: the
// file is the same whatever made the run stop.)
TEST(MpiRanks, CtrlCToMpirunWritesACheckpointOnEveryRank) {
  const std::string deck = deck_file("mpi_sigint", 500);
  const std::string cut = test::scratch_dir("mpi_sigint_cut");
  // SIGINT to mpirun once the step loop runs (energy.csv appears in the staging folder
  // after the handler is set). mpirun waits odls_base_sigkill_timeout seconds (1 by default), sends the
  // ranks SIGTERM, waits as long again and kills them: 1 s to finish the step (tens of
  // milliseconds here) and write the checkpoint.
  const std::string script = cut + "/../mpi_sigint.sh";
  std::ofstream(script) << fmt::format(
      "{} '{}' run '{}' --out '{}' --quiet --no-plot --threads 1 > '{}.log' 2>&1 &\npid=$!\n"
      "for i in $(seq 600); do [ -s '{}/.staging/energy.csv' ] && break; sleep 0.1; done\nkill -INT $pid\nwait $pid\n",
      mpirun(2), MPMX_BINARY, deck, cut, cut, cut);
  const int status = std::system(("bash '" + script + "'").c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_NE(WEXITSTATUS(status), 0);
  const std::string log = test::read_file(cut + ".log");
  ASSERT_TRUE(std::filesystem::exists(cut + "/checkpoint.bin")) << log;
  EXPECT_NE(log.find("--resume"), std::string::npos) << log;
  EXPECT_EQ(log.find("mpmx: interrupted"), log.rfind("mpmx: interrupted")) << log;  // printed once
  const std::string rec = test::read_file(cut + "/run.json");
  EXPECT_NE(rec.find("\"interrupted\""), std::string::npos);
  EXPECT_EQ(rec.find("\"steps\" : 500,"), std::string::npos) << "the run ended before the signal came";
  // Both ranks read it back and go on (two more steps).
  const auto at = log.find("step ");
  ASSERT_NE(at, std::string::npos) << log;
  const int step = std::atoi(log.c_str() + at + 5);
  ASSERT_GT(step, 0) << log;
  EXPECT_EQ(run(2, deck, cut, fmt::format("--threads 1 --resume --stop-after {}", step + 2)), 130)
      << test::read_file(cut + ".log");
  EXPECT_NE(test::read_file(cut + ".log").find(fmt::format("step {} of 500", step + 2)), std::string::npos);
}

TEST(MpiRanks, NonFiniteBoxOnOneRankStopsEveryRank) {
  const std::string deck = deck_file("mpi_nan", 8);
  // 7 points over 3 ranks: blocks [0, 2), [2, 4), [4, 7); point 5 is rank 2's.
  for (const auto& [ranks, point, owner] : {std::tuple{3, 5, 2}, std::tuple{2, 1, 0}}) {
    const std::string out = test::scratch_dir(fmt::format("mpi_nan_{}", ranks));
    const std::string cmd =
        fmt::format("MPMX_TEST_NAN_POINT={} {} -x MPMX_TEST_NAN_POINT '{}' run '{}' --out '{}' --quiet --no-plot "
                    "--threads 1 > '{}.log' 2>&1",
                    point, mpirun(ranks), MPMX_BINARY, deck, out, out);
    const int status = std::system(cmd.c_str());
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 3);  // stopped by the physics
    const std::string log = test::read_file(out + ".log");
    const std::string message =
        fmt::format("rank {}: the MD box of material point {} gave a non-finite stress", owner, point);
    EXPECT_NE(log.find("mpmx: run stopped: " + message), std::string::npos) << log;
    EXPECT_EQ(log.find("mpmx: run stopped"), log.rfind("mpmx: run stopped")) << log;  // printed once
    // With the step and the time it failed in.
    EXPECT_TRUE(std::regex_search(log, std::regex(R"(non-finite stress \([^)]*\) in step [0-9]+ \(t = [0-9.e+-]+\))")))
        << log;
    const std::string rec = test::read_file(out + "/run.json");
    EXPECT_NE(rec.find("\"stopped\""), std::string::npos);
    EXPECT_NE(rec.find(message), std::string::npos);
    EXPECT_FALSE(test::read_file(out + "/particles.csv").empty());  // the partial result stays
    // The state it stopped in, written once (by rank 0) as the final record.
    const std::size_t at = rec.find("\"final_record\"");
    ASSERT_NE(at, std::string::npos) << rec;
    EXPECT_NE(rec.find(message, at), std::string::npos);
    EXPECT_NE(rec.find("final_particles.csv", at), std::string::npos) << rec;
    EXPECT_FALSE(test::read_file(out + "/final_particles.csv").empty());
  }
}

}  // namespace

// P1 in 2-D: a flyer on a target with a 108-atom box per point (the 2-D closure: full
// gradients, rotations, eq. 7.11) gives the same VTK files and run.json under 1, 2 and
// 3 ranks, and a checkpoint taken under 2 ranks resumes under 3 to the same bytes.
TEST(MpiRanks, TwoDimensionalClosureGivesTheSameBytes) {
  const std::string deck = test::scratch_dir("mpi_2d") + "/flyer.toml";
  std::ofstream(deck) << test::flyer_2d_deck(50.0, 4);
  const std::string single = test::scratch_dir("mpi_2d_single");
  ASSERT_EQ(run(0, deck, single, "--threads 1"), 0) << test::read_file(single + ".log");
  // The points start alike and share boxes, which split as the flyer strikes, with
  // auditors on private boxes: the groups' path is the one every rank count must repeat.
  const std::string rec = test::read_file(single + "/run.json");
  const auto boxes = rec.find("\"boxes\"");
  ASSERT_NE(boxes, std::string::npos);
  auto figure = [&](const char* key) { return std::stoi(rec.substr(rec.find(key, boxes) + std::string(key).size() + 3)); };
  EXPECT_EQ(figure("\"initial\""), 1);
  EXPECT_GT(figure("\"max\""), 1);
  EXPECT_NE(rec.find("\"audit_rel_rms\""), std::string::npos);
  auto same_vtk = [&](const std::string& out) {
    for (const auto& f : std::filesystem::recursive_directory_iterator(single + "/vtk")) {
      const std::string rel = std::filesystem::relative(f.path(), single).string();
      EXPECT_EQ(test::read_file(single + "/" + rel), test::read_file(out + "/" + rel)) << out << "/" << rel;
    }
    EXPECT_EQ(test::read_file(single + "/energy.csv"), test::read_file(out + "/energy.csv")) << out;
    EXPECT_EQ(physics(single), physics(out)) << out;
  };
  for (int ranks : {2, 3}) {
    const std::string out = test::scratch_dir(fmt::format("mpi_2d_{}", ranks));
    ASSERT_EQ(run(ranks, deck, out, "--threads 1"), 0) << test::read_file(out + ".log");
    same_vtk(out);
  }
  const std::string cut = test::scratch_dir("mpi_2d_2to3");
  EXPECT_EQ(run(2, deck, cut, "--threads 1 --stop-after 2"), 130) << test::read_file(cut + ".log");
  ASSERT_EQ(run(3, deck, cut, "--threads 1 --resume"), 0) << test::read_file(cut + ".log");
  same_vtk(cut);
}

// P1 for J2 at its smallest: the CI-size DDMP-MD jet (its first 0.25 ps, against the
// direct MD of the tiny jet cut to the same time) gives the same VTK files and run.json
// (eq. 7.12 included) under 1, 2 and 3 ranks.
TEST(MpiRanks, SmallestJetGivesTheSameBytes) {
  const std::string base = test::scratch_dir("mpi_j2");
  const std::string md_deck = base + "/j1.toml", md_out = base + "/j1", deck = base + "/j2.toml";
  std::string j1 = test::read_file(std::string(MPMX_SOURCE_DIR) + "/examples/J1_direct_md_tiny.toml");
  j1.replace(j1.find("duration_ps = 30.0"), 18, "duration_ps = 5.0 ");  // 0.25 ps at s = 0.05
  std::ofstream(md_deck) << j1;
  const std::string cmd = fmt::format("'{}' md '{}' --out '{}' --quiet > '{}.log' 2>&1", MPMX_BINARY, md_deck,
                                      md_out, md_out);
  ASSERT_EQ(std::system(cmd.c_str()), 0) << test::read_file(md_out + ".log");
  const auto c = test::deck_with(test::example("J2_ddmp_md_20x10_1ppc_tiny.toml"), [&](toml::table& t) {
    t["time"].as_table()->insert_or_assign("end", 0.25);
    t["output"].as_table()->insert_or_assign("times", toml::array{0.25});
    t["reference"].as_table()->insert_or_assign("times", toml::array{0.25});
    t["reference"].as_table()->insert_or_assign("file", md_out);
  });
  std::ofstream(deck) << c.deck;
  const std::string single = test::scratch_dir("mpi_j2_single");
  ASSERT_EQ(run(0, deck, single, "--threads 1"), 0) << test::read_file(single + ".log");
  EXPECT_NE(test::read_file(single + "/run.json").find("stress_vs_direct_md"), std::string::npos);
  for (int ranks : {2, 3}) {
    const std::string out = test::scratch_dir(fmt::format("mpi_j2_{}", ranks));
    ASSERT_EQ(run(ranks, deck, out, "--threads 1"), 0) << test::read_file(out + ".log");
    for (const auto& f : std::filesystem::recursive_directory_iterator(single + "/vtk")) {
      const std::string rel = std::filesystem::relative(f.path(), single).string();
      EXPECT_EQ(test::read_file(single + "/" + rel), test::read_file(out + "/" + rel)) << out << "/" << rel;
    }
    EXPECT_EQ(physics(single), physics(out)) << out;
  }
}

// Issue 31: a deck that one rank cannot see (here a launch with a command line per rank;
// on a cluster, a file on one node's disk only) stops every rank at once with exit 2 and
// that rank's message, printed once, and leaves no output folder; it used to hang for ever
// (the rank that failed to parse left, the others waited in the deck's agreement).
TEST(MpiRanks, DeckOneRankCannotReadStopsEveryRank) {
  const std::string deck = deck_file("mpi_unreadable", 2);
  const std::string dir = test::scratch_dir("mpi_unreadable_out");
  const std::string out = dir + "/out", missing = dir + "/no_such_deck.toml";
  const std::string cmd = fmt::format(
      "timeout 120 {} '{}' run '{}' --out '{}' --quiet --no-plot : -np 1 '{}' run '{}' --out '{}' --quiet --no-plot "
      "> '{}.log' 2>&1",
      mpirun(1), MPMX_BINARY, deck, out, MPMX_BINARY, missing, out, out);
  const int status = std::system(cmd.c_str());
  ASSERT_TRUE(WIFEXITED(status));
  const std::string log = test::read_file(out + ".log");
  EXPECT_EQ(WEXITSTATUS(status), 2) << log;  // 124: the timeout, the old hang
  EXPECT_NE(log.find("[rank 1 of 2]"), std::string::npos) << log;
  EXPECT_NE(log.find("no_such_deck.toml"), std::string::npos) << log;
  EXPECT_EQ(log.find("[rank 1 of 2]"), log.rfind("[rank 1 of 2]")) << log;  // printed once
  EXPECT_FALSE(std::filesystem::exists(out));
}

// Ranks given different valid decks (once MPI_ERR_TRUNCATE, exit 15, with OUT/.staging
// left) are refused together before any work: exit 2, one message, nothing written.
TEST(MpiRanks, DifferentDecksOnTheRanksAreRefused) {
  const std::string a = deck_file("mpi_deck_a", 2), b = deck_file("mpi_deck_b", 3);
  const std::string dir = test::scratch_dir("mpi_two_decks_out");
  const std::string out = dir + "/out";
  const std::string cmd = fmt::format(
      "timeout 120 {} '{}' run '{}' --out '{}' --quiet --no-plot : -np 1 '{}' run '{}' --out '{}' --quiet --no-plot "
      "> '{}.log' 2>&1",
      mpirun(1), MPMX_BINARY, a, out, MPMX_BINARY, b, out, out);
  const int status = std::system(cmd.c_str());
  ASSERT_TRUE(WIFEXITED(status));
  const std::string log = test::read_file(out + ".log");
  EXPECT_EQ(WEXITSTATUS(status), 2) << log;
  EXPECT_NE(log.find("differs from another rank's"), std::string::npos) << log;
  EXPECT_EQ(log.find("differs from"), log.rfind("differs from")) << log;  // printed once
  EXPECT_FALSE(std::filesystem::exists(out));
}

// Issue 31: a rank that never reaches the deck's agreement (here its deck is a named pipe
// nobody writes, as a file on a hung network disk would be) no longer keeps the others
// spinning for ever: they wait MPMX_AGREE_SECONDS, then end the job with exit 2 and a
// sentence, and nothing is written.
TEST(MpiRanks, ARankThatNeverAnswersEndsTheJobAfterTheBound) {
  const std::string deck = deck_file("mpi_stuck", 2);
  const std::string dir = test::scratch_dir("mpi_stuck_out");
  const std::string out = dir + "/out", pipe = dir + "/deck_on_a_hung_disk.toml";
  ASSERT_EQ(std::system(fmt::format("mkfifo '{}'", pipe).c_str()), 0);
  const std::string cmd = fmt::format(
      "MPMX_AGREE_SECONDS=3 timeout 120 {} -x MPMX_AGREE_SECONDS '{}' run '{}' --out '{}' --quiet --no-plot : "
      "-np 1 '{}' run '{}' --out '{}' --quiet --no-plot > '{}.log' 2>&1",
      mpirun(1), MPMX_BINARY, deck, out, MPMX_BINARY, pipe, out, out);
  const int status = std::system(cmd.c_str());
  ASSERT_TRUE(WIFEXITED(status));
  const std::string log = test::read_file(out + ".log");
  EXPECT_EQ(WEXITSTATUS(status), 2) << log;  // 124: the timeout, a hang
  EXPECT_NE(log.find("[rank 0 of 2] mpmx: the other ranks did not reach"), std::string::npos) << log;
  EXPECT_NE(log.find("within 3 s"), std::string::npos) << log;
  EXPECT_FALSE(std::filesystem::exists(out));
}

// Issue 47 in 2-D under ranks: the CI-size jet block of bcc Ta with x along [110] in
// every point's box, the boxes built at the lattice constant one NPT box found at 10 K
// (prepared once on every rank alike): the same VTK files and run.json under 1 and 2
// ranks and 2 threads, and that constant is NPT's, not the 0 K one.
TEST(MpiRanks, OrientedBccBoxesPreparedByNptGiveTheSameBytes) {
  const auto c = test::deck_with(test::example("J3_ddmp_md_10x5_1ppc_tiny.toml"), [&](toml::table& t) {
    t.erase("reference");
    t["time"].as_table()->insert_or_assign("end", 0.25);
    t["output"].as_table()->insert_or_assign("times", toml::array{0.25});
    auto& mat = *t["material"].as_table();
    mat.insert_or_assign("potential", toml::table{{"style", "eam"}, {"file", "CuTa.eam.alloy"},
                                                  {"elements", toml::array{"Ta"}}});
    auto& md = *mat["md"].as_table();
    md.insert_or_assign("lattice", "bcc");
    md.insert_or_assign("orient", toml::array{toml::array{1, 1, 0}, toml::array{-1, 1, 0}, toml::array{0, 0, 1}});
    md.insert_or_assign("prepare", "npt");
    md.insert_or_assign("prepare_steps", 2000);
  });
  const std::string deck = test::scratch_dir("mpi_ta") + "/ta.toml";
  std::ofstream(deck) << c.deck;
  const std::string single = test::scratch_dir("mpi_ta_single");
  ASSERT_EQ(run(0, deck, single, "--threads 1"), 0) << test::read_file(single + ".log");
  const std::string rec = test::read_file(single + "/run.json");
  auto number = [&](const std::string& key) {
    const auto at = rec.find("\"" + key + "\"");
    return at == std::string::npos ? std::nan("") : std::stod(rec.substr(rec.find(':', at) + 1));
  };
  const double a = number("lattice_constant_A"), a0 = number("lattice_constant_0K_A");
  // CuTa's Ta at 0 K, from the potential itself
  const auto md = test::closure_config(c);
  EXPECT_EQ(a0, multiscale::md_closure_properties(md.potential, md.units, md.lattice).equilibrium.lattice_constant);
  EXPECT_GT(a, a0);                 // 10 K expands it, a little
  EXPECT_LT(a, a0 * 1.001);
  for (const auto& [ranks, threads] : {std::pair{2, 1}, std::pair{0, 2}}) {
    const std::string out = test::scratch_dir(fmt::format("mpi_ta_{}_{}", ranks, threads));
    ASSERT_EQ(run(ranks, deck, out, fmt::format("--threads {}", threads)), 0) << test::read_file(out + ".log");
    for (const auto& f : std::filesystem::recursive_directory_iterator(single + "/vtk")) {
      const std::string rel = std::filesystem::relative(f.path(), single).string();
      EXPECT_EQ(test::read_file(single + "/" + rel), test::read_file(out + "/" + rel)) << out << "/" << rel;
    }
    EXPECT_EQ(physics(single), physics(out)) << out;
  }
}
