#pragma once
// The one place that decides where the installed data lives (language
// corpora, few-shot examples, prompt orders, the paper's result tables, the
// domain packs' files, the example dataset). Searched in order:
//   1. $CLIPS_DATA_DIR (the data root: it holds language/, paper/, domains/),
//      and nothing else when it is set;
//   2. data/ beside the binary this code is linked into (the pip-installed
//      Python package: site-packages/clips_assist/data);
//   3. <prefix>/share/clips-assist, up to four levels above that binary
//      (<prefix>/bin/clips-assist, <prefix>/lib[/<multiarch>]/libclips_assist*,
//      the Python package in <prefix>/lib/python3[.X]/dist-packages/clips_assist);
//   4. build-tree binaries only: the source tree's data/;
//   5. the same above the running executable (a program linking the library);
//   6. the installed static library only: its configured
//      <datadir>/clips-assist, /usr/local/share/clips-assist, /usr/share/clips-assist.
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
