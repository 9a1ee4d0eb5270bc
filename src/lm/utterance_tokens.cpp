#include "lm/utterance_tokens.hpp"

#include <cctype>

namespace clips::lm {
namespace {

bool is_word_char(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) != 0;
}

// Append a word, expanding a contraction suffix that followed an apostrophe.
void push_contracted(std::vector<std::string>& out, std::string stem, const std::string& suffix) {
  if (suffix == "t" && !stem.empty() && stem.back() == 'n') {
    // "can't" -> can not, "won't" -> will not, "don't" -> do not.
    if (stem == "won") {
      stem = "will";
    } else if (stem == "can") {
      // keep "can"
    } else {
      stem.pop_back();
    }
    if (!stem.empty()) out.push_back(stem);
    out.emplace_back("not");
    return;
  }
  if (!stem.empty()) out.push_back(stem);
  if (suffix == "ll") {
    out.emplace_back("will");
  } else if (suffix == "m") {
    out.emplace_back("am");
  } else if (suffix == "re") {
    out.emplace_back("are");
  } else if (suffix == "ve") {
    out.emplace_back("have");
  } else if (suffix == "d") {
    out.emplace_back("would");
  } else if (!suffix.empty()) {
    out.push_back(suffix);  // "'s" -> "s", and anything unusual verbatim
  }
}

// Chat spellings of common words ("can u get it pls"), read as the words.
// Only forms that are not English words themselves.
void push_word(std::vector<std::string>& out, std::string word) {
  struct Spelling {
    std::string_view chat, first, second;
  };
  static constexpr Spelling kSpellings[] = {
      {"u", "you", ""},      {"ya", "you", ""},       {"ur", "your", ""},       {"pls", "please", ""},
      {"plz", "please", ""}, {"plox", "please", ""},  {"thx", "thanks", ""},    {"dis", "this", ""},
      {"dat", "that", ""},   {"da", "the", ""},       {"gimme", "give", "me"},  {"gonna", "going", "to"},
      {"wanna", "want", "to"}, {"gotta", "got", "to"}, {"lemme", "let", "me"}, {"cuz", "because", ""},
      {"coz", "because", ""}, {"thru", "through", ""}, {"tho", "though", ""},
      {"im", "i", "am"},     {"ive", "i", "have"},     {"em", "them", ""},     {"dont", "do", "not"},
      {"doesnt", "does", "not"}, {"didnt", "did", "not"}, {"isnt", "is", "not"}, {"youre", "you", "are"},
  };
  for (const Spelling& sp : kSpellings) {
    if (word != sp.chat) continue;
    out.emplace_back(sp.first);
    if (!sp.second.empty()) out.emplace_back(sp.second);
    return;
  }
  out.push_back(std::move(word));
}

}  // namespace

bool is_punctuation_token(std::string_view token) {
  return token == "," || token == "." || token == "?" || token == "!";
}

bool is_clause_end(std::string_view token) {
  return is_punctuation_token(token) || token == "and" || token == "while" || token == "but" ||
         token == "then" || token == "whilst" || token == "so";
}

std::vector<std::string> tokenize_utterance(std::string_view text) {
  std::vector<std::string> out;
  size_t i = 0;
  const size_t n = text.size();
  while (i < n) {
    const char c = text[i];
    if (is_word_char(c)) {
      std::string word;
      while (i < n && is_word_char(text[i])) {
        word.push_back(static_cast<char>(std::tolower(static_cast<unsigned char>(text[i]))));
        ++i;
      }
      // Contraction: apostrophe (ASCII or the UTF-8 right single quote) followed by letters.
      size_t j = i;
      bool apostrophe = false;
      if (j < n && text[j] == '\'') {
        apostrophe = true;
        ++j;
      } else if (j + 2 < n && static_cast<unsigned char>(text[j]) == 0xE2 &&
                 static_cast<unsigned char>(text[j + 1]) == 0x80 &&
                 static_cast<unsigned char>(text[j + 2]) == 0x99) {
        apostrophe = true;
        j += 3;
      }
      if (apostrophe && j < n && std::isalpha(static_cast<unsigned char>(text[j]))) {
        std::string suffix;
        while (j < n && is_word_char(text[j])) {
          suffix.push_back(static_cast<char>(std::tolower(static_cast<unsigned char>(text[j]))));
          ++j;
        }
        push_contracted(out, std::move(word), suffix);
        i = j;
      } else {
        push_word(out, std::move(word));
      }
      continue;
    }
    switch (c) {
      case ',':
      case ';':
      case ':':
        out.emplace_back(",");
        break;
      case '.':
        out.emplace_back(".");
        break;
      case '?':
        out.emplace_back("?");
        break;
      case '!':
        out.emplace_back("!");
        break;
      default:
        break;  // separator
    }
    ++i;
  }
  return out;
}

}  // namespace clips::lm
