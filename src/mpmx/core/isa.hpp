#pragma once
// Which vector path the vector kernels take (the 1-D continuum's, mpm/fused1d; the MD
// engine's, md/potential/eam_one_type and md/neighbor_search). One build holds a path
// per instruction set (Google Highway's dynamic dispatch) and runs the best this machine
// has, or the one named by the environment variable MPMX_ISA (read once, at the first
// kernel call): a Highway target in lower case, "avx512" for AVX3. Paths are named
// widest first: "avx512", "avx2", "sse4", then the portable fallback, "scalar" (GCC) or
// "emu128" (clang), on x86.
#include <cstdint>
#include <string>
#include <vector>

namespace mpmx {

std::vector<std::string> isa_compiled();   // the paths in this build, the portable fallback last
std::vector<std::string> isa_supported();  // those this machine can run
// The path the kernels take; InputError where MPMX_ISA names no path of this build or
// one this machine cannot run.
std::string isa_chosen();
// Takes the named path from now on (tests, benches); InputError as for MPMX_ISA.
void isa_use(const std::string& name);
// Applies MPMX_ISA (once, InputError as above at every call): each kernel entry point
// that dispatches calls it first, so that its first dispatch already takes that path.
void isa_prepare();
// A Highway target's name as MPMX_ISA spells it.
std::string isa_name(int64_t target);
// "paths avx512 avx2 sse4 scalar; this machine: ...; chosen: avx512 (MPMX_ISA=...)",
// for `mpmx --version`.
std::string isa_summary();

}  // namespace mpmx
