#pragma once
// One fuzz target = one function `int clips_fuzz_<name>(const uint8_t*, size_t)`.
// The libFuzzer build (CLIPS_FUZZ=ON) compiles each target file on its own
// with CLIPS_LIBFUZZER defined, which adds libFuzzer's entry point calling it;
// the normal build links all of them into test_fuzz, which replays the seed
// corpora and the regression inputs through the very same functions.
//
// A target returns normally for input the code rejects with its documented
// error (InputError, LmError); any other exception, crash, sanitizer report,
// leak or slow input is a finding.
#include <cstddef>
#include <cstdint>
#include <string>

#define CLIPS_FUZZ_DECLARE(name) int clips_fuzz_##name(const uint8_t* data, size_t size)

#ifdef CLIPS_LIBFUZZER
#define CLIPS_FUZZ_TARGET(name)                                                     \
  CLIPS_FUZZ_DECLARE(name);                                                         \
  extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {         \
    return clips_fuzz_##name(data, size);                                           \
  }                                                                                 \
  CLIPS_FUZZ_DECLARE(name)
#else
#define CLIPS_FUZZ_TARGET(name) CLIPS_FUZZ_DECLARE(name)
#endif

namespace clips::fuzz {

inline std::string as_text(const uint8_t* data, size_t size) {
  return std::string(reinterpret_cast<const char*>(data), size);
}

}  // namespace clips::fuzz
