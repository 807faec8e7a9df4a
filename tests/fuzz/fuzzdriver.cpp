// SPDX-License-Identifier: MIT
// A small mutation driver for LLVMFuzzerTestOneInput when libFuzzer is not there (GCC builds):
// it runs every seed, then mutates seeds and earlier inputs (bit flips, byte and token inserts,
// deletions, duplicated ranges, splices) for a fixed time. Crashes and sanitizer reports abort the
// process, and the input is saved as NAME-crash.bin so that it can be replayed. An input that
// runs longer than --timeout seconds, or a process that grows past --rss-limit-mb, is a finding
// too (the stack of the input's thread is printed), as with libFuzzer's -timeout and -rss_limit_mb.
//
//   fuzz_x [--seconds S] [--seed N] [--timeout S] [--rss-limit-mb MB] [--dict FILE] CORPUS_DIR_OR_FILE...
//   fuzz_x NAME-crash.bin            (replays one input)
//
// --seconds 0 only runs the given inputs (the crash regression tests). --dict reads a libFuzzer
// dictionary (lines `"token"` or `name="token"`, with \xNN escapes) for the token inserts.
#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <pthread.h>
#include <random>
#include <string>
#include <thread>
#include <unistd.h>
#include <vector>

#if defined(__has_include)
#if __has_include(<sanitizer/common_interface_defs.h>)
#include <sanitizer/common_interface_defs.h>
#define FUZZ_HAVE_SANITIZER_STACK 1
#endif
#endif

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);
extern "C" __attribute__((weak)) int LLVMFuzzerInitialize(int* argc, char*** argv);

namespace {
using Bytes = std::vector<uint8_t>;

Bytes readFile(const std::filesystem::path& path)
{
    std::ifstream in(path, std::ios::binary);
    return Bytes(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

std::string g_artifact = "fuzz-crash.bin";
double g_timeoutSeconds = 20;
long g_rssLimitMb = 2048;
pthread_t g_mainThread;
std::atomic<int64_t> g_inputStartedMs {0}; ///< 0: no input running
std::atomic<int> g_finding {0}; ///< 1 timeout, 2 out of memory
void saveCurrent();

int64_t nowMs()
{
    return std::chrono::duration_cast<std::chrono::milliseconds>(
               std::chrono::steady_clock::now().time_since_epoch())
        .count();
}

long rssMb()
{
    std::ifstream statm("/proc/self/statm");
    long pages = 0;
    long resident = 0;
    statm >> pages >> resident;
    return resident * (sysconf(_SC_PAGESIZE) / 1024) / 1024;
}

/// Runs on the thread that runs the input: says what happened, shows where, and ends the process.
void onFinding(int)
{
    saveCurrent();
    const char* what = g_finding.load() == 1 ? "timeout: an input ran longer than the limit"
                                             : "out of memory: the process grew past the RSS limit";
    std::fprintf(stderr, "==fuzzdriver== %s; the input is in %s\n", what, g_artifact.c_str());
#ifdef FUZZ_HAVE_SANITIZER_STACK
    __sanitizer_print_stack_trace();
#endif
    std::fflush(stderr);
    _exit(g_finding.load() == 1 ? 70 : 71);
}

void watchdog()
{
    for (;;) {
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
        const int64_t started = g_inputStartedMs.load();
        int finding = 0;
        if (started != 0 && double(nowMs() - started) > g_timeoutSeconds * 1000)
            finding = 1;
        else if (g_rssLimitMb > 0 && rssMb() > g_rssLimitMb)
            finding = 2;
        if (finding != 0) {
            g_finding = finding;
            pthread_kill(g_mainThread, SIGUSR2);
            std::this_thread::sleep_for(std::chrono::seconds(5));
            _exit(finding == 1 ? 70 : 71); // the input's thread did not answer
        }
    }
}

const Bytes* g_current = nullptr; ///< the input that runs, for the crash paths

/// Saves the running input (async-signal-safe: called from signal handlers and sanitizer deaths).
void saveCurrent()
{
    if (g_current == nullptr)
        return;
    const int fd = ::open(g_artifact.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd < 0)
        return;
    const uint8_t* p = g_current->data();
    std::size_t left = g_current->size();
    while (left > 0) {
        const ssize_t n = ::write(fd, p, left);
        if (n <= 0)
            break;
        p += n;
        left -= std::size_t(n);
    }
    ::close(fd);
    const char note[] = "==fuzzdriver== the failing input is saved\n";
    (void)!::write(2, note, sizeof note - 1);
}

/// A failed FUZZ_CHECK or an assertion: save the input, then die of the same signal.
void onAbort(int sig)
{
    saveCurrent();
    std::signal(sig, SIG_DFL);
    std::raise(sig);
}

void runOne(const Bytes& input)
{
    g_current = &input;
    g_inputStartedMs = nowMs();
    LLVMFuzzerTestOneInput(input.data(), input.size());
    g_inputStartedMs = 0;
    g_current = nullptr;
}

/// Tokens of a libFuzzer dictionary: `"token"` or `name="token"` per line, `#` comments.
std::vector<std::string> readDictionary(const std::string& path)
{
    std::vector<std::string> tokens;
    std::ifstream in(path);
    std::string line;
    while (std::getline(in, line)) {
        const std::size_t first = line.find_first_not_of(" \t");
        const std::size_t open = line.find('"');
        const std::size_t close = line.rfind('"');
        if (first == std::string::npos || line[first] == '#' || open == std::string::npos || close <= open)
            continue;
        std::string token;
        for (std::size_t i = open + 1; i < close; ++i) {
            if (line[i] == '\\' && i + 1 < close) {
                if (line[i + 1] == 'x' && i + 3 < close) {
                    token += char(std::stoi(line.substr(i + 2, 2), nullptr, 16));
                    i += 3;
                } else {
                    token += line[++i];
                }
            } else {
                token += line[i];
            }
        }
        tokens.push_back(token);
    }
    return tokens;
}

/// Without a dictionary: pieces that matter to a CSV of times (separators, quotes, line ends,
/// signs, exponents, long digits).
std::vector<std::string> g_tokens {",",           "\"",
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
            const std::string& t = g_tokens[pick(g_tokens.size())];
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
    if (LLVMFuzzerInitialize)
        LLVMFuzzerInitialize(&argc, &argv);
    double seconds = 20;
    uint64_t seed = std::random_device {}();
    std::vector<Bytes> pool;
    std::size_t files = 0;
    g_artifact = std::filesystem::path(argv[0]).filename().string() + "-crash.bin";
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--seconds" && i + 1 < argc) {
            seconds = std::stod(argv[++i]);
        } else if (arg == "--seed" && i + 1 < argc) {
            seed = std::stoull(argv[++i]);
        } else if (arg == "--timeout" && i + 1 < argc) {
            g_timeoutSeconds = std::stod(argv[++i]);
        } else if (arg == "--rss-limit-mb" && i + 1 < argc) {
            g_rssLimitMb = std::stol(argv[++i]);
        } else if (arg == "--dict" && i + 1 < argc) {
            std::vector<std::string> tokens = readDictionary(argv[++i]);
            if (!tokens.empty())
                g_tokens = std::move(tokens);
        } else if (std::filesystem::is_directory(arg)) {
            for (const auto& entry : std::filesystem::directory_iterator(arg))
                if (entry.is_regular_file() && entry.path().filename().string()[0] != '.'
                    && entry.path().filename() != "README.md")
                    pool.push_back(readFile(entry.path()));
        } else if (std::filesystem::is_regular_file(arg)) {
            pool.push_back(readFile(arg));
            ++files;
        } else {
            std::fprintf(stderr,
                         "usage: %s [--seconds S] [--seed N] [--timeout S] [--rss-limit-mb MB] [--dict FILE] "
                         "CORPUS_DIR_OR_FILE...\n",
                         argv[0]);
            return 2;
        }
    }
    if (pool.empty()) {
        std::fprintf(stderr, "no seed inputs\n");
        return 2;
    }
    g_mainThread = pthread_self();
    std::signal(SIGUSR2, onFinding);
    std::signal(SIGABRT, onAbort);
#ifdef FUZZ_HAVE_SANITIZER_STACK
    __sanitizer_set_death_callback(saveCurrent); // ASan and UBSan reports end the process here
#endif
    std::thread(watchdog).detach();

    for (const Bytes& input : pool)
        runOne(input);
    if (seconds <= 0 || (argc == 2 && files == 1)) {
        std::printf("replayed %zu inputs\n", pool.size());
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
    std::printf("%llu inputs in %.0f s, no failure\n", static_cast<unsigned long long>(runs), seconds);
    return 0;
}
