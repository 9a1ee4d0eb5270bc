// clips: Cooperative Language-Guided Inverse Plan Search, command line.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>

#include "app/cli.hpp"
#include "util/error.hpp"

namespace clips::app {
int g_exit_code = 0;
std::string default_dataset_hint() {
  return "a dataset directory such as ../shared/dataset/doors-keys-gems (containing domain.pddl)";
}

namespace {

bool all_digits(const std::string& s) {
  size_t i = !s.empty() && s[0] == '+' ? 1 : 0;
  if (i == s.size()) return false;
  for (; i < s.size(); ++i)
    if (s[i] < '0' || s[i] > '9') return false;
  return true;
}

}  // namespace

const CLI::Validator PositiveInteger(
    [](std::string& in) -> std::string {
      if (all_digits(in) && in.find_first_not_of("+0") != std::string::npos) return {};
      return in + " is not a positive integer";
    },
    "POSITIVE");
const CLI::Validator NonNegativeInteger(
    [](std::string& in) -> std::string {
      if (all_digits(in)) return {};
      return in + " is not a non-negative integer";
    },
    "NONNEGATIVE");
const CLI::Validator PositiveSeconds(
    [](std::string& in) -> std::string {
      char* end = nullptr;
      const double v = std::strtod(in.c_str(), &end);
      if (!in.empty() && end == in.c_str() + in.size() && std::isfinite(v) && v > 0) return {};
      return in + " is not a positive number of seconds";
    },
    "SECONDS>0");
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
  clips::app::register_serve(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // `clips foo`: CLI11 leaves "foo" unparsed and only reports that a
    // subcommand is required; name it and the valid ones instead.
    if (app.get_subcommands().empty() && !app.remaining().empty() && dynamic_cast<const CLI::RequiredError*>(&e)) {
      std::string names;
      for (const CLI::App* sub : app.get_subcommands({})) names += (names.empty() ? "" : ", ") + sub->get_name();
      std::fprintf(stderr, "clips: unknown subcommand '%s'; valid subcommands: %s\nRun with --help for more information.\n",
                   app.remaining().front().c_str(), names.c_str());
      return static_cast<int>(CLI::ExitCodes::RequiredError);
    }
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
