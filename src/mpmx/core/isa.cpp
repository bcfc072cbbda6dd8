#include "mpmx/core/isa.hpp"

// clang-format off
#include "mpmx/core/simd_targets.hpp"  // first: the same targets as the kernels
// clang-format on

#include <cctype>
#include <cstdint>
#include <cstdlib>
#include <mutex>

#include <hwy/targets.h>

#include "mpmx/core/error.hpp"

namespace mpmx {

namespace {

std::string name_of(int64_t target) {
  if (target == HWY_AVX3) return "avx512";
  std::string s = hwy::TargetName(target);
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// Targets in a mask, best (lowest bit) first.
std::vector<int64_t> targets_in(int64_t mask) {
  std::vector<int64_t> out;
  for (; mask != 0; mask &= mask - 1) out.push_back(mask & -mask);
  return out;
}

std::string names(int64_t mask) {
  std::string s;
  for (const int64_t t : targets_in(mask)) {
    if (!s.empty()) s += ' ';
    s += name_of(t);
  }
  return s;
}

// What this machine runs, read once before any path is forced: hwy::SupportedTargets
// then reflects the forcing, and a call to it also resets the dispatch to every target
// until the next dispatch's own call masks it again, so nothing here calls it after.
int64_t machine_targets() {
  static const int64_t mask = hwy::SupportedTargets() & HWY_TARGETS;
  return mask;
}

int64_t forced = 0;  // the target forced last, 0 for none

int64_t target_named(const std::string& name, const char* what) {
  std::string low = name;
  for (char& c : low) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (low == "avx3") low = "avx512";
  for (const int64_t t : targets_in(HWY_TARGETS))
    if (name_of(t) == low) {
      if (!(machine_targets() & t))
        throw InputError(std::string(what) + name + ": this machine cannot run that path (it runs: " +
                         names(machine_targets()) + ")");
      return t;
    }
  // The old hand-written kernels had an SSE2 form; Highway's narrowest x86 vector is SSE4.
  const char* hint = low == "sse2" ? "; the 128-bit path is sse4" : "";
  throw InputError(std::string(what) + name + ": no such vector path in this build (paths: " +
                   names(HWY_TARGETS) + ")" + hint);
}

void force(int64_t target) {
  // Every better target off: the next dispatch takes the best one left.
  machine_targets();
  hwy::DisableTargets(target - 1);
  forced = target;
}

// MPMX_ISA, applied once before the first dispatch; its error again at every call.
void from_environment() {
  static std::once_flag once;
  static std::string error;
  std::call_once(once, [] {
    machine_targets();
    const char* env = std::getenv("MPMX_ISA");
    if (!env || !*env) return;
    try {
      force(target_named(env, "MPMX_ISA="));
    } catch (const InputError& e) {
      error = e.what();
    }
  });
  if (!error.empty()) throw InputError(error);
}

}  // namespace

void isa_prepare() { from_environment(); }

std::string isa_name(int64_t target) { return name_of(target); }

std::vector<std::string> isa_compiled() {
  std::vector<std::string> out;
  for (const int64_t t : targets_in(HWY_TARGETS)) out.push_back(name_of(t));
  return out;
}

std::vector<std::string> isa_supported() {
  std::vector<std::string> out;
  for (const int64_t t : targets_in(machine_targets())) out.push_back(name_of(t));
  return out;
}

std::string isa_chosen() {
  from_environment();
  return name_of(forced ? forced : targets_in(machine_targets()).front());
}

void isa_use(const std::string& name) {
  from_environment();
  force(target_named(name, ""));
}

std::string isa_summary() {
  const char* env = std::getenv("MPMX_ISA");
  return "1-D kernels: paths " + names(HWY_TARGETS) + "; this machine: " + names(machine_targets()) +
         "; chosen: " + isa_chosen() + (env && *env ? std::string(" (MPMX_ISA=") + env + ")" : "");
}

}  // namespace mpmx
