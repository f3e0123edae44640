#pragma once
/// \file
/// Reading a whole file and writing one atomically, as every reader and writer of pgm does (and
/// a program built on it may). Output is written to a temporary file beside the target and
/// renamed over it only once complete, so a failure never leaves a half-written file that looks
/// finished.

#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <random>
#include <sstream>
#include <string>
#include <system_error>
#include <vector>

#include "pgm/core/compilation.hpp"
#include "pgm/core/error.hpp"
#include "pgm/core/limits.hpp"

namespace pgm {

/// A path's extension in lower case (".BIF" -> ".bif"), as file kinds are told apart.
[[nodiscard]] PGM_DECL std::string lowercase_extension(const std::filesystem::path& path);

/// The whole of a file, refused (io_error naming the limit) beyond `max_bytes`: a regular file
/// by its size before it is read, a device or pipe as soon as it has given more.
[[nodiscard]] PGM_DECL std::string read_file(const std::filesystem::path& path,
                                             std::uint64_t max_bytes = max_file_bytes);

/// Throws io_error unless a file could be written at `path`: its folder exists and `path` is
/// not a folder. Commands with several outputs check them all before writing any.
PGM_DECL void check_output_path(const std::filesystem::path& path);

/// Calls `write` with a stream to a temporary file and renames it to `path` on success (the
/// file a symbolic link points to; a device or pipe such as /dev/stdout is written directly).
/// On any failure — including an exception from `write` — the temporary file is removed and
/// the previous content of `path`, if any, is left untouched. `before_replacing`, when given, runs
/// once the new content is complete and before it replaces the old (before anything is written
/// to a device): what may still fail there (a summary to a full standard output) leaves `path`
/// as it was.
PGM_DECL void write_file_atomically(const std::filesystem::path& path, const std::function<void(std::ostream&)>& write,
                                    const std::function<void()>& before_replacing = {});

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/core/impl/file.ipp"
#endif
