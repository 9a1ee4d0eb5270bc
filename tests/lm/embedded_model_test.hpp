#pragma once
// The includes, helpers and fixtures of the lm tests in embedded_model_test.cpp, shared by
// the files of that name in tests/lm/ and its label folders
// (docs/testing.md, "Labels").
// EmbeddedLanguageModel: normalisation, determinism, prompt handling, errors.
#include <gtest/gtest.h>
#include <iomanip>
#include <map>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <thread>

#include "lm/alignment_model.hpp"
#include "lm/embedded_model.hpp"
#include "lm/utterance_tokens.hpp"
#include "lm/wordnet_lexicon.hpp"
#include "util/error.hpp"
#include "lm/embedded_prompts.hpp"

namespace clips::lm {
namespace embedded_model_test {

using testing::literal_prompt;
using testing::pragmatic_prompt;
using testing::vh_prompt;

EmbeddedLanguageModel& model() {
  static EmbeddedLanguageModel m;
  return m;
}

double score(const std::string& prompt, const std::string& utterance) {
  return model().score({{prompt, " " + utterance + "\n"}}).at(0);
}

// ---- the on-disk cache of trained models ----------------------------------------

std::filesystem::path fresh_dir(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / (name + "_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  return dir;
}

// The snapshot and cache tests check mechanics (bytes, files, hits), not the
// quality of the scores, so their models are trained small: one corpus file
// and a few EM iterations, a few percent of the default training's work.
EmbeddedModelOptions with_cache(const std::string& dir) {
  EmbeddedModelOptions o;
  o.corpus_files = {"corpus-vh.tsv"};
  o.em_iterations = 3;
  o.cache_dir = dir;
  return o;
}

// Commands and utterances scored by the snapshot tests (DKG and VH prompts,
// seen and unseen words, the empty-command prompt).
std::vector<ScoreRequest> probe_batch() {
  std::vector<ScoreRequest> batch;
  for (const char* c : {"(pickup you key1) where (iscolor key1 red)", "(unlock you key1 door1) where (iscolor door1 blue)",
                        "(handover you me key1) (handover you me key2) where (iscolor key1 red) (iscolor key2 red)"}) {
    for (const char* u : {" Could you grab the red key for me?\n", " Unlock the blue door.\n", " Fetch both keys pls\n",
                          " Bring me both red", " zyzzyva quux!\n"}) {
      batch.push_back({literal_prompt(c), u});
      batch.push_back({pragmatic_prompt(c), u});
    }
    batch.push_back({vh_prompt("(grab you mug1) (grab you plate1)"), " Get a mug and a plate.\n"});
  }
  batch.push_back({"\n", " Hello there.\n"});
  return batch;
}

}  // namespace embedded_model_test
using namespace embedded_model_test;
}  // namespace clips::lm

namespace clips::lm {
}  // namespace clips::lm
