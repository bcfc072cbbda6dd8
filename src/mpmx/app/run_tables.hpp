#pragma once
// The tables a resumable run appends to as it goes (thermo rows, profiles, dump frames):
// a fresh run opens each with its header; a resumed one cuts each back to the length its
// checkpoint recorded and appends, so its tables equal an uninterrupted run's.
#include <fstream>
#include <map>
#include <string>
#include <string_view>

#include "mpmx/app/checkpoint_fields.hpp"

namespace mpmx::app {

class RunTables {
 public:
  // `resume`: the checkpoint's marks (empty: a fresh run).
  explicit RunTables(std::string dir, TableMarks resume = {}) : dir_(std::move(dir)), resume_(std::move(resume)) {}
  // The table `name` of the run folder; `header` starts a fresh one.
  std::ofstream& open(const std::string& name, std::string_view header = {});
  // Flushes every table and returns their lengths; SystemError (the file, the system's
  // reason) when a table could not be written whole.
  TableMarks marks();

 private:
  std::string dir_;
  TableMarks resume_;
  std::map<std::string, std::ofstream> files_;  // a map's entries stay where they are
};

}  // namespace mpmx::app
