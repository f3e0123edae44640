// The registry of network formats: the built-in ones, listed once here, and the users'.

#include "pgm/io/network_format.hpp"

#include <algorithm>
#include <cctype>
#include <deque>
#include <mutex>

#include "io/builtin_formats.hpp"
#include "pgm/core/error.hpp"
#include "pgm/core/file.hpp"
#include "pgm/core/text.hpp"
#include "pgm/core/unknown_name.hpp"

namespace pgm {

namespace {

// Codecs live in a deque so that the handles (pointers) stay valid as formats are added.
class format_registry {
 public:
  static format_registry& instance() {
    static format_registry registry = [] {
      format_registry r;
      for (auto* make :
           {detail::bif_format, detail::xmlbif_format, detail::net_format, detail::json_format, detail::uai_format}) {
        r.add(make());
      }
      return r;
    }();
    return registry;
  }

  format_registry() = default;
  format_registry(format_registry&& other) noexcept : codecs_(std::move(other.codecs_)) {}

  void add(network_format_codec codec) {
    if (codec.name.empty()) throw model_error("a network format needs a non-empty name");
    if (codec.extensions.empty()) throw model_error("the network format '" + codec.name + "' needs an extension");
    if (!codec.read || !codec.write) {
      throw model_error("the network format '" + codec.name + "' needs both a reader and a writer");
    }
    for (auto& extension : codec.extensions) {
      if (extension.size() < 2 || extension[0] != '.') {
        throw model_error("the network format '" + codec.name + "' has the extension '" + extension +
                          "'; an extension starts with '.'");
      }
      for (auto& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    }
    const std::lock_guard lock(mutex_);
    for (const auto& known : codecs_) {
      if (known.name == codec.name)
        throw model_error("a network format named '" + codec.name + "' is registered already");
      for (const auto& extension : codec.extensions) {
        if (std::ranges::find(known.extensions, extension) != known.extensions.end()) {
          throw model_error("the extension " + extension + " of the network format '" + codec.name +
                            "' is the format '" + known.name + "''s already");
        }
      }
    }
    codecs_.push_back(std::move(codec));
  }

  [[nodiscard]] std::vector<const network_format_codec*> all() const {
    const std::lock_guard lock(mutex_);
    std::vector<const network_format_codec*> result;
    for (const auto& codec : codecs_) result.push_back(&codec);
    return result;
  }

 private:
  mutable std::mutex mutex_;
  std::deque<network_format_codec> codecs_;
};

// "a, b or c" with `last` as "or".
[[nodiscard]] std::string join_with(std::vector<std::string> items, std::string_view last) {
  if (items.size() < 2) return text::join(items);
  auto end = std::move(items.back());
  items.pop_back();
  return text::join(items) + std::string(last) + end;
}

[[nodiscard]] std::string format_titles() {
  std::vector<std::string> titles;
  for (const auto& format : network_formats()) titles.push_back(format.codec().title);
  return text::join(titles);
}

}  // namespace

network_format::network_format(std::string_view name) : codec_(nullptr) {
  for (const auto* codec : format_registry::instance().all()) {
    if (codec->name == name) {
      codec_ = codec;
      return;
    }
  }
  throw unknown_name("network format", std::string(name), known_network_formats());
}

void add_network_format(network_format_codec codec) { format_registry::instance().add(std::move(codec)); }

std::vector<network_format> network_formats() {
  std::vector<network_format> formats;
  for (const auto* codec : format_registry::instance().all()) formats.push_back(network_format(codec));
  return formats;
}

std::vector<std::string> known_network_formats() {
  std::vector<std::string> names;
  for (const auto& format : network_formats()) names.push_back(format.name());
  return names;
}

std::vector<std::string> network_file_extensions() {
  std::vector<std::string> extensions;
  for (const auto& format : network_formats()) {
    extensions.insert(extensions.end(), format.codec().extensions.begin(), format.codec().extensions.end());
  }
  return extensions;
}

std::string network_file_kinds() {
  std::vector<std::string> firsts;
  for (const auto& format : network_formats()) firsts.push_back(format.codec().extensions.front());
  return join_with(std::move(firsts), " or ");
}

std::string network_format_descriptions() {
  std::vector<std::string> described;
  for (const auto& format : network_formats()) {
    described.push_back(format.codec().title + " (" + text::join(format.codec().extensions) + ")");
  }
  return join_with(std::move(described), " and ");
}

std::optional<network_format> find_format_of(const std::filesystem::path& path) {
  const auto extension = lowercase_extension(path);
  for (const auto& format : network_formats()) {
    if (std::ranges::find(format.codec().extensions, extension) != format.codec().extensions.end()) return format;
  }
  return std::nullopt;
}

network_format format_of(const std::filesystem::path& path) {
  if (const auto format = find_format_of(path)) return *format;
  throw io_error("'" + path.string() + "': not a network file; expected one of " +
                 text::join(network_file_extensions()) + " (" + format_titles() + ")");
}

network_format format_to_read(const std::filesystem::path& path) {
  const auto format = find_format_of(lowercase_extension(path) == ".gz" ? path.stem() : path);
  if (format) return *format;
  throw io_error("'" + path.string() + "': not a network file; expected one of " +
                 text::join(network_file_extensions()) + " (" + format_titles() +
                 "), or one of them compressed with gzip (" + network_file_extensions().front() + ".gz, ...)");
}

}  // namespace pgm
