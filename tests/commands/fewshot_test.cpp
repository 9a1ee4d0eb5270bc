#include "commands/fewshot_test.hpp"

namespace clips::commands {
namespace fewshot_test {
TEST(FewShotFile, ShippedExamplesMatchTheReferenceLists) {
  const auto examples = load_fewshot_examples(kTsv);
  ASSERT_EQ(examples.size(), 30u);
  EXPECT_EQ(examples[17].command,
            "(handover you me key1) (handover you me key2) (pickup me ?gem1) where (iscolor key1 red) "
            "(iscolor key2 red) (iscolor gem1 green)");  // the literal ?gem1 is kept
  EXPECT_EQ(examples[17].utterance, "Pass me the red keys, I'm going for the green gem.");
  EXPECT_TRUE(examples[11].in_literal_prompt);
  EXPECT_FALSE(examples[12].in_literal_prompt);
  EXPECT_EQ(examples[18].domain, "virtual-home");
  EXPECT_EQ(examples[18].command, "(grab you plate1)");
}

TEST(FewShotFile, ShippedPromptOrders) {
  const auto orders = load_prompt_orders(kOrders);
  ASSERT_EQ(orders.size(), 2u);
  const auto& dkg = orders.at("doors-keys-gems");
  EXPECT_EQ(dkg.pragmatic, (std::vector<int>{14, 13, 15, 7, 10, 3, 2, 16, 5, 12, 6, 8, 9, 4, 18, 11, 17, 1}));
  EXPECT_EQ(dkg.literal, (std::vector<int>{9, 12, 2, 11, 6, 5, 3, 8, 10, 1, 7, 4}));
  const auto& vh = orders.at("virtual-home");
  EXPECT_EQ(vh.pragmatic, (std::vector<int>{5, 7, 2, 9, 4, 8, 11, 12, 6, 10, 3, 1}));
  EXPECT_EQ(vh.literal, vh.pragmatic);

  const auto examples = load_fewshot_examples(kTsv);
  const auto literal = order_examples(examples, "doors-keys-gems", dkg.literal);
  EXPECT_EQ(indices(literal), dkg.literal);
  for (const auto& ex : literal) EXPECT_TRUE(ex.in_literal_prompt);
  EXPECT_THROW(order_examples(examples, "virtual-home", {13}), InputError);
}

TEST(Prompt, SmallCaseByteForByte) {
  const auto examples = parse_fewshot_examples(
      "domain\tindex\tcommand\tutterance\tin_literal_prompt\n"
      "d\t1\t(pickup you key1)\tGet the key over there.\tyes\n"
      "d\t2\t(handover you me key1)\tCan you hand me that key?\tyes\n",
      "inline.tsv");
  const auto ordered = order_examples(examples, "d", {2, 1});
  EXPECT_EQ(build_prompt(ordered, "(unlock you key1 door1) where (iscolor door1 red)"),
            "Input: (handover you me key1)\nOutput: Can you hand me that key?\n"
            "Input: (pickup you key1)\nOutput: Get the key over there.\n"
            "Input: (unlock you key1 door1) where (iscolor door1 red)\nOutput:");
}

TEST(Prompt, PragmaticDkgPromptStartsWithExample14AndEndsWithTheQuery) {
  const auto examples = load_fewshot_examples(kTsv);
  const auto ordered =
      order_examples(examples, "doors-keys-gems", load_prompt_orders(kOrders).at("doors-keys-gems").pragmatic);
  const std::string prompt = build_prompt(ordered, "(handover you me key1) where (iscolor key1 blue)");
  EXPECT_EQ(prompt.rfind("Input: (unlock you key1 door1) (pickup me key2) where (iscolor door1 green) "
                         "(iscolor key2 blue)\nOutput: I'm getting the blue key, can you open the green door?\n"
                         "Input: (pickup me key1) (pickup you key2)",
                         0),
            0u);
  const std::string tail =
      "Input: (pickup you key1)\nOutput: Get the key over there.\n"
      "Input: (handover you me key1) where (iscolor key1 blue)\nOutput:";
  ASSERT_GE(prompt.size(), tail.size());
  EXPECT_EQ(prompt.substr(prompt.size() - tail.size()), tail);
  EXPECT_EQ(std::count(prompt.begin(), prompt.end(), '\n'), 2 * 18 + 1);
}

TEST(Prompt, VirtualHomePromptForAnEnumeratedCommand) {
  const auto config = virtual_home_language();
  const auto commands = enumerate_commands(
      testing::salient_of("(grab helper cutleryfork1 cabinet4) (grab helper cutleryknife1 cabinet4)",
                          "(itemtype cutleryfork1 cutleryfork) (itemtype cutleryknife1 cutleryknife)", config),
      config, testing::vh_type_of);
  const auto examples = order_examples(load_fewshot_examples(kTsv), "virtual-home",
                                       load_prompt_orders(kOrders).at("virtual-home").pragmatic);
  const auto prompts = command_prompts(commands, examples);
  ASSERT_EQ(prompts.size(), 3u);
  EXPECT_DOUBLE_EQ(prompts[2].weight, 1.0 / 3.0);
  const std::string& p = prompts[2].prompt;
  EXPECT_EQ(p.rfind("Input: (grab you cutleryfork1) (grab you cutleryknife1)\nOutput: Can you get me a fork and knife?\n"
                    "Input: (grab you carrot1) (grab you onion1)\nOutput: Hand me the veggies.\n",
                    0),
            0u);
  const std::string tail =
      "Input: (grab you plate1)\nOutput: Can you get a plate?\n"
      "Input: (grab you cutleryfork1) (grab you cutleryknife1)\nOutput:";
  EXPECT_EQ(p.substr(p.size() - tail.size()), tail);
}

TEST(Prompt, NoCommandMeansTheNewlinePrompt) {
  const auto prompts = command_prompts({}, {});
  ASSERT_EQ(prompts.size(), 1u);
  EXPECT_EQ(prompts[0].prompt, "\n");
  EXPECT_EQ(prompts[0].weight, 1.0);
}

TEST(Prompt, ContinuationHasOneLeadingSpaceAndTheStopNewline) {
  EXPECT_EQ(utterance_continuation("Can you pass me the red key?"), " Can you pass me the red key?\n");
  EXPECT_EQ(utterance_continuation(" Can you pass me the red key?"), " Can you pass me the red key?\n");
}

TEST(FewShotFile, BadRowsNameFileAndLine) {
  EXPECT_EQ(tsv_error("d\t1\t(a)\tA.\tyes\nd\t2\t(b)\tB.\n"), "ex.tsv:3: expected 5 tab-separated fields, found 4");
  EXPECT_EQ(tsv_error("d\tone\t(a)\tA.\tyes\n"), "ex.tsv:2: index 'one' is not a positive integer");
  EXPECT_EQ(tsv_error("d\t0\t(a)\tA.\tyes\n"), "ex.tsv:2: index '0' is not a positive integer");
  EXPECT_EQ(tsv_error("d\t1\t(a)\tA.\tmaybe\n"), "ex.tsv:2: in_literal_prompt must be 'yes' or 'no', found 'maybe'");
  EXPECT_EQ(tsv_error("d\t1\t(a)\tA.\tyes\nd\t1\t(b)\tB.\tno\n"), "ex.tsv:3: duplicate example d #1");
  EXPECT_EQ(tsv_error("d\t1\t\tA.\tyes\n"), "ex.tsv:2: empty command");
  EXPECT_EQ(tsv_error("d\t1\t(a)\t\tyes\n"), "ex.tsv:2: empty utterance");
  EXPECT_EQ(tsv_error("d\t1\t(a)\tA.\tyes\r\n\n"), "no error");  // CRLF and a blank last line are fine

  try {
    parse_fewshot_examples("domain,index,command,utterance,in_literal_prompt\n", "ex.tsv");
    FAIL() << "expected an error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("ex.tsv:1: expected the header", 0), 0u);
  }
  EXPECT_THROW(load_fewshot_examples("/nonexistent/examples.tsv"), InputError);
}

TEST(FewShotFile, BadPromptOrders) {
  EXPECT_THROW(parse_prompt_orders(R"({"d": {"pragmatic": [1, 1], "literal": [1]}})", "o.json"), InputError);
  EXPECT_THROW(parse_prompt_orders(R"({"d": {"pragmatic": [1]}})", "o.json"), InputError);
  EXPECT_THROW(parse_prompt_orders(R"([1, 2])", "o.json"), InputError);
}

}  // namespace fewshot_test

}  // namespace clips::commands
