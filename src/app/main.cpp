// clips: Cooperative Language-Guided Inverse Plan Search, command line.
#include <cstdio>
#include <exception>

#include "app/cli.hpp"
#include "util/error.hpp"

namespace clips::app {
int g_exit_code = 0;
std::string default_dataset_hint() {
  return "a dataset directory such as ../shared/dataset/doors-keys-gems (containing domain.pddl)";
}
}  // namespace clips::app

int main(int argc, char** argv) {
  CLI::App app{"clips: infer a human's goal from their actions and instructions, and help them reach it.\n"
               "Implements Cooperative Language-Guided Inverse Plan Search (Zhi-Xuan et al., AAMAS 2024)."};
  app.require_subcommand(1);
  app.set_help_all_flag("--help-all", "Print help for every subcommand");
  clips::app::register_validate(app);
  clips::app::register_show(app);
  clips::app::register_plan(app);
  clips::app::register_assist(app);
  clips::app::register_bench(app);
  clips::app::register_infer(app);
  clips::app::register_listen(app);
  clips::app::register_lm_score(app);
  clips::app::register_export_strips(app);
  clips::app::register_render(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  } catch (const clips::InputError& e) {
    std::fprintf(stderr, "clips: error: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "clips: error: %s\n", e.what());
    return 2;
  }
  return clips::app::g_exit_code;
}
