// The continuum checkpoint reader (framing, checksums, state, the material's per-point
// state with md_closure's MD boxes), against two fixed decks: a 1-D elastic bar and a
// tiny md_closure bar. The first byte picks the deck (bit 0) and how the rest is used:
//   0: a whole checkpoint file (its header and checksums must hold first);
//   1: a payload, parsed with no checksum in the way (the range checks alone);
//   2: byte edits (offset, xor) to a real payload, parsed: deep damage past the checks
//      a random payload never gets beyond;
//   3: the same edits to a real file: every one must be refused by the checksums.
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <memory>
#include <sstream>

#include "fuzz_util.hpp"
#include "mpmx/core/error.hpp"
#include "mpmx/io/checked_file.hpp"
#include "mpmx/app/mpm/deck.hpp"
#include "mpmx/app/mpm/checkpoint.hpp"
#include "mpmx/app/mpm/run.hpp"
#include "mpmx/app/mpm/setup.hpp"

namespace mpmx::fuzz {
namespace {

const char* kElastic = R"([case]
id = "fuzz_elastic"
[grid]
lower = 0.0
upper = 1.0
cells = 6
[particles]
per_cell = 2
[scheme]
name = "mpm"
[material]
model = "linear_elastic"
density = 1.0
youngs_modulus = 1.0
[initial.velocity]
profile = "sinusoid"
amplitude = 0.01
mode = 1
[boundary]
left = { type = "fixed" }
right = { type = "fixed" }
[time]
dt = 1e-3
end = 0.01
)";

const char* kClosure = R"([case]
id = "fuzz_closure"
units = "nm_ps_GPa"
[grid]
lower = 0.0
upper = 1.4098208
cells = 2
[particles]
per_cell = 1
[scheme]
name = "mpm"
[material]
model = "md_closure"
[material.potential]
style = "eam"
file = "/usr/share/lammps/potentials/Cu_mishin1.eam.alloy"
elements = ["Cu"]
[material.md]
cells = 1
temperature = 0.0
seed = 1
dt = 0.001
[boundary]
left = { type = "fixed" }
right = { type = "fixed" }
[time]
dt = 0.01
end = 0.05
)";

struct Case {
  app::MpmConfig config;
  std::string text;    // the deck's canonical text
  std::string file;    // a real checkpoint of it, after step 1
  std::string payload;
  // Made once (its material reads the potential file) and loaded into by every input:
  // load_state replaces all it reads, and keeps a particle array only once it is whole.
  std::unique_ptr<mpm::State<1>> state;
};

std::string canonical(const app::MpmConfig& c) {
  std::ostringstream ss;
  ss << c.deck;
  return ss.str();
}

io::CheckedKind kind_of(const Case& k) {
  return app::run_checkpoint_kind(k.text, k.config.cells * k.config.per_cell);
}

Case make_case(const char* deck, const std::string& name) {
  Case k;
  k.config = app::read_mpm_deck_text(deck, name);
  k.text = canonical(k.config);
  app::RunOptions o;
  o.quiet = true;
  o.plot = false;
  o.threads = 1;
  o.stop_after = 1;
  o.out_dir = (fuzz::temp_dir() / name).string();
  app::run_mpm(k.config, o);
  std::ifstream f(app::checkpoint_path(o.out_dir), std::ios::binary);
  k.file.assign(std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>());
  k.payload = std::string(io::unframe(k.file, kind_of(k), name));
  k.state = std::make_unique<mpm::State<1>>(app::make_state<1>(k.config, false, 1));
  return k;
}

void parse(const Case& k, std::string_view payload) {
  mpm::State<1>& s = *k.state;
  std::istringstream f{std::string(payload), std::ios::binary};
  app::CheckpointIn in(f, "fuzz", io::kCheckedHeaderBytes);
  (void)in.text();
  app::load_state(in, s);
}

std::string edited(std::string bytes, std::string_view edits) {
  for (std::size_t i = 0; i + 3 <= edits.size() && !bytes.empty(); i += 3) {
    const std::size_t at = (static_cast<unsigned char>(edits[i]) | static_cast<unsigned char>(edits[i + 1]) << 8) %
                           bytes.size();
    bytes[at] = static_cast<char>(bytes[at] ^ (edits[i + 2] == 0 ? 1 : edits[i + 2]));
  }
  return bytes;
}

}  // namespace

inline int checkpoint(const std::uint8_t* data, std::size_t size) {
  static const Case cases[2] = {make_case(kElastic, "elastic"), make_case(kClosure, "closure")};
  if (size < 1) return 0;
  const Case& k = cases[data[0] & 1];
  const std::string_view rest = fuzz::view(data + 1, size - 1);
  try {
    switch ((data[0] >> 1) & 3) {
      case 0:
        parse(k, io::unframe(rest, kind_of(k), "fuzz"));
        break;
      case 1:
        parse(k, rest);
        break;
      case 2:
        parse(k, edited(k.payload, rest));
        break;
      case 3: {
        const std::string file = edited(k.file, rest);
        if (file == k.file) return 0;
        try {
          io::unframe(file, kind_of(k), "fuzz");
        } catch (const InputError&) {
          return 0;
        }
        std::abort();  // a damaged file the checksums let through
      }
    }
  } catch (const InputError&) {
  }
  return 0;
}

}  // namespace mpmx::fuzz

// tests/fuzz/fuzz_replay_test.cpp includes every target with MPMX_FUZZ_REPLAY.
#ifndef MPMX_FUZZ_REPLAY
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return mpmx::fuzz::checkpoint(data, size);
}
#endif
