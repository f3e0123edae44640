#pragma once
/// \file
/// The network file formats, by name and extension: BIF (`.bif`), XMLBIF (`.xml`, `.xmlbif`,
/// `.bifxml`), Hugin NET (`.net`) and pgm's JSON model (`.json`), and any a user registers.
/// A format is a `network_format_codec`: its names, its extensions and how it reads and writes.
/// Every command and Python function that reads or writes a model goes through this registry
/// (pgm/io/network_file.hpp), so a format registered here is read, written, converted and listed
/// in every command's help. A user's format joins from its own translation unit:
///
///     static const pgm::register_network_format registered(my_format_codec());
///
/// Compiled into the library (src/lib/io/network_format.cpp, pgm::pgm).

#include <filesystem>
#include <functional>
#include <optional>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "pgm/core/bayesian_network.hpp"
#include "pgm/io/json_model.hpp"
#include "pgm/io/read_options.hpp"
#include "pgm/learn/fit_statistics.hpp"

namespace pgm {

struct network_write_options {
  /// Write interval edges and semantic tags where the format allows (all four built-in do).
  bool properties = true;
  /// Receives a line for anything written that a peer would read differently.
  std::vector<std::string>* notes = nullptr;
  /// The counts and priors to keep with the network, for `pgm update`: under "statistics" in
  /// JSON, in a network-level property pgm.statistics elsewhere (which peers ignore).
  const fit_statistics* statistics = nullptr;
  /// Writing a file: runs once the new file is complete, before it replaces the old one
  /// (write_file_atomically), so that a failure there leaves the old file as it was.
  std::function<void()> before_replacing;
};

/// One network file format.
struct network_format_codec {
  /// What `--to` takes and messages print: "bif".
  std::string name;
  /// What the format is called in messages: "Hugin NET".
  std::string title;
  /// The extensions that name it, in lower case with the dot; the first is the one help texts show.
  std::vector<std::string> extensions;
  /// A model from text: a structure, with tables (a format may allow a structure alone, as
  /// pgm's JSON does) and the counts of `pgm fit --keep-counts` when the file keeps them.
  /// `source` names the text in error messages.
  std::function<model_document(std::string_view text, const std::string& source, const network_read_options&)> read;
  /// The text of a fitted network; throws model_error, before anything is written, for what the
  /// format cannot hold.
  std::function<std::string(const bayesian_network&, const network_write_options&)> write;
  /// Optional: the same text streamed to `out` as it is made, for a format whose documents may be
  /// large (pgm's JSON); writing a file then uses it, so the text is never held whole.
  std::function<void(std::ostream& out, const bayesian_network&, const network_write_options&)> write_to;
};

/// A registered format: a handle to its codec, compared by name.
class network_format {
 public:
  /// The format registered as `name`; throws unknown_name listing the known ones.
  explicit network_format(std::string_view name);

  [[nodiscard]] const std::string& name() const noexcept { return codec_->name; }
  [[nodiscard]] const network_format_codec& codec() const noexcept { return *codec_; }

  friend bool operator==(const network_format& a, const network_format& b) noexcept { return a.codec_ == b.codec_; }
  friend std::ostream& operator<<(std::ostream& out, const network_format& format) { return out << format.name(); }

 private:
  friend std::vector<network_format> network_formats();
  explicit network_format(const network_format_codec* codec) noexcept : codec_(codec) {}
  const network_format_codec* codec_;
};

/// Adds a format to the program-wide registry. A name or extension that is taken, an empty
/// name, no extension, or a missing reader or writer is a model_error.
void add_network_format(network_format_codec codec);

/// Registers a format from a static object in a user's translation unit.
struct register_network_format {
  explicit register_network_format(network_format_codec codec) { add_network_format(std::move(codec)); }
};

/// Every registered format: the built-in ones (bif, xmlbif, net, json), then the users', in the
/// order they were added.
[[nodiscard]] std::vector<network_format> network_formats();

/// The formats' names (bif, xmlbif, net, json, ...), for messages and `--to`'s allowed values.
[[nodiscard]] std::vector<std::string> known_network_formats();

/// The format a name stands for; throws unknown_name for any other.
[[nodiscard]] inline network_format network_format_named(std::string_view name) { return network_format(name); }

/// Every extension a network file may have, in the order the formats are listed.
[[nodiscard]] std::vector<std::string> network_file_extensions();

/// Each format's first extension, for help texts: ".bif, .xml, .net or .json".
[[nodiscard]] std::string network_file_kinds();

/// Each format's title and extensions, for help texts: "BIF (.bif), XMLBIF (.xml, .xmlbif,
/// .bifxml), Hugin NET (.net) and pgm JSON (.json)".
[[nodiscard]] std::string network_format_descriptions();

/// The format a path's extension names (case-insensitive), or nothing.
[[nodiscard]] std::optional<network_format> find_format_of(const std::filesystem::path& path);

/// The format a path's extension names; throws io_error listing the supported extensions.
[[nodiscard]] network_format format_of(const std::filesystem::path& path);

/// The format of a model file to read: its extension's, or for a compressed file (`.bif.gz`,
/// `.xml.gz`, `.net.gz`, `.json.gz`) that of the name without `.gz`.
[[nodiscard]] network_format format_to_read(const std::filesystem::path& path);

/// The format's name, as `--to` takes it.
[[nodiscard]] inline std::string_view name_of(const network_format& format) { return format.name(); }

}  // namespace pgm
