#pragma once
// The one place that decides where clips's installed data lives (language
// corpora, few-shot examples, prompt orders, the paper's result tables, the
// domain packs' files). Searched in order:
//   1. $CLIPS_DATA_DIR (the data root: it holds language/, paper/, domains/);
//   2. <prefix>/share/clips beside an installed executable or library
//      (<prefix>/bin/clips, <prefix>/lib[/<multiarch>]/libclips*, or the
//      Python module in <prefix>/lib/python3/dist-packages);
//   3. the source tree's data/ folder, for builds run from their build tree.
// The first that exists wins; data_path() names the file it looked for when
// none has it.
#include <string>

namespace clips::util {

// The data root (a directory), never empty.
std::string data_dir();
// data_dir() + "/" + relative, checked to exist; throws InputError naming the
// places searched when it does not.
std::string data_path(const std::string& relative);

}  // namespace clips::util
