#pragma once
// The definitions of pgm/core/file.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/core/file.hpp"

namespace pgm {

PGM_DECL std::string lowercase_extension(const std::filesystem::path& path) {
  auto extension = path.extension().string();
  for (auto& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return extension;
}

PGM_DECL std::string read_file(const std::filesystem::path& path, std::uint64_t max_bytes) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {
    throw io_error("cannot read '" + path.string() + "': it is a directory");
  }
  const auto too_large = [&] {
    const auto limit =
        max_bytes % (1 << 20) == 0 ? std::to_string(max_bytes >> 20) + " MiB" : std::to_string(max_bytes) + " bytes";
    return io_error("cannot read '" + path.string() + "': it is larger than " + limit +
                    ", pgm's limit of a file it reads whole (models, tasks, scenarios; docs/limits.md)");
  };
  std::ifstream in(path, std::ios::binary);
  if (!in) throw io_error("cannot open '" + path.string() + "': " + std::strerror(errno));
  std::string text;
  if (std::filesystem::is_regular_file(path, ec)) {
    const auto size = std::filesystem::file_size(path, ec);
    if (!ec && size > max_bytes) throw too_large();
    if (!ec) text.reserve(static_cast<std::size_t>(size));
  }
  std::vector<char> buffer(std::size_t{1} << 16);
  while (in) {
    in.read(buffer.data(), static_cast<std::streamsize>(buffer.size()));
    const auto got = static_cast<std::size_t>(in.gcount());
    if (text.size() + got > max_bytes) throw too_large();
    text.append(buffer.data(), got);
  }
  if (in.bad()) throw io_error("cannot read '" + path.string() + "'");
  return text;
}

PGM_DECL void check_output_path(const std::filesystem::path& path) {
  const auto directory = path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
  std::error_code ec;
  if (!std::filesystem::is_directory(directory, ec)) {
    throw io_error("cannot write '" + path.string() + "': the directory '" + directory.string() + "' does not exist");
  }
  if (std::filesystem::is_directory(path, ec)) {
    throw io_error("cannot write '" + path.string() + "': it is a folder");
  }
}

PGM_DECL void write_file_atomically(const std::filesystem::path& path, const std::function<void(std::ostream&)>& write,
                                    const std::function<void()>& before_replacing) {
  check_output_path(path);
  errno = 0;
  const auto reason = [] {
    return errno != 0 ? std::string(": ") + std::strerror(errno) : std::string(" (disk full?)");
  };
  std::error_code ec;
  // A device or pipe (/dev/stdout, a named pipe) cannot be replaced by a rename, and renaming
  // over what /dev/stdout points to would detach the shell's redirection: written straight.
  const auto status = std::filesystem::status(path, ec);
  const auto text = path.lexically_normal().string();
  if ((std::filesystem::exists(status) && !std::filesystem::is_regular_file(status)) || text.starts_with("/dev/") ||
      text.starts_with("/proc/")) {
    if (before_replacing) before_replacing();
    std::ofstream out(path, std::ios::binary);
    if (!out) throw io_error("cannot write '" + path.string() + "': " + std::strerror(errno));
    write(out);
    out.close();  // a device reports a full disk or a closed pipe when flushed
    if (!out) throw io_error("cannot write '" + path.string() + "'" + reason());
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
      out.close();  // some file systems report a full disk or quota only when the file is closed
      if (!out) throw io_error("cannot write '" + path.string() + "'" + reason());
    }
    if (before_replacing) before_replacing();
    std::filesystem::rename(temporary, target, ec);
    if (ec) throw io_error("cannot write '" + path.string() + "': " + ec.message());
  } catch (...) {
    std::filesystem::remove(temporary, ec);
    throw;
  }
}

}  // namespace pgm
