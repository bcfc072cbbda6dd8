#pragma once
// A progress line with ETA on a terminal (stderr), at most a few updates a second;
// silent when stderr is not a terminal or when quiet.
#include <chrono>
#include <cstdint>
#include <string>

namespace mpmx {

class Progress {
 public:
  Progress(std::string label, std::int64_t total, bool quiet = false);
  void update(std::int64_t done);
  void finish();

 private:
  using clock = std::chrono::steady_clock;
  std::string label_;
  std::int64_t total_;
  bool active_;
  clock::time_point start_, last_;
};

}  // namespace mpmx
