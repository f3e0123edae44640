#include "pgm/io/csv_counts.hpp"

#include <fcntl.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>
#include <zlib.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "pgm/data/discretizer.hpp"
#include "pgm/io/csv.hpp"
#include "support/folder_test.hpp"
#include "support/random_csv.hpp"
#include "support/thread_processes.hpp"

namespace pgm::csv_counts_tests {
namespace {

using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

using csv_input_test = pgm::testing::folder_test;

const std::vector<family_names> random_families{
    {"c4", {"c0", "c1"}}, {"c3", {"c2"}}, {"c1", {}}, {"c2", {"c4", "c0", "c3"}}, {"c0", {"c3", "c4"}}};

family_count_request request_for(const std::vector<family_names>& families, unsigned threads = 0, std::size_t chunk = 0,
                                 std::size_t window = 0) {
  family_count_request request;
  for (const auto& family : families) {
    for (const auto* name : {&family.child}) request.columns.push_back(*name);
    for (const auto& parent : family.parents) request.columns.push_back(parent);
  }
  request.families = families;
  request.threads = threads;
  request.chunk_bytes = chunk;
  request.window_bytes = window;
  return request;
}

/// The reference: count_family over the data set read_csv gives.
void expect_counts_of(const family_counts& counts, const dataset& data, const std::vector<family_names>& families,
                      const std::string& context) {
  ASSERT_EQ(counts.rows, data.rows()) << context;
  ASSERT_EQ(counts.families.size(), families.size()) << context;
  for (std::size_t f = 0; f < families.size(); ++f) {
    const auto expected = count_family(data, families[f].child, families[f].parents);
    EXPECT_EQ(counts.families[f], expected) << context << " family of " << families[f].child;
  }
}

void write_gzip(const std::filesystem::path& path, const std::string& text) {
  gzFile out = gzopen(path.c_str(), "wb");
  ASSERT_NE(out, nullptr);
  ASSERT_EQ(gzwrite(out, text.data(), static_cast<unsigned>(text.size())), static_cast<int>(text.size()));
  ASSERT_EQ(gzclose(out), Z_OK);
}

csv_options discrete_options() {
  csv_options options;
  options.default_kind = column_kind::discrete;
  return options;
}

TEST(csv_counts_test, equal_in_memory_counts_for_any_threads_chunks_and_windows) {
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    const auto csv = testing::make_random_csv(seed, {.rows = 300, .final_newline = seed % 2 == 0});
    const auto data = parse_csv(csv.text, "r.csv", discrete_options());
    ASSERT_EQ(data.rows(), csv.rows);
    for (unsigned threads : {1u, 2u, 3u, 8u}) {
      for (std::size_t chunk : {1u, 7u, 64u, 0u}) {
        for (std::size_t window : {1u, 50u, 0u}) {
          csv_reader input(csv.text, "r.csv");
          const auto counts = count_csv(input, request_for(random_families, threads, chunk, window));
          expect_counts_of(counts, data, random_families,
                           "seed " + std::to_string(seed) + " threads " + std::to_string(threads) + " chunk " +
                               std::to_string(chunk) + " window " + std::to_string(window));
        }
      }
    }
  }
}

TEST_F(csv_input_test, equal_in_memory_counts_when_streamed_from_gzip) {
  // A stream is held a window at a time: records, quoted line ends and CRLFs cross windows.
  for (std::uint64_t seed = 5; seed <= 7; ++seed) {
    const auto csv = testing::make_random_csv(seed, {.rows = 300});
    const auto data = parse_csv(csv.text, path("r.csv.gz").string(), discrete_options());
    write_gzip(path("r.csv.gz"), csv.text);
    for (std::size_t window : {1u, 13u, 200u, 0u}) {
      csv_reader input(path("r.csv.gz"));
      const auto counts = count_csv(input, request_for(random_families, 2, 5, window));
      expect_counts_of(counts, data, random_families, "gzip window " + std::to_string(window));
    }
    EXPECT_EQ(read_csv(path("r.csv.gz"), discrete_options()), data);
  }
}

TEST_F(csv_input_test, a_pipe_is_streamed) {
  const auto csv = testing::make_random_csv(11, {.rows = 400});
  const auto fifo = path("pipe.csv");
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  // The writer hands the text over in small pieces, so that reads return part of a record.
  auto write_slowly = [&] {
    const int fd = ::open(fifo.c_str(), O_WRONLY);
    for (std::size_t at = 0; at < csv.text.size(); at += 61) {
      const auto piece = csv.text.substr(at, 61);
      if (::write(fd, piece.data(), piece.size()) != static_cast<ssize_t>(piece.size())) break;
    }
    ::close(fd);
  };
  const auto data = parse_csv(csv.text, fifo.string(), discrete_options());
  {
    std::jthread writer(write_slowly);
    csv_reader input(fifo);
    expect_counts_of(count_csv(input, request_for(random_families, 2, 16, 40)), data, random_families, "pipe");
  }
  {
    std::jthread writer(write_slowly);
    EXPECT_EQ(read_csv(fifo, discrete_options()), data);
  }
}

TEST(csv_counts_test, known_states_and_binned_columns) {
  const auto csv = testing::make_random_csv(21, {.rows = 400});
  std::vector<std::string> reversed;
  for (int v = 12; v >= 0; --v) reversed.push_back(std::to_string(v));
  const variable c0("c0", reversed);
  const auto c1 = variable::intervals("c1", {-5, 0, 2, 10});

  csv_options options = discrete_options();
  options.variables.emplace("c0", c0);
  options.kinds["c1"] = column_kind::continuous;
  const auto raw = parse_csv(csv.text, "r.csv", options);
  const auto data = apply_discretization(raw, {{"c1", c1}});
  std::size_t outside = 0;
  for (double v : raw.continuous("c1").values()) outside += v < -5 || v > 10;
  ASSERT_GT(outside, 0u);

  const std::vector<family_names> families{{"c0", {"c1", "c4"}}, {"c1", {"c0"}}};
  for (std::size_t chunk : {3u, 0u}) {
    auto request = request_for(families, 3, chunk, 100);
    request.variables.emplace("c0", c0);
    request.intervals.emplace("c1", c1);
    csv_reader input(csv.text, "r.csv");
    const auto counts = count_csv(input, request);
    expect_counts_of(counts, data, families, "known and binned");
    EXPECT_EQ(counts.variables[0], c0);  // the given states, in the given order
    EXPECT_EQ(counts.variables[1], c1);
    EXPECT_EQ(counts.outside.at("c1"), outside);
  }
}

TEST(csv_counts_test, states_are_sorted_as_read_csv_sorts_them) {
  // "1" and "1.0" are one state, labelled as it first appears; "-0" equals "0".
  const std::string text = "n,w\n10,b\n1.0,a\n-0,c\n9,b\n1,a\n0,a\n1e3,c\n";
  for (std::size_t chunk : {1u, 0u}) {
    auto request = request_for({{"n", {"w"}}}, 2, chunk, 0);
    csv_reader input(text, "t.csv");
    const auto counts = count_csv(input, request);
    EXPECT_EQ(counts.variables[0].states(), (std::vector<std::string>{"-0", "1.0", "9", "10", "1e3"}));
    EXPECT_EQ(counts.variables[1].states(), (std::vector<std::string>{"a", "b", "c"}));
    const auto& table = counts.families[0];
    // n = 1.0 (two rows, both with w = a)
    EXPECT_EQ(table(state_index(1), config_index(0)), 2u);
    EXPECT_EQ(table.total(), 7u);
  }
}

TEST(csv_counts_test, partial_counts_of_byte_ranges_add_up) {
  const auto csv = testing::make_random_csv(31, {.rows = 600, .quotes = false});
  const auto data = parse_csv(csv.text, "r.csv", discrete_options());
  csv_reader input(csv.text, "r.csv");
  const auto request = request_for(random_families, 2, 50, 0);
  const csv_counter counter("r.csv", input.header(), request);
  // The body after the header, split at a line end near its middle.
  const auto body_start = csv.text.find('\n') + 1;
  const auto body = std::string_view(csv.text).substr(body_start);
  const auto split = body.find('\n', body.size() / 2) + 1;
  auto first = counter.count(body.substr(0, split), 2);
  auto second = counter.count(body.substr(split), 2 + first.lines());
  EXPECT_EQ(first.rows() + second.rows(), data.rows());
  csv_partial_counts total;
  total += std::move(second);  // the order of the sum does not matter
  total += std::move(first);
  expect_counts_of(counter.finish(total), data, random_families, "ranges");
}

TEST(csv_counts_test, errors_in_the_middle_name_their_line_and_column) {
  std::string text = "a,b\n";
  for (int row = 0; row < 3000; ++row) text += std::to_string(row % 3) + "," + std::to_string(row % 2) + "\n";
  auto with_row = [&](std::size_t row, const std::string& line, const std::string& base = {}) {
    // Data row `row` (1-based) is on line row + 1.
    std::string changed = base.empty() ? text : base;
    std::size_t at = 0;
    for (std::size_t r = 0; r < row; ++r) at = changed.find('\n', at) + 1;
    const auto end = changed.find('\n', at);
    return changed.replace(at, end - at, line);
  };
  const variable b("b", {"0", "1"});
  auto count = [&](const std::string& csv) {
    auto request = request_for({{"a", {"b"}}}, 4, 64, 1000);
    request.variables.emplace("b", b);
    csv_reader input(csv, "big.csv");
    return count_csv(input, request);
  };
  auto read = [&](const std::string& csv) {
    csv_options options = discrete_options();
    options.variables.emplace("b", b);
    options.threads = 4;
    options.chunk_bytes = 64;
    return parse_csv(csv, "big.csv", options);
  };
  const auto bad_state = with_row(1500, "0,x");
  const std::string state_message = "big.csv:1501:3: column 'b': 'x' is not a state of 'b' (states: 0, 1)";
  EXPECT_THAT([&] { (void)count(bad_state); }, ThrowsMessage<parse_error>(HasSubstr(state_message)));
  EXPECT_THAT([&] { (void)read(bad_state); }, ThrowsMessage<parse_error>(HasSubstr(state_message)));
  // Of two errors, the one earlier in the file, whichever thread meets it.
  const auto two = with_row(2900, "1");
  const auto both = with_row(1500, "0,x", two);
  EXPECT_THAT([&] { (void)count(both); }, ThrowsMessage<parse_error>(HasSubstr(state_message)));
  EXPECT_THAT([&] { (void)read(both); }, ThrowsMessage<parse_error>(HasSubstr(state_message)));
  const std::string ragged = "big.csv:2901:1: expected 2 fields as in the header, found 1";
  EXPECT_THAT([&] { (void)count(two); }, ThrowsMessage<parse_error>(HasSubstr(ragged)));
  EXPECT_THAT([&] { (void)read(two); }, ThrowsMessage<parse_error>(HasSubstr(ragged)));
  const auto unclosed = with_row(2000, "\"1,0");
  EXPECT_THAT([&] { (void)count(unclosed); },
              ThrowsMessage<parse_error>(HasSubstr("big.csv:2001:1: a quoted field is never closed")));
  // Found when the states are sorted, after the whole file: still at its place.
  const auto not_finite = with_row(1200, "nan,1");
  const std::string nan_message = "big.csv:1201:1: column 'a': 'nan' is not a finite number";
  EXPECT_THAT([&] { (void)count(not_finite); }, ThrowsMessage<parse_error>(HasSubstr(nan_message)));
  EXPECT_THAT([&] { (void)read(not_finite); }, ThrowsMessage<parse_error>(HasSubstr(nan_message)));
  EXPECT_THAT([&] { (void)count("a,b\n\n"); }, ThrowsMessage<data_error>(HasSubstr("big.csv: there are no data rows")));
  EXPECT_THAT([&] { (void)count("a,c\n1,2\n"); },
              ThrowsMessage<data_error>(HasSubstr("big.csv: there is no column 'b' (columns: a, c)")));
}

TEST_F(csv_input_test, corrupt_and_truncated_gzip_are_errors_naming_the_file) {
  const auto csv = testing::make_random_csv(41, {.rows = 2000});
  write_gzip(path("good.csv.gz"), csv.text);
  const auto bytes = slurp(path("good.csv.gz"));
  ASSERT_GT(bytes.size(), 100u);
  const auto truncated = path("cut.csv.gz");
  std::ofstream(truncated, std::ios::binary) << bytes.substr(0, bytes.size() / 2);
  // The first deflate block (after the 10-byte header) of an impossible type, and a wrong
  // checksum in the trailer (found only at the end of the data).
  auto corrupt_bytes = bytes;
  corrupt_bytes[10] = static_cast<char>(corrupt_bytes[10] | 0x06);
  const auto corrupt = path("bad.csv.gz");
  std::ofstream(corrupt, std::ios::binary) << corrupt_bytes;
  auto wrong_check = bytes;
  wrong_check[bytes.size() - 8] = static_cast<char>(~wrong_check[bytes.size() - 8]);
  std::ofstream(path("check.csv.gz"), std::ios::binary) << wrong_check;
  const auto plain = file("plain.csv.gz", "a,b\n1,2\n");
  std::ofstream(path("trailing.csv.gz"), std::ios::binary) << bytes << "garbage";

  auto count = [&](const std::filesystem::path& p) {
    csv_reader input(p);
    return count_csv(input, request_for(random_families, 2, 0, 1000));
  };
  EXPECT_THAT([&] { (void)count(truncated); }, ThrowsMessage<io_error>(HasSubstr("cut.csv.gz' is truncated")));
  EXPECT_THAT([&] { (void)read_csv(truncated); }, ThrowsMessage<io_error>(HasSubstr("cut.csv.gz' is truncated")));
  EXPECT_THAT([&] { (void)count(corrupt); }, ThrowsMessage<io_error>(HasSubstr("bad.csv.gz' is corrupt")));
  EXPECT_THAT([&] { (void)count(path("check.csv.gz")); },
              ThrowsMessage<io_error>(
                  HasSubstr("check.csv.gz' is corrupt: cannot inflate its gzip data (incorrect data check)")));
  EXPECT_THAT([&] { (void)read_csv(plain); }, ThrowsMessage<io_error>(HasSubstr("plain.csv.gz' is not gzip data")));
  EXPECT_THAT([&] { (void)count(path("trailing.csv.gz")); },
              ThrowsMessage<io_error>(HasSubstr("data after the end of the gzip stream is not gzip")));
  EXPECT_THAT([&] { (void)read_csv(path("absent.csv")); },
              ThrowsMessage<io_error>(HasSubstr("cannot open '" + path("absent.csv").string() + "'")));
  EXPECT_THAT([&] { (void)read_csv(dir_); }, ThrowsMessage<io_error>(HasSubstr("it is a directory")));
  // Members one after another read as one text, as gzip writes them.
  const std::string first = "a,b\n1,2\n";
  write_gzip(path("one.gz"), first);
  write_gzip(path("two.gz"), "3,4\n");
  std::ofstream(path("both.csv.gz"), std::ios::binary) << slurp(path("one.gz")) << slurp(path("two.gz"));
  EXPECT_EQ(read_csv(path("both.csv.gz")).rows(), 2u);
}

// ---- over processes (threads play them) --------------------------------------------------

TEST(csv_counts_test, counts_over_processes_equal_one_process) {
  for (bool quotes : {false, true}) {  // with quotes process 0 counts alone
    const auto csv = testing::make_random_csv(21, {.rows = 400, .quotes = quotes});
    const auto data = parse_csv(csv.text, "r.csv", discrete_options());
    for (std::size_t ranks = 1; ranks <= 6; ++ranks) {
      std::vector<family_counts> results(ranks);
      testing::run_group(ranks, [&](process_group& group) {
        csv_reader input(csv.text, "r.csv");
        results[group.rank()] = count_csv(input, request_for(random_families, 1, 64), group);
      });
      const std::string context = std::to_string(ranks) + " processes, quotes " + std::to_string(quotes);
      expect_counts_of(results[0], data, random_families, context);
      csv_reader input(csv.text, "r.csv");
      const auto alone = count_csv(input, request_for(random_families));
      EXPECT_EQ(results[0].variables, alone.variables) << context;
      for (std::size_t r = 1; r < ranks; ++r) EXPECT_EQ(results[r].rows, 0U) << "only process 0 gets the counts";
    }
  }
}

TEST(csv_counts_test, a_bad_record_over_processes_is_reported_by_every_process_with_its_line) {
  std::string text = "a,b\n";
  for (int row = 0; row < 200; ++row) text += row == 150 ? "1\n" : std::to_string(row % 3) + ",x\n";
  family_count_request request;
  request.columns = {"a", "b"};
  request.families = {{"a", {"b"}}};
  const auto outcomes = testing::run_group(4, [&](process_group& group) {
    csv_reader input(text, "bad.csv");
    static_cast<void>(count_csv(input, request, group));
  });
  for (const auto& o : outcomes) EXPECT_THAT(o.message, HasSubstr("bad.csv:152:")) << o.message;
}

// Counts `text` over 1 to 8 processes and expects process 0's counts to be those of one
// process, the others' to be empty and no process to fail.
void expect_as_one_process(const std::string& text, const family_count_request& request, const std::string& what) {
  csv_reader input(text, "p.csv");
  const auto alone = count_csv(input, request);
  for (std::size_t ranks = 1; ranks <= 8; ++ranks) {
    std::vector<family_counts> results(ranks);
    const auto outcomes = testing::run_group(ranks, [&](process_group& group) {
      csv_reader theirs(text, "p.csv");
      results[group.rank()] = count_csv(theirs, request, group);
    });
    const std::string context = what + ", " + std::to_string(ranks) + " processes";
    for (const auto& o : outcomes) EXPECT_EQ(o.message, "") << context;
    EXPECT_EQ(results[0].rows, alone.rows) << context;
    EXPECT_EQ(results[0].dropped, alone.dropped) << context;
    EXPECT_EQ(results[0].variables, alone.variables) << context;
    EXPECT_EQ(results[0].families, alone.families) << context;
    EXPECT_EQ(results[0].outside, alone.outside) << context;
    for (std::size_t r = 1; r < ranks; ++r) EXPECT_TRUE(results[r].families.empty()) << context;
  }
}

TEST(csv_counts_test, labels_met_first_on_different_processes_keep_the_order_of_one_process) {
  // Every eighth of the file brings new labels of `a`; `b` meets "x" and "w" late and `late`
  // has states only in the last rows, on the last process.
  const std::vector<std::string> a_labels{"q", "p", "z", "10", "0", "2", "r", "1"};
  std::string text = "a,b,late,n,k\n";
  for (std::size_t row = 0; row < 240; ++row) {
    const auto region = row * a_labels.size() / 240;
    text += a_labels[region - row % (region + 1)] + ",";
    text += std::string(row < 150 ? "y" : row % 3 == 0 ? "x" : row < 230 ? "y" : "w") + ",";
    text += std::string(row < 220 ? "0" : row % 2 ? "t" : "s") + ",";
    text += std::to_string(static_cast<int>(row % 17) - 3) + "," + (row % 5 ? "lo" : "hi") + "\n";
  }
  family_count_request request;
  request.columns = {"a", "b", "late", "n", "k"};
  request.families = {{"a", {"b", "late"}}, {"late", {"a"}}, {"n", {"a", "k"}}, {"b", {}}, {"k", {"late"}}};
  request.intervals.emplace("n", variable::intervals("n", {0, 4, 10}));
  request.variables.emplace("k", variable("k", {"hi", "lo"}));
  for (unsigned threads : {1U, 2U}) {
    request.threads = threads;
    request.chunk_bytes = 40;
    expect_as_one_process(text, request, std::to_string(threads) + " threads");
  }
}

TEST(csv_counts_test, rows_dropped_for_missing_values_are_summed_over_processes) {
  std::string text = "a,b,c\n";
  for (int row = 0; row < 300; ++row) {
    text += (row % 37 == 5 ? "NA" : std::to_string(row % 4)) + ",";
    text += (row % 23 == 7 ? "" : row > 200 && row % 2 ? "v" : "u") + std::string(",");
    text += (row % 41 == 40 ? "?" : std::to_string(row % 3)) + "\n";
  }
  family_count_request request;
  request.columns = {"a", "b", "c"};
  request.families = {{"a", {"b"}}, {"c", {"a", "b"}}, {"b", {}}};
  request.threads = 1;
  for (auto policy : {missing_policy::drop, missing_policy::available}) {
    request.missing.policy = policy;
    if (policy == missing_policy::drop) {
      csv_reader input(text, "p.csv");
      EXPECT_GT(count_csv(input, request).dropped, 0U) << "the test drops rows";
    }
    expect_as_one_process(text, request, policy == missing_policy::drop ? "drop" : "available");
  }
}

TEST(csv_counts_test, a_family_too_large_on_one_process_or_only_over_all_is_counted_sparse_as_by_one_process) {
  // 300 labels in each of u, v and w: 2.7e7 cells, past pgm's limit of a dense table, so u's
  // family is counted sparse. The labels are all in the second half of the file's bytes: on two
  // processes the second has the family sparse, on more no process has but all together do.
  std::string text = "u,v,w\n";
  for (int row = 0; row < 1000; ++row) {
    const auto label = std::to_string(row < 700 ? 0 : row - 699);
    text += label + "," + label + "," + label + "\n";
  }
  family_count_request request;
  request.columns = {"u", "v", "w"};
  request.families = {{"v", {}}, {"u", {"v", "w"}}};
  request.threads = 1;
  csv_reader input(text, "big.csv");
  const auto alone = count_csv(input, request);
  ASSERT_TRUE(alone.families[1].is_sparse());
  EXPECT_EQ(alone.families[1].stored_configurations().size(), 301u);
  EXPECT_EQ(alone.families[1].total(), 1000u);
  expect_as_one_process(text, request, "a sparse family");
  // The sparse rows are gathered after the sum of the dense counts, agreed on first.
  std::vector<std::string> steps;
  testing::run_group(
      4,
      [&](process_group& group) {
        csv_reader theirs(text, "big.csv");
        static_cast<void>(count_csv(theirs, request, group));
      },
      &steps);
  EXPECT_EQ(steps, (std::vector<std::string>{"smallest", "sum", "smallest", "gather", "smallest", "broadcast",
                                             "smallest", "sum", "smallest", "gather"}));
}

TEST(csv_counts_test, processes_agree_on_labels_then_sum_their_counts_in_one_reduction) {
  const auto csv = testing::make_random_csv(5, {.rows = 300, .quotes = false});
  std::vector<std::string> steps;
  testing::run_group(
      4,
      [&](process_group& group) {
        csv_reader input(csv.text, "r.csv");
        static_cast<void>(count_csv(input, request_for(random_families, 1), group));
      },
      &steps);
  // Line ends summed (after an agreement), the counting agreed on, the labels gathered, process
  // 0's ids agreed on and broadcast, the tables summed (after an agreement).
  EXPECT_EQ(steps, (std::vector<std::string>{"smallest", "sum", "smallest", "gather", "smallest", "broadcast",
                                             "smallest", "sum"}));
}

}  // namespace
}  // namespace pgm::csv_counts_tests
