#pragma once
// What the interrupt tests of `md`, `dpd` and `run` share: a command started in the
// background and sent a signal once one of its tables has grown to some lines (so the
// step loop runs), the exit status it then ends with, and comparisons of two run folders
// file by file, run.json without its wall-clock figures.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "cli_util.hpp"

namespace mpmx::test {

// Runs `command` (a shell command line, its stderr to `log`), sends `signal` ("INT",
// "TERM") once `table` is there holding at least `lines` lines (or after 60 s), and
// returns the exit status (-1 when it did not exit).
inline int signal_when(const std::string& command, const std::string& table, int lines, const std::string& signal,
                       const std::string& log) {
  const std::string script = log + ".sh";
  {
    std::ofstream f(script);
    f << fmt::format(
        "{} > /dev/null 2> '{}' &\npid=$!\n"
        "for i in $(seq 600); do [ -e '{}' ] && {{ [ {} -eq 0 ] || [ $(wc -l < '{}') -ge {} ]; }} && break; sleep 0.1; done\n"
        "kill -{} $pid\nwait $pid\n",
        command, log, table, lines, table, lines, signal);
  }
  const int status = std::system(("bash '" + script + "'").c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// run.json without the figures of the wall clock and the machine (they differ between
// any two runs: the continuum's "phases" object of seconds too) and without the threads
// (a resumed run may take another count).
inline std::string physics_of_record(const std::string& json) {
  std::istringstream in(json);
  std::string out;
  bool in_phases = false;
  for (std::string line; std::getline(in, line);) {
    if (in_phases || line.find("\"phases\"") != std::string::npos) {
      in_phases = line.find('}') == std::string::npos;
      continue;
    }
    bool clock = false;
    for (const char* key :
         {"\"wall_seconds\"", "\"run_seconds\"", "_per_second\"", "\"threads\"", "\"peak_memory_bytes\""})
      clock = clock || line.find(key) != std::string::npos;
    if (!clock) out += line + "\n";
  }
  return out;
}

// The files of a run folder, relative, sorted (the staging folder and checkpoint aside).
inline std::vector<std::string> files_of(const std::filesystem::path& dir) {
  std::vector<std::string> files;
  for (const auto& e : std::filesystem::recursive_directory_iterator(dir)) {
    const std::string rel = std::filesystem::relative(e.path(), dir).string();
    if (e.is_regular_file() && rel.rfind(".staging", 0) != 0 && rel != "checkpoint.bin" && rel != "stderr" &&
        rel.find(".sh") == std::string::npos)
      files.push_back(rel);
  }
  std::sort(files.begin(), files.end());
  return files;
}

// Every file under `dir`, the hidden ones too (relative name -> bytes): a folder as it
// was, to compare with itself after a run that must not touch it.
inline std::map<std::string, std::string> snapshot(const std::filesystem::path& dir) {
  std::map<std::string, std::string> m;
  for (const auto& e : std::filesystem::recursive_directory_iterator(dir))
    if (e.is_regular_file()) m[std::filesystem::relative(e.path(), dir).string()] = slurp(e.path());
  return m;
}

// Every file of the uninterrupted run `whole` is in the resumed run `cut`, the same bytes
// (run.json's physics), and the resumed run left no checkpoint or staging folder.
inline void expect_same_folders(const std::filesystem::path& whole, const std::filesystem::path& cut) {
  const auto files = files_of(whole);
  EXPECT_EQ(files, files_of(cut));
  for (const std::string& f : files) {
    const std::string a = slurp(whole / f), b = slurp(cut / f);
    if (f == "run.json") {
      EXPECT_EQ(physics_of_record(a), physics_of_record(b));
      EXPECT_NE(b.find("\"completed\""), std::string::npos);
    } else {
      EXPECT_EQ(a, b) << f;
    }
  }
  EXPECT_FALSE(std::filesystem::exists(cut / "checkpoint.bin"));
  EXPECT_FALSE(std::filesystem::exists(cut / ".staging"));
}

// A folder of the test program's own in the temporary folder, removed at its end.
class ScratchFolder {
 public:
  explicit ScratchFolder(const std::string& prefix)
      : path_(std::filesystem::temp_directory_path() / (prefix + "_" + std::to_string(getpid()))) {
    std::filesystem::create_directories(path_);
  }
  ~ScratchFolder() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  ScratchFolder(const ScratchFolder&) = delete;
  ScratchFolder& operator=(const ScratchFolder&) = delete;
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }
  // Writes `text` to the file `name` in it; its path.
  std::string file(const std::string& name, const std::string& text) const {
    std::ofstream(path_ / name) << text;
    return (path_ / name).string();
  }

 private:
  std::filesystem::path path_;
};

}  // namespace mpmx::test
