#pragma once
// Words for what the file system and files say, for messages: why a path cannot be used
// (instead of the library's "filesystem error: ..."), and a file's content quoted short
// and printable (a binary file's bytes are not echoed to a terminal).
#include <filesystem>
#include <string>
#include <string_view>
#include <system_error>

namespace mpmx {

// Why `path` could not be used, as a sentence's end: "does not exist", "is 5000
// characters long, more than the system's limit of 4095", "has a name of 300 bytes, more
// than the 255 a name may have", "is on a read-only file system", "permission denied"...
std::string path_problem(const std::filesystem::path& path, const std::error_code& ec);

// Why `path` cannot be read as a file ("" when it can be opened): it does not exist, is a
// folder, is too long, cannot be read. `what` names it in the sentence ("deck file").
std::string file_problem(const std::filesystem::path& path, std::string_view what);

// A path for a message (control characters escaped): whole when short, else its first and
// last characters and its length.
std::string short_path(const std::string& path);

// `text` safe to print: each control character (bytes 0-31 and 127: NUL, ESC, newline...)
// written \xNN, other bytes (UTF-8 included) as they are. `keep_line_breaks` keeps '\n'
// and '\t' (a whole message of several lines). Every text a user gave (deck strings,
// keys, paths) passes through it before it reaches a terminal or a message.
std::string escape_controls(std::string_view text, bool keep_line_breaks = false);

// `text` with each byte outside printable ASCII written \xNN.
std::string escape_unprintable(std::string_view text);

// `text` in single quotes, at most `most` characters of it, each byte outside printable
// ASCII as \xNN, and "..." (with the full length) when cut.
std::string quote_excerpt(std::string_view text, std::size_t most = 40);

}  // namespace mpmx
