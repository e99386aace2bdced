/*=========================================================================

  Program:   ApertureLighting
  Module:    FuzzReplay.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "FuzzReplay.h"

#include "vtkObject.h"

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <iterator>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace
{
// A small deterministic generator (splitmix64), so that a failure can be replayed.
struct Random
{
  std::uint64_t State = 0x5eed;
  std::uint64_t Next()
  {
    std::uint64_t z = (this->State += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
  }
  size_t Below(size_t n) { return n ? static_cast<size_t>(this->Next() % n) : 0; }
};

// Mostly within the first 512 bytes (headers), where a damaged field changes the most.
size_t Offset(Random& random, size_t size)
{
  return random.Below(2) ? random.Below(std::min<size_t>(size, 512)) : random.Below(size);
}

void Mutate(std::vector<char>& bytes, const std::vector<FuzzSeed>& seeds, Random& random)
{
  static const unsigned char edgeBytes[] = { 0x00, 0x01, 0x7f, 0x80, 0xff };
  static const std::uint32_t edgeWords[] = { 0u, 1u, 0xffffffffu, 0x7fffffffu, 0x80000000u, 0xffffu,
    1u << 20, 1u << 30 };
  const int count = 1 + static_cast<int>(random.Below(4));
  for (int m = 0; m < count && !bytes.empty(); ++m)
  {
    const size_t size = bytes.size();
    switch (random.Below(7))
    {
      case 0:
        for (int b = 1 + static_cast<int>(random.Below(8)); b > 0; --b)
        {
          bytes[Offset(random, size)] ^= static_cast<char>(1u << random.Below(8));
        }
        break;
      case 1:
        bytes[Offset(random, size)] = static_cast<char>(edgeBytes[random.Below(5)]);
        break;
      case 2:
        if (size >= 4)
        {
          const std::uint32_t word = edgeWords[random.Below(8)];
          std::memcpy(&bytes[std::min(Offset(random, size), size - 4)], &word, 4);
        }
        break;
      case 3:
        bytes.resize(random.Below(size));
        break;
      case 4:
      {
        const size_t from = random.Below(size), to = random.Below(size);
        const size_t n = std::min(random.Below(64) + 1, size - std::max(from, to));
        std::memmove(&bytes[to], &bytes[from], n);
        break;
      }
      case 5:
      {
        std::vector<char> block(random.Below(32) + 1);
        for (char& c : block)
        {
          c = static_cast<char>(random.Next());
        }
        const size_t at = Offset(random, size);
        bytes.insert(bytes.begin() + at, block.begin(), block.end());
        break;
      }
      default:
      {
        const std::vector<char>& other = seeds[random.Below(seeds.size())].Bytes;
        const size_t cut = random.Below(size), from = random.Below(other.size());
        bytes.resize(cut);
        bytes.insert(bytes.end(), other.begin() + from, other.end());
        break;
      }
    }
  }
}

void Feed(const std::vector<char>& bytes)
{
  if (const char* last = std::getenv("APERTURE_FUZZ_LAST"))
  {
    std::ofstream(last, std::ios::binary)
      .write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  }
  LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
}
}

int RunFuzzReplay(int argc, char* argv[], const std::vector<FuzzSeed>& seeds,
  const std::string& extension, const std::function<std::string(const FuzzSeed&)>& checkSeed)
{
  if (argc == 3 && std::string(argv[1]) == "--write-seeds")
  {
    for (const FuzzSeed& seed : seeds)
    {
      std::ofstream out(std::string(argv[2]) + "/" + seed.Name + extension, std::ios::binary);
      out.write(seed.Bytes.data(), static_cast<std::streamsize>(seed.Bytes.size()));
      if (!out)
      {
        std::cerr << "cannot write the seeds into " << argv[2] << "\n";
        return EXIT_FAILURE;
      }
    }
    std::cout << seeds.size() << " seeds written into " << argv[2] << "\n";
    return EXIT_SUCCESS;
  }
  long iterations = 3000;
  std::vector<std::string> files;
  for (int i = 1; i < argc; ++i)
  {
    if (std::string(argv[i]) == "--iterations" && i + 1 < argc)
    {
      iterations = std::atol(argv[++i]);
    }
    else
    {
      files.emplace_back(argv[i]);
    }
  }

  // The seeds must read: otherwise the mutants would only ever test the rejection of bad headers.
  int failures = 0;
  for (const FuzzSeed& seed : seeds)
  {
    const std::string problem = checkSeed(seed);
    if (!problem.empty())
    {
      std::cerr << "FAIL seed " << seed.Name << " " << problem << "\n";
      ++failures;
    }
  }

  vtkObject::GlobalWarningDisplayOff();
  for (const FuzzSeed& seed : seeds)
  {
    Feed(seed.Bytes);
  }
  Random random;
  for (long i = 0; i < iterations; ++i)
  {
    std::vector<char> bytes = seeds[random.Below(seeds.size())].Bytes;
    Mutate(bytes, seeds, random);
    Feed(bytes);
  }
  for (const std::string& name : files)
  {
    std::ifstream in(name, std::ios::binary);
    if (!in)
    {
      std::cerr << "FAIL cannot read " << name << "\n";
      ++failures;
      continue;
    }
    Feed(std::vector<char>(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()));
  }
  std::cout << seeds.size() << " seeds, " << iterations << " damaged copies and " << files.size()
            << " files read without a crash\n";
  return failures ? EXIT_FAILURE : EXIT_SUCCESS;
}
