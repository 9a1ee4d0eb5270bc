#pragma once
// The includes, helpers and fixtures of the commands tests in fewshot_test.cpp, shared by
// the files of that name in tests/commands/ and its label folders
// (docs/testing.md, "Labels").
// Few-shot examples, prompt orders and prompt strings (spec 7.7-7.9, VH spec 10).
#include <gtest/gtest.h>

#include <filesystem>

#include "paper_languages.hpp"
#include "commands/fixtures.hpp"
#include "commands/enumerate.hpp"
#include "commands/fewshot.hpp"
#include "util/error.hpp"

namespace clips::commands {
namespace fewshot_test {

const std::string kTsv = CLIPS_SOURCE_DIR "/data/language/fewshot-examples.tsv";
const std::string kOrders = CLIPS_SOURCE_DIR "/data/language/prompt-orders.json";

std::vector<int> indices(const std::vector<FewShotExample>& examples) {
  std::vector<int> out;
  for (const auto& ex : examples) out.push_back(ex.index);
  return out;
}

std::string tsv_error(const std::string& body) {
  try {
    parse_fewshot_examples("domain\tindex\tcommand\tutterance\tin_literal_prompt\n" + body, "ex.tsv");
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace fewshot_test
using namespace fewshot_test;
}  // namespace clips::commands
