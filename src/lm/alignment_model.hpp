#pragma once
// The generative utterance model behind EmbeddedLanguageModel.
//
// P(u | c) for a token sequence u = w_1..w_n (see utterance_tokens.hpp) and a
// command frame c (see command_frame.hpp) is defined by this process:
//
//  1. Length: n ~ P_len(n | number of actions of c). This is the explicit end
//     event: the training histogram, long lengths spread over their
//     neighbours, mixed with a Poisson+geometric base that keeps at least a
//     tenth of every bucket, so every length has mass and padded utterances
//     longer than the corpus's are about as likely under any command size.
//  2. Mentions: each group g of c is "mentioned" (m_g = 1) with probability
//     rho_group; given a mentioned group, each of its optional units is mentioned
//     independently: its recipient "me" (hand-over groups) with rho_recipient and
//     each of its attribute values (colours) with rho_attribute. A unit that is
//     not mentioned cannot emit words, which is what penalises commands holding
//     actions or colours the utterance never talks about (a fertility model).
//     The rho are estimated by EM (clamped to [0.05, 0.95]); the exact sum over
//     all mention patterns is taken (at most 2^10 patterns).
//     A mentioned action group (the first 4) is REQUIRED to speak: it emits one
//     anchor token at a position drawn uniformly from the n positions
//     (independently per group; n > 0); an anchored token comes from its
//     anchoring groups' own emission (fields plus mentioned units, uniform over
//     groups sharing the position), every other token from the mixture of 4.
//     So a group the utterance never talks about pays about log(1 - rho) rather
//     than mere dilution. The sum over anchor placements is exact (a forward pass
//     over tokens whose state is the set of groups already anchored, times the
//     clause type); for a prefix, the unseen length is summed out. The E-step
//     credits table counts by the mixture responsibilities (anchors ignored), an
//     approximation; mention counts use the exact posteriors.
//  3. Clauses: the tokens are cut into clauses after punctuation and a few
//     conjunctions; each clause independently gets a speech-act type t:
//     R (a request to the listener, "can you open the blue door") with P = 0.8 or
//     S (a statement about the speaker's own part, "I'll get the red key") with 0.2.
//     A clause whose subject is the listener ("um, could you ...", "you bring
//     ...": "you" first after fillers and at most one auxiliary) is R with
//     0.99 (EncodedUtterance::subject): there "can you open the cupboard" is
//     not the speaker's own opening. One that announces the speaker's own
//     next step ("I'll open the shed", "I'm going to get ...", "let me ...",
//     "while I get ..."; not "I'll need ..." or "I think ...") is S with 0.99, and
//     there a group of the listener's anchors (item 2) at a tenth of its
//     weight, so "I'll open the shed" cannot stand for the listener's
//     opening just because the verb fits.
//  4. Words: each token of a clause of type t is drawn independently from the mixture
//       pi_bg * BG(w) + pi_agent * A_t(w) + pi_content * Content_{m,t}(w)
//     where BG is a background English unigram whose base is a character bigram
//     model (so every string of [a-z0-9]+ has mass: unknown words are fine) and
//     a tenth of which stays on the raw training frequencies (a word EM hands to
//     one field, "more" to the number words, keeps some mass of its own) and
//     another tenth is the character model itself (words a templated corpus
//     never had, such as filler, cost a command not much more than they cost
//     the empty-command prompt),
//     A_t emits speech-act markers ("can", "could", "you" / "i", "will", "am"),
//     and Content_{m,t} is a uniform mixture over the mentioned groups of
//     t's role (R: the listener's; S: the speaker's own and those handing
//     their objects to the speaker, so "I'm in need of the blue key" names
//     what a hand-over brings) plus a small share of GEN, a generic
//     source of domain content words (used entirely when no group qualifies; this
//     is where "I'll get the red key" goes when the command omits the speaker).
//     The content words of an earlier clause that a later request's "it" or
//     "them" points back to ("I need the larger board, could you get it?")
//     describe the request's object: they take R's content in either type
//     (EncodedUtterance::about_request).
//     A group emits through its fields, with fixed weights:
//       V  verb, table keyed by (action, agent, whether "me" is the recipient);
//       N  noun, keyed by (object type, plural iff the group has 2+ actions);
//       Q  number words, keyed by the group's action count (only if >= 2);
//     and through its mentioned optional units, whose weights are added to the
//     group's and renormalised:
//       C  attribute (a qualifier value of any predicate: colour, size,
//          material, owner, ...): copy the value with probability alpha, else
//          a shared residual table R (the values, and the words naming each
//          qualifier's kind: "coloured", "size"; WordNetLexicon::qualifier_words).
//          alpha is ONE parameter shared by all values, so a value seen once
//          in training is as copyable as any;
//       P  recipient: "me", "my way", "here", ... for hand-overs to the speaker.
//  5. Modifiers. Tokens inside a post-nominal prepositional modifier ("I need a
//     key [for this yellow door]", "the key [to that door]") are not mentions of
//     any action: there a group's noun and number fields are replaced by M, one
//     shared "modifier" table (purpose/goal nouns), while its verb field and its
//     optional units (colours, recipient) stay. So "door" in "a key for this
//     door" is equally likely under every command and cannot vouch for an unlock
//     action the utterance never asks for: an unlock group must be mentioned by
//     its verb ("open", "unlock") or by its noun in object position ("get the
//     door"), else it pays its mention odds. The modifier span starts after
//     "for"/"to" that follows a noun introduced by a determiner ("a key for",
//     "the red key to", "the yellow one for", "something for") and runs over
//     determiners, pronouns and adjectives/colours up to its head noun (or
//     pronoun: "the door for me"); an infinitive ("the key to open ...") ends it
//     at the verb, so its object is read as usual. A clause may also start
//     with the span ("For this yellow door, I need a key."); it then attaches
//     to the first noun phrase of the next clause.
//
//  6. Colour binding (of any qualifier value: "big" and "metal" bind the same
//     way). A colour copied from an object's attribute must describe
//     a noun that can name that object's type: in "can you open the red door"
//     the "red" is not a copy of a red gem's colour. The noun a colour describes
//     is read from the utterance (encode(): the head of its noun phrase, and in a
//     modifier span, the object of a purpose infinitive or of a relative clause
//     also the noun they attach to, so "a key for this yellow door", "a key to
//     open this yellow door" and "the key that opens the yellow door" let a
//     yellow key's colour through). A head noun names a type
//     when some trained noun table gives it real mass; an attribute unit may copy
//     the colour at full weight only if its own type's noun tables give the head
//     at least kBindRatio of the best type's mass, else at kMisboundCopy of it.
//     A colour after its noun with no noun following ("pass me the key blue")
//     describes that noun. Untyped heads ("one", "thing") and colours with no
//     head are unconstrained.
//     Number words bind the same way: a group's number field Q emits a
//     determiner ("two", "both", "some") at full weight only if the noun it
//     counts can name the group's type, so in "two forks" the number cannot
//     make a pair of wine glasses in the command count as mentioned.
//  7. Contradicted colours (any qualifier). A speaker who means the command's
//     blue door does not call it red, whatever source the word would come
//     from. A value token whose typed head nouns (item 6) can each name some
//     object of the command, all of whose values of the token's own qualifier
//     kind are known and differ from it, is multiplied by kContradictedColour
//     in every source; a value of another kind ("wooden" for an object whose
//     size alone is known) contradicts nothing. Roles count: in a
//     request clause only the listener's ("you") objects are checked, in a
//     statement only those of its role (item 4), so "I'm going for the red key" says nothing
//     against a command asking the listener for the yellow key. A colour that
//     a later request points back to with "it"/"them" ("This red door has me
//     stuck; could you open it?") is checked against the request's objects
//     whatever its own clause's type. A value whose noun phrase is headed
//     by "one" ("the red one") is checked against every object of its
//     clause's role. A command that leaves an object's colour open is
//     never contradicted.
//
// Apart from the colour binding and contradiction, which look ahead to the head noun,
// and the marked clauses' prior and anchors (item 3), which read the clause's first words, every
// factor is a normalised distribution and the clause cuts and modifier spans
// depend only on already generated tokens, so the sum over all token sequences
// is exactly 1 (with items 6 and 7 and the off-role anchors it is at most 1: a
// deficient model, which only lowers the score of commands whose colours the
// utterance attaches to nouns of another type, or contradicts, or whose part
// it gives the other agent; the marked clauses' prior reweights the two
// readings of such a clause, the same way under every command).
// Emission tables are Dirichlet posteriors: expected counts from EM over the
// training pairs (corpus + few-shot examples) plus kappa times a lexical base from
// WordNet (nouns, verbs) or small closed lists (speech-act markers, number words).
// Content fields never emit closed-class words unless their base contains them;
// verb fields only learn verb-like words and noun fields noun-like ones (WordNet
// sense counts), so a noun table shared by several actions cannot soak up verbs.
//
// Files, by job: alignment_model.cpp (binding commands and the probability
// model), english_reader.cpp (encode(): spelling repair, lexical classes,
// clauses and whom they address, modifier spans, the nouns colours and
// numbers describe, pronoun antecedents), alignment_training.cpp (EM), alignment_snapshot.cpp (save and
// load); alignment_internal.hpp holds what they share. tests/lm/
// alignment_behaviour_test.cpp pins golden scores across refactorings.
#include <array>
#include <cstdint>
#include <memory>
#include <mutex>
#include <shared_mutex>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "lm/command_frame.hpp"
#include "lm/training_pair.hpp"
#include "lm/wordnet_lexicon.hpp"

namespace clips::lm {

class AlignmentModel;

// A tokenised utterance bound to one trained model's vocabulary.
struct EncodedUtterance {
  std::vector<int> ids;             // vocabulary id, or -1 if unknown
  std::vector<std::string> words;   // the tokens themselves
  std::vector<int> clause_end;      // exclusive end index of each clause
  // in_modifier[i] != 0: token i lies in a post-nominal prepositional modifier
  // ("a key [for this red door]", "the key [to that door]"); decided from the
  // tokens before i only, so the model stays a left-to-right process.
  std::vector<char> in_modifier;
  // noun_heads[i]: for an adjective or colour token, the noun tokens it may
  // describe (-1: none): [0] the head noun of its own noun phrase ("red" in
  // "the red door" -> "door"); [1] inside a modifier span or the object of a
  // purpose infinitive, the noun they attach to ("yellow" in "a key for this
  // yellow door" or "a key to open this yellow door" -> "key"). Used to
  // bind a copied colour to an object of a matching type (see evaluate()).
  std::vector<std::array<int, 2>> noun_heads;
  // asked_for[i] != 0: colour token i describes the last coloured noun before
  // an "it"/"them" in a later request-like clause ("I'm stuck at this red
  // door, could you open it?"): whatever its own clause, it names the object
  // of that request (used by the colour contradiction of evaluate()).
  std::vector<char> asked_for;
  // about_request[i] != 0: token i is a content word of the nearest earlier
  // clause with a noun, and a later request-like clause asks for "it"/"them"
  // ("I need the larger board off the rack, could you get it?"): it
  // describes the request's object, so in either clause type it comes from
  // the listener's groups, not the speaker's own.
  std::vector<char> about_request;
  // subject[k]: whose part clause k says it is about, from its first words.
  // kSubjectListener ("can you ...", "you bring ...") is read as a request,
  // kSubjectSpeaker ("I'll get ...", "let me ...", "while I get ...") as a
  // statement, each with kMarkedClause rather than kRequestClause; in the
  // latter only the speaker's groups anchor at full weight.
  std::vector<char> subject;
  // negated[i] != 0: token i is a qualifier value or adjective in the scope
  // of a negation ("not the red one", "any except the green ones", "I don't
  // need the big one"): it says what the object is not, so it is no mention
  // of that value, and it contradicts an object that has it.
  std::vector<char> negated;
};

inline constexpr char kSubjectUnmarked = 0;
inline constexpr char kSubjectListener = 1;
inline constexpr char kSubjectSpeaker = 2;

// Trained parameters. Immutable after train(), except for a thread-safe cache of
// tables created on demand for command elements unseen in training.
class AlignmentModel {
 public:
  // Train by EM on the pairs (throws LmError naming the pair's origin if a
  // command cannot be parsed).
  // `senses`: the WordNet sense the domain means by a type name where it is
  // not the first (lexical bases of its nouns follow it).
  // `threads` (0: the machine's cores, at most 8) share each E-step; the
  // model is the same, bit for bit, whatever their number.
  static std::shared_ptr<AlignmentModel> train(const std::vector<TrainingPair>& pairs, int iterations,
                                               const NounSenses& senses = {}, int threads = 0);

  struct Bound;  // a command frame bound to this model's tables
  std::shared_ptr<const Bound> bind(const std::string& command) const;

  // Tokenises (utterance_tokens.hpp) and binds to the vocabulary. A token the
  // vocabulary lacks is first repaired if it is a slip: an elongation
  // ("neeed") read as its word, or a word WordNet does not know either read as
  // the vocabulary's content word one edit away ("yelow" -> "yellow").
  EncodedUtterance encode(const std::string& text) const;
  // log P(u | c). If `complete` is false the text is a prefix and the result is
  // the probability of all utterances starting with these tokens.
  double log_prob(const Bound& c, const EncodedUtterance& u, bool complete) const;
  // log P(u) with no context at all: the empty-command prompt "\n" of the
  // utterance model. An unprimed language model has no reason to expect this
  // domain's content words, so each token is a mixture (weights 1/2, 1/2) of
  // the background restricted to closed-class words and punctuation, and the
  // character model that spells any word out; the length model is the
  // zero-action one. Both parts are proper distributions, so this is one too.
  double log_prob_unprimed(const EncodedUtterance& u, bool complete) const;

  // For tests: the total probability that the next token is drawn from the
  // model's vocabulary plus the mass of all unknown strings, given a command,
  // a prefix and an assumed clause type; equals 1 for a proper model.
  double next_token_mass(const std::string& command, bool mentioned_all, bool request_clause) const;
  // For tests: sum of P_len(n | actions) for n = 0..max_n.
  double length_mass(int actions, int max_n) const;
  size_t vocabulary_size() const { return words_.size(); }
  // Human-readable per-token source probabilities (all groups mentioned), for debugging.
  std::string explain(const std::string& command, const std::string& utterance) const;

  // Lets each typed action group also emit what its object is for
  // (WordNetLexicon::function_words: "dig" for a spade), a field with a
  // fixed weight and an untrained WordNet table. Off by default: the paper
  // domains' hand-written corpora say what they need. Set before scoring.
  void set_function_words(bool on) { function_words_ = on; }
  // The noun senses the model was trained with, for tables made on demand
  // (a snapshot does not hold them). Set before scoring.
  void set_noun_senses(const NounSenses& senses) { noun_senses_ = senses; }

  // A binary snapshot of the trained parameters, for the embedded model's
  // on-disk cache (tables created on demand are not part of it). load() throws
  // LmError on anything but a complete snapshot of this format; a loaded model
  // scores bit for bit like the one saved.
  std::string save() const;
  static std::shared_ptr<AlignmentModel> load(const std::string& bytes);

  ~AlignmentModel();
  AlignmentModel(const AlignmentModel&) = delete;
  AlignmentModel& operator=(const AlignmentModel&) = delete;

 private:
  AlignmentModel();
  struct Table;
  struct Counts;
  friend struct Trainer;

  int add_word(const std::string& w);
  int table_index(const std::string& key);  // training-time: create if missing
  const Table* find_or_make_table(const std::string& key) const;
  double char_prob(const std::string& w) const;
  double char_log_prob(const std::string& w) const;
  double bg_prob(int id, const std::string& w) const;
  // The steps of log_prob() and of the E-step (alignment_model.cpp).
  struct TokenSources;  // each token's probability under every source of the mixture
  // With `deferred`, the E-step's additions to `counts` are listed there, in
  // order, instead of made: training evaluates pairs in parallel and replays
  // the lists in pair order, so the sums are the sequential ones, bit for bit.
  using DeferredAdds = std::vector<std::pair<double*, double>>;
  double evaluate(const Bound& c, const EncodedUtterance& u, bool complete, Counts* counts,
                  double weight, DeferredAdds* deferred = nullptr) const;
  double best_noun_mass(int id, const std::string& w) const;
  double colour_binding(const Bound& c, size_t g, const EncodedUtterance& u, size_t i) const;
  std::vector<double> colour_contradictions(const Bound& c, const EncodedUtterance& u) const;
  unsigned qualifier_kinds(const Bound& c, size_t unit) const;
  TokenSources token_sources(const Bound& c, const EncodedUtterance& u) const;
  double rescale_tiny_tokens(TokenSources& s, const EncodedUtterance& u) const;
  double length_log_prob(int actions, int n, bool complete) const;

  // Lexical class bits of a vocabulary word (kWord* in the .cpp), for the
  // noun-phrase reading of encode().
  uint8_t word_flags(int id, const std::string& w) const;
  // A token unknown to the vocabulary, read as the word it misspells, if any.
  std::string respell(const std::string& w) const;
  std::string respelled(const std::string& w) const;  // respell(), memoised
  // The qualifier value an out-of-vocabulary word names by WordNet ("big" ->
  // large, "tiny" -> small, "wood" -> wooden), or "" if none or several do;
  // also for a plain modifier of the vocabulary, and for a value only of bags
  // (bag_kinds_: "big" of a goal's name, where the items' size is "large").
  std::string attribute_synonym(const std::string& w) const;
  void read_place_numbers(EncodedUtterance& u) const;
  void mark_negations(EncodedUtterance& u) const;
  void mark_modifiers(EncodedUtterance& u) const;
  void mark_pronoun_antecedents(EncodedUtterance& u) const;
  void mark_clause_subjects(EncodedUtterance& u) const;

  std::unordered_map<std::string, int> word_ids_;
  std::vector<std::string> words_;
  std::vector<uint8_t> word_flags_;  // per vocabulary id
  // Per vocabulary id: nonzero for a qualifier value of some training command,
  // one bit per qualifier predicate it is a value of (colour, size, ...).
  std::vector<char> attribute_word_;
  // The bits of attribute_word_ whose predicate gives one object several
  // values in a training command: a bag of words about it (a goal's name
  // words), not a qualifier with one value per object.
  uint8_t bag_kinds_ = 0;
  std::vector<double> char_first_;  // char bigram model: first char
  std::vector<double> char_next_;   // [prev * 37 + next], next 36 = end
  std::vector<double> bg_;          // background probs over the vocabulary
  double bg_unknown_scale_ = 0;     // BG(unknown w) = scale * char_prob(w)
  double closed_mass_ = 0;          // total background mass of closed-class words

  std::vector<std::unique_ptr<Table>> tables_;
  std::unordered_map<std::string, int> table_ids_;
  std::vector<int> noun_tables_;  // ids of the trained noun tables ("N:<type>/sg|pl")
  double copy_alpha_ = 0.8;
  bool function_words_ = false;
  NounSenses noun_senses_;
  // rho: action groups, recipients, attribute values, numbers of numbered places
  double mention_[4] = {0.85, 0.85, 0.85, 0.85};
  std::vector<std::vector<double>> length_;  // [actions][n] for n <= kMaxLen
  std::vector<double> length_tail_scale_;    // weight of the base beyond kMaxLen
  std::vector<double> length_mean_;

  mutable std::shared_mutex lazy_mutex_;
  mutable std::unordered_map<std::string, std::unique_ptr<Table>> lazy_tables_;
  // respell() results: an utterance is encoded once per command it is scored
  // against, and each repair scans the vocabulary.
  mutable std::shared_mutex respell_mutex_;
  mutable std::unordered_map<std::string, std::string> respelled_;
  mutable std::once_flag synonyms_once_;
  mutable std::unordered_map<std::string, std::string> attribute_synonyms_;
};

}  // namespace clips::lm
