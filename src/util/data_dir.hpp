#pragma once
// The one place that decides where the installed data lives (language
// corpora, few-shot examples, prompt orders, the paper's result tables, the
// domain packs' files, the example dataset). Searched in order:
//   1. $CLIPS_DATA_DIR (the data root: it holds language/, paper/, domains/);
//   2. data/ beside the binary this code is linked into (the pip-installed
//      Python package: site-packages/clips_assist/data);
//   3. <prefix>/share/clips-assist beside an installed executable or library
//      (<prefix>/bin/clips-assist, <prefix>/lib[/<multiarch>]/libclips_assist*,
//      or the Python package in <prefix>/lib/python3[.X]/dist-packages);
//   4. a build-tree binary: the source tree's data/ folder; the installed
//      library (libclips_assist.a): its configured <datadir>/clips-assist,
//      then /usr/local/share/clips-assist and /usr/share/clips-assist.
// The first that exists wins; data_path() names the places it looked in when
// none has the file.
#include <string>

namespace clips::util {

// The data root (a directory), never empty.
std::string data_dir();
// data_dir() + "/" + relative, checked to exist; throws InputError naming the
// places searched when it does not.
std::string data_path(const std::string& relative);

}  // namespace clips::util
