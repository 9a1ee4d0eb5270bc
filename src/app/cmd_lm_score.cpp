// `clips lm-score`: log P(continuation | prompt) under one LM backend, for
// debugging prompts and backends by hand.
#include <fmt/core.h>

#include <fstream>
#include <iostream>
#include <iterator>
#include <sstream>

#include "app/cli.hpp"
#include "language/commands/fewshot.hpp"
#include "language/listener.hpp"
#include "util/error.hpp"

namespace clips::app {

namespace {

std::string read_prompt(const std::string& path) {
  std::string text;
  if (path == "-") {
    text.assign(std::istreambuf_iterator<char>(std::cin), std::istreambuf_iterator<char>());
  } else {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(SourceLoc{path, 0, 0}, "cannot open the prompt file");
    std::ostringstream ss;
    ss << in.rdbuf();
    text = ss.str();
  }
  return text;
}

}  // namespace

void register_lm_score(CLI::App& app) {
  auto* cmd = app.add_subcommand("lm-score", "Print log P(continuation | prompt) under a language model");
  struct Opts {
    std::string prompt_file, continuation;
    LmFlags lm;
    bool raw = false;
  };
  auto o = std::make_shared<Opts>();
  cmd->add_option("--prompt-file", o->prompt_file,
                  "File holding the prompt ('-' = stdin). One trailing newline is dropped (editors add it; prompts "
                  "end with \"Output:\"), unless --raw or the file is just \"\\n\" (the empty-command prompt)")
      ->required();
  cmd->add_option("--continuation", o->continuation,
                  "The utterance; scored as \" <utterance>\\n\" like the listener does, unless --raw")
      ->required();
  cmd->add_flag("--raw", o->raw, "Score the prompt file and the continuation byte for byte");
  add_lm_options(cmd, o->lm);
  cmd->callback([o] {
    std::string prompt = read_prompt(o->prompt_file);
    std::string continuation = o->continuation;
    if (!o->raw) {
      if (prompt.size() > 1 && prompt.back() == '\n') prompt.pop_back();
      if (continuation.find_first_not_of(" \t\r\n\f\v") == std::string::npos)
        throw InputError("--continuation is empty");
      continuation = commands::utterance_continuation(continuation);
    }
    auto lm = make_lm(o->lm);
    const double score = lm->score({{prompt, continuation}}).at(0);
    fmt::print("{:.6f}\t{}\n", score, lm->name());
  });
}

}  // namespace clips::app
