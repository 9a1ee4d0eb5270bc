// Throughput of the embedded language model: (command, utterance) pairs scored
// per second with the literal-listener prompt (12 mDKG few-shot examples) and
// the VirtualHome prompt, after the one-off training of each few-shot block.
#include <benchmark/benchmark.h>

#include <string>
#include <vector>

#include "lm/embedded_model.hpp"

namespace {

using clips::lm::EmbeddedLanguageModel;
using clips::lm::ScoreRequest;

// The literal-listener few-shot block (clips-spec 7.7 order 9, 12, 2, 11, 6, 5, 3, 8, 10, 1, 7, 4).
const char* kDkgBlock =
    "Input: (unlock you key1 door1) (unlock you key2 door2) where (iscolor door1 green) (iscolor door2 yellow)\n"
    "Output: Help me unlock the green and yellow doors.\n"
    "Input: (unlock you key1 door1) (unlock you key2 door2) (unlock you key3 door3)\n"
    "Output: Could you unlock these three doors for me?\n"
    "Input: (handover you me key1)\nOutput: Can you hand me that key?\n"
    "Input: (handover you me key1) (handover you me key2) where (iscolor key1 red) (iscolor key2 red)\n"
    "Output: Can you pass me two red keys?\n"
    "Input: (unlock you key1 door1) where (iscolor door1 blue)\nOutput: Can you open the blue door?\n"
    "Input: (handover you me key1) where (iscolor key1 blue)\nOutput: Could you pass me the blue key?\n"
    "Input: (unlock you key1 door1)\nOutput: Unlock this door for me please.\n"
    "Input: (handover you me key1) (handover you me key2) where (iscolor key1 green) (iscolor key2 red)\n"
    "Output: Hand me the green and red keys.\n"
    "Input: (pickup you key1) (pickup you key2) where (iscolor key1 green) (iscolor key2 green)\n"
    "Output: Can you go and get the green keys?\n"
    "Input: (pickup you key1)\nOutput: Get the key over there.\n"
    "Input: (unlock you key1 door1) (handover you me key2)\nOutput: Would you unlock the door and bring me that key?\n"
    "Input: (pickup you key1) where (iscolor key1 yellow)\nOutput: Please pick up the yellow key.";

std::vector<ScoreRequest> dkg_requests() {
  const std::vector<std::string> commands = {
      "(handover you me key1) where (iscolor key1 red)",
      "(pickup you key1) where (iscolor key1 blue)",
      "(unlock you key1 door1) where (iscolor door1 yellow)",
      "(handover you me key1) (handover you me key2) where (iscolor key1 red) (iscolor key2 red)",
      "(unlock you key1 door1) (handover you me key2) where (iscolor door1 blue) (iscolor key2 red)",
      "(pickup you key1) (handover you me key2) (handover you me key3) where (iscolor key1 blue) "
      "(iscolor key2 yellow) (iscolor key3 yellow)",
  };
  const std::vector<std::string> utterances = {
      " Could you grab me the red key?\n", " Can you open the yellow door for me please?\n",
      " I'll get the blue key, can you pick up the red one?\n", " Pass me both red keys.\n"};
  std::vector<ScoreRequest> out;
  for (const auto& c : commands) {
    for (const auto& u : utterances) {
      out.push_back({std::string(kDkgBlock) + "\nInput: " + c + "\nOutput:", u});
    }
  }
  return out;
}

void BM_EmbeddedScoreDkg(benchmark::State& state) {
  static EmbeddedLanguageModel model;
  const auto batch = dkg_requests();
  model.score(batch);  // train the few-shot block outside the timed loop
  for (auto _ : state) {
    benchmark::DoNotOptimize(model.score(batch));
  }
  state.counters["pairs/s"] =
      benchmark::Counter(static_cast<double>(state.iterations() * batch.size()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_EmbeddedScoreDkg)->Unit(benchmark::kMicrosecond);

void BM_EmbeddedScoreVirtualHome(benchmark::State& state) {
  static EmbeddedLanguageModel model;
  const std::string block =
      "Input: (grab you cutleryfork1) (grab you cutleryknife1)\nOutput: Can you get me a fork and knife?\n"
      "Input: (grab you plate1) (grab you plate2)\nOutput: Go find two plates.";
  std::vector<ScoreRequest> batch;
  for (const char* c : {"(grab you plate1)", "(grab you plate1) (grab you plate2) (grab you bowl1)",
                        "(grab you cutleryfork1) (grab you cutleryknife1) (grab you plate1) (grab you bowl1)",
                        "(grab you wine1) (grab you wineglass1)"}) {
    for (const char* u : {" Could you bring two plates and a bowl?\n", " We need a fork.\n",
                          " Grab the wine and a glass, please.\n"}) {
      batch.push_back({block + "\nInput: " + c + "\nOutput:", u});
    }
  }
  model.score(batch);
  for (auto _ : state) {
    benchmark::DoNotOptimize(model.score(batch));
  }
  state.counters["pairs/s"] =
      benchmark::Counter(static_cast<double>(state.iterations() * batch.size()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_EmbeddedScoreVirtualHome)->Unit(benchmark::kMicrosecond);

void BM_EmbeddedTrainBlock(benchmark::State& state) {
  for (auto _ : state) {
    EmbeddedLanguageModel model;
    benchmark::DoNotOptimize(model.score({{std::string(kDkgBlock) + "\nInput: (pickup you key1)\nOutput:", " Go.\n"}}));
  }
}
BENCHMARK(BM_EmbeddedTrainBlock)->Unit(benchmark::kMillisecond)->Iterations(3);

}  // namespace
