// A damaged checkpoint never resumes: every flipped byte (header, payload), every
// truncation, a checkpoint of another deck, a negative or past-the-end step count: each
// is refused with the byte offset and the reason, and `mpmx run --resume` exits 2.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <sys/wait.h>

#include <fmt/format.h>

#include "mpmx/app/checkpoint_fields.hpp"
#include "mpmx/core/exit_codes.hpp"
#include "mpmx/io/checked_file.hpp"
#include "mpmx/app/mpm/checkpoint.hpp"
#include "multiscale/ms_test_util.hpp"

namespace {

using namespace mpmx;

struct Cut {
  app::MpmConfig config;
  app::RunOptions options;
  std::string path, bytes;
};

// An md_closure bar stopped after 2 of its 6 steps: checkpoint.bin holds MD boxes.
Cut cut_run(const std::string& name) {
  Cut k{test::tiny_bar(4, 2, 6), {}, {}, {}};
  k.options.quiet = true;
  k.options.plot = false;
  k.options.out_dir = test::scratch_dir(name);
  k.options.stop_after = 2;
  app::run_mpm(k.config, k.options);
  k.options.stop_after = 0;
  k.options.resume = true;
  k.path = app::checkpoint_path(k.options.out_dir);
  k.bytes = test::read_file(k.path);
  return k;
}

void write(const std::string& path, const std::string& bytes) {
  std::ofstream f(path, std::ios::binary | std::ios::trunc);
  f << bytes;
}

std::string deck_text(const app::MpmConfig& c) {
  std::ostringstream ss;
  ss << c.deck;
  return ss.str();
}

// The message of the InputError `f` throws ("" when it throws none).
template <class F>
std::string damage_refusal(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(CheckpointDamage, EveryFlippedByteIsRefused) {
  const Cut k = cut_run("ckpt_flip");
  ASSERT_GT(k.bytes.size(), io::kCheckedHeaderBytes + 1000);
  const auto kind = app::run_checkpoint_kind(deck_text(k.config), k.config.cells * k.config.per_cell);
  EXPECT_NO_THROW(io::unframe(k.bytes, kind, k.path));
  // Every header byte, and a spread of payload bytes including the last, each flipped
  // in all 8 bits at once and in its lowest bit.
  std::vector<std::size_t> at;
  for (std::size_t i = 0; i < io::kCheckedHeaderBytes; ++i) at.push_back(i);
  for (std::size_t i = io::kCheckedHeaderBytes; i < k.bytes.size(); i += 37) at.push_back(i);
  at.push_back(k.bytes.size() - 1);
  for (std::size_t i : at) {
    for (unsigned char mask : {0xffu, 0x01u}) {
      std::string b = k.bytes;
      b[i] = static_cast<char>(b[i] ^ mask);
      const std::string why = damage_refusal([&] { io::unframe(b, kind, k.path); });
      EXPECT_NE(why.find("byte "), std::string::npos) << "flip at " << i << " accepted";
    }
  }
}

TEST(CheckpointDamage, FlippedByteStopsTheResumeWithItsOffset) {
  const Cut k = cut_run("ckpt_resume_flip");
  for (std::size_t i : {std::size_t{3}, std::size_t{20}, io::kCheckedHeaderBytes + 100, k.bytes.size() / 2}) {
    std::string b = k.bytes;
    b[i] = static_cast<char>(b[i] ^ 0x10);
    write(k.path, b);
    const std::string why = damage_refusal([&] { app::run_mpm(k.config, k.options); });
    EXPECT_NE(why.find(fmt::format("checkpoint {}: byte ", k.path)), std::string::npos) << i << ": " << why;
  }
  // Undamaged, it resumes and completes.
  write(k.path, k.bytes);
  const auto r = app::run_mpm(k.config, k.options);
  EXPECT_EQ(r.steps, 6);
}

TEST(CheckpointDamage, TruncationIsRefused) {
  const Cut k = cut_run("ckpt_truncate");
  const auto kind = app::run_checkpoint_kind(deck_text(k.config), k.config.cells * k.config.per_cell);
  for (std::size_t n : {std::size_t{0}, std::size_t{7}, io::kCheckedHeaderBytes - 1, io::kCheckedHeaderBytes,
                        k.bytes.size() / 3, k.bytes.size() - 1}) {
    const std::string why = damage_refusal([&] { io::unframe(std::string_view(k.bytes).substr(0, n), kind, k.path); });
    EXPECT_NE(why.find("byte "), std::string::npos) << n;
  }
  write(k.path, k.bytes.substr(0, k.bytes.size() - 8));
  EXPECT_NE(damage_refusal([&] { app::run_mpm(k.config, k.options); }).find("truncated"), std::string::npos);
}

TEST(CheckpointDamage, AnotherDeckIsRefused) {
  const Cut k = cut_run("ckpt_other_deck");
  auto other = k.config;
  other.deck.insert_or_assign("extra", 1);
  EXPECT_NE(damage_refusal([&] { app::run_mpm(other, k.options); }).find("another deck"), std::string::npos);
}

// A well-framed checkpoint (valid checksums) whose step count is out of range: the
// range checks, not the checksum, refuse it.
TEST(CheckpointDamage, NegativeOrPastTheEndStepIsRefused) {
  const Cut k = cut_run("ckpt_step");
  const std::string text = deck_text(k.config);
  const auto kind = app::run_checkpoint_kind(text, k.config.cells * k.config.per_cell);
  const std::string payload(io::unframe(k.bytes, kind, k.path));
  // After the deck's text and the input files' digests, the state's magic, then the step.
  std::istringstream fields_in(payload);
  app::CheckpointIn fields(fields_in, k.path);
  ASSERT_EQ(fields.text(), text);
  for (std::int64_t n = fields.integer(); n > 0; --n) fields.text(), fields.integer();
  const std::size_t step_at = static_cast<std::size_t>(fields.offset()) + 8;
  std::int64_t step = 0;
  std::memcpy(&step, payload.data() + step_at, sizeof step);
  ASSERT_EQ(step, 2);
  for (std::int64_t bad : {std::int64_t{-1}, std::int64_t{-5}, std::int64_t{6}, std::int64_t{1000}}) {
    std::string p = payload;
    std::memcpy(p.data() + step_at, &bad, sizeof bad);
    write(k.path, io::frame(kind, p));
    const std::string why = damage_refusal([&] { app::run_mpm(k.config, k.options); });
    EXPECT_NE(why.find("step"), std::string::npos) << bad << ": " << why;
  }
}

TEST(CheckpointDamage, CommandLineExitsTwo) {
  const Cut k = cut_run("ckpt_cli");
  const std::string deck = k.options.out_dir + "/../ckpt_cli_deck.toml";
  write(deck, deck_text(k.config));
  std::string b = k.bytes;
  b[b.size() - 5] = static_cast<char>(b[b.size() - 5] ^ 0x40);
  write(k.path, b);
  const std::string err = k.options.out_dir + "/../ckpt_cli_stderr";
  const int status = std::system(fmt::format("'{}' run '{}' --out '{}' --resume --quiet --no-plot 2> '{}'",
                                             MPMX_BINARY, deck, k.options.out_dir, err)
                                     .c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), exit_code::bad_input);
  EXPECT_NE(test::read_file(err).find("does not match"), std::string::npos) << test::read_file(err);
}

// Issue 31: a checkpoint.bin that is a folder is an input error with a sentence, not
// the standard library's "basic_filebuf::underflow error" (exit 1).
TEST(CheckpointDamage, AFolderIsRefusedWithASentence) {
  const std::string dir = ::testing::TempDir() + "checkpoint_is_a_folder";
  std::filesystem::create_directories(dir);
  try {
    (void)io::read_checked(dir, io::CheckedKind{"mpm_run", 1, 0, 0});
    ADD_FAILURE() << "a folder was read as a checkpoint";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("is a folder, not a file"), std::string::npos) << e.what();
  }
}

// The streamed writer's file is frame() of what it was given, across its 1 MiB blocks
// (a payload of 2.5 MiB written in uneven pieces), and read_checked gives the payload
// back; a writer left without commit() leaves the earlier file as it was.
TEST(CheckpointDamage, StreamedFileIsTheFrameOfItsPayload) {
  const std::string path = test::scratch_dir("ckpt_streamed") + "/streamed.bin";
  const io::CheckedKind kind{"mpm_run", 1, 12345, 678};
  std::string payload(5 * (1 << 19) + 3, '\0');
  for (std::size_t i = 0; i < payload.size(); ++i) payload[i] = static_cast<char>((i * 2654435761u) >> 13);
  {
    io::CheckedWriter w(path, kind);
    for (std::size_t at = 0, piece = 1; at < payload.size(); at += piece, piece = piece * 7 % 100003 + 1)
      w.stream().write(payload.data() + at, static_cast<std::streamsize>(std::min(piece, payload.size() - at)));
    w.commit();
  }
  const std::string framed = io::frame(kind, payload);
  EXPECT_TRUE(test::read_file(path) == framed);
  EXPECT_TRUE(io::read_checked(path, kind) == payload);
  {
    io::CheckedWriter w(path, kind);
    w.stream() << "a checkpoint never committed";
  }
  EXPECT_TRUE(test::read_file(path) == framed);
  EXPECT_FALSE(std::filesystem::exists(path + ".tmp"));
}

}  // namespace
