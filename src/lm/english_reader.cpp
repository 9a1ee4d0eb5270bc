// The alignment model's reading of an English utterance: spelling repair,
// lexical classes, clauses and whose part each is about, post-nominal
// modifiers, the nouns colours and numbers describe, and the antecedents of
// "it"/"them" (see alignment_model.hpp, items 3, 5-7).
#include "lm/alignment_model.hpp"

#include <algorithm>
#include <mutex>
#include <set>
#include <string_view>
#include <unordered_map>
#include <unordered_set>
#include <cctype>
#include <string>

#include "lm/alignment_internal.hpp"
#include "lm/utterance_tokens.hpp"
#include "lm/wordnet_lexicon.hpp"

namespace clips::lm {

namespace {

bool is_relative_pronoun(std::string_view w) { return w == "that" || w == "which"; }

}  // namespace

uint8_t closed_class_flags(std::string_view w) {
  static const std::set<std::string_view> determiners = {
      "a",    "an",   "the",   "this",    "that", "these", "those", "some",  "any",  "my",
      "your", "our",  "his",   "her",     "their", "its",  "another", "each", "every", "both",
      "one",  "two",  "three", "four",    "five",  "six",  "no"};
  static const std::set<std::string_view> pronouns = {"me", "you", "us", "him", "her", "them",
                                                      "it", "myself", "yourself", "ourselves"};
  static const std::set<std::string_view> indefinite = {"something", "anything", "everything", "someone"};
  uint8_t f = 0;
  if (is_function_word(w)) f |= kWordFunction;
  if (determiners.count(w) != 0) f |= kWordDeterminer;
  if (pronouns.count(w) != 0) f |= kWordPronoun;
  if (w == "for" || w == "to") f |= kWordPreposition;
  if (indefinite.count(w) != 0) f |= kWordIndefinite;
  return f;
}

namespace {

// One edit apart: a substitution, an insertion or deletion, or a swap of two
// neighbouring letters ("yelow", "kye", "bleu" from "yellow", "key", "blue").
bool one_edit_apart(const std::string& a, const std::string& b) {
  if (a == b) return false;
  if (a.size() == b.size()) {
    size_t i = 0;
    while (a[i] == b[i]) ++i;
    if (a.compare(i + 1, std::string::npos, b, i + 1, std::string::npos) == 0) return true;  // substitution
    return i + 1 < a.size() && a[i] == b[i + 1] && a[i + 1] == b[i] &&
           a.compare(i + 2, std::string::npos, b, i + 2, std::string::npos) == 0;  // swap
  }
  const std::string& l = a.size() > b.size() ? a : b;
  const std::string& s = a.size() > b.size() ? b : a;
  if (l.size() != s.size() + 1) return false;
  size_t i = 0;
  while (i < s.size() && l[i] == s[i]) ++i;
  return l.compare(i + 1, std::string::npos, s, i, std::string::npos) == 0;
}

// Runs of three or more equal letters cut to `keep` letters ("pleeease").
std::string shorten_runs(const std::string& w, size_t keep) {
  std::string out;
  for (size_t i = 0; i < w.size();) {
    size_t j = i;
    while (j < w.size() && w[j] == w[i]) ++j;
    out.append(j - i >= 3 ? keep : j - i, w[i]);
    i = j;
  }
  return out;
}

}  // namespace

// Spelling repair for a token the model has never seen. Elongated words
// ("neeed", "pleeease") are read with their letter runs shortened when that
// gives a known word. A word that WordNet does not know either is read as the
// content word of the vocabulary one edit away, the most frequent if several
// are: "yelow" -> "yellow", "kye" -> "key", "rd" -> "red" (a two-letter token
// only by a dropped letter). Real words stay as written ("soon" is never read
// as "spoon"), and so do function words and tokens with digits.
std::string AlignmentModel::respell(const std::string& w) const {
  if (w.size() < 2 || is_function_word(w)) return w;
  for (char ch : w)
    if (ch < 'a' || ch > 'z') return w;
  WordNetLexicon& wn = WordNetLexicon::instance();
  auto known = [&](const std::string& x) { return word_ids_.count(x) != 0 || is_function_word(x) || wn.knows(x); };
  const bool one_letter = w.find_first_not_of(w[0]) == std::string::npos;  // "zzzz" is no elongated word
  if (const std::string two = shorten_runs(w, 2); two != w && !one_letter) {
    if (known(two)) return two;
    if (const std::string one = shorten_runs(w, 1); known(one)) return one;
  }
  if (std::string v = attribute_synonym(w); !v.empty()) return v;
  if (wn.knows(w)) return w;
  int best = -1;
  bool best_full = false;
  for (size_t id = 0; id < words_.size() && id < bg_.size() && id < word_flags_.size(); ++id) {
    const std::string& v = words_[id];
    if (v.size() < 3 || v.size() + 1 < w.size() || v.size() > w.size() + 1) continue;
    if (w.size() == 2 && v.size() != 3) continue;  // "rd", "gt": only a dropped letter
    const uint8_t f = word_flags_[id];
    if ((f & kWordFunction) != 0 || (f & (kWordNoun | kWordVerb | kWordModifier)) == 0) continue;
    if (!one_edit_apart(w, v)) continue;
    // A dropped letter is the commoner slip than an extra one ("glases" is
    // "glasses" rather than "glass"); among equals, the more frequent word.
    const bool full = v.size() >= w.size();
    if (best < 0 || full > best_full || (full == best_full && bg_[id] > bg_[static_cast<size_t>(best)])) {
      best = static_cast<int>(id);
      best_full = full;
    }
  }
  return best >= 0 ? words_[static_cast<size_t>(best)] : w;
}

// Qualifier values are few and a domain names them one way ("large"), while
// people say "big", "huge", "tiny", "wood". Each value's WordNet relatives
// (adjective_relatives: its own sense's words, then similar adjectives) and
// its derivational neighbours by English suffixes (wood/wooden, metal/
// metallic) are read as the value. A word close to two values equally
// ("medium"-like words between sizes) is left alone, and so is a word whose
// dominant sense is not an adjective ("cherry" is a fruit before a red).
std::string AlignmentModel::attribute_synonym(const std::string& w) const {
  std::call_once(synonyms_once_, [this] {
    WordNetLexicon& wn = WordNetLexicon::instance();
    struct Best {
      int strength = 0;
      std::string value;
      bool ambiguous = false;
    };
    std::unordered_map<std::string, Best> best;
    // A word of the vocabulary is a synonym too if the vocabulary has it as a
    // modifier that is not a value (the few-shot examples' "little" for
    // small): else it stayed a word of its own, which no value contradicts.
    auto in_vocabulary_as_other = [&](const std::string& word) {
      auto it = word_ids_.find(word);
      if (it == word_ids_.end()) return false;
      const auto id = static_cast<size_t>(it->second);
      const uint8_t f = id < word_flags_.size() ? word_flags_[id] : 0;
      const bool value = id < attribute_word_.size() && attribute_word_[id] != 0;
      return value || (f & kWordModifier) == 0 || (f & kWordFunction) != 0;
    };
    auto offer = [&](const std::string& word, int strength, const std::string& value) {
      if (word.size() < 3 || in_vocabulary_as_other(word) || is_function_word(word)) return;
      Best& b = best[word];
      if (strength > b.strength) {
        b = Best{strength, value, false};
      } else if (strength == b.strength && value != b.value) {
        b.ambiguous = true;
      }
    };
    // A value only of bags of words (a goal's name words: "big") that is a
    // close relative of a qualifier's value reads as that value ("large", the
    // items' size): else the size would have no word but its own name, and
    // the value's other relatives ("huge") would be torn between the two.
    std::unordered_map<std::string, Best> absorbed;
    auto kinds_of = [&](const std::string& word) -> unsigned {
      auto it = word_ids_.find(word);
      if (it == word_ids_.end() || static_cast<size_t>(it->second) >= attribute_word_.size()) return 0;
      return static_cast<unsigned char>(attribute_word_[static_cast<size_t>(it->second)]);
    };
    for (size_t id = 0; id < attribute_word_.size() && id < words_.size(); ++id) {
      const unsigned mine = static_cast<unsigned char>(attribute_word_[id]);
      if (mine == 0) continue;
      for (const auto& [word, strength] : wn.adjective_relatives(words_[id])) {
        const unsigned theirs = kinds_of(word);
        if (strength < 3 || theirs == 0 || (theirs & ~bag_kinds_) != 0 || (mine & ~bag_kinds_) == 0) continue;
        Best& b = absorbed[word];
        if (strength > b.strength) b = Best{strength, words_[id], false};
        else if (strength == b.strength && words_[id] != b.value) b.ambiguous = true;
      }
    }
    for (auto it = absorbed.begin(); it != absorbed.end();)
      it = it->second.ambiguous ? absorbed.erase(it) : std::next(it);
    static constexpr std::string_view kSuffixes[] = {"en", "n", "ic", "lic", "y", "ish"};
    for (size_t id = 0; id < attribute_word_.size() && id < words_.size(); ++id) {
      if (!attribute_word_[id] || absorbed.count(words_[id]) != 0) continue;
      const std::string& value = words_[id];
      for (const auto& [word, strength] : wn.adjective_relatives(value))
        if (wn.word_class(word).adjective_like) offer(word, strength, value);
      for (std::string_view suffix : kSuffixes) {
        if (value.size() > suffix.size() + 2 && value.compare(value.size() - suffix.size(), suffix.size(), suffix) == 0) {
          const std::string stem = value.substr(0, value.size() - suffix.size());
          if (wn.knows(stem)) offer(stem, 1, value);
        }
        const std::string derived = value + std::string(suffix);
        if (wn.knows(derived)) offer(derived, 1, value);
      }
    }
    for (auto& [word, b] : best)
      if (!b.ambiguous) attribute_synonyms_.emplace(word, b.value);
    for (auto& [word, b] : absorbed) attribute_synonyms_[word] = b.value;
  });
  auto it = attribute_synonyms_.find(w);
  return it == attribute_synonyms_.end() ? std::string() : it->second;
}

std::string AlignmentModel::respelled(const std::string& w) const {
  {
    std::shared_lock lock(respell_mutex_);
    if (auto it = respelled_.find(w); it != respelled_.end()) return it->second;
  }
  std::string r = respell(w);
  std::unique_lock lock(respell_mutex_);
  if (respelled_.size() > (1u << 14)) respelled_.clear();  // bound memory in a long-running server
  respelled_.emplace(w, r);
  return r;
}

EncodedUtterance AlignmentModel::encode(const std::string& text) const {
  EncodedUtterance u;
  u.words = tokenize_utterance(text);
  u.ids.reserve(u.words.size());
  for (size_t i = 0; i < u.words.size(); ++i) {
    if (word_ids_.count(u.words[i]) == 0) {
      u.words[i] = respelled(u.words[i]);
    } else if (std::string v = attribute_synonym(u.words[i]); !v.empty()) {
      u.words[i] = v;  // a plain modifier of the vocabulary that names a value ("little")
    }
    auto it = word_ids_.find(u.words[i]);
    u.ids.push_back(it == word_ids_.end() ? -1 : it->second);
    if (is_clause_end(u.words[i])) u.clause_end.push_back(static_cast<int>(i) + 1);
  }
  if (u.clause_end.empty() || u.clause_end.back() != static_cast<int>(u.words.size())) {
    u.clause_end.push_back(static_cast<int>(u.words.size()));
  }
  read_place_numbers(u);
  mark_modifiers(u);
  mark_pronoun_antecedents(u);
  mark_clause_subjects(u);
  mark_negations(u);
  return u;
}

// Negated noun phrases: after "not", "except", "excluding", "without",
// "never", "other than", "rather than", "instead of", "apart from", "any(thing)
// but", and "no" before a noun phrase ("no red ones"), the values and
// adjectives up to the phrase's head (a noun, "one", "ones"), within the
// clause and a few tokens, say what is not meant. "No, the big one" is a
// correction, not a negation: the clause after "no" is read as usual.
void AlignmentModel::mark_negations(EncodedUtterance& u) const {
  const size_t n = u.words.size();
  u.negated.assign(n, 0);
  static const std::unordered_set<std::string> single = {"not", "except", "excluding", "without", "never"};
  static const std::unordered_set<std::string> any = {"any", "anything", "all", "everything", "anyone", "one"};
  auto negator_ends_at = [&](size_t i) -> size_t {  // the last token of a negator starting at i, or n
    const std::string& w = u.words[i];
    if (single.count(w) != 0) return i;
    if (i + 1 < n) {
      const std::string& next = u.words[i + 1];
      if ((w == "other" || w == "rather") && next == "than") return i + 1;
      if ((w == "instead" && next == "of") || (w == "apart" && next == "from")) return i + 1;
      if (w == "no" && !is_clause_end(next) && !is_punctuation_token(next)) return i;
      if (w == "but" && i > 0 && any.count(u.words[i - 1]) != 0) return i;
    }
    return n;
  };
  for (size_t i = 0; i < n; ++i) {
    const size_t end = negator_ends_at(i);
    if (end >= n) continue;
    for (size_t j = end + 1, k = 0; j < n && k < kMaxNegationScope; ++j, ++k) {
      if (is_clause_end(u.words[j]) || is_punctuation_token(u.words[j])) break;
      const uint8_t f = word_flags(u.ids[j], u.words[j]);
      const bool value = u.ids[j] >= 0 && static_cast<size_t>(u.ids[j]) < attribute_word_.size() &&
                         attribute_word_[static_cast<size_t>(u.ids[j])] != 0;
      if (value || ((f & kWordModifier) != 0 && (f & kWordFunction) == 0)) {
        u.negated[j] = 1;
        continue;
      }
      if (u.words[j] == "one" || u.words[j] == "ones") break;
      const bool head = (f & kWordNoun) != 0 && (f & (kWordFunction | kWordVerb)) == 0;
      if (head) break;
    }
    i = end;
  }
}

namespace {

// The number a cardinal or ordinal word says ("three", "third", "3rd"), or 0.
int number_word_value(const std::string& w) {
  static const std::unordered_map<std::string, int> words = {
      {"one", 1},        {"two", 2},          {"three", 3},       {"four", 4},        {"five", 5},
      {"six", 6},        {"seven", 7},        {"eight", 8},       {"nine", 9},        {"ten", 10},
      {"eleven", 11},    {"twelve", 12},      {"first", 1},       {"second", 2},      {"third", 3},
      {"fourth", 4},     {"fifth", 5},        {"sixth", 6},       {"seventh", 7},     {"eighth", 8},
      {"ninth", 9},      {"tenth", 10},       {"eleventh", 11},   {"twelfth", 12}};
  if (auto it = words.find(w); it != words.end()) return it->second;
  // "3rd", "12th"
  size_t k = 0;
  while (k < w.size() && std::isdigit(static_cast<unsigned char>(w[k]))) ++k;
  if (k > 0 && k < w.size() && k + 2 == w.size()) {
    const std::string suffix = w.substr(k);
    if (suffix == "st" || suffix == "nd" || suffix == "rd" || suffix == "th") return std::stoi(w.substr(0, k));
  }
  return 0;
}

bool is_ordinal_word(const std::string& w) {
  return number_word_value(w) > 0 && !std::isdigit(static_cast<unsigned char>(w.back())) &&
         (w.size() > 2 && (w.compare(w.size() - 2, 2, "th") == 0 || w == "first" || w == "second" || w == "third" ||
                           w.compare(w.size() - 2, 2, "st") == 0 || w.compare(w.size() - 2, 2, "nd") == 0 ||
                           w.compare(w.size() - 2, 2, "rd") == 0));
}

}  // namespace

// The number of a numbered place said in words ("shelf three", "the third
// shelf", "bed number 2", "bay no. 4", "the 3rd shelf") read as the digits
// its name carries ("3"), when the model has such numbers in its vocabulary
// (a domain whose commands name numbered places: commands::numbered_names).
// A cardinal is a place's number after a noun or "number"/"no" ("one" only
// after those two); an ordinal also before a noun. "two cans" stays a
// quantity, "the red one" a pronoun.
void AlignmentModel::read_place_numbers(EncodedUtterance& u) const {
  const size_t n = u.words.size();
  for (size_t i = 0; i < n; ++i) {
    const int value = number_word_value(u.words[i]);
    if (value <= 0) continue;
    const std::string digits = std::to_string(value);
    auto it = word_ids_.find(digits);
    if (it == word_ids_.end()) continue;
    auto place_word = [&](size_t j) {
      const uint8_t f = word_flags(u.ids[j], u.words[j]);
      return (f & kWordFunction) == 0 && !is_punctuation_token(u.words[j]) && number_word_value(u.words[j]) == 0 &&
             ((f & kWordNoun) != 0 || (f & kWordModifier) != 0);
    };
    // A cardinal before a noun phrase counts it ("we need two glasses") when
    // the noun names one of the domain's kinds; "shelf two needs sorting
    // out" counts no needs. (While training, no noun table exists yet: any
    // noun or adjective after it counts.)
    auto counts = [&](size_t j) {
      if (!place_word(j)) return false;
      return noun_tables_.empty() || best_noun_mass(u.ids[j], u.words[j]) >= kTypedNoun;
    };
    bool place_number = false;
    if (i > 0 && (u.words[i - 1] == "number" || u.words[i - 1] == "no" || u.words[i - 1] == "num")) place_number = true;
    // "shelf three", but not "we need two glasses".
    else if (i > 0 && place_word(i - 1) && u.words[i] != "one" && !(i + 1 < n && counts(i + 1)))
      place_number = true;
    else if (is_ordinal_word(u.words[i]) && i + 1 < n && place_word(i + 1)) place_number = true;
    if (!place_number) continue;
    u.words[i] = digits;
    u.ids[i] = it->second;
  }
}

namespace {
// The speaker announces their own next step: "i will get ...", "i am going to
// ...", "i am gonna ...", "i shall ...", "let me ...", or says it in the
// present ("while i get the potato", "i take the compost"). Not when the verb
// that follows asks for something ("i will need the saw", "i am going to want
// ..."): that names what the listener may bring; nor a present that says how
// the speaker stands ("i think", "i reckon", "i fancy ...").
template <class IsVerb>
bool announces_own_step(const std::vector<std::string>& w, size_t i, size_t end, IsVerb&& is_verb) {
  static const std::unordered_set<std::string> asking = {"need", "want", "like", "require", "have", "love"};
  static const std::unordered_set<std::string> stance = {
      "think", "reckon", "guess", "know", "mean", "hope", "suppose", "believe", "wonder", "see", "fancy",
      "wish", "prefer", "feel", "bet", "forgot", "forget", "remember", "got", "still", "just", "really"};
  auto at = [&](size_t k, const char* s) { return i + k < end && w[i + k] == s; };
  size_t verb = 0;
  if (at(0, "let") && at(1, "me")) verb = 2;
  else if (at(0, "i") && (at(1, "will") || at(1, "shall"))) verb = 2;
  else if (at(0, "i") && at(1, "am") && at(2, "gonna")) verb = 3;
  else if (at(0, "i") && at(1, "am") && at(2, "going") && at(3, "to")) verb = 4;
  else if (at(0, "i") && i + 1 < end && is_verb(i + 1)) return asking.count(w[i + 1]) == 0 && stance.count(w[i + 1]) == 0;
  else return false;
  if (i + verb < end && w[i + verb] == "just") ++verb;
  return i + verb < end && asking.count(w[i + verb]) == 0;
}
}  // namespace

// Whose part a clause is about, from its subject: the listener ("you" first,
// after nothing but discourse fillers and an auxiliary: "um, could you ...",
// "you bring ...") or the speaker announcing their own step.
void AlignmentModel::mark_clause_subjects(EncodedUtterance& u) const {
  static const std::unordered_set<std::string> lead = {
      "um", "uh", "er", "erm", "oh", "ok", "okay", "right", "so", "hey", "please", "and", "then", "now", "well",
      "also", "just", "yeah", "yes", "oi", "alright", "actually", "maybe", "hi", "hmm", "ah", "look", "listen"};
  static const std::unordered_set<std::string> auxiliary = {"can", "could", "would", "will", "wo", "do", "might",
                                                            "shall", "should", "must"};
  const size_t n = u.words.size();
  u.subject.assign(u.clause_end.size(), kSubjectUnmarked);
  auto is_verb = [&](size_t j) {
    const uint8_t f = word_flags(u.ids[j], u.words[j]);
    return (f & kWordVerb) != 0 && (f & kWordFunction) == 0;
  };
  size_t start = 0;
  for (size_t k = 0; k < u.clause_end.size(); ++k) {
    const size_t end = std::min(static_cast<size_t>(u.clause_end[k]), n);
    size_t i = start;
    while (i < end && (lead.count(u.words[i]) != 0 || is_punctuation_token(u.words[i]))) ++i;
    if (announces_own_step(u.words, i, end, is_verb)) {
      u.subject[k] = kSubjectSpeaker;
    } else {
      if (i < end && auxiliary.count(u.words[i]) != 0) ++i;
      if (i < end && (u.words[i] == "you" || u.words[i] == "u")) u.subject[k] = kSubjectListener;
    }
    start = end;
  }
}

uint8_t AlignmentModel::word_flags(int id, const std::string& w) const {
  if (id >= 0 && static_cast<size_t>(id) < word_flags_.size()) return word_flags_[static_cast<size_t>(id)];
  // Unknown words: closed-class lists, else read as a noun (a name of something).
  const uint8_t f = closed_class_flags(w);
  return (f & kWordFunction) != 0 ? f : static_cast<uint8_t>(f | kWordNoun);
}

// For each object "it"/"them" in a clause that reads as a request (it has
// "you", or no "i"/"we" subject: "come get it open"), the closest
// colour-bearing noun phrase of an earlier clause is what the request is
// about. A simple recency rule: the reading only decides which role's
// objects a colour may contradict.
void AlignmentModel::mark_pronoun_antecedents(EncodedUtterance& u) const {
  // "it" before a verb of being or an auxiliary is the empty subject of "it
  // would be great if ...", which points back at nothing.
  static const std::unordered_set<std::string> dummy_next = {
      "is", "s", "was", "would", "will", "d", "might", "could", "should", "may", "must",
      "seems", "looks", "be", "has", "can", "does", "did", "sounds"};
  const size_t n = u.words.size();
  u.asked_for.assign(n, 0);
  u.about_request.assign(n, 0);
  if (u.noun_heads.size() != n) return;
  std::vector<uint8_t> f(n);
  for (size_t i = 0; i < n; ++i) f[i] = word_flags(u.ids[i], u.words[i]);
  auto content = [&](size_t i) { return (f[i] & kWordFunction) == 0; };
  // "the red one": a noun phrase whose noun is left out.
  auto names_one = [&](size_t i) { return u.words[i] == "one" || u.words[i] == "ones"; };
  std::vector<size_t> starts;  // of the clauses before the current one
  size_t clause_start = 0;
  for (size_t e : u.clause_end) {
    const size_t end = std::min(e, n);
    bool you = false, first_person = false, pronoun = false;
    for (size_t i = clause_start; i < end; ++i) {
      const std::string& w = u.words[i];
      you = you || w == "you";
      first_person = first_person || w == "i" || w == "we";
      const bool dummy = w == "it" && i + 1 < n && dummy_next.count(u.words[i + 1]) != 0;
      pronoun = pronoun || (w == "it" && !dummy) || w == "them";
    }
    if (pronoun && (you || !first_person)) {
      // The latest colour token before this clause that has a head noun.
      for (size_t i = clause_start; i-- > 0;) {
        if (u.noun_heads[i][0] >= 0 && i < u.ids.size() && u.ids[i] >= 0 &&
            static_cast<size_t>(u.ids[i]) < attribute_word_.size() && attribute_word_[static_cast<size_t>(u.ids[i])]) {
          u.asked_for[i] = 1;
          break;
        }
      }
      // The nearest earlier clause with a noun (or a noun-less "one") holds
      // what "it" stands for.
      for (size_t k = starts.size(); k-- > 0;) {
        const size_t b = starts[k], c_end = k + 1 < starts.size() ? starts[k + 1] : clause_start;
        bool has_noun = false;
        for (size_t i = b; i < c_end; ++i) has_noun = has_noun || (content(i) && (f[i] & kWordNoun) != 0) || names_one(i);
        if (!has_noun) continue;
        for (size_t i = b; i < c_end; ++i) u.about_request[i] = content(i) ? 1 : 0;
        break;
      }
    }
    starts.push_back(clause_start);
    clause_start = end;
  }
}

// Post-nominal prepositional modifiers, read left to right: a span opens after
// "for"/"to" whose preceding word heads a noun phrase (a noun after a
// determiner, possibly with adjectives between, or "something"), and covers the
// following determiners, pronouns, adjectives and participles up to and
// including the head noun or pronoun. A verb right after the preposition is an
// infinitive ("a key to open the door"): it ends the span, so its object is not
// inside it. The flag of token i depends only on tokens before i.
void AlignmentModel::mark_modifiers(EncodedUtterance& u) const {
  const size_t n = u.words.size();
  u.in_modifier.assign(n, 0);
  std::vector<uint8_t> f(n);
  for (size_t i = 0; i < n; ++i) f[i] = word_flags(u.ids[i], u.words[i]);
  auto heads_noun_phrase = [&](size_t j) {
    if ((f[j] & kWordIndefinite) != 0) return true;
    const bool one = u.words[j] == "one" || u.words[j] == "ones";
    if (!one && ((f[j] & kWordFunction) != 0 || (f[j] & kWordNoun) == 0)) return false;
    for (size_t back = 1; back <= 3 && back <= j; ++back) {
      const uint8_t g = f[j - back];
      if ((g & kWordDeterminer) != 0) return true;
      const bool modifier = (g & kWordModifier) != 0 || ((g & kWordFunction) == 0 && (g & kWordNoun) != 0 &&
                                                         (g & kWordVerb) == 0);
      if (!modifier) return false;
    }
    return false;
  };
  // Head nouns of adjectives and colours: the first following token that is
  // neither a closed-class word nor a modifier, if it is a noun and comes
  // within kMaxHeadDistance tokens without crossing a clause end.
  // Determiners and number words ("two", "both", "some") get their head noun
  // the same way, for the number binding of evaluate().
  u.noun_heads.assign(n, {-1, -1});
  for (size_t i = 0; i < n; ++i) {
    if ((f[i] & (kWordModifier | kWordDeterminer)) == 0) continue;
    for (size_t j = i + 1; j < n && j <= i + kMaxHeadDistance; ++j) {
      if (is_clause_end(u.words[j]) || (f[j] & kWordFunction) != 0) break;
      if ((f[j] & kWordModifier) != 0) continue;
      if ((f[j] & kWordNoun) != 0) u.noun_heads[i][0] = static_cast<int>(j);
      break;
    }
    // A colour placed after its noun ("pass me the key blue") describes the
    // noun just before it when no noun follows.
    const bool ends_phrase = i + 1 == n || is_clause_end(u.words[i + 1]) || (f[i + 1] & kWordFunction) != 0;
    if (u.noun_heads[i][0] < 0 && (f[i] & kWordModifier) != 0 && ends_phrase && i > 0 &&
        (f[i - 1] & kWordNoun) != 0 && (f[i - 1] & (kWordFunction | kWordModifier)) == 0)
      u.noun_heads[i][0] = static_cast<int>(i) - 1;
  }
  bool open = false;
  int k = 0;
  int anchor = -1;   // the noun the open span attaches to
  int purpose = -1;  // after "a key to open": that noun, for the verb's object
  int relative = -1;  // after "the key that": that noun, once the verb is read
  int pk = 0;
  for (size_t i = 0; i < n; ++i) {
    if (open) {
      u.in_modifier[i] = 1;
      if ((f[i] & kWordModifier) != 0) u.noun_heads[i][1] = anchor;
    }
    if (is_clause_end(u.words[i])) {
      open = false;
      purpose = relative = -1;
      continue;
    }
    if (purpose >= 0 && !open) {
      // The object of a purpose infinitive ("a key to open [this yellow
      // door]") is read as usual, but its colours may describe the key too.
      if ((f[i] & kWordModifier) != 0) u.noun_heads[i][1] = purpose;
      const bool np_word = (f[i] & kWordFunction) != 0 || (f[i] & kWordModifier) != 0;
      if (++pk > kMaxModifierSpan || !np_word) purpose = -1;
    }
    if (relative >= 0 && i > 0 && is_relative_pronoun(u.words[i - 1])) {
      purpose = relative;  // token i is the relative clause's verb
      pk = 0;
      relative = -1;
    }
    if (open) {
      ++k;
      const uint8_t g = f[i];
      if ((g & kWordPronoun) == 0 && k == 1 && (g & kWordVerb) != 0) {
        open = false;  // an infinitive's verb ("a key to open ..."): its object follows
        purpose = anchor;
        pk = 0;
      } else if ((g & kWordPronoun) != 0 || (k == 1 && (g & kWordVerb) != 0)) {
        open = false;  // a pronoun
      } else if ((g & kWordFunction) != 0 || (g & kWordModifier) != 0 ||
                 ((g & kWordVerb) != 0 && (g & kWordNoun) == 0)) {
        // Determiners, adjectives, colours and participles ("the locked door").
        open = k < kMaxModifierSpan;
      } else {
        open = false;  // the head noun, or an infinitive's verb
      }
    } else if ((f[i] & kWordPreposition) != 0 && i > 0 && heads_noun_phrase(i - 1)) {
      open = true;
      k = 0;
      anchor = static_cast<int>(i) - 1;
    } else if ((f[i] & kWordPreposition) != 0 && (i == 0 || is_clause_end(u.words[i - 1]))) {
      // Fronted: "For this yellow door, I need a key." The span opens as
      // usual (it depends on earlier tokens only); the noun it attaches to is
      // the first noun phrase of the next clause, read ahead like the heads.
      open = true;
      k = 0;
      anchor = -1;
      size_t j = i + 1;
      while (j < n && !is_clause_end(u.words[j])) ++j;
      for (++j; j < n && !is_clause_end(u.words[j]); ++j)
        if (heads_noun_phrase(j)) {
          anchor = static_cast<int>(j);
          break;
        }
    } else if (is_relative_pronoun(u.words[i]) && i > 0 && i + 1 < n && heads_noun_phrase(i - 1) &&
               (f[i + 1] & kWordVerb) != 0 && (f[i + 1] & kWordModifier) == 0) {
      // A relative clause ("the key that opens this yellow door") reads like
      // a purpose infinitive: its object's colours may describe the noun too.
      relative = static_cast<int>(i) - 1;  // takes effect after the verb
    }
  }
}

}  // namespace clips::lm
