#pragma once
// Random CSV text for tests that compare ways of reading it: labels of every kind the reader
// treats differently (small whole numbers, other numbers such as "1.0", "01", "-0" and "1e3",
// words, labels that need quotes, some with a line end inside), CRLF and LF line ends, blank
// lines, blanks around fields, a byte order mark.

#include <cstddef>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "pgm/io/csv.hpp"

namespace pgm::testing {

struct random_csv_options {
  std::size_t rows = 500;
  bool quotes = true;       // labels that need quoting, some holding a line end
  bool crlf = true;         // some lines end in CRLF
  bool blank_lines = true;  // blank lines here and there
  bool final_newline = true;
};

/// The text and the number of data rows. Column c0 holds small whole numbers, c1 numbers written
/// several ways, c2 words (quoted where needed), c3 up to 300 distinct labels, c4 0/1.
struct random_csv {
  std::string text;
  std::size_t rows;
};

[[nodiscard]] inline random_csv make_random_csv(std::uint64_t seed, const random_csv_options& options = {}) {
  std::mt19937_64 engine(seed);
  auto pick = [&](std::size_t n) { return static_cast<std::size_t>(engine() % n); };
  const std::vector<std::string> numbers{"1", "1.0", "01", "-0", "0", "1e3", "1000", "2.5", "+2.5", "-3"};
  const std::vector<std::string> plain_words{"Red", "Blue", "Green", "nan", "a b"};
  const std::vector<std::string> quoted_words{
      "\"x,y\"", "\"say \"\"hi\"\"\"", "\"two\nlines\"", "\" padded \"", "\"Red\"", "\"\r\n\""};
  std::string text = seed % 2 ? "\xEF\xBB\xBF" : "";
  text += "c0,c1,c2,c3,c4\n";
  auto line_end = [&] { return options.crlf && pick(4) == 0 ? std::string("\r\n") : std::string("\n"); };
  for (std::size_t row = 0; row < options.rows; ++row) {
    if (options.blank_lines && pick(20) == 0) text += pick(2) ? "\n" : "  \r\n";
    std::string c2 = options.quotes && pick(3) == 0 ? quoted_words[pick(quoted_words.size())]
                                                    : plain_words[pick(plain_words.size())];
    text += std::to_string(pick(13)) + "," + (pick(5) == 0 ? " " : "") + numbers[pick(numbers.size())] + "," + c2 +
            ",item" + std::to_string(pick(row < 50 ? 300 : 40)) + "," + std::to_string(pick(2));
    if (row + 1 < options.rows || options.final_newline) text += line_end();
  }
  return {text, options.rows};
}

}  // namespace pgm::testing
