#pragma once
/// \file
/// Internal, do not depend on it: reading a whole file and writing one atomically. Output is
/// written to a temporary file beside the target and renamed over it only once complete, so a
/// failure never leaves a half-written file that looks finished.

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <random>
#include <sstream>
#include <string>
#include <system_error>

#include "pgm/core/error.hpp"

namespace pgm::detail {

[[nodiscard]] inline std::string read_file(const std::filesystem::path& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {
    throw io_error("cannot read '" + path.string() + "': it is a directory");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) throw io_error("cannot open '" + path.string() + "': " + std::strerror(errno));
  std::ostringstream buffer;
  buffer << in.rdbuf();
  if (in.bad()) throw io_error("cannot read '" + path.string() + "'");
  return std::move(buffer).str();
}

/// Throws io_error unless a file could be written at `path`: its folder exists and `path` is
/// not a folder. Commands with several outputs check them all before writing any.
inline void check_output_path(const std::filesystem::path& path) {
  const auto directory = path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
  std::error_code ec;
  if (!std::filesystem::is_directory(directory, ec)) {
    throw io_error("cannot write '" + path.string() + "': the directory '" + directory.string() + "' does not exist");
  }
  if (std::filesystem::is_directory(path, ec)) {
    throw io_error("cannot write '" + path.string() + "': it is a folder");
  }
}

/// Calls `write` with a stream to a temporary file and renames it to `path` on success (the
/// file a symbolic link points to; a device or pipe such as /dev/stdout is written directly).
/// On any failure — including an exception from `write` — the temporary file is removed and
/// the previous content of `path`, if any, is left untouched.
inline void write_file_atomically(const std::filesystem::path& path, const std::function<void(std::ostream&)>& write) {
  check_output_path(path);
  std::error_code ec;
  // A device or pipe (/dev/stdout, a named pipe) cannot be replaced by a rename, and renaming
  // over what /dev/stdout points to would detach the shell's redirection: written straight.
  const auto status = std::filesystem::status(path, ec);
  const auto text = path.lexically_normal().string();
  if ((std::filesystem::exists(status) && !std::filesystem::is_regular_file(status)) || text.starts_with("/dev/") ||
      text.starts_with("/proc/")) {
    std::ofstream out(path, std::ios::binary);
    if (!out) throw io_error("cannot write '" + path.string() + "': " + std::strerror(errno));
    write(out);
    out.flush();
    if (!out) throw io_error("cannot write '" + path.string() + "'");
    return;
  }
  // A symbolic link stays a link: the file it points to is replaced.
  const auto target = std::filesystem::is_symlink(path, ec) ? std::filesystem::weakly_canonical(path, ec) : path;
  std::random_device entropy;
  const auto temporary =
      std::filesystem::path(target.string() + ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(entropy()));
  try {
    {
      std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
      if (!out) {
        throw io_error("cannot write '" + path.string() + "': " + std::strerror(errno));
      }
      write(out);
      out.flush();
      if (!out) throw io_error("cannot write '" + path.string() + "' (disk full?)");
    }
    std::filesystem::rename(temporary, target, ec);
    if (ec) throw io_error("cannot write '" + path.string() + "': " + ec.message());
  } catch (...) {
    std::filesystem::remove(temporary, ec);
    throw;
  }
}

}  // namespace pgm::detail
