#include "language/deixis.hpp"

#include <cctype>
#include <regex>

#include "lm/wordnet_lexicon.hpp"

namespace clips::language {

KindNoun kind_noun(const std::string& type) {
  std::string words;
  for (char c : type) {
    if (c == '-' || c == '_') {
      if (!words.empty() && words.back() != ' ') words.push_back(' ');
    } else if (std::isalpha(static_cast<unsigned char>(c))) {
      words.push_back(static_cast<char>(std::tolower(static_cast<unsigned char>(c))));
    }
  }
  if (words.empty()) return {};
  lm::WordNetLexicon& wn = lm::WordNetLexicon::instance();
  const std::vector<std::string> phrases = wn.noun_phrases(words);
  const std::string noun = phrases.empty() ? words : phrases.front();
  return {noun, wn.plural(noun)};
}

std::string resolve_deixis(const std::string& text, const KindNoun& kind) {
  if (kind.singular.empty()) return text;
  using std::regex;
  static const regex of_these(
      R"(\b(another|one more|a second|one|some more|a few more|two more|three more|more)( ones?)? of (these|those|them)\b)",
      regex::icase);
  static const regex another_one(R"(\b(another|one more|a second) one\b)", regex::icase);
  static const regex bare(
      R"(\b(another|one more)(?=\s*([,.!?;]|$|please\b|for\b|to\b|on\b|onto\b|in\b|into\b|over\b|from\b|as\b|too\b)))",
      regex::icase);
  std::string out;
  // Quantities of one take the singular ("one more can"), others the plural.
  std::smatch m;
  std::string rest = text;
  while (std::regex_search(rest, m, of_these)) {
    const std::string q = m[1].str();
    std::string lower;
    for (char c : q) lower.push_back(static_cast<char>(std::tolower(static_cast<unsigned char>(c))));
    const bool one = lower == "another" || lower == "one more" || lower == "a second" || lower == "one";
    out += m.prefix().str() + (lower == "one" ? "one" : q) + " " + (one ? kind.singular : kind.plural);
    rest = m.suffix().str();
  }
  out += rest;
  out = std::regex_replace(out, another_one, "$1 " + kind.singular);
  out = std::regex_replace(out, bare, "$1 " + kind.singular);
  return out;
}

std::string resolve_deixis(const std::string& text, const KindNoun& kind, const std::string& except) {
  std::string out = resolve_deixis(text, kind);
  if (except.empty() || out == text) return out;
  size_t end = out.size();
  while (end > 0 && std::isspace(static_cast<unsigned char>(out[end - 1]))) --end;
  size_t cut = end;
  while (cut > 0 && (out[cut - 1] == '.' || out[cut - 1] == '?' || out[cut - 1] == '!')) --cut;
  return out.substr(0, cut) + ", not the " + except + " one" + out.substr(cut, end - cut);
}

}  // namespace clips::language
