#pragma once
// EmbeddedLanguageModel: the default, offline scorer of log P(utterance | command).
//
// It needs no network and no API key. Instead of a neural LM it uses a small
// generative alignment model of command-conditioned utterances (alignment_model.hpp)
// trained at load time on
//   * a command -> utterance corpus shipped in data/language/ (corpus-*.tsv), and
//   * the few-shot examples found in each prompt (weighted higher), one trained
//     model per distinct few-shot block, cached for the life of the object;
// with WordNet (wordnet_lexicon.hpp) supplying synonyms and inflections.
//
// Prompt convention: few-shot lines "Input: <cmd>\nOutput: <utt>"
// joined by "\n", then "\nInput: <query cmd>\nOutput:". The prompt "\n" (a
// hypothesis without commands) means the empty command. The continuation is
// " <utterance>\n"; the final "\n" is the end-of-utterance event. A continuation
// without the final "\n" is scored as a prefix (probability of all completions).
//
// Scores are natural logs over the model's token sequences (utterance_tokens.hpp):
// lower-cased words and the punctuation tokens , . ? ! — a proper distribution.
// Thread-safe; deterministic (no randomness anywhere).
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "lm/language_model.hpp"
#include "lm/training_pair.hpp"
#include "lm/wordnet_lexicon.hpp"

namespace clips::lm {

class AlignmentModel;

// What training produces, as far as the model cache is concerned: bump it
// with any change to the code that trains (features, EM, the snapshot's
// parameters), so that no build reads a model another training made. The
// test EmbeddedCache.TheTrainingVersionGoesWithWhatTrainingProduces holds the
// scores of a reference training for this version and fails when they move.
inline constexpr int kEmbeddedTrainingVersion = 3;

struct EmbeddedModelOptions {
  // Directory holding the corpus files. Empty: the language/ folder of
  // util::data_dir() ($CLIPS_DATA_DIR, the install prefix or the source tree).
  std::string data_dir;
  // Files read from data_dir (each line "command<TAB>utterance"; '#' comments).
  std::vector<std::string> corpus_files = {"corpus-dkg.tsv", "corpus-vh.tsv"};
  // Pairs trained on after the files' pairs, e.g. a corpus generated from a
  // domain's command grammar (domain_corpus.hpp) for a domain that ships no
  // hand-written corpus; such a domain leaves corpus_files empty.
  std::vector<TrainingPair> extra_corpus;
  // Weight of each few-shot example relative to one corpus pair.
  double fewshot_weight = 4.0;
  int em_iterations = 25;
  // Where trained models are kept between runs (training takes about a
  // second; loading a snapshot a few milliseconds). Empty: $CLIPS_LM_CACHE_DIR
  // if set, else $XDG_CACHE_HOME/clips, else $HOME/.cache/clips. "off" (also
  // as the variable's value) disables the cache. An entry is keyed by the
  // training pairs, the iterations, the noun senses, kEmbeddedTrainingVersion
  // and the WordNet database files: a rebuilt program (or the Python module)
  // with the same training reads what another trained.
  std::string cache_dir;
  // Let commands' objects also emit what they are for, from WordNet
  // (AlignmentModel::set_function_words); for domains read through a
  // generated corpus, which says nothing of uses.
  bool function_words = false;
  // The WordNet sense a domain means by its type names where it is not the
  // first (lm::domain_noun_senses): their nouns' lexical bases follow it.
  NounSenses noun_senses;
};

class EmbeddedLanguageModel : public LanguageModel {
 public:
  // Reads the corpus now (throws LmError naming file and line on a missing or
  // malformed file); training happens lazily per few-shot block.
  explicit EmbeddedLanguageModel(EmbeddedModelOptions options = {});
  explicit EmbeddedLanguageModel(const std::string& data_dir);
  ~EmbeddedLanguageModel() override;

  std::string name() const override { return "embedded"; }
  std::vector<double> score(const std::vector<ScoreRequest>& batch) override;
  double score_one(const std::string& prompt, const std::string& continuation);

  // The trained model for a prompt's few-shot block (exposed for tests).
  std::shared_ptr<const AlignmentModel> model_for_prompt(const std::string& prompt);
  // Number of distinct few-shot blocks trained (or loaded) so far.
  size_t trained_blocks() const;
  // Of those, how many came from the on-disk cache; and the cache directory
  // in use (empty when disabled or unusable).
  size_t cache_hits() const;
  const std::string& cache_dir() const { return cache_dir_; }
  const std::string& data_dir() const { return data_dir_; }

 private:
  struct BlockState;
  std::shared_ptr<BlockState> block_state(const std::string& block);
  std::shared_ptr<BlockState> train_block(const std::string& block);  // or load it from the cache

  EmbeddedModelOptions options_;
  std::string data_dir_;
  std::vector<TrainingPair> corpus_;
  std::string cache_dir_;         // empty: no cache
  std::string cache_identity_;    // training version and WordNet files, part of every key
  size_t cache_hits_ = 0;
  size_t trained_ = 0;
  // Each block trains once, outside mutex_: two threads that need different
  // blocks (two bench plans, two sessions) train them at the same time.
  struct BlockSlot;
  mutable std::mutex mutex_;  // guards blocks_, trained_ and cache_hits_
  std::map<std::string, std::shared_ptr<BlockSlot>> blocks_;
};

// Split a prompt into (few-shot block, query command). Throws LmError if the
// prompt does not end with "Output:" after an "Input:" line (the single "\n"
// prompt gives an empty block and an empty command).
std::pair<std::string, std::string> split_prompt(const std::string& prompt);

// Few-shot (command, utterance) pairs of a block, in order.
std::vector<std::pair<std::string, std::string>> parse_fewshot_block(const std::string& block);

}  // namespace clips::lm
