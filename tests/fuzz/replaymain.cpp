// replaymain: drives a fuzz target without libFuzzer, for CTest and for compilers without it.
//
// Usage: fuzz_X [--corpus DIR]... [--iterations N] [--seed S] [--max-seconds T] [--max-len B]
//               [--save-iteration K FILE] [FILE]...
//  - every FILE and every file of each corpus folder is run once, as is;
//  - then N inputs are generated from them by a small mutator seeded with S, so a run is
//    reproducible: the same binary with the same arguments tries the same inputs in order;
//  - generation stops early after T seconds, so a slow machine or a sanitizer build stays bounded;
//  - --save-iteration writes generated input K to FILE and runs nothing (to keep a repro).
// A crash, a sanitizer report or a violated FUZZ_CHECK ends the process abnormally, which CTest
// counts as a failure. The input being run is first written to fuzz-crash-<target>.bin in the
// working folder, ready to replay with `fuzz_X fuzz-crash-<target>.bin` or under libFuzzer.
#include "fuzzcheck.h"

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <random>
#include <string>
#include <unistd.h>
#include <vector>

#if defined(__SANITIZE_ADDRESS__)
#define TIPSCOPE_SANITIZED 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define TIPSCOPE_SANITIZED 1
#endif
#endif
#ifdef TIPSCOPE_SANITIZED
#include <sanitizer/common_interface_defs.h>
#endif

namespace {

using Bytes = std::vector<std::uint8_t>;

// The input being run and where to save it; plain globals because a signal handler reads them.
const Bytes *g_current = nullptr;
char g_crashPath[512] = "fuzz-crash.bin";

void saveCurrentInput() {
    if (!g_current)
        return;
    const int fd = ::open(g_crashPath, O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd < 0)
        return;
    const ssize_t written = ::write(fd, g_current->data(), g_current->size());
    ::close(fd);
    const char note[] = "fuzz: the failing input was saved to ";
    if (written >= 0 && ::write(STDERR_FILENO, note, sizeof note - 1) > 0 &&
        ::write(STDERR_FILENO, g_crashPath, std::strlen(g_crashPath)) > 0)
        (void)!::write(STDERR_FILENO, "\n", 1);
}

void onFatalSignal(int sig) {
    saveCurrentInput();
    std::signal(sig, SIG_DFL);
    std::raise(sig);
}

struct Options {
    std::vector<std::string> corpusDirs;
    std::vector<std::string> files;
    long iterations = 5000;
    std::uint64_t seed = 1;
    double maxSeconds = 20;
    std::size_t maxLen = 8192;
    long saveIteration = -1;
    std::string savePath;
};

bool readFile(const std::filesystem::path &path, Bytes *out) {
    std::ifstream in(path, std::ios::binary);
    if (!in)
        return false;
    out->assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    return true;
}

bool parseOptions(int argc, char **argv, Options *o) {
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        const bool hasValue = i + 1 < argc;
        if (a == "--corpus" && hasValue)
            o->corpusDirs.push_back(argv[++i]);
        else if (a == "--iterations" && hasValue)
            o->iterations = std::stol(argv[++i]);
        else if (a == "--seed" && hasValue)
            o->seed = std::stoull(argv[++i]);
        else if (a == "--max-seconds" && hasValue)
            o->maxSeconds = std::stod(argv[++i]);
        else if (a == "--max-len" && hasValue)
            o->maxLen = std::stoul(argv[++i]);
        else if (a == "--save-iteration" && i + 2 < argc) {
            o->saveIteration = std::stol(argv[++i]);
            o->savePath = argv[++i];
        } else if (a.rfind("--", 0) == 0)
            return false;
        else
            o->files.push_back(a);
    }
    return true;
}

// Bytes that matter to the formats under test: frame delimiters, digits, signs, JSON syntax,
// hex prefixes and the start of a multi-byte UTF-8 sequence.
const std::uint8_t kInteresting[] = {0x02, 0x03, 0x00, 0xff, 0x7f, 0x80, 0xc3, '0', '9', '-',
                                     '.',  ' ',  '"',  '{',  '}',  '[',  ':',  ',', 'x', 'A'};

class Mutator {
public:
    Mutator(std::uint64_t seed, const std::vector<Bytes> &corpus, std::size_t maxLen)
        : m_rng(seed)
        , m_corpus(corpus)
        , m_maxLen(maxLen) {}

    Bytes next() {
        Bytes b;
        if (m_corpus.empty() || below(16) == 0) {
            b.resize(below(65));
            for (auto &c : b)
                c = std::uint8_t(m_rng());
            return b;
        }
        b = pick();
        for (std::size_t n = 1 + below(4); n > 0; --n)
            mutate(b);
        if (b.size() > m_maxLen)
            b.resize(m_maxLen);
        return b;
    }

private:
    std::size_t below(std::size_t n) { return n == 0 ? 0 : std::size_t(m_rng() % n); }
    const Bytes &pick() { return m_corpus[below(m_corpus.size())]; }
    std::uint8_t interesting() { return kInteresting[below(sizeof kInteresting)]; }

    void mutate(Bytes &b) {
        const std::size_t pos = below(b.size() + 1);
        const std::size_t len = 1 + below(std::min<std::size_t>(16, b.size() - pos + 1));
        const auto at = b.begin() + std::ptrdiff_t(pos);
        switch (below(11)) {
        case 0: // flip one bit
            if (pos < b.size())
                b[pos] ^= std::uint8_t(1u << below(8));
            break;
        case 1:
            if (pos < b.size())
                b[pos] = std::uint8_t(m_rng());
            break;
        case 2:
            if (pos < b.size())
                b[pos] = interesting();
            break;
        case 3:
            b.insert(at, interesting());
            break;
        case 4: // erase a range
            b.erase(at, at + std::ptrdiff_t(std::min(len, b.size() - pos)));
            break;
        case 5: { // repeat a range
            const Bytes part(at, at + std::ptrdiff_t(std::min(len, b.size() - pos)));
            b.insert(b.begin() + std::ptrdiff_t(below(b.size() + 1)), part.begin(), part.end());
            break;
        }
        case 6: { // this input's head, another one's tail
            const Bytes &o = pick();
            b.resize(pos);
            const std::size_t from = below(o.size() + 1);
            b.insert(b.end(), o.begin() + std::ptrdiff_t(from), o.end());
            break;
        }
        case 7: // cut short
            b.resize(pos);
            break;
        case 8: { // another input inserted whole: frames back to back, nested documents
            const Bytes &o = pick();
            b.insert(at, o.begin(), o.end());
            break;
        }
        case 9: // a digit changed: values just inside and outside their ranges
            if (pos < b.size() && b[pos] >= '0' && b[pos] <= '9')
                b[pos] = std::uint8_t('0' + below(10));
            break;
        default:
            if (pos + 1 < b.size())
                std::swap(b[pos], b[pos + 1]);
            break;
        }
    }

    std::mt19937_64 m_rng;
    const std::vector<Bytes> &m_corpus;
    std::size_t m_maxLen;
};

void run(const Bytes &input) {
    g_current = &input;
    LLVMFuzzerTestOneInput(input.data(), input.size());
    g_current = nullptr;
}

} // namespace

int main(int argc, char **argv) {
    Options o;
    if (!parseOptions(argc, argv, &o)) {
        std::cerr << "usage: " << argv[0]
                  << " [--corpus DIR]... [--iterations N] [--seed S] [--max-seconds T]"
                     " [--max-len B] [--save-iteration K FILE] [FILE]...\n";
        return 2;
    }
    const std::string target = std::filesystem::path(argv[0]).filename().string();
    std::snprintf(g_crashPath, sizeof g_crashPath, "fuzz-crash-%s.bin", target.c_str());
    for (int sig : {SIGABRT, SIGSEGV, SIGBUS, SIGFPE, SIGILL})
        std::signal(sig, onFatalSignal);
#ifdef TIPSCOPE_SANITIZED
    __sanitizer_set_death_callback(saveCurrentInput);
#endif

    std::vector<Bytes> corpus;
    std::vector<std::filesystem::path> paths(o.files.begin(), o.files.end());
    for (const std::string &dir : o.corpusDirs) {
        std::vector<std::filesystem::path> inDir;
        for (const auto &entry : std::filesystem::directory_iterator(dir))
            if (entry.is_regular_file())
                inDir.push_back(entry.path());
        std::sort(inDir.begin(), inDir.end()); // the same order on every file system
        paths.insert(paths.end(), inDir.begin(), inDir.end());
    }
    for (const auto &p : paths) {
        Bytes b;
        if (!readFile(p, &b)) {
            std::cerr << target << ": cannot read " << p << '\n';
            return 2;
        }
        corpus.push_back(std::move(b));
    }

    Mutator mutator(o.seed, corpus, o.maxLen);
    if (o.saveIteration >= 0) {
        Bytes b;
        for (long i = 0; i <= o.saveIteration; ++i)
            b = mutator.next();
        std::ofstream(o.savePath, std::ios::binary)
            .write(reinterpret_cast<const char *>(b.data()), std::streamsize(b.size()));
        return 0;
    }

    for (const Bytes &b : corpus)
        run(b);
    const auto start = std::chrono::steady_clock::now();
    long done = 0;
    double seconds = 0;
    for (; done < o.iterations && seconds < o.maxSeconds; ++done) {
        run(mutator.next());
        if (done % 64 == 0)
            seconds =
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }
    seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::cout << target << ": " << corpus.size() << " seed inputs and " << done
              << " generated inputs (seed " << o.seed << ") in " << seconds << " s, no failure\n";
    return 0;
}
