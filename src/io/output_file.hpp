#pragma once
// Helpers shared by the output writers: opening files with a clear error and replacing a file
// atomically, so that a reader (ParaView, a script) never sees a half-written state.
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

namespace abut::output_file {

// Opens `path` for writing (truncating) in binary mode; throws std::runtime_error naming the path
// and the system's reason when it cannot.
std::ofstream open(const std::filesystem::path& path);

// Throws std::runtime_error if an earlier write to `out` failed (disk full, ...).
void check(const std::ofstream& out, const std::filesystem::path& path);

// Where the content of `path` is written before it is renamed over `path`: same directory, so
// the rename stays on one file system and is atomic (POSIX rename(2)).
std::filesystem::path temporary_for(const std::filesystem::path& path);

// Removes a temporary file left by a failed write (best effort, never throws).
void discard(const std::filesystem::path& temporary) noexcept;

// Renames the complete temporary file over `path`.
void commit(const std::filesystem::path& temporary, const std::filesystem::path& path);

// Writes `content` to `path` through a temporary file and an atomic rename.
void replace(const std::filesystem::path& path, std::string_view content);

// `text` with the five XML special characters replaced by entities, for attribute values.
std::string xml_escaped(std::string_view text);

}  // namespace abut::output_file
