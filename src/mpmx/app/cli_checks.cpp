#include "mpmx/app/cli_checks.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <limits>

#include <fmt/format.h>

#include "mpmx/core/machine.hpp"

namespace mpmx::app {

namespace {

// The value as a whole number, or an error message.
bool parse_whole(const std::string& s, std::int64_t& v, std::string& why) {
  const char* b = s.data();
  const char* e = b + s.size();
  if (b != e && *b == '+') ++b;
  const auto r = std::from_chars(b, e, v);
  if (r.ec == std::errc::result_out_of_range) {
    why = fmt::format("{} is out of range", s);
    return false;
  }
  if (s.empty() || r.ec != std::errc() || r.ptr != e) {
    why = fmt::format("'{}' is not a whole number", s);
    return false;
  }
  return true;
}

}  // namespace

CLI::Validator thread_count() {
  const unsigned most = max_threads();
  return CLI::Validator(
      [most](std::string& s) -> std::string {
        std::int64_t v = 0;
        std::string why;
        if (!parse_whole(s, v, why)) return why + fmt::format(": give 0 (all cores) or up to {}", most);
        if (v < 0) return fmt::format("{} is negative: give 0 (all cores) or a count up to {}", s, most);
        if (v > static_cast<std::int64_t>(most))
          return fmt::format("{} is too many: at most {} on this machine ({} x {} hardware threads)", s, most,
                             kThreadsPerHardwareThread, hardware_threads());
        return {};
      },
      fmt::format("0..{}", most), "THREADS");
}

CLI::Validator whole_number(std::int64_t lo, std::int64_t hi) {
  return CLI::Validator(
      [lo, hi](std::string& s) -> std::string {
        std::int64_t v = 0;
        std::string why;
        if (!parse_whole(s, v, why)) return why;
        if (v < lo) return fmt::format("{} is below {}", s, lo);
        if (v > hi) return fmt::format("{} is above {}", s, hi);
        return {};
      },
      hi == std::numeric_limits<std::int64_t>::max() ? fmt::format(">= {}", lo) : fmt::format("{}..{}", lo, hi),
      "WHOLE");
}

CLI::Validator finite_non_negative() {
  return CLI::Validator(
      [](std::string& s) -> std::string {
        char* end = nullptr;
        const double v = std::strtod(s.c_str(), &end);
        if (s.empty() || end != s.c_str() + s.size()) return fmt::format("'{}' is not a number", s);
        if (!std::isfinite(v)) return fmt::format("{} is not a finite number", s);
        if (v < 0) return fmt::format("{} is negative", s);
        return {};
      },
      ">= 0", "FINITE_NON_NEGATIVE");
}

CLI::Validator non_empty_path() {
  return CLI::Validator(
      [](std::string& s) -> std::string { return s.empty() ? "the path is empty: give a directory" : ""; }, "",
      "NON_EMPTY");
}

void apply_shared_checks(CLI::App& app) {
  for (CLI::Option* o : app.get_options()) {
    // transform() puts the check first, so its message is the one a bad value gets.
    if (o->check_lname("threads")) o->transform(thread_count());
    if (o->check_lname("checkpoint-minutes")) o->transform(finite_non_negative());
    if (o->check_lname("checkpoint-every"))
      o->transform(whole_number(0, std::numeric_limits<std::int64_t>::max()));
    if (o->check_lname("out")) o->transform(non_empty_path());
  }
  for (CLI::App* sub : app.get_subcommands({})) apply_shared_checks(*sub);
}

void say_ignored(const CLI::App& command, std::initializer_list<IgnoredOption> options) {
  for (const IgnoredOption& o : options)
    if (const CLI::Option* given = command.get_option_no_throw(o.name); given && given->count() > 0)
      fmt::print(stderr, "mpmx {}: {} ignored: {}\n", command.get_name(), o.name, o.reason);
}

void say_ignored_by_check(const CLI::App& command) {
  say_ignored(command, {{"--out", "a check writes nothing"},
                        {"--threads", "a check runs nothing"},
                        {"--resume", "a check runs nothing"},
                        {"--quiet", "a check draws no progress line"},
                        {"--no-plot", "a check draws no figures"}});
}

std::string out_dir_of(const std::string& out, const std::string& deck) {
  return out.empty() ? "runs/" + std::filesystem::path(deck).stem().string() : out;
}

int threads_of(int requested) {
  const int cores = static_cast<int>(hardware_threads());
  return requested > 0 ? std::min(requested, cores) : cores;
}

int run_threads_of(int requested) { return requested > 0 ? threads_of(requested) : 0; }

int threads_for(int threads, double items, double per_thread) {
  const double most = std::max(1.0, std::floor(items / per_thread));
  return most < threads ? static_cast<int>(most) : std::max(1, threads);
}

}  // namespace mpmx::app
