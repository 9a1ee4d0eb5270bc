#pragma once
// Text for a command: a sampler built from the scorers clips has, for
// `clips generate`. The language models here only score (P(u | prompt)), so a
// phrasing is drawn from a finite pool of candidates with probability
// proportional to P_LM(u | prompt(command)), the CLIPS speaker's own
// likelihood (inference/utterance_model.hpp). The pool, first non-empty of:
//   1. corpus: the pack's hand-written corpora (data/language/corpus-*.tsv)
//      and few-shot examples, for every entry whose command has the same
//      shape as the wanted one, i.e. equal up to qualifier values, with those
//      values rewritten in the text ("the yellow key" becomes "the red key"
//      when yellow -> red is a one-to-one renaming of the command's values);
//   2. listener part: the same for the part of a joint command addressed to
//      the listener, when given (the speaker leaves their own part unsaid);
//   3. generated: 1 and 2 over the corpus generated from the domain's PDDL
//      names for this problem (lm/domain_corpus.hpp);
//   4. any: every utterance of the hand-written corpora and few-shot examples
//      about this domain's actions that names no qualifier value outside the
//      command's (so no colour the command does not mention); also the pool
//      of the empty command, a speaker with nothing to ask, scored under the
//      "\n" prompt.
// Whatever the pool, texts are scored under the wanted command's prompt.
// Candidates are de-duplicated and kept in text order, so the draw depends
// only on the scores and the generator.
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "domains/pack.hpp"
#include "commands/command.hpp"
#include "commands/salient.hpp"
#include "lm/language_model.hpp"
#include "pddl/ast.hpp"
#include "util/rng.hpp"

namespace clips::language {

struct Realisation {
  std::string text;
  std::string command;      // the command's prompt form; "" for the empty command
  std::string pool;         // "corpus", "listener part", "generated" or "any" (see above)
  size_t candidates = 0;    // the pool's size
  double probability = 0;   // of `text` within the pool
};

class UtteranceSampler {
 public:
  // `language_dir`: where the corpora and few-shot files are ("" = language_data_dir()).
  UtteranceSampler(domains::PackPtr pack, std::shared_ptr<const pddl::Domain> domain, lm::LanguageModel& lm,
                   const std::string& language_dir = "");
  ~UtteranceSampler();

  // A phrasing of `command` (null: the empty command) as the speaker model
  // (literal = false) or the literal listener's prompt (literal = true)
  // would score it; `problem` names the objects for the generated corpus.
  // `listener_part`: the command's part addressed to the listener (pool 2), or null.
  Realisation realise(const commands::Command* command, bool literal, const pddl::Problem& problem, util::Rng& rng,
                      const commands::Command* listener_part = nullptr);

 private:
  struct Entry;
  std::vector<Entry> entries_of(const std::vector<std::pair<std::string, std::string>>& pairs) const;
  const std::vector<Entry>& generated_entries(const pddl::Problem& problem);

  domains::PackPtr pack_;
  std::shared_ptr<const pddl::Domain> domain_;
  lm::LanguageModel& lm_;
  std::vector<commands::FewShotExample> pragmatic_, literal_;
  std::vector<Entry> corpus_;
  std::set<std::string> value_words_;  // every qualifier value the corpus names, lower case
  std::map<std::string, std::vector<Entry>> generated_;  // per problem name
};

// The part of a command addressed to the listener: its actions whose agent
// is the listener, lifted again (as the literal utterance files of the paper
// drop the speaker's own part). nullopt when the command holds no speaker
// action (the literal command is the command itself) or nothing else.
std::optional<commands::Command> listener_part(const commands::Command& command,
                                               const commands::LanguageConfig& config,
                                               const commands::QualifierLookup& qualifier_of,
                                               const commands::TypeLookup& type_of);

// `text` with each whole word equal (ignoring case) to from[i] replaced by
// to[i], keeping a leading capital; nullopt unless from -> to is one-to-one.
std::optional<std::string> rename_values(const std::string& text, const std::vector<std::string>& from,
                                         const std::vector<std::string>& to);

}  // namespace clips::language
