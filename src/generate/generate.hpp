#pragma once
// `clips generate`: a dataset of random problems and plans whose true goals
// are known, in the layout Dataset::load reads.
//
// Problems come from the domain's pack (Pack::generate_problem); every
// candidate goal must be reachable from the start by optimal A* with the
// pack's admissible heuristic, else the problem is drawn again. For each plan:
//   1. a goal uniformly among the candidates, and a plan tag uniformly among
//      the pack's tags that have an assistance option in the problem (mDKG:
//      keys, and doors when there are doors); the tag's true cost profile;
//   2. the observed length k, uniform in 0..2m (m: the principal's moves
//      before the first salient action on the policy's greedy joint plan);
//      for those k steps the assistant does its no-op, as in the paper's
//      observed plans (it is passive until the instruction);
//   3. the joint action sequence from the human model's own policy (RTAA*
//      values refined at every state, as inference does), each action of
//      the agent whose turn it is drawn from Boltzmann(Q / T), until the goal
//      holds; a sequence that reaches a second candidate goal, or none within
//      the step cap, is drawn again, and so (a bounded number of times) is
//      one in which the assistant takes no assistance option of the tag. The
//      first k actions are the observed plan, the rest the completed plan;
//   4. an utterance step u, uniform in 0..k: the command is drawn uniformly
//      from those the CLIPS speaker model enumerates at s_u (utterance_model:
//      greedy rollout of the policy, salient actions, lifted commands, paper
//      speaker rule), and its text from language::UtteranceSampler. The
//      literal utterance phrases only the part addressed to the assistant.
//      The speaker's policy is the one inference holds when it hears the
//      instruction (refined along s_0 .. s_u only, with the same budget), so
//      the instruction is a draw from the model inference assumes; with
//      partial lookahead searches a policy that had learned from the rest of
//      the sequence could ask for things the observer's model never would.
// Every draw comes from util::Rng streams derived from the seed and the
// problem and plan numbers, and the files hold no time or path, so the same
// options give byte-identical files.
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "domains/pack.hpp"
#include "language/listener.hpp"
#include "lm/language_model.hpp"

namespace clips::generate {

struct GenerateOptions {
  std::string domain_file;          // the PDDL domain (copied into the dataset)
  domains::GenerateParams map;      // size and object counts; problem_name is set per problem
  int problems = 1;
  int plans_per_problem = 2;
  uint64_t seed = 0;
  // Boltzmann temperature of the sampled actions; nullopt: one per plan from
  // the pack's temperature prior (the model's own, often very noisy).
  std::optional<double> temperature = 0.5;
  int max_steps = 0;                // longest plan; 0: the pack's horizon
  int problem_attempts = 200;       // draws per problem before giving up
  int plan_attempts = 20;           // trajectories per plan before giving up
  size_t solvable_nodes = size_t{1} << 20;  // A* budget of each solvability check
  // Expansions per lookahead search of the simulated human's refinements;
  // give inference the same (--max-nodes) for a dataset drawn from its model.
  size_t refine_nodes = size_t{1} << 18;
  std::string lm = "embedded";
  language::LanguageModelOptions lm_options;
};

struct GeneratedPlan {
  std::string id, problem_id, goal, tag;
  double temperature = 0;
  int observed_steps = 0, completed_steps = 0, utterance_step = 0;
  std::string command, utterance;          // "" command: the speaker had nothing to ask
  std::string literal_command, literal_utterance;
  std::vector<std::string> options;        // the assistant's options in the completion
};

struct GeneratedDataset {
  std::map<std::string, std::string> files;  // relative path -> content
  std::vector<GeneratedPlan> plans;
};

// Builds the dataset in memory. `lm` null: the model GenerateOptions::lm
// names, for the pack's domain. Throws InputError for parameters the pack
// rejects or when no solvable problem or plan turns up within the attempts.
GeneratedDataset generate_dataset(const GenerateOptions& options, lm::LanguageModel* lm = nullptr);

// Writes the files under `dir`. An existing non-empty `dir` is refused
// unless `force`, which first removes the folders a dataset has there
// (problems/, plans/, utterances/) so no stale plan is left behind.
void write_dataset(const GeneratedDataset& dataset, const std::string& dir, bool force);

}  // namespace clips::generate
