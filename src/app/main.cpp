// clips: Cooperative Language-Guided Inverse Plan Search, command line.
#include <fmt/core.h>
#include <system_error>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <string>
#include <string_view>
#include <algorithm>

#include <new>

#include "app/cli.hpp"
#include "app/exit_codes.hpp"
#include "multimodal/multimodal.hpp"
#include "lm/http_client.hpp"
#include "lm/language_model.hpp"
#include "util/error.hpp"
#include "util/program_name.hpp"
#include "util/shared_library.hpp"
#include "util/version.hpp"

namespace clips::app {
int g_exit_code = 0;
std::string default_dataset_hint() {
  return "a dataset directory such as ../shared/dataset/doors-keys-gems (containing domain.pddl)";
}

void add_dataset_option(CLI::App* cmd, std::string& dir, const std::string& help) {
  cmd->add_option("--dataset", dir,
                  help + "; default $CLIPS_DATASET when it holds domain.pddl, and a name not found here is looked "
                         "up under $CLIPS_DATASET");
}

std::string dataset_dir(const std::string& given) {
  namespace fs = std::filesystem;
  const char* env = std::getenv("CLIPS_DATASET");
  const std::string root = env ? env : "";
  std::error_code ec;
  if (!given.empty()) {
    if (fs::exists(given, ec) || root.empty() || fs::path(given).is_absolute()) return given;
    const fs::path under = fs::path(root) / given;
    return fs::is_directory(under, ec) ? under.string() : given;
  }
  if (root.empty()) throw UsageError("--dataset is required (or set $CLIPS_DATASET to a dataset directory)");
  if (fs::exists(fs::path(root) / "domain.pddl", ec)) return root;
  std::string names;
  for (const auto& e : fs::directory_iterator(root, ec))
    if (fs::exists(e.path() / "domain.pddl", ec)) names += (names.empty() ? "" : ", ") + e.path().filename().string();
  throw UsageError("--dataset is required: $CLIPS_DATASET=" + root + " is not a dataset (no domain.pddl)" +
                   (names.empty() ? "" : "; it holds " + names + ": give e.g. --dataset " + names.substr(0, names.find(','))));
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

std::string exit_code_help() {
  return "Exit status:\n"
         "  0  success\n"
         "  1  ran to the end, but some items failed (validate: plans that do not check; bench: plans, or a method "
         "on some plan, that could not be evaluated)\n"
         "  2  usage error: unknown subcommand or option, missing or malformed value\n"
         "  3  input error: a file or field is unreadable or invalid (the message names it)\n"
         "  4  no plan exists: the search proved the goal unreachable\n"
         "  5  a time, node or step limit stopped the search before it found a plan\n"
         "  6  the language model or chat server failed (connection, HTTP status, malformed reply), or the server "
         "cannot score a given text (the start-up check)\n"
         "  7  out of memory\n"
         "  8  internal error (a bug; please report it with the command line)\n"
         "  9  serve: cannot listen (the port is in use, or the address cannot be bound)\n";
}

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
const CLI::Validator SeedValue(
    [](std::string& in) -> std::string {
      if (all_digits(in)) {
        errno = 0;
        char* end = nullptr;
        std::strtoull(in.c_str(), &end, 10);
        if (errno != ERANGE) return {};
      }
      return in + " is not a seed (an integer from 0 to 18446744073709551615)";
    },
    "SEED");
const CLI::Validator HttpUrl([](std::string& in) -> std::string { return lm::base_url_problem(in); }, "URL");
const CLI::Validator PositiveSeconds(
    [](std::string& in) -> std::string {
      char* end = nullptr;
      const double v = std::strtod(in.c_str(), &end);
      if (!in.empty() && end == in.c_str() + in.size() && std::isfinite(v) && v > 0) return {};
      return in + " is not a positive number of seconds";
    },
    "SECONDS>0");
// More expansions than this fill any machine's memory long before they end.
const CLI::Validator NodeBudget(
    [](std::string& in) -> std::string {
      if (all_digits(in) && in.size() <= 11 && std::stoull(in) <= (1ull << 30)) return {};
      return in + " is more than 2^30 (1073741824) expansions per search";
    },
    "<=2^30");
const CLI::Validator FiniteNumber(
    [](std::string& in) -> std::string {
      char* end = nullptr;
      const double v = std::strtod(in.c_str(), &end);
      // Only what reads as a number is judged here; CLI11 reports the rest.
      if (end != in.c_str() && !std::isfinite(v)) return in + " is not a finite number";
      return {};
    },
    "");

void require_finite_numbers(CLI::App& app) {
  for (CLI::Option* o : app.get_options())
    if (o->get_type_name().rfind("FLOAT", 0) == 0) o->check(FiniteNumber);
  for (CLI::App* sub : app.get_subcommands({})) require_finite_numbers(*sub);
}

void add_time_limit_option(CLI::App* cmd, std::optional<double>& seconds, const std::string& what) {
  cmd->add_option("--time-limit", seconds,
                  "Wall-clock limit in seconds for " + what + " (default: none); reaching it exits with status 5")
      ->check(PositiveSeconds);
}

void bound_grounding(data::Dataset& ds, const std::string& command, const std::optional<double>& seconds) {
  if (!seconds || *seconds >= 1e9) return;
  data::GroundingLimits limits;
  limits.deadline = std::chrono::steady_clock::now() +
                    std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(*seconds));
  limits.deadline_label = fmt::format("{}: stopped: --time-limit of {:g} s", command, *seconds);
  ds.set_grounding_limits(limits);
}

std::string time_limit_message(const std::string& command, double seconds) {
  return fmt::format("{}: stopped: --time-limit of {:g} s reached before the answer was complete", command, seconds);
}

}  // namespace clips::app

int main(int argc, char** argv) {
  using namespace clips::app;
  // "clips" in the build tree, "clips-assist" installed: every message, --help and --version say which.
  clips::util::set_program_name(argc > 0 ? argv[0] : nullptr);
  const std::string& self = clips::util::program_name();
  CLI::App app{self + ": infer a human's goal from their actions and instructions, and help them reach it.\n"
                      "Implements Cooperative Language-Guided Inverse Plan Search (Zhi-Xuan et al., AAMAS 2024).",
               self};
  app.require_subcommand(1);
  app.set_help_all_flag("--help-all", "Print help for every subcommand");
  app.set_version_flag("--version", clips::util::version_line(), "Print the version (and git commit) and exit");
  app.footer(exit_code_help());
  // Every subcommand, in the order --help lists them. A call that names one
  // builds only its options: all of them are about 400 CLI11 objects and half
  // a megabyte, a fifth of a short call's start-up (page faults, mostly).
  // --help, --help-all and an unknown name get every subcommand.
  const std::pair<const char*, void (*)(CLI::App&)> subcommands[] = {
      {"validate", register_validate}, {"show", register_show},     {"plan", register_plan},
      {"assist", register_assist},     {"bench", register_bench},   {"infer", register_infer},
      {"listen", register_listen},     {"lm-score", register_lm_score}, {"export-strips", register_export_strips},
      {"render", register_render},     {"serve", register_serve},   {"generate", register_generate}};
  const char* named = nullptr;
  bool help_all = false;
  for (int i = 1; i < argc; ++i) {
    if (std::string_view(argv[i]) == "--help-all") help_all = true;
    if (named == nullptr && argv[i][0] != '-') named = argv[i];
  }
  const auto* chosen = std::find_if(std::begin(subcommands), std::end(subcommands),
                                    [&](const auto& s) { return named != nullptr && s.first == std::string_view(named); });
  for (const auto& s : subcommands)
    if (help_all || chosen == std::end(subcommands) || &s == chosen) s.second(app);
  // The table's name is the one the function registers (cli_docs_test runs each NAME --help).
  if (!help_all && chosen != std::end(subcommands) &&
      (app.get_subcommands({}).size() != 1 || app.get_subcommands({}).front()->get_name() != chosen->first)) {
    std::fprintf(stderr, "%s: internal error: subcommand table: '%s' registers another name\n", self.c_str(), chosen->first);
    return kExitInternal;
  }
  require_finite_numbers(app);  // NaN and infinities, for every number any subcommand reads
  const std::string exit_footer = "Exit status: 0 ok, 2 usage, 3 input error, ...; see " + self + " --help.";
  for (CLI::App* sub : app.get_subcommands({})) {
    sub->footer(exit_footer);
    for (CLI::App* nested : sub->get_subcommands({})) nested->footer(exit_footer);  // e.g. bench merge
  }
  auto fail = [&self](int code, const char* what) {
    std::fprintf(stderr, "%s: error: %s\n", self.c_str(), what);
    return code;
  };
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // `clips foo`: CLI11 leaves "foo" unparsed and only reports that a
    // subcommand is required; name it and the valid ones instead.
    if (app.get_subcommands().empty() && !app.remaining().empty() && dynamic_cast<const CLI::RequiredError*>(&e)) {
      std::string names;
      for (const CLI::App* sub : app.get_subcommands({})) names += (names.empty() ? "" : ", ") + sub->get_name();
      std::fprintf(stderr, "%s: unknown subcommand '%s'; valid subcommands: %s\nRun with --help for more information.\n",
                   self.c_str(), app.remaining().front().c_str(), names.c_str());
      return kExitUsage;
    }
    // --help and --version print and succeed; every other parse error is a usage error.
    return app.exit(e) == 0 ? kExitOk : kExitUsage;
  } catch (const UsageError& e) {
    std::fprintf(stderr, "%s: error: %s\nRun with --help for more information.\n", self.c_str(), e.what());
    return kExitUsage;
  } catch (const clips::InputError& e) {
    return fail(kExitInput, e.what());
  } catch (const clips::CallStoppedError& e) {
    // --time-limit / --max-seconds (grounding included), and the session
    // engine's call limits.
    return fail(kExitLimit, e.what());
  } catch (const clips::MemoryLimitError& e) {
    return fail(kExitOutOfMemory, e.what());
  } catch (const clips::lm::LmError& e) {
    return fail(kExitLanguageModel, e.what());
  } catch (const clips::multimodal::MultimodalError& e) {
    return fail(kExitLanguageModel, e.what());
  } catch (const clips::util::SharedLibraryError& e) {
    // A part of the installation is missing (the HTTP module, libcurl).
    return fail(kExitInternal, e.what());
  } catch (const std::bad_alloc&) {
    return fail(kExitOutOfMemory, "out of memory");
  } catch (const std::system_error& e) {
    // A thread that cannot start (EAGAIN: the memory or process limits) is the
    // machine's resources running out, not a bug.
    if (e.code() == std::errc::resource_unavailable_try_again) return fail(kExitOutOfMemory, e.what());
    std::fprintf(stderr, "%s: internal error: %s\n", self.c_str(), e.what());
    return kExitInternal;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s: internal error: %s\n", self.c_str(), e.what());
    return kExitInternal;
  }
  return g_exit_code;
}
