// Feeds files to a harness without libFuzzer: the seed corpus and the saved crashers run as
// ordinary tests in every build (GCC included). Every harness is compiled into this one program
// (PGM_FUZZ_REPLAY); the first argument names it, the others are files or directories (every
// regular file below them, in sorted order); an empty or missing directory is fine, since
// crasher directories are usually empty.
//   usage: pgm_fuzz_replay HARNESS [FILE|DIR]...

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <vector>

#include "harness.hpp"

int main(int argc, char** argv) {
  namespace fs = std::filesystem;
  const auto& harnesses = pgm::fuzz::replay_harnesses();
  const auto harness = argc > 1 ? harnesses.find(argv[1]) : harnesses.end();
  if (harness == harnesses.end()) {
    std::cerr << "usage: pgm_fuzz_replay HARNESS [FILE|DIR]...\nharnesses:";
    for (const auto& [name, function] : harnesses) std::cerr << ' ' << name;
    std::cerr << std::endl;
    return 2;
  }
  std::vector<fs::path> files;
  for (int i = 2; i < argc; ++i) {
    const fs::path arg = argv[i];
    if (fs::is_directory(arg)) {
      for (const auto& entry : fs::recursive_directory_iterator(arg)) {
        if (entry.is_regular_file() && entry.path().filename().string().front() != '.') files.push_back(entry.path());
      }
    } else if (fs::exists(arg)) {
      files.push_back(arg);
    }
  }
  std::sort(files.begin(), files.end());
  for (const auto& file : files) {
    std::ifstream in(file, std::ios::binary);
    const std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::cout << "replaying " << file.string() << " (" << bytes.size() << " bytes)" << std::endl;
    harness->second(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
  }
  std::cout << files.size() << " inputs replayed" << std::endl;
  return 0;
}
