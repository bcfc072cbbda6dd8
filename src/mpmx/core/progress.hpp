#pragma once
// A progress line with ETA on a terminal (stderr), at most a few updates a second;
// when stderr is a file (a batch job's log), a plain line every minute instead;
// silent when quiet.
#include <chrono>
#include <cstdint>
#include <string>
#include <utility>

namespace mpmx {

class Progress {
 public:
  // `from`: steps already done before this process (a resumed run); the ETA uses the rate since.
  Progress(std::string label, std::int64_t total, bool quiet = false, std::int64_t from = 0);
  // Also show the rate of `items` x steps a second (an MD box's atoms: "atom-steps").
  void show_rate(double items, std::string unit);
  void update(std::int64_t done);
  // A run whose step count is not known ahead (dt = "cfl"): `fraction` of it is done
  // (its time over its end time); the line shows the steps run and "~" the total
  // estimated from the fraction, and finish(done) says the steps actually run.
  void update(std::int64_t done, double fraction);
  // A few words shown after the step count (dt = "cfl": the last step and what set it).
  void note(std::string text) { note_ = std::move(text); }
  void finish();
  // A run that stopped early (a state gone non-finite): the steps it did.
  void finish(std::int64_t done);

 private:
  using clock = std::chrono::steady_clock;
  void show(std::int64_t done, double fraction, bool estimated);
  std::string label_;
  std::int64_t total_, from_;
  double items_ = 0;
  std::string unit_, note_;
  bool active_, terminal_;
  clock::time_point start_, last_;
};

}  // namespace mpmx
