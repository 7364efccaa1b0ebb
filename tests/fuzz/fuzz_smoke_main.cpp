// The driver of a fuzz target where libFuzzer is not linked (a GCC build, as CI's): it runs
// every file of the given corpus folders through the target, then mutates them at random for a
// few seconds (bytes flipped, inserted, deleted, runs repeated) with a fixed seed. It keeps the
// targets building and catches regressions on the seeds; the campaigns that find new faults use
// libFuzzer (AIRSHAPE_FUZZ, docs/reliability.md).
#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace {

namespace fs = std::filesystem;

std::vector<std::string> corpus(const std::vector<std::string>& folders) {
  std::vector<std::string> inputs;
  for (const std::string& folder : folders) {
    std::vector<fs::path> files;
    for (const auto& entry : fs::directory_iterator(folder))
      if (entry.is_regular_file()) files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    for (const fs::path& file : files) {
      std::ifstream in(file, std::ios::binary);
      std::stringstream content;
      content << in.rdbuf();
      inputs.push_back(content.str());
    }
  }
  return inputs;
}

void run(const std::string& input) {
  LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(input.data()), input.size());
}

/// One random change of the kinds libFuzzer makes most often.
std::string mutated(std::string input, std::mt19937& random) {
  const auto at = [&](std::size_t limit) {
    return limit == 0 ? 0 : std::uniform_int_distribution<std::size_t>(0, limit - 1)(random);
  };
  const std::size_t position = at(input.size() + 1);
  switch (at(4)) {
    case 0:
      if (!input.empty()) input[at(input.size())] = static_cast<char>(at(256));
      break;
    case 1:
      input.insert(input.begin() + static_cast<std::ptrdiff_t>(position), static_cast<char>(at(256)));
      break;
    case 2:
      if (position < input.size()) input.erase(position, 1 + at(std::min<std::size_t>(64, input.size() - position)));
      break;
    default:
      if (position < input.size()) input.insert(position, input.substr(position, 1 + at(64)));
      break;
  }
  return input;
}

}  // namespace

int main(int argc, char** argv) {
  double seconds = 3.0;
  std::vector<std::string> folders;
  for (int i = 1; i < argc; ++i) {
    const std::string argument = argv[i];
    if (argument == "--seconds" && i + 1 < argc) {
      seconds = std::atof(argv[++i]);
    } else {
      folders.push_back(argument);
    }
  }
  const std::vector<std::string> seeds = corpus(folders);
  if (seeds.empty()) {
    std::cerr << "no seed inputs in the corpus folders given\n";
    return 2;
  }
  for (const std::string& seed : seeds) run(seed);
  std::mt19937 random(20261201);
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  std::size_t runs = seeds.size();
  for (; std::chrono::steady_clock::now() < end; ++runs) {
    std::string input = seeds[runs % seeds.size()];
    for (int changes = 1 + static_cast<int>(random() % 8); changes > 0; --changes) input = mutated(input, random);
    run(input);
  }
  std::cout << runs << " inputs run (" << seeds.size() << " seeds, the rest mutants), no crash\n";
  return 0;
}
