# Writes OUT: a C++ file defining clips::domains::builtin_pack_texts() with the
# pack files given in FILES (data/domains/<name>/pack.json, "|"-separated)
# embedded as raw string literals, so the paper's packs work with no data
# folder. The files stay the source: a shipped or dataset pack.json wins.
include(${CMAKE_CURRENT_LIST_DIR}/raw_string.cmake)
set(code "// Generated from data/domains/*/pack.json by cmake/embed_packs.cmake: do not edit.\n#include <map>\n#include <string>\n#include <string_view>\n\nnamespace clips::domains {\n\nconst std::map<std::string, std::string_view>& builtin_pack_texts() {\n  static const std::map<std::string, std::string_view> packs = {\n")
string(REPLACE "|" ";" FILES "${FILES}")
foreach(f IN LISTS FILES)
  get_filename_component(dir ${f} DIRECTORY)
  get_filename_component(name ${dir} NAME)
  file(READ ${f} content)
  clips_raw_string(pieces "${content}" clipspack ${f})
  string(APPEND code "      {\"${name}\", std::string_view(\n${pieces})},\n")
endforeach()
string(APPEND code "  };\n  return packs;\n}\n\n}  // namespace clips::domains\n")
file(WRITE ${OUT}.tmp "${code}")
file(COPY_FILE ${OUT}.tmp ${OUT} ONLY_IF_DIFFERENT)
