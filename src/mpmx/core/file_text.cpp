#include "mpmx/core/file_text.hpp"

#include <algorithm>
#include <climits>
#include <fstream>

#include <fmt/format.h>

namespace mpmx {

namespace fs = std::filesystem;

namespace {

// The system's limits on a path and on one name in it (Linux: 4096 with the final NUL, 255).
constexpr std::size_t kPathMax = PATH_MAX - 1;
constexpr std::size_t kNameMax = NAME_MAX;

}  // namespace

std::string path_problem(const fs::path& path, const std::error_code& ec) {
  const std::string text = path.string();
  if (text.size() > kPathMax)
    return fmt::format("is {} characters long, more than the system's limit of {}", text.size(), kPathMax);
  std::size_t longest = 0;
  for (const auto& part : path) longest = std::max(longest, part.string().size());
  if (longest > kNameMax)
    return fmt::format("has a name of {} bytes in it, more than the {} a file or folder name may have", longest,
                       kNameMax);
  switch (static_cast<std::errc>(ec.value())) {
    case std::errc::no_such_file_or_directory: return "does not exist";
    case std::errc::not_a_directory: return "runs through a file as if it were a folder";
    case std::errc::permission_denied:
    case std::errc::operation_not_permitted: return "cannot be written or read here: permission denied";
    case std::errc::read_only_file_system: return "is on a read-only file system";
    case std::errc::no_space_on_device: return "cannot be written: the disk is full";
    case std::errc::too_many_symbolic_link_levels: return "runs through too many symbolic links";
    case std::errc::is_a_directory: return "is a folder";
    case std::errc::filename_too_long: return "is too long for the system";
    default: return fmt::format("cannot be used: {}", ec.message());
  }
}

std::string file_problem(const fs::path& path, std::string_view what) {
  std::error_code ec;
  const auto st = fs::status(path, ec);
  if (fs::is_directory(st)) return fmt::format("is a directory, not a {}", what);
  if (!ec && !fs::exists(st)) return fmt::format("no such {}", what);
  if (ec) {
    const std::string why = path_problem(path, ec);
    return why == "does not exist" ? fmt::format("no such {}", what) : why;
  }
  if (!std::ifstream(path)) return "cannot be read: permission denied";
  return "";
}

std::string short_path(const std::string& path) {
  constexpr std::size_t kEnds = 60;
  if (path.size() <= 3 * kEnds) return escape_controls(path);
  return fmt::format("{}...{} ({} characters)", escape_controls(path.substr(0, kEnds)),
                     escape_controls(path.substr(path.size() - kEnds)), path.size());
}

std::string escape_controls(std::string_view text, bool keep_line_breaks) {
  std::string out;
  out.reserve(text.size());
  for (const char ch : text) {
    const auto c = static_cast<unsigned char>(ch);
    if ((c >= 0x20 && c != 0x7f) || (keep_line_breaks && (c == '\n' || c == '\t'))) out += ch;
    else out += fmt::format("\\x{:02x}", c);
  }
  return out;
}

std::string escape_unprintable(std::string_view text) {
  std::string out;
  for (const char ch : text) {
    const auto c = static_cast<unsigned char>(ch);
    if (c >= 0x20 && c < 0x7f) out += ch;
    else out += fmt::format("\\x{:02x}", c);
  }
  return out;
}

std::string quote_excerpt(std::string_view text, std::size_t most) {
  std::string out(1, '\'');
  out += escape_unprintable(text.substr(0, most));
  out += '\'';
  if (text.size() > most) out += fmt::format("... ({} bytes)", text.size());
  return out;
}

}  // namespace mpmx
