#pragma once
// What this machine has, for refusing up front a run it cannot hold or finish: physical
// memory and hardware threads.
#include <cstdint>
#include <string>

namespace mpmx {

// Physical memory in bytes (sysconf; /proc/meminfo as a fallback); 0 when unknown.
std::uint64_t physical_memory_bytes();

// The most memory this process has held so far (its peak resident set), in bytes.
std::uint64_t peak_memory_bytes();

// std::thread::hardware_concurrency(), at least 1.
unsigned hardware_threads();

// The most threads a --threads option accepts: kThreadsPerHardwareThread x the hardware threads.
inline constexpr unsigned kThreadsPerHardwareThread = 4;
unsigned max_threads();

// "1.5 GiB", "512 MiB", "12 KiB", "100 B": a byte count for messages.
std::string format_bytes(double bytes);
// "12.3 s", "4.5 min", "2.50 h", "3.2 days": a duration for messages and progress lines.
std::string format_duration(double seconds);

}  // namespace mpmx
