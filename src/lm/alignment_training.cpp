// Training of the alignment model: EM over the training pairs (see alignment_model.hpp).
#include "lm/alignment_model.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <map>
#include <mutex>
#include <set>
#include <string_view>
#include <thread>
#include <unordered_set>

#include "lm/alignment_internal.hpp"
#include "lm/language_model.hpp"
#include "lm/utterance_tokens.hpp"
#include "lm/wordnet_lexicon.hpp"
#include "util/worker_pool.hpp"

namespace clips::lm {

// ------------------------------------------------------------------------------------

struct Trainer {
  static std::shared_ptr<AlignmentModel> run(const std::vector<TrainingPair>& pairs, int iterations,
                                             const NounSenses& senses, int threads) {
    std::shared_ptr<AlignmentModel> m(new AlignmentModel());
    AlignmentModel& M = *m;
    M.noun_senses_ = senses;

    // Parse everything first so malformed input fails before any work.
    std::vector<CommandFrame> frames;
    std::vector<std::vector<std::string>> tokens;
    for (const TrainingPair& p : pairs) {
      frames.push_back(parse_command_frame(p.command, p.origin));
      tokens.push_back(tokenize_utterance(p.utterance));
    }

    // Vocabulary: punctuation first (always present), training tokens, base words.
    for (const char* punct : {",", ".", "?", "!"}) M.add_word(punct);
    for (const auto& t : tokens) {
      for (const std::string& w : t) M.add_word(w);
    }
    std::set<std::string> keys = {"A:you", "A:me", "P:me"};
    std::set<std::string> attributes;
    // The qualifier predicates of the training commands and the values each takes.
    std::map<std::string, std::set<std::string>> qualifier_values;
    std::set<std::string> bag_predicates;
    for (const CommandFrame& f : frames) {
      for (const FrameGroup& g : f.groups) {
        keys.insert(verb_key(g));
        if (!g.type.empty()) keys.insert(noun_key(g));
        if (g.count >= 2) keys.insert(number_key(g.count));
        for (const std::string& a : g.attributes) attributes.insert(a);
        std::map<std::string, int> per_predicate;
        for (size_t k = 0; k < g.attributes.size() && k < g.attribute_predicates.size(); ++k) {
          qualifier_values[g.attribute_predicates[k]].insert(g.attributes[k]);
          // One object (a group of count 1) with two values of a predicate.
          if (++per_predicate[g.attribute_predicates[k]] == 2 && g.count == 1)
            bag_predicates.insert(g.attribute_predicates[k]);
        }
      }
    }
    std::map<std::string, WordDistribution> bases;
    for (const std::string& k : keys) {
      bases[k] = base_for_key(k, senses);
      for (const auto& [w, p] : bases[k]) M.add_word(w);
    }
    for (const std::string& a : attributes) M.add_word(a);
    const size_t V = M.words_.size();

    // GEN: domain content words in general. R: what an attribute field says when
    // it does not copy its value (e.g. "coloured", another attribute word).
    WordDistribution gen_base;
    {
      std::map<std::string, double> acc;
      double parts = 0;
      for (const auto& [k, d] : bases) {
        if (k[0] != 'V' && k[0] != 'N') continue;
        parts += 1;
        for (const auto& [w, p] : d) {
          if (!is_function_word(w)) acc[w] += p;
        }
      }
      for (const std::string& a : attributes) acc[a] += parts / 4.0 / std::max<double>(1, attributes.size());
      double z = 0;
      for (auto& [w, p] : acc) z += p;
      for (auto& [w, p] : acc) gen_base.emplace_back(w, p / z);
    }
    // R: the values, and the words naming each qualifier's kind ("coloured",
    // "size", "material"; WordNetLexicon::qualifier_words).
    WordDistribution residual_base;
    for (const std::string& a : attributes) residual_base.emplace_back(a, 1.0);
    for (const auto& [predicate, values] : qualifier_values) {
      for (const std::string& w : WordNetLexicon::instance().qualifier_words(predicate)) {
        const bool listed = std::any_of(residual_base.begin(), residual_base.end(),
                                        [&](const auto& entry) { return entry.first == w; });
        if (!listed) residual_base.emplace_back(w, 1.0);
      }
    }
    for (auto& [w, p] : residual_base) {
      M.add_word(w);
      p /= static_cast<double>(residual_base.size());
    }
    bases["GEN"] = gen_base;
    bases["M"] = gen_base;  // modifier heads: domain nouns ("door", "table"), learned by EM
    bases["R"] = residual_base;
    const size_t V2 = M.words_.size();
    (void)V;

    // Character bigram model over the vocabulary's word types (add-1/2 smoothing).
    {
      std::vector<double> first(kCharSymbols, 0.5);
      std::vector<double> next(static_cast<size_t>(kCharSymbols * (kCharSymbols + 1)), 0.5);
      for (const std::string& w : M.words_) {
        int prev = -1;
        bool ok = !w.empty();
        for (char ch : w) ok = ok && char_index(ch) >= 0;
        if (!ok) continue;
        for (char ch : w) {
          const int c = char_index(ch);
          if (prev < 0) {
            first[static_cast<size_t>(c)] += 1;
          } else {
            next[static_cast<size_t>(prev * (kCharSymbols + 1) + c)] += 1;
          }
          prev = c;
        }
        next[static_cast<size_t>(prev * (kCharSymbols + 1) + kCharSymbols)] += 1;
      }
      double z = 0;
      for (double v : first) z += v;
      for (double& v : first) v /= z;
      for (int p = 0; p < kCharSymbols; ++p) {
        double s = 0;
        for (int c = 0; c <= kCharSymbols; ++c) s += next[static_cast<size_t>(p * (kCharSymbols + 1) + c)];
        for (int c = 0; c <= kCharSymbols; ++c) next[static_cast<size_t>(p * (kCharSymbols + 1) + c)] /= s;
      }
      M.char_first_ = std::move(first);
      M.char_next_ = std::move(next);
    }
    std::vector<double> char_in_vocab(V2);
    for (size_t i = 0; i < V2; ++i) char_in_vocab[i] = M.char_prob(M.words_[i]);

    // Tables. The prior base of a table is its lexical base mixed with a small
    // uniform floor over the words its kind may emit (content words for content
    // fields, closed-class words for the speech-act sources), so EM can discover
    // words the lexicon lacks (WordNet has no grab -> pick up). The first E-step
    // uses a much larger floor, the usual uniform start of alignment models, so
    // that co-occurrence decides the first responsibilities.
    // Verb fields may only learn verb-like words and noun fields noun-like ones:
    // otherwise a noun field shared by several actions (N:key) soaks up their
    // verbs ("grab") and the verb fields stop telling actions apart. Nor do
    // noun fields learn places ("kitchen", "cupboard") beyond their lexical
    // base: from "kitchen knife" the chef's knife table would otherwise take
    // "kitchen", and "the wine is in the kitchen" would ask for a knife.
    // The head word of each command type names an object whatever WordNet's
    // sense counts say: "plank" and "saw" have more verb senses, yet in "the big
    // plank" the plank is the noun the size describes.
    std::set<std::string> type_heads;
    for (const std::string& k : keys) {
      if (k.rfind("N:", 0) != 0) continue;
      const std::string type = k.substr(2, k.rfind('/') - 2);
      const std::vector<std::string> names = WordNetLexicon::instance().noun_phrases(type);
      if (names.empty()) continue;
      const std::string head = names.front().substr(names.front().rfind(' ') + 1);
      type_heads.insert(head);
      type_heads.insert(WordNetLexicon::instance().plural(head));
    }
    auto word_class = [&](const std::string& w) {
      WordNetLexicon::WordClass wc = WordNetLexicon::instance().word_class(w);
      if (type_heads.count(w) != 0) wc.noun_like = true;
      return wc;
    };
    std::vector<int> content_ids, function_ids, noun_ids, verb_ids;
    for (size_t i = 0; i < V2; ++i) {
      const std::string& w = M.words_[i];
      if (is_function_word(w)) {
        function_ids.push_back(static_cast<int>(i));
        continue;
      }
      content_ids.push_back(static_cast<int>(i));
      if (is_punctuation_token(w)) continue;
      const WordNetLexicon::WordClass wc = word_class(w);
      if (wc.noun_like && !WordNetLexicon::instance().names_place(w)) noun_ids.push_back(static_cast<int>(i));
      if (wc.verb_like) verb_ids.push_back(static_cast<int>(i));
    }
    // Word classes for reading noun phrases (AlignmentModel::mark_modifiers).
    // Attribute values (colours, also as residual words) are pure modifiers.
    std::set<std::string> modifier_words(attributes.begin(), attributes.end());
    for (const auto& [w, p] : residual_base) modifier_words.insert(w);
    M.word_flags_.assign(V2, 0);
    M.attribute_word_.assign(V2, 0);
    // attribute_word_ holds a bit per qualifier predicate (in name order, eight
    // bits, wrapping), so a value contradicts only values of its own kind: "wooden"
    // says nothing against a plank the command only knows to be big.
    {
      size_t bit = 0;
      for (const auto& [predicate, values] : qualifier_values) {
        for (const std::string& a : values)
          M.attribute_word_[static_cast<size_t>(M.word_ids_.at(a))] |= static_cast<char>(1u << (bit % 8));
        if (bag_predicates.count(predicate) != 0) M.bag_kinds_ |= static_cast<uint8_t>(1u << (bit % 8));
        ++bit;
      }
    }
    for (size_t i = 0; i < V2; ++i) {
      const std::string& w = M.words_[i];
      uint8_t f = closed_class_flags(w);
      if ((f & kWordFunction) == 0 && !is_punctuation_token(w)) {
        if (modifier_words.count(w) != 0) {
          f |= kWordModifier;
        } else {
          const WordNetLexicon::WordClass wc = word_class(w);
          if (wc.noun_like) f |= kWordNoun;
          if (wc.verb_like) f |= kWordVerb;
          if (wc.adjective_like) f |= kWordModifier;
        }
      }
      M.word_flags_[i] = f;
    }
    auto with_floor = [&](const WordDistribution& d, const std::vector<int>& floor_ids, double eps) {
      std::vector<std::pair<int, double>> out;
      for (const auto& [w, p] : d) out.emplace_back(M.word_ids_.at(w), (1 - eps) * p);
      for (int id : floor_ids) out.emplace_back(id, eps / static_cast<double>(floor_ids.size()));
      if (d.empty()) {
        // No lexical base (R when no command has a qualifier): the floor is all of it.
        for (auto& [id, p] : out) p /= eps;
      } else if (floor_ids.empty()) {
        for (auto& [id, p] : out) p /= 1 - eps;
      }
      return out;
    };
    for (const auto& [k, d] : bases) {
      const int ti = M.table_index(k);
      AlignmentModel::Table& t = *M.tables_[static_cast<size_t>(ti)];
      const bool agent = k[0] == 'A' || k[0] == 'P';
      t.kappa = agent ? kKappaAgent : (k == "GEN" || k == "M") ? kKappaGeneric : kKappaContent;
      // The recipient unit is a closed set of words ("me", "my way", "here").
      static const std::vector<int> no_floor;
      const std::vector<int>& floor_ids = k[0] == 'P'   ? no_floor
                                          : agent       ? function_ids
                                          : k[0] == 'N' ? noun_ids
                                          : k[0] == 'V' ? verb_ids
                                                        : content_ids;
      t.base = with_floor(d, floor_ids, kBaseFloor);
      t.prob.assign(V2, 0.0);
      // GEN starts flat: it must not out-compete the command's own fields for
      // the words they co-occur with before EM has seen the data.
      const double init_floor = (k == "GEN" || k == "M") ? 0.95 : kInitialFloor;
      for (const auto& [id, p] : with_floor(d, floor_ids, init_floor)) t.prob[static_cast<size_t>(id)] += p;
    }

    // Relative frequencies of the training tokens.
    std::vector<double> unigram(V2, 0.0);
    {
      double total = 0;
      for (size_t p = 0; p < pairs.size(); ++p)
        for (const std::string& w : tokens[p]) {
          unigram[static_cast<size_t>(M.word_ids_.at(w))] += pairs[p].weight;
          total += pairs[p].weight;
        }
      if (total > 0)
        for (double& u : unigram) u /= total;
    }
    // Background initialised to smoothed relative frequencies of all tokens.
    // A share of it stays on the plain token frequencies: a word that EM hands
    // entirely to some command field ("short" to one noun, "more" to a number)
    // keeps a little background mass, so in an utterance about something else
    // it is not evidence for whichever command happens to own it.
    auto set_background = [&](const std::vector<double>& cnt) {
      double total = 0;
      for (double v : cnt) total += v;
      M.bg_.assign(V2, 0.0);
      for (size_t i = 0; i < V2; ++i) {
        M.bg_[i] = (1 - kUnigramShare) * (cnt[i] + kKappaBackground * char_in_vocab[i]) / (total + kKappaBackground) +
                   kUnigramShare * unigram[i];
      }
      M.bg_unknown_scale_ = (1 - kUnigramShare) * kKappaBackground / (total + kKappaBackground);
      // Mix in the novel-word share: with it every word gets at least
      // kNovelWordShare times its spelled-out probability.
      for (size_t i = 0; i < V2; ++i) M.bg_[i] = (1 - kNovelWordShare) * M.bg_[i] + kNovelWordShare * char_in_vocab[i];
      M.bg_unknown_scale_ = (1 - kNovelWordShare) * M.bg_unknown_scale_ + kNovelWordShare;
    };
    std::vector<double> punct_pseudo(V2, 0.0);
    for (int i = 0; i < 4; ++i) punct_pseudo[static_cast<size_t>(i)] = 0.5;
    {
      std::vector<double> cnt = punct_pseudo;
      for (size_t p = 0; p < pairs.size(); ++p) {
        // Content words start with a tenth of their frequency so the first
        // E-step credits them to the command's fields where those fit.
        for (const std::string& w : tokens[p]) {
          cnt[static_cast<size_t>(M.word_ids_.at(w))] += pairs[p].weight * (is_function_word(w) ? 1.0 : 0.1);
        }
      }
      set_background(cnt);
    }

    // Length model placeholder (uniform-ish) for the E-steps; refit each M-step.
    M.length_.assign(kMaxActionsBucket + 1, std::vector<double>(kMaxLen + 1, 0.0));
    M.length_tail_scale_.assign(kMaxActionsBucket + 1, 1.0);
    M.length_mean_.assign(kMaxActionsBucket + 1, 8.0);
    for (auto& row : M.length_) {
      for (int k = 0; k <= kMaxLen; ++k) row[static_cast<size_t>(k)] = length_base(k, 8.0);
    }

    std::vector<EncodedUtterance> encoded;
    for (const TrainingPair& p : pairs) encoded.push_back(M.encode(p.utterance));

    constexpr size_t kBatch = 16;  // each pair lists tens of thousands of additions
    util::WorkerPool pool(threads);
    std::vector<AlignmentModel::DeferredAdds> adds(kBatch);
    for (int it = 0; it < std::max(1, iterations); ++it) {
      AlignmentModel::Counts counts;
      counts.table.assign(M.tables_.size(), std::vector<double>(V2, 0.0));
      counts.bg = punct_pseudo;
      counts.length.assign(kMaxActionsBucket + 1, std::vector<double>(kMaxLen + 1, 0.0));
      // The E-step: on one thread, pair by pair; on several, in batches whose
      // pairs list their additions, then made in pair order, so the counts do
      // not depend on the threads.
      for (size_t p = 0; threads == 1 && p < pairs.size(); ++p) {
        auto b = M.bind(pairs[p].command);
        M.evaluate(*b, encoded[p], true, &counts, pairs[p].weight);
      }
      for (size_t first = 0; threads > 1 && first < pairs.size(); first += kBatch) {
        const size_t count = std::min(kBatch, pairs.size() - first);
        std::vector<std::shared_ptr<const AlignmentModel::Bound>> bound(count);
        for (size_t k = 0; k < count; ++k) bound[k] = M.bind(pairs[first + k].command);
        pool.run(count, [&](size_t k) {
          adds[k].clear();
          M.evaluate(*bound[k], encoded[first + k], true, &counts, pairs[first + k].weight, &adds[k]);
        });
        for (size_t k = 0; k < count; ++k)
          for (const auto& [slot, v] : adds[k]) *slot += v;
      }
      // M-step.
      for (size_t ti = 0; ti < M.tables_.size(); ++ti) {
        AlignmentModel::Table& t = *M.tables_[ti];
        std::vector<double>& cnt = counts.table[ti];
        // Content fields keep closed-class words at zero unless the base has them;
        // EM cannot move mass there anyway (their probability starts at zero).
        double total = 0;
        for (double v : cnt) total += v;
        t.prob.assign(V2, 0.0);
        for (size_t w = 0; w < V2; ++w) t.prob[w] = cnt[w] / (total + t.kappa);
        for (const auto& [id, p] : t.base) t.prob[static_cast<size_t>(id)] += t.kappa * p / (total + t.kappa);
      }
      set_background(counts.bg);
      for (int kind = 0; kind < 4; ++kind) {
        M.mention_[kind] = (counts.mention_on[kind] + 2 * kMention) / (counts.mention_all[kind] + 2);
        M.mention_[kind] = std::clamp(M.mention_[kind], 0.05, 0.95);
      }
      M.copy_alpha_ = (counts.copy + kAlphaPriorCopy) /
                      (counts.copy + counts.non_copy + kAlphaPriorCopy + kAlphaPriorOther);
      fit_length(M, counts.length);
    }
    return m;
  }

  // A length histogram with every long observation spread over nearby lengths
  // (triangular, half-width a fifth of the length; kept inside 0..kMaxLen), so
  // that one long training utterance does not make its exact length several
  // nats likelier than its neighbours. Short lengths are dense in training and
  // stay as counted. Total mass is kept.
  static std::vector<double> spread_lengths(const std::vector<double>& cnt) {
    std::vector<double> out(cnt.size(), 0.0);
    const int last = static_cast<int>(cnt.size()) - 1;
    for (int k = 0; k <= last; ++k) {
      const double c = cnt[static_cast<size_t>(k)];
      if (c <= 0) continue;
      if (k < kLengthSpreadFrom) {
        out[static_cast<size_t>(k)] += c;
        continue;
      }
      const int w = std::max(1, static_cast<int>(std::lround(kLengthSpread * k)));
      double z = 0;
      for (int d = -w; d <= w; ++d)
        if (k + d >= 0 && k + d <= last) z += w + 1 - std::abs(d);
      for (int d = -w; d <= w; ++d)
        if (k + d >= 0 && k + d <= last) out[static_cast<size_t>(k + d)] += c * (w + 1 - std::abs(d)) / z;
    }
    return out;
  }

  static void fit_length(AlignmentModel& M, const std::vector<std::vector<double>>& cnt) {
    // Mean length per action bucket, borrowing from neighbours when a bucket is empty.
    double all_n = 0, all_sum = 0;
    for (const auto& row : cnt) {
      for (int k = 0; k <= kMaxLen; ++k) {
        all_n += row[static_cast<size_t>(k)];
        all_sum += k * row[static_cast<size_t>(k)];
      }
    }
    const double overall = all_n > 0 ? all_sum / all_n : 8.0;
    for (size_t a = 0; a < cnt.size(); ++a) {
      double n = 0, s = 0;
      for (int k = 0; k <= kMaxLen; ++k) {
        n += cnt[a][static_cast<size_t>(k)];
        s += k * cnt[a][static_cast<size_t>(k)];
      }
      const double prior_mean = overall + 2.0 * (static_cast<double>(a) - 1.5);
      const double mean = std::max(2.0, (s + 3.0 * prior_mean) / (n + 3.0));
      M.length_mean_[a] = mean;
      // The base keeps at least kLengthBaseShare in every bucket, so beyond the
      // lengths seen in training all buckets have about the same tail: a long,
      // padded utterance says little about how many actions a command has, and
      // with a count-dependent share (kappa / (n + kappa)) the tail would be
      // thinnest for the commands the corpus happens to hold most of.
      const double base_share = std::max(kLengthBaseShare, kKappaLength / (n + kKappaLength));
      const std::vector<double> smooth = spread_lengths(cnt[a]);
      M.length_tail_scale_[a] = base_share;
      for (int k = 0; k <= kMaxLen; ++k) {
        const double seen = n > 0 ? smooth[static_cast<size_t>(k)] / n : 0.0;
        M.length_[a][static_cast<size_t>(k)] =
            (n > 0 ? (1 - base_share) * seen : 0.0) + (n > 0 ? base_share : 1.0) * length_base(k, mean);
      }
    }
  }
};

std::shared_ptr<AlignmentModel> AlignmentModel::train(const std::vector<TrainingPair>& pairs, int iterations,
                                                      const NounSenses& senses, int threads) {
  // By default the cores are shared among the trainings running at the time
  // (the embedded model trains a prompt's blocks side by side).
  static std::atomic<int> running{0};
  const int others = running.fetch_add(1);
  struct Leave {
    std::atomic<int>& n;
    ~Leave() { n.fetch_sub(1); }
  } leave{running};
  const int cores = std::min(8, static_cast<int>(std::max(1u, std::thread::hardware_concurrency())));
  auto m = Trainer::run(pairs, iterations, senses, threads > 0 ? threads : std::max(1, cores / (others + 1)));
  // Mass of the closed-class words and punctuation, for log_prob_unprimed.
  double closed = 0;
  for (size_t id = 0; id < m->words_.size() && id < m->bg_.size() && id < m->word_flags_.size(); ++id) {
    const uint8_t f = m->word_flags_[id];
    const bool punct = !m->words_[id].empty() && char_index(m->words_[id][0]) < 0 &&
                       !(f & (kWordNoun | kWordVerb | kWordModifier));
    if ((f & kWordFunction) || punct) closed += m->bg_[id];
  }
  m->closed_mass_ = closed;
  return m;
}

}  // namespace clips::lm
