#pragma once
// What the tests of the command line share: running the built program (MPMX_BINARY) with
// its output and exit status, and reading what it wrote: a file whole, a number of its
// JSON, how often a text occurs.
#include <sys/wait.h>

#include <cmath>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace mpmx::test {

struct CliResult {
  int status;          // the exit status, -1 when the program did not exit
  std::string output;  // stdout and stderr together
};

// The program under `prefix` (an `env ...` that changes its environment, or "").
inline CliResult run_cli_env(const std::string& prefix, const std::string& args) {
  const std::string cmd = prefix + (prefix.empty() ? "" : " ") + std::string(MPMX_BINARY) + " " + args + " 2>&1";
  CliResult r{-1, {}};
  FILE* p = popen(cmd.c_str(), "r");
  if (!p) return r;
  char buf[4096];
  while (std::fgets(buf, sizeof buf, p)) r.output += buf;
  const int st = pclose(p);
  r.status = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
  return r;
}

inline CliResult run_cli(const std::string& args) { return run_cli_env("", args); }

inline std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// The number after the first `"key" : ` in a JSON text; nan when the key is absent.
inline double json_number(const std::string& json, const std::string& key) {
  const std::string tag = "\"" + key + "\" : ";
  const auto at = json.find(tag);
  if (at == std::string::npos) return std::nan("");
  return std::strtod(json.c_str() + at + tag.size(), nullptr);
}

// How many times `what` occurs in `s`.
inline std::size_t count(const std::string& s, const std::string& what) {
  std::size_t n = 0;
  for (auto p = s.find(what); p != std::string::npos; p = s.find(what, p + 1)) ++n;
  return n;
}

}  // namespace mpmx::test
