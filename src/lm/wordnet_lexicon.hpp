#pragma once
// Lexical prior knowledge from WordNet (Debian's wordnet-dev, /usr/share/wordnet).
//
// The embedded model's emission tables are Dirichlet-smoothed towards *lexical
// bases*: distributions over words that a command element can plausibly emit,
// built here from WordNet, so that synonyms and inflections never seen in the
// training corpus still get probability mass:
//   * noun_base("cutleryfork", plural) -> fork(s), cutlery, tableware, ...
//     (type names are split into WordNet words when the whole name is not one;
//      the head is the last part; synonyms and hypernyms are added with
//      smaller weights: the direct hypernyms of the first two senses, or two
//      levels of the sense the domain means and one of the first; plural forms are generated
//      by English rules and kept only if WordNet's morphology maps them back);
//   * verb_base("handover", to_speaker) -> hand, over, pass, give, deliver, ...
//     plus inflections (hands, handing, handed) checked the same way.
// The WordNet C library keeps global state and is not thread-safe, so every
// call goes through one process-wide mutex; results are memoised.
#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace clips::lm {

// A finite distribution over words (weights sum to 1, sorted by word).
using WordDistribution = std::vector<std::pair<std::string, double>>;

// The WordNet noun sense (0-based, in WordNet's order) a domain means by a
// type name, for the types whose sense is not the first.
using NounSenses = std::map<std::string, int>;

class WordNetLexicon {
 public:
  // The process-wide instance; throws LmError if the dictionary cannot be opened.
  static WordNetLexicon& instance();

  // `sense`: the noun sense the domain means (domain_noun_senses); 0: the
  // first, with the second as runner-up.
  WordDistribution noun_base(const std::string& type, bool plural, int sense = 0);

  // Which noun sense each type name means in a domain, from the domain's own
  // type hierarchy: the sense most similar (Wu-Palmer, over WordNet's
  // hypernyms) to the senses of its declared supertypes and of the types
  // declared beside it. "saw - tool" is the hand tool, not a saying; "base -
  // reagent" the chemical, not a military base. The first sense stays unless
  // another is clearly closer (kSenseMargin of the context's weight).
  // `parent_type`: child -> parent ("object" at the top); `types`: the
  // types to decide. Types WordNet does not know, or knows in one sense,
  // are left out.
  NounSenses domain_noun_senses(const std::map<std::string, std::string>& parent_type,
                                const std::vector<std::string>& types);
  // The WordNet noun a type name is read as: the name, its lemma ("oats" ->
  // "oat"), its two-word compound or the compound's head ("cutleryfork" ->
  // "fork"); empty if WordNet knows none of them.
  std::string type_noun(const std::string& type);
  // The gloss of a type name's noun sense (0-based), without its examples:
  // "hand tool having a toothed blade for cutting". Empty if unknown.
  std::string noun_gloss(const std::string& type, int sense);
  static constexpr size_t kMaxDomainSenses = 8;  // senses of a type considered
  static constexpr size_t kContextSenses = 3;    // senses of a context type compared
  static constexpr double kContextSenseDecay = 0.6;  // weight of a context type's next sense
  static constexpr double kSenseMargin = 0.15;
  WordDistribution verb_base(const std::string& action, bool to_speaker);
  // Base (uninflected) noun form of a word if WordNet knows one, else the word.
  std::string noun_lemma(const std::string& word);

  // Whether WordNet lists the word, or a base form of it, under any part of
  // speech (used to tell a misspelling from a word the corpus never had).
  bool knows(const std::string& word);
  // Whether an object's name holds a word people could say ("shelf3",
  // "fume-hood", "pantry1"), not just a code ("c3-4", "p12"): some part of
  // three or more letters that WordNet knows.
  bool sayable_name(const std::string& name);

  // Words that name the kind of a qualifier predicate, for what an attribute
  // field says when it does not copy the value: "iscolor" -> colored,
  // coloured, color, colour; "issize" -> sized, size; "ismaterial" ->
  // material. The kind is the predicate name without an "is"/"has" prefix
  // (or "-of" suffix); its spelling variants are the dominant sense's
  // synonyms one letter apart; participles ("sized") only if WordNet lists
  // them as adjectives. Empty if WordNet does not know the kind as a noun.
  std::vector<std::string> qualifier_words(const std::string& predicate);

  // Words a speaker may use for a qualifier value, with how close each is:
  // 3 for the words of the value's dominant adjective sense ("large" -> big),
  // 2 for the heads of the adjective senses similar to it ("large" -> huge,
  // "small" -> tiny). Lower-case single words only; the value itself is left
  // out. Empty when WordNet does not know the value as an adjective.
  std::vector<std::pair<std::string, int>> adjective_relatives(const std::string& value);

  // Phrases a speaker may use for an action name ("pickup" -> "pick up",
  // "get", "grab", ...) and for a type name ("plank" -> "plank", "board"),
  // most typical first; for the generated corpus (domain_corpus.hpp). The
  // name is split into WordNet words when it is run together; colloquial
  // verbs come from a small table of everyday verb families, chosen by the
  // WordNet synonyms and hypernyms of the action's first senses.
  std::vector<std::string> verb_phrases(const std::string& action);
  std::vector<std::string> noun_phrases(const std::string& type, int sense = 0);
  // English plural of a noun phrase's last word, checked by WordNet when it can.
  std::string plural(const std::string& noun);

  // What a thing of this type is for, in the words people use when they ask
  // for it by its use ("something to dig with", "something sharp"): from
  // its noun senses that are instruments or containers (hypernym
  // instrumentality, and a gloss that calls it a tool, utensil, container,
  // ... or says what it is used for), the verbs derived from it with their
  // hypernyms (spade -> spade, dig), the purpose verbs of the gloss ("used to
  // deliver", "for scooping") and its describing adjectives ("sharp"), with
  // their inflections. Empty for types that are not instruments (food,
  // plants) or unknown to WordNet.
  WordDistribution function_words(const std::string& type);

  // Whether the word's dominant noun sense is a place: an area, region or
  // location ("kitchen", "corner", "cupboard"), not an object one could fetch.
  bool names_place(const std::string& word);

  // Dominant word class: whether a word may be learned by a noun field and by a
  // verb field. Decided by WordNet's sense counts of the word's base forms (e.g.
  // "grab" has more verb than noun senses, "key" more noun senses); a word that
  // WordNet does not know as either (unknown, adjective, adverb) may be both.
  struct WordClass {
    bool noun_like = true;
    bool verb_like = true;
    // More adjective senses than noun and verb senses ("yellow", "locked" is not:
    // WordNet lists it under the verb "lock"). Used to read noun-phrase modifiers.
    bool adjective_like = false;
  };
  WordClass word_class(const std::string& word);

 private:
  WordNetLexicon();
};

// Closed-class English words (determiners, pronouns, auxiliaries, prepositions,
// conjunctions, punctuation tokens). Content fields may emit one only when it is
// part of their own lexical base (e.g. "up" in "pick up").
bool is_function_word(std::string_view word);

}  // namespace clips::lm
