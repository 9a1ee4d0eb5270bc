#pragma once
// One (command, utterance) example the embedded model trains on.
#include <string>

namespace clips::lm {

struct TrainingPair {
  std::string command;
  std::string utterance;
  double weight = 1.0;
  std::string origin;  // "file:line" or "prompt example N", for error messages
};

}  // namespace clips::lm
