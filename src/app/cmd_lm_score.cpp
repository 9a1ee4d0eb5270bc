// `clips lm-score`: log P(continuation | prompt) under one LM backend, for
// debugging prompts and backends by hand.
#include <fmt/core.h>

#include <filesystem>
#include <fstream>
#include <iostream>

#include "app/cli.hpp"
#include "commands/fewshot.hpp"
#include "language/listener.hpp"
#include "util/error.hpp"

namespace clips::app {

namespace {

// Prompts are a few kilobytes; a cap keeps a wrong path (a device, a huge
// file) from filling the memory.
constexpr size_t kMaxPromptBytes = size_t{16} << 20;

std::string read_all(std::istream& in, const std::string& name) {
  std::string text;
  char buf[1 << 16];
  while (in.read(buf, sizeof buf) || in.gcount() > 0) {
    text.append(buf, static_cast<size_t>(in.gcount()));
    if (text.size() > kMaxPromptBytes)
      throw InputError(SourceLoc{name, 0, 0}, "the prompt is larger than 16 MiB; is this the right file?");
  }
  if (in.bad()) throw InputError(SourceLoc{name, 0, 0}, "reading the prompt failed");
  return text;
}

std::string read_prompt(const std::string& path) {
  if (path == "-") return read_all(std::cin, "<stdin>");
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw InputError(SourceLoc{path, 0, 0}, "is a directory, not a prompt file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(SourceLoc{path, 0, 0}, "cannot open the prompt file");
  return read_all(in, path);
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
                  "end with \"Output:\") and Windows line endings are read as \"\\n\", unless --raw or the file is just \"\\n\" "
                  "(the empty-command prompt)")
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
      // Windows line endings: prompts are line-based, so read them as "\n".
      for (size_t at; (at = prompt.find("\r\n")) != std::string::npos;) prompt.erase(at, 1);
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
