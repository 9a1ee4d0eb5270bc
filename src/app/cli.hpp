#pragma once
// The `clips` command line: one register_* function per subcommand. Each
// subcommand is a thin layer over the library API of the same name.
#include <CLI/CLI.hpp>
#include <string>

namespace clips::app {

// Exit status of the subcommand that ran (0 = success).
extern int g_exit_code;

// The dataset directory default: $CLIPS_DATASET, else ../shared/dataset/<domain>.
std::string default_dataset_hint();

void register_validate(CLI::App& app);
void register_show(CLI::App& app);
void register_plan(CLI::App& app);
void register_bench(CLI::App& app);
void register_assist(CLI::App& app);
void register_infer(CLI::App& app);
void register_listen(CLI::App& app);
void register_lm_score(CLI::App& app);
void register_export_strips(CLI::App& app);
void register_render(CLI::App& app);

}  // namespace clips::app
