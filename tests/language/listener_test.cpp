#include "language/listener_test.hpp"

namespace clips::language {
namespace listener_test {
TEST(LanguageModelFactory, UnknownKindIsAnInputError) {
  try {
    make_language_model("gpt-17");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("gpt-17"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("embedded"), std::string::npos);
  }
}

TEST(LanguageModelFactory, WrapsBackendsInACache) {
  LanguageModelOptions o;
  o.base_url = "http://127.0.0.1:9/v1";  // never contacted: construction only
  o.model = "test-model";
  o.api_key = "";
  EXPECT_EQ(make_language_model("openai", o)->name(), "cached(openai:test-model)");
  EXPECT_EQ(make_language_model("")->name(), "cached(embedded)");
}

TEST(ListenerSetup, UnknownDomain) { EXPECT_THROW(literal_listener_setup("sokoban"), InputError); }

}  // namespace listener_test

}  // namespace clips::language
