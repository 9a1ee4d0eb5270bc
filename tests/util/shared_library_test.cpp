// Libraries opened when first used: what is found, and the errors a missing
// library or function gives.
#include "util/shared_library.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstring>

namespace clips::util {
namespace {

using ::testing::AllOf;
using ::testing::HasSubstr;

TEST(SharedLibrary, TheFirstCandidateThatLoadsServes) {
  SharedLibrary libc({"libclips-no-such-library.so.7", "libc.so.6"}, "");
  EXPECT_EQ(libc.path(), "libc.so.6");
  const auto length = libc.function<size_t (*)(const char*)>("strlen");
  EXPECT_EQ(length("four"), 4u);
}

TEST(SharedLibrary, AMissingLibraryNamesEveryCandidateAndTheRemedy) {
  try {
    SharedLibrary lib({"libclips-no-such-library.so.7", "/nowhere/libclips-other.so"}, "install clips-test-package");
    FAIL() << "loaded " << lib.path();
  } catch (const SharedLibraryError& e) {
    EXPECT_THAT(e.what(), AllOf(HasSubstr("libclips-no-such-library.so.7"), HasSubstr("/nowhere/libclips-other.so"),
                                HasSubstr("install clips-test-package")));
  }
}

TEST(SharedLibrary, AMissingFunctionIsNamed) {
  SharedLibrary libc({"libc.so.6"}, "");
  try {
    libc.function<void (*)()>("clips_no_such_function");
    FAIL();
  } catch (const SharedLibraryError& e) {
    EXPECT_THAT(e.what(), AllOf(HasSubstr("libc.so.6"), HasSubstr("clips_no_such_function")));
  }
}

TEST(SharedLibrary, TheExecutablesFolderIsKnown) {
  const std::string dir = executable_dir();
  ASSERT_FALSE(dir.empty());
  EXPECT_EQ(dir.front(), '/');
}

}  // namespace
}  // namespace clips::util
