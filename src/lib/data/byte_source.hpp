#pragma once
// Internal to the CSV reader (src/lib/data), not installed: where the bytes of an input come from.
// A regular file is mapped (the pages already parsed are given back, so memory stays bounded
// by the window however large the file); standard input and pipes are read into a buffer;
// gzip data is inflated into one. Every source shows the bytes it holds from the current
// position on, and grows them on request.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <string_view>

namespace pgm::detail {

class byte_source {
 public:
  virtual ~byte_source() = default;

  /// The bytes in memory from the current position on.
  [[nodiscard]] virtual std::string_view available() const = 0;
  /// Whether available() reaches the end of the input.
  [[nodiscard]] virtual bool at_end() const = 0;
  /// Makes at least `bytes` bytes available from the current position, or all that remain.
  /// Throws io_error when the input cannot be read (or inflated).
  virtual void fetch(std::size_t bytes) = 0;
  /// Moves the current position `bytes` on: those bytes are not looked at again.
  virtual void consume(std::size_t bytes) = 0;
};

/// Text already in memory (it must outlive the source).
[[nodiscard]] std::unique_ptr<byte_source> memory_source(std::string_view text);

/// Opens `path` ("-": standard input): a regular file is mapped, anything else streamed, and
/// gzip data (by its magic bytes; a .gz name requires them) inflated. `name` is the name used
/// in messages.
[[nodiscard]] std::unique_ptr<byte_source> open_source(const std::filesystem::path& path, const std::string& name);

/// "<stdin>" for "-", else the path.
[[nodiscard]] std::string source_name(const std::filesystem::path& path);

}  // namespace pgm::detail
