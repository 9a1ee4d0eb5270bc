#pragma once
// Combining the literal listener's readings of several utterances of one plan
//: each probable command of the next utterance is merged with
// each kept combination; probabilities multiply and scores add.
#include <vector>

#include "commands/command.hpp"

namespace clips::commands {

struct RankedCommand {
  Command command;
  double probability = 0.0;  // posterior of the command given the utterance(s)
  double score = 0.0;        // LLM score (summed over merged utterances)
};

// The shortest prefix of a list sorted by decreasing probability whose
// cumulative probability reaches `threshold` (the whole list if it never does).
std::vector<RankedCommand> probable_prefix(const std::vector<RankedCommand>& sorted, double threshold = 0.99);

// For each command of `next` (sorted, stopping after the prefix that reaches
// `threshold`) and each entry of `kept`, merge_commands(kept, next) with
// probability p_kept * p_next and score s_kept + s_next; the result is sorted
// by decreasing summed score (stable). Probabilities are not renormalised.
std::vector<RankedCommand> combine_utterance_rankings(const std::vector<RankedCommand>& kept,
                                                      const std::vector<RankedCommand>& next,
                                                      double threshold = 0.99);

}  // namespace clips::commands
