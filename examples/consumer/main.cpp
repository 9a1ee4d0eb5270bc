// Opens a session on a Doors-Keys-Gems example, observes the human's first
// moves and an instruction, and prints the goal posterior and the robot's
// next action. Usage: consumer <dataset dir> (e.g. data/examples/doors-keys-gems)
#include <clips/clips.hpp>

#include <cstdio>

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s DATASET_DIR\n", argv[0]);
    return 2;
  }
  try {
    std::printf("clips-assist %s, data in %s\n", clips::library_version().c_str(), clips::data_directory().c_str());
    clips::Session session = clips::Session::open_dataset(argv[1], "e1");
    session.observe("(left human)");
    session.observe("(wait robot)");
    session.hear("Can you get me the yellow key?");
    session.observe("(left human)");  // now the robot is to move
    const clips::Posterior p = session.posterior();
    for (size_t g = 0; g < p.goals.size(); ++g) std::printf("P(%s) = %.4f\n", p.goals[g].c_str(), p.goal_probabilities[g]);
    const clips::AssistDecision d = session.assist();
    std::printf("assistant: %s\n", d.action.c_str());
    return 0;
  } catch (const clips::InputError& e) {
    std::fprintf(stderr, "input error: %s\n", e.what());
    return 1;
  }
}
