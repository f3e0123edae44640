#include "pgm/io/gzip.hpp"

#include <zlib.h>

#include <algorithm>
#include <limits>
#include <vector>

#include "pgm/core/error.hpp"

namespace pgm {

std::string inflate_gzip(std::string_view bytes, const std::string& source, std::uint64_t max_bytes) {
  if (!is_gzip(bytes)) throw io_error("'" + source + "': not gzip data (its name ends in .gz)");
  z_stream stream{};
  if (inflateInit2(&stream, 15 + 16) != Z_OK) throw io_error("'" + source + "': cannot start inflating");
  std::string out;
  // The last member's trailer holds its inflated size mod 2^32: for the usual single member the
  // exact size, reserved so that growing the text never holds twice its bytes (and never more than
  // deflate can give: 1,032 bytes a byte).
  if (bytes.size() >= 18) {
    std::uint64_t size = 0;
    for (int k = 3; k >= 0; --k) size = (size << 8) | static_cast<unsigned char>(bytes[bytes.size() - 4 + k]);
    out.reserve(static_cast<std::size_t>(std::min({size, max_bytes, std::uint64_t{bytes.size()} * 1032})));
  }
  std::vector<char> buffer(std::size_t{1} << 16);
  const auto* next = reinterpret_cast<const Bytef*>(bytes.data());
  std::size_t left = bytes.size();
  int status = Z_OK;
  try {
    while (true) {
      if (stream.avail_in == 0 && left > 0) {
        const auto chunk = std::min<std::size_t>(left, std::numeric_limits<uInt>::max());
        stream.next_in = const_cast<Bytef*>(next);
        stream.avail_in = static_cast<uInt>(chunk);
        next += chunk;
        left -= chunk;
      }
      stream.next_out = reinterpret_cast<Bytef*>(buffer.data());
      stream.avail_out = static_cast<uInt>(buffer.size());
      status = inflate(&stream, Z_NO_FLUSH);
      if (status != Z_OK && status != Z_STREAM_END) {
        throw io_error("'" + source + "': damaged gzip data" +
                       (stream.msg ? std::string(" (") + stream.msg + ")" : ""));
      }
      const auto produced = buffer.size() - stream.avail_out;
      if (out.size() + produced > max_bytes) {
        const auto limit = max_bytes % (1 << 20) == 0 ? std::to_string(max_bytes >> 20) + " MiB"
                                                      : std::to_string(max_bytes) + " bytes";
        throw io_error("'" + source + "': inflates to more than " + limit +
                       ", pgm's limit of a file it reads whole (models, tasks, scenarios; docs/limits.md)");
      }
      out.append(buffer.data(), produced);
      if (status == Z_STREAM_END) {
        if (stream.avail_in == 0 && left == 0) break;
        if (inflateReset(&stream) != Z_OK) throw io_error("'" + source + "': damaged gzip data");  // next member
        continue;
      }
      if (stream.avail_in == 0 && left == 0 && produced == 0) {
        throw io_error("'" + source + "': the gzip data ends early (a truncated file?)");
      }
    }
  } catch (...) {
    inflateEnd(&stream);
    throw;
  }
  inflateEnd(&stream);
  return out;
}

}  // namespace pgm
