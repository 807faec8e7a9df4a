// SPDX-License-Identifier: MIT
// A small mutation driver for LLVMFuzzerTestOneInput when libFuzzer is not there (GCC builds):
// it runs every seed, then mutates seeds and earlier inputs (bit flips, byte and token inserts,
// deletions, duplicated ranges, splices) for a fixed time. Crashes and sanitizer reports abort the
// process; the input is first written to fuzz-crash.bin so that it can be replayed:
//
//   fuzz_suitecsv [--seconds S] [--seed N] CORPUS_DIR_OR_FILE...
//   fuzz_suitecsv fuzz-crash.bin            (replays one input)
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);

namespace {
using Bytes = std::vector<uint8_t>;

Bytes readFile(const std::filesystem::path& path)
{
    std::ifstream in(path, std::ios::binary);
    return Bytes(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

void runOne(const Bytes& input)
{
    { // kept on disk while it runs: a crash leaves it behind
        std::ofstream out("fuzz-crash.bin", std::ios::binary | std::ios::trunc);
        out.write(reinterpret_cast<const char*>(input.data()), std::streamsize(input.size()));
    }
    LLVMFuzzerTestOneInput(input.data(), input.size());
}

/// Pieces that matter to a CSV of times: separators, quotes, line ends, signs, exponents, long digits.
const std::vector<std::string> kTokens {",",           "\"",
                                        "\"\"",        "\r\n",
                                        "\n",          "\r",
                                        ".",           "-",
                                        "+",           "e",
                                        "E309",        "0",
                                        "9",           "\xef\xbb\xbf",
                                        "1700000000.", "999999999999999999999",
                                        ".000000001",  "nan",
                                        "inf",         " ",
                                        "\t",          std::string(1, '\0'),
                                        "/topic",      ",,",
                                        "\"a,b\""};

Bytes mutate(Bytes b, const std::vector<Bytes>& pool, std::mt19937_64& rng)
{
    auto pick = [&rng](std::size_t n) { return n == 0 ? 0 : std::size_t(rng() % n); };
    const int steps = 1 + int(rng() % 6);
    for (int i = 0; i < steps; ++i) {
        switch (rng() % 7) {
        case 0: // flip a bit
            if (!b.empty())
                b[pick(b.size())] ^= uint8_t(1u << (rng() % 8));
            break;
        case 1: // a random byte
            b.insert(b.begin() + std::ptrdiff_t(pick(b.size() + 1)), uint8_t(rng()));
            break;
        case 2: { // a token
            const std::string& t = kTokens[pick(kTokens.size())];
            b.insert(b.begin() + std::ptrdiff_t(pick(b.size() + 1)), t.begin(), t.end());
            break;
        }
        case 3: // delete a range
            if (!b.empty()) {
                const std::size_t at = pick(b.size());
                const std::size_t n = 1 + pick(std::min<std::size_t>(16, b.size() - at));
                b.erase(b.begin() + std::ptrdiff_t(at),
                        b.begin() + std::ptrdiff_t(std::min(b.size(), at + n)));
            }
            break;
        case 4: // duplicate a range (more rows, longer cells)
            if (!b.empty() && b.size() < 64 * 1024) {
                const std::size_t at = pick(b.size());
                const std::size_t n = 1 + pick(std::min<std::size_t>(256, b.size() - at));
                const Bytes range(b.begin() + std::ptrdiff_t(at), b.begin() + std::ptrdiff_t(at + n));
                b.insert(b.begin() + std::ptrdiff_t(pick(b.size() + 1)), range.begin(), range.end());
            }
            break;
        case 5: { // splice with another input
            const Bytes& other = pool[pick(pool.size())];
            if (!other.empty()) {
                const std::size_t cut = pick(b.size() + 1);
                const std::size_t from = pick(other.size());
                b.resize(cut);
                b.insert(b.end(), other.begin() + std::ptrdiff_t(from), other.end());
            }
            break;
        }
        default: // truncate
            b.resize(pick(b.size() + 1));
            break;
        }
    }
    return b;
}
} // namespace

int main(int argc, char** argv)
{
    double seconds = 20;
    uint64_t seed = std::random_device {}();
    std::vector<Bytes> pool;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--seconds" && i + 1 < argc) {
            seconds = std::stod(argv[++i]);
        } else if (arg == "--seed" && i + 1 < argc) {
            seed = std::stoull(argv[++i]);
        } else if (std::filesystem::is_directory(arg)) {
            for (const auto& entry : std::filesystem::directory_iterator(arg))
                if (entry.is_regular_file())
                    pool.push_back(readFile(entry.path()));
        } else if (std::filesystem::is_regular_file(arg)) {
            pool.push_back(readFile(arg));
        } else {
            std::fprintf(stderr, "usage: %s [--seconds S] [--seed N] CORPUS_DIR_OR_FILE...\n", argv[0]);
            return 2;
        }
    }
    if (pool.empty()) {
        std::fprintf(stderr, "no seed inputs\n");
        return 2;
    }
    for (const Bytes& input : pool)
        runOne(input);
    if (argc == 2 && std::filesystem::is_regular_file(argv[1])) {
        std::printf("replayed %s\n", argv[1]);
        std::remove("fuzz-crash.bin");
        return 0;
    }

    std::printf("seed %llu, %zu inputs, %.0f s\n", static_cast<unsigned long long>(seed), pool.size(),
                seconds);
    std::mt19937_64 rng(seed);
    const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    uint64_t runs = 0;
    while (std::chrono::steady_clock::now() < end) {
        for (int i = 0; i < 100; ++i, ++runs) {
            Bytes input = mutate(pool[std::size_t(rng() % pool.size())], pool, rng);
            runOne(input);
            if (rng() % 64 == 0 && pool.size() < 4096) // keep some mutants to mutate further
                pool.push_back(std::move(input));
        }
    }
    std::remove("fuzz-crash.bin");
    std::printf("%llu inputs, no failure\n", static_cast<unsigned long long>(runs));
    return 0;
}
