#include "util/numbered_names.hpp"

#include <algorithm>
#include <cctype>
#include <map>

namespace clips::util {

namespace {

// Where a name's trailing number starts (after a letter, optionally through
// one '-' or '_'), or npos when it has none.
std::size_t number_start(const std::string& name) {
  std::size_t i = name.size();
  while (i > 0 && std::isdigit(static_cast<unsigned char>(name[i - 1]))) --i;
  if (i == name.size() || i == 0) return std::string::npos;
  std::size_t stem_end = i;
  if (name[stem_end - 1] == '-' || name[stem_end - 1] == '_') --stem_end;
  if (stem_end == 0 || !std::isalpha(static_cast<unsigned char>(name[stem_end - 1]))) return std::string::npos;
  return i;
}

std::string stem_of(const std::string& name, std::size_t number) {
  std::size_t end = number;
  if (end > 0 && (name[end - 1] == '-' || name[end - 1] == '_')) --end;
  return name.substr(0, end);
}

}  // namespace

std::vector<std::string> numbered_names(const std::vector<std::string>& names) {
  std::map<std::string, std::vector<std::string>> by_stem;
  for (const std::string& n : names)
    if (const std::size_t k = number_start(n); k != std::string::npos) by_stem[stem_of(n, k)].push_back(n);
  std::vector<std::string> out;
  for (auto& [stem, group] : by_stem)
    if (group.size() >= 2) out.insert(out.end(), group.begin(), group.end());
  std::sort(out.begin(), out.end());
  return out;
}

std::string number_marked(const std::string& name) {
  const std::size_t k = number_start(name);
  if (k == std::string::npos) return name;
  return stem_of(name, k) + "#" + name.substr(k);
}

std::string mark_numbered(const std::string& command, const std::vector<std::string>& names) {
  if (names.empty()) return command;
  auto is_name_char = [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == '?' || c == '#';
  };
  std::string out;
  std::size_t i = 0;
  while (i < command.size()) {
    if (!is_name_char(command[i])) {
      out.push_back(command[i++]);
      continue;
    }
    std::size_t j = i;
    while (j < command.size() && is_name_char(command[j])) ++j;
    const std::string word = command.substr(i, j - i);
    out += std::find(names.begin(), names.end(), word) != names.end() ? number_marked(word) : word;
    i = j;
  }
  return out;
}

}  // namespace clips::util
