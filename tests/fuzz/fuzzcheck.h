// The contract between a fuzz target and whatever drives it.
//
// Each target defines LLVMFuzzerTestOneInput() and nothing else, so the same source builds two
// ways: with clang and -fsanitize=fuzzer, libFuzzer drives it (scripts/fuzz); with any compiler,
// replaymain.cpp drives it from the committed seed corpus plus a fixed-seed generator, so CTest
// runs it with gcc too. A target states what must hold for every input with FUZZ_CHECK: a
// violated property aborts, which both drivers report as a failure with the input that caused it
// (libFuzzer writes crash-*, the replay driver fuzz-crash-*.bin).
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size);

namespace tipscope::fuzz {

[[noreturn]] inline void checkFailed(const char *condition, const char *file, int line) {
    std::fprintf(stderr, "fuzz: property violated at %s:%d: %s\n", file, line, condition);
    std::abort();
}

} // namespace tipscope::fuzz

#define FUZZ_CHECK(condition)                                                                      \
    do {                                                                                           \
        if (!(condition))                                                                          \
            ::tipscope::fuzz::checkFailed(#condition, __FILE__, __LINE__);                         \
    } while (false)
