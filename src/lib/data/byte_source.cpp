#include "data/byte_source.hpp"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>
#include <zlib.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <limits>
#include <vector>

#include "pgm/core/error.hpp"

namespace pgm::detail {
namespace {

constexpr std::string_view gzip_magic = "\x1f\x8b";
// Mapped pages are given back once this many bytes behind the position are parsed.
constexpr std::size_t release_bytes = std::size_t{4} << 20;
constexpr std::size_t read_bytes = std::size_t{1} << 20;

[[noreturn]] void fail_read(const std::string& name) {
  throw io_error("cannot read '" + name + "': " + std::strerror(errno));
}

class text_source final : public byte_source {
 public:
  explicit text_source(std::string_view text) : text_(text) {}
  [[nodiscard]] std::string_view available() const override { return text_.substr(position_); }
  [[nodiscard]] bool at_end() const override { return true; }
  void fetch(std::size_t) override {}
  void consume(std::size_t bytes) override { position_ += bytes; }

 private:
  std::string_view text_;
  std::size_t position_ = 0;
};

/// A regular file, mapped whole; the pages behind the position are dropped from memory.
class mapped_source final : public byte_source {
 public:
  mapped_source(int fd, std::size_t size, const std::string& name) : size_(size) {
    if (size_ == 0) return;
    void* map = ::mmap(nullptr, size_, PROT_READ, MAP_PRIVATE, fd, 0);
    if (map == MAP_FAILED) fail_read(name);
    data_ = static_cast<const char*>(map);
    ::madvise(map, size_, MADV_SEQUENTIAL);
  }
  ~mapped_source() override {
    if (data_) ::munmap(const_cast<char*>(data_), size_);
  }
  mapped_source(const mapped_source&) = delete;
  mapped_source& operator=(const mapped_source&) = delete;

  [[nodiscard]] std::string_view available() const override { return {data_ + position_, size_ - position_}; }
  [[nodiscard]] bool at_end() const override { return true; }
  void fetch(std::size_t) override {}
  void consume(std::size_t bytes) override {
    position_ += bytes;
    const std::size_t page = static_cast<std::size_t>(::sysconf(_SC_PAGESIZE));
    const std::size_t done = position_ / page * page;
    if (done >= released_ + release_bytes) {
      ::madvise(const_cast<char*>(data_) + released_, done - released_, MADV_DONTNEED);
      released_ = done;
    }
  }

 private:
  const char* data_ = nullptr;
  std::size_t size_;
  std::size_t position_ = 0;
  std::size_t released_ = 0;
};

/// Bytes held in a growing buffer: [begin_, end_) are available.
class buffered_source : public byte_source {
 public:
  [[nodiscard]] std::string_view available() const override { return {buffer_.data() + begin_, end_ - begin_}; }
  [[nodiscard]] bool at_end() const override { return end_of_input_; }
  void consume(std::size_t bytes) override { begin_ += bytes; }
  void fetch(std::size_t bytes) override {
    while (!end_of_input_ && end_ - begin_ < bytes) {
      make_room(std::min(bytes - (end_ - begin_), read_bytes));
      const std::size_t added = fill(buffer_.data() + end_, buffer_.size() - end_);
      if (added == 0) {
        end_of_input_ = true;
      } else {
        end_ += added;
      }
    }
  }

 protected:
  /// Writes up to `room` bytes at `to`; 0 at the end of the input.
  virtual std::size_t fill(char* to, std::size_t room) = 0;

 private:
  void make_room(std::size_t wanted) {
    if (begin_ > 0 && buffer_.size() - end_ < wanted) {
      std::memmove(buffer_.data(), buffer_.data() + begin_, end_ - begin_);
      end_ -= begin_;
      begin_ = 0;
    }
    if (buffer_.size() - end_ < wanted) buffer_.resize(std::max(buffer_.size() * 2, end_ + wanted));
  }

  std::vector<char> buffer_;
  std::size_t begin_ = 0;
  std::size_t end_ = 0;
  bool end_of_input_ = false;
};

/// Standard input, a pipe or any file that cannot be mapped.
class stream_source final : public buffered_source {
 public:
  stream_source(int fd, bool owned, std::string name) : fd_(fd), owned_(owned), name_(std::move(name)) {}
  ~stream_source() override {
    if (owned_) ::close(fd_);
  }
  stream_source(const stream_source&) = delete;
  stream_source& operator=(const stream_source&) = delete;

 private:
  std::size_t fill(char* to, std::size_t room) override {
    while (true) {
      const auto got = ::read(fd_, to, room);
      if (got >= 0) return static_cast<std::size_t>(got);
      if (errno != EINTR) fail_read(name_);
    }
  }

  int fd_;
  bool owned_;
  std::string name_;
};

/// gzip data from another source, inflated (members one after another, as gzip writes them).
class gzip_source final : public buffered_source {
 public:
  gzip_source(std::unique_ptr<byte_source> compressed, std::string name)
      : compressed_(std::move(compressed)), name_(std::move(name)) {
    if (::inflateInit2(&stream_, 15 + 16) != Z_OK) throw io_error("cannot inflate '" + name_ + "': out of memory");
  }
  ~gzip_source() override { ::inflateEnd(&stream_); }
  gzip_source(const gzip_source&) = delete;
  gzip_source& operator=(const gzip_source&) = delete;

 private:
  std::size_t fill(char* to, std::size_t room) override {
    stream_.next_out = reinterpret_cast<Bytef*>(to);
    stream_.avail_out = static_cast<uInt>(std::min<std::size_t>(room, std::numeric_limits<uInt>::max()));
    const auto out_before = stream_.avail_out;
    while (stream_.avail_out == out_before) {
      auto input = compressed_->available();
      if (input.empty()) {
        compressed_->fetch(read_bytes);
        input = compressed_->available();
      }
      if (input.empty()) {
        if (in_member_) {
          throw io_error("'" + name_ + "' is truncated: the gzip data ends before its end marker");
        }
        return 0;  // every member ended cleanly
      }
      if (!in_member_) {
        ::inflateReset(&stream_);
        in_member_ = true;
        member_start_ = true;
      }
      stream_.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(input.data()));
      stream_.avail_in = static_cast<uInt>(std::min<std::size_t>(input.size(), std::numeric_limits<uInt>::max()));
      const auto in_before = stream_.avail_in;
      const int status = ::inflate(&stream_, Z_NO_FLUSH);
      compressed_->consume(in_before - stream_.avail_in);
      if (status == Z_STREAM_END) {
        in_member_ = false;
      } else if (status != Z_OK && status != Z_BUF_ERROR) {
        const std::string why = stream_.msg ? stream_.msg : "invalid data";
        throw io_error("'" + name_ + "' is corrupt: " +
                       (member_start_ && members_ > 0
                            ? "data after the end of the gzip stream is not gzip (" + why + ")"
                            : "cannot inflate its gzip data (" + why + ")"));
      }
      if (stream_.avail_out != out_before || in_before != stream_.avail_in) {
        if (member_start_) ++members_;
        member_start_ = false;
      }
    }
    return out_before - stream_.avail_out;
  }

  std::unique_ptr<byte_source> compressed_;
  std::string name_;
  z_stream stream_{};
  bool in_member_ = false;
  bool member_start_ = false;
  std::size_t members_ = 0;
};

[[nodiscard]] bool starts_gzip(byte_source& source) {
  source.fetch(gzip_magic.size());
  return source.available().starts_with(gzip_magic);
}

/// Inflates `source` if it holds gzip data; a .gz name requires it.
[[nodiscard]] std::unique_ptr<byte_source> maybe_inflate(std::unique_ptr<byte_source> source,
                                                         const std::filesystem::path& path, const std::string& name) {
  if (starts_gzip(*source)) return std::make_unique<gzip_source>(std::move(source), name);
  if (path.extension() == ".gz") {
    throw io_error("'" + name + "' is not gzip data: it does not start with the gzip bytes 1f 8b");
  }
  return source;
}

}  // namespace

std::string source_name(const std::filesystem::path& path) { return path == "-" ? "<stdin>" : path.string(); }

std::unique_ptr<byte_source> memory_source(std::string_view text) { return std::make_unique<text_source>(text); }

std::unique_ptr<byte_source> open_source(const std::filesystem::path& path, const std::string& name) {
  if (path == "-") {
    return maybe_inflate(std::make_unique<stream_source>(STDIN_FILENO, false, name), path, name);
  }
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) throw io_error("cannot open '" + name + "': " + std::strerror(errno));
  struct stat info {};
  if (::fstat(fd, &info) != 0) {
    const int saved = errno;
    ::close(fd);
    errno = saved;
    fail_read(name);
  }
  if (S_ISDIR(info.st_mode)) {
    ::close(fd);
    throw io_error("cannot read '" + name + "': it is a directory");
  }
  if (!S_ISREG(info.st_mode)) return maybe_inflate(std::make_unique<stream_source>(fd, true, name), path, name);
  // A regular file: gzip is streamed, anything else mapped.
  char magic[2] = {};
  const auto got = ::pread(fd, magic, sizeof magic, 0);
  if (got == 2 && std::string_view(magic, 2) == gzip_magic) {
    return std::make_unique<gzip_source>(std::make_unique<stream_source>(fd, true, name), name);
  }
  if (path.extension() == ".gz") {
    ::close(fd);
    throw io_error("'" + name + "' is not gzip data: it does not start with the gzip bytes 1f 8b");
  }
  std::unique_ptr<byte_source> mapped;
  try {
    mapped = std::make_unique<mapped_source>(fd, static_cast<std::size_t>(info.st_size), name);
  } catch (...) {
    ::close(fd);
    throw;
  }
  ::close(fd);  // the mapping keeps the file
  return mapped;
}

}  // namespace pgm::detail
