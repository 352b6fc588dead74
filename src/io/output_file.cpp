#include "io/output_file.hpp"

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <system_error>

namespace abut::output_file {

std::ofstream open(const std::filesystem::path& path) {
  errno = 0;
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) {
    const int reason = errno;
    throw std::runtime_error("cannot open '" + path.string() + "' for writing" +
                             (reason != 0 ? std::string(": ") + std::strerror(reason) : ""));
  }
  return out;
}

void check(const std::ofstream& out, const std::filesystem::path& path) {
  if (!out) throw std::runtime_error("writing '" + path.string() + "' failed (disk full?)");
}

std::filesystem::path temporary_for(const std::filesystem::path& path) {
  std::filesystem::path temporary = path;
  temporary += ".tmp";
  return temporary;
}

void commit(const std::filesystem::path& temporary, const std::filesystem::path& path) {
  std::error_code error;
  std::filesystem::rename(temporary, path, error);
  if (error) {
    throw std::runtime_error("cannot rename '" + temporary.string() + "' to '" + path.string() +
                             "': " + error.message());
  }
}

void replace(const std::filesystem::path& path, std::string_view content) {
  const std::filesystem::path temporary = temporary_for(path);
  try {
    std::ofstream out = open(temporary);
    out.write(content.data(), static_cast<std::streamsize>(content.size()));
    out.close();
    check(out, temporary);
  } catch (...) {
    discard(temporary);
    throw;
  }
  commit(temporary, path);
}

void discard(const std::filesystem::path& temporary) noexcept {
  std::error_code ignored;  // best effort: the original error is the one to report
  std::filesystem::remove(temporary, ignored);
}

std::string xml_escaped(std::string_view text) {
  std::string escaped;
  escaped.reserve(text.size());
  for (const char c : text) {
    switch (c) {
      case '&':
        escaped += "&amp;";
        break;
      case '<':
        escaped += "&lt;";
        break;
      case '>':
        escaped += "&gt;";
        break;
      case '"':
        escaped += "&quot;";
        break;
      case '\'':
        escaped += "&apos;";
        break;
      default:
        escaped += c;
    }
  }
  return escaped;
}

}  // namespace abut::output_file
