#include "lm/wordnet_lexicon.hpp"

#include <wn.h>

#include <algorithm>
#include <cctype>
#include <map>
#include <mutex>
#include <set>
#include <tuple>
#include <unordered_map>
#include <unordered_set>

#include "lm/language_model.hpp"

namespace clips::lm {
namespace {

std::mutex& wordnet_mutex() {
  static std::mutex m;
  return m;
}

// --- raw WordNet access; callers hold wordnet_mutex() ---------------------------

// Both are asked about the same words again and again (every model's
// vocabulary, every type's table), and each answer costs the C library a
// binary search with seeks in the index files: remembered here.
bool wn_has(const std::string& word, int pos) {
  if (word.empty()) return false;
  static std::map<std::pair<int, std::string>, bool> memo;
  auto [it, fresh] = memo.try_emplace({pos, word}, false);
  if (fresh) {
    std::string buf = word;
    it->second = in_wn(buf.data(), pos) != 0;
  }
  return it->second;
}

std::vector<std::string> wn_base_forms(const std::string& word, int pos) {
  static std::map<std::pair<int, std::string>, std::vector<std::string>> memo;
  auto [it, fresh] = memo.try_emplace({pos, word});
  if (fresh) {
    std::string buf = word;
    char* r = morphstr(buf.data(), pos);
    while (r != nullptr) {
      it->second.emplace_back(r);
      r = morphstr(nullptr, pos);
    }
  }
  return it->second;
}

// Is `form` an inflection of `lemma` according to WordNet's morphology?
bool inflects_to(const std::string& form, const std::string& lemma, int pos) {
  for (const std::string& b : wn_base_forms(form, pos)) {
    if (b == lemma) return true;
  }
  return false;
}

std::string lower_word(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// Words of the synsets of `word` (first `senses` senses) and of their hypernyms
// up to `levels` levels, split by relation: synonyms vs hypernym words.
void wn_related(const std::string& word, int pos, int senses, int levels,
                std::vector<std::string>& synonyms, std::vector<std::string>& hypernyms) {
  std::string buf = word;
  SynsetPtr head = findtheinfo_ds(buf.data(), pos, HYPERPTR, ALLSENSES);
  int sense = 0;
  for (SynsetPtr s = head; s != nullptr && sense < senses; s = s->nextss, ++sense) {
    for (int k = 0; k < s->wcount; ++k) synonyms.push_back(lower_word(s->words[k]));
    // Breadth over hypernym levels: ptrlist holds the first level; each of those
    // has its own ptrlist for the next.
    std::vector<SynsetPtr> frontier;
    for (SynsetPtr h = s->ptrlist; h != nullptr; h = h->nextss) frontier.push_back(h);
    for (int level = 0; level < levels && !frontier.empty(); ++level) {
      std::vector<SynsetPtr> next;
      for (SynsetPtr h : frontier) {
        for (int k = 0; k < h->wcount; ++k) hypernyms.push_back(lower_word(h->words[k]));
        for (SynsetPtr g = h->ptrlist; g != nullptr; g = g->nextss) next.push_back(g);
      }
      frontier = std::move(next);
      if (sense > 0) break;  // deeper hypernyms only for the dominant sense
    }
  }
  if (head != nullptr) free_syns(head);
}

// As wn_related, for chosen senses: (0-based sense, hypernym levels) pairs.
// The hypernyms are read by offset, so every level is reached.
void wn_related_senses(const std::string& word, int pos, const std::vector<std::pair<int, int>>& sense_levels,
                       std::vector<std::string>& synonyms, std::vector<std::string>& hypernyms) {
  std::string buf = word;
  IndexPtr idx = index_lookup(buf.data(), pos);
  if (idx == nullptr) return;
  const auto read = [&](long offset, std::vector<std::string>& words, std::vector<long>& up) {
    SynsetPtr s = read_synset(pos, offset, nullptr);
    if (s == nullptr) return;
    for (int k = 0; k < s->wcount; ++k) words.push_back(lower_word(s->words[k]));
    for (int i = 0; i < s->ptrcount; ++i)
      if ((s->ptrtyp[i] == HYPERPTR || s->ptrtyp[i] == INSTANCE) && s->ppos[i] == pos) up.push_back(s->ptroff[i]);
    free_synset(s);
  };
  for (const auto& [sense, levels] : sense_levels) {
    if (sense < 0 || sense >= idx->off_cnt) continue;
    std::vector<long> frontier;
    read(static_cast<long>(idx->offset[sense]), synonyms, frontier);
    for (int level = 0; level < levels && !frontier.empty(); ++level) {
      std::vector<long> next;
      for (long off : frontier) read(off, hypernyms, next);
      frontier = std::move(next);
    }
  }
  free_index(idx);
}

// --- English inflection candidates, kept only if WordNet maps them back -----------

std::vector<std::string> plural_forms(const std::string& w) {
  if (w.empty()) return {};
  std::vector<std::string> cand;
  auto ends = [&](std::string_view suf) {
    return w.size() >= suf.size() && w.compare(w.size() - suf.size(), suf.size(), suf) == 0;
  };
  const auto vowel = [](char c) { return std::string_view("aeiou").find(c) != std::string_view::npos; };
  if (ends("s") || ends("x") || ends("z") || ends("ch") || ends("sh")) {
    cand.push_back(w + "es");
  } else if (ends("y") && w.size() > 1 && !vowel(w[w.size() - 2])) {
    cand.push_back(w.substr(0, w.size() - 1) + "ies");
  } else if (ends("fe")) {
    cand.push_back(w.substr(0, w.size() - 2) + "ves");
    cand.push_back(w + "s");
  } else if (ends("f")) {
    cand.push_back(w.substr(0, w.size() - 1) + "ves");
    cand.push_back(w + "s");
  } else if (ends("o")) {
    cand.push_back(w + "es");
    cand.push_back(w + "s");
  } else {
    cand.push_back(w + "s");
  }
  std::vector<std::string> out;
  for (const std::string& c : cand) {
    if (inflects_to(c, w, NOUN)) out.push_back(c);
  }
  if (out.empty()) out.push_back(cand.front());
  return out;
}

std::vector<std::string> verb_forms(const std::string& w) {
  if (w.size() < 2) return {};
  const auto vowel = [](char c) { return std::string_view("aeiou").find(c) != std::string_view::npos; };
  std::string stem_ing = w;
  std::string stem_ed = w;
  if (w.back() == 'e') {
    stem_ing.pop_back();
    stem_ed.pop_back();
  } else if (w.size() <= 4 && w.size() >= 3 && !vowel(w.back()) && vowel(w[w.size() - 2]) &&
             !vowel(w[w.size() - 3]) && w.back() != 'w' && w.back() != 'x' && w.back() != 'y') {
    stem_ing.push_back(w.back());  // grab -> grabbing, get -> getting
    stem_ed.push_back(w.back());
  }
  std::vector<std::string> cand = {w + "s", w + "es", stem_ing + "ing", stem_ed + "ed"};
  std::vector<std::string> out;
  for (const std::string& c : cand) {
    if (c != w && inflects_to(c, w, VERB)) out.push_back(c);
  }
  return out;
}

// --- base construction ---------------------------------------------------------------

struct Accum {
  std::map<std::string, double> w;
  void add(const std::string& word, double weight) {
    if (word.empty() || weight <= 0) return;
    w[word] += weight;
  }
  // Spread `total` uniformly over the distinct single-token words of `words`
  // that are not function words and not already among `exclude`.
  void spread(const std::vector<std::string>& words, double total) {
    std::set<std::string> uniq;
    for (const std::string& x : words) {
      if (x.find_first_of("_ -'.") != std::string::npos) continue;
      if (is_function_word(x)) continue;
      uniq.insert(x);
    }
    for (const std::string& x : uniq) add(x, total / static_cast<double>(uniq.size()));
  }
  WordDistribution normalised() const {
    double z = 0;
    for (const auto& [k, v] : w) z += v;
    WordDistribution out;
    for (const auto& [k, v] : w) out.emplace_back(k, v / z);
    return out;
  }
};

// The lemma WordNet files a noun under: the word, or the base form of an
// inflected one that WordNet lacks as it is ("oats" -> "oat", "seeds" ->
// "seed"), so a type named in the plural still gets its senses.
std::string filed_noun(const std::string& word) {
  if (wn_has(word, NOUN)) return word;
  for (const std::string& b : wn_base_forms(word, NOUN))
    if (b != word && wn_has(b, NOUN)) return b;
  return word;
}

// Split a run-together name into WordNet words: ("pickup", VERB) -> {"pick", "up"}.
// Returns {name} if WordNet knows the whole name, else the split with the most
// balanced parts whose pieces are all known (or whose underscore compound is).
std::vector<std::string> split_name(const std::string& name, int pos) {
  if (wn_has(name, pos) || name.size() < 5) return {name};
  if (pos == NOUN && filed_noun(name) != name) return {name};  // an inflected noun, not two words
  std::vector<std::string> best;
  size_t best_min = 0;
  for (size_t i = 2; i + 2 <= name.size(); ++i) {
    const std::string a = name.substr(0, i);
    const std::string b = name.substr(i);
    const bool compound = wn_has(a + "_" + b, pos);
    const bool pieces = wn_has(a, pos == VERB ? VERB : NOUN) &&
                        (wn_has(b, NOUN) || wn_has(b, VERB) || is_function_word(b));
    if (!compound && !pieces) continue;
    // A known compound beats any split into pieces.
    const size_t score = std::min(a.size(), b.size()) + (compound ? 100 : 0);
    if (score > best_min) {
      best_min = score;
      best = {a, b};
    }
  }
  if (best.empty()) return {name};
  return best;
}

// The WordNet word a type name is looked up under, as noun_base does: the
// name, its two-word compound, or the compound's head.
std::string noun_lookup(const std::string& type) {
  const std::vector<std::string> parts = split_name(type, NOUN);
  if (parts.size() == 2) {
    const std::string compound = parts[0] + "_" + parts[1];
    return wn_has(compound, NOUN) ? compound : filed_noun(parts.back());
  }
  return filed_noun(type);
}

// Offsets of a word's first `max` noun senses, in WordNet's order.
std::vector<long> noun_sense_offsets(const std::string& word, size_t max) {
  std::vector<long> out;
  std::string buf = word;
  IndexPtr idx = index_lookup(buf.data(), NOUN);
  if (idx == nullptr) return out;
  for (int i = 0; i < idx->off_cnt && out.size() < max; ++i) out.push_back(static_cast<long>(idx->offset[i]));
  free_index(idx);
  return out;
}

// The noun hypernym graph (instance hypernyms too), read lazily by offset.
class NounGraph {
 public:
  const std::vector<long>& parents(long off) {
    if (auto it = parents_.find(off); it != parents_.end()) return it->second;
    std::vector<long> ps;
    if (SynsetPtr s = read_synset(NOUN, off, nullptr)) {
      for (int i = 0; i < s->ptrcount; ++i)
        if ((s->ptrtyp[i] == HYPERPTR || s->ptrtyp[i] == INSTANCE) && s->ppos[i] == NOUN) ps.push_back(s->ptroff[i]);
      kind_.emplace(off, s->fnum);
      free_synset(s);
    }
    return parents_.emplace(off, std::move(ps)).first->second;
  }
  // The synset's lexicographer file: its broad kind (artifact, food,
  // substance, body, person, ...).
  int kind(long off) {
    parents(off);
    const auto it = kind_.find(off);
    return it == kind_.end() ? -1 : it->second;
  }
  // Shortest hypernym path to a root.
  int depth(long off, int guard = 0) {
    if (auto it = depth_.find(off); it != depth_.end()) return it->second;
    int d = 0;
    const std::vector<long> ps = parents(off);
    if (!ps.empty() && guard < 40) {
      d = 1 << 20;
      for (long p : ps) d = std::min(d, 1 + depth(p, guard + 1));
    }
    depth_.emplace(off, d);
    return d;
  }
  // The synset and every hypernym above it.
  const std::set<long>& closure(long off) {
    if (auto it = closure_.find(off); it != closure_.end()) return it->second;
    std::set<long> seen{off};
    std::vector<long> todo{off};
    while (!todo.empty()) {
      const long x = todo.back();
      todo.pop_back();
      for (long p : parents(x))
        if (seen.insert(p).second) todo.push_back(p);
    }
    return closure_.emplace(off, std::move(seen)).first->second;
  }
  // Wu and Palmer's similarity: how deep the most specific common hypernym
  // lies against the depths of the two senses (1: the same synset).
  double similarity(long a, long b) {
    const std::set<long>& ca = closure(a);
    const std::set<long>& cb = closure(b);
    int shared = -1;
    for (long x : cb)
      if (ca.count(x)) shared = std::max(shared, depth(x));
    if (shared < 0) return 0;
    return 2.0 * (shared + 1) / static_cast<double>(depth(a) + depth(b) + 2);
  }

 private:
  std::unordered_map<long, std::vector<long>> parents_;
  std::unordered_map<long, int> depth_;
  std::unordered_map<long, std::set<long>> closure_;
  std::unordered_map<long, int> kind_;
};

}  // namespace

bool is_function_word(std::string_view w) {
  static const std::unordered_set<std::string_view> words = {
      "a", "an", "the", "this", "that", "these", "those", "some", "any", "each", "every",
      "my", "your", "his", "her", "its", "our", "their", "i", "me", "you", "we", "us", "it",
      "they", "them", "he", "she", "him", "myself", "yourself", "can", "could", "would",
      "will", "shall", "should", "may", "might", "must", "do", "does", "did", "be", "am",
      "is", "are", "was", "were", "been", "being", "have", "has", "had", "to", "for", "of",
      "on", "in", "at", "with", "from", "by", "up", "over", "off", "out", "into", "onto",
      "and", "or", "but", "while", "then", "so", "as", "if", "there", "here", "too", "also",
      "just", "now", "not", "no", "please", "s", "what", "which", "who", "where", "when",
      "how", "all", "both", "one", "ones", "two", "three", "four", "go", "going", "let",
      ",", ".", "?", "!"};
  return words.count(w) != 0;
}

WordNetLexicon& WordNetLexicon::instance() {
  static WordNetLexicon lex;
  return lex;
}

WordNetLexicon::WordNetLexicon() {
  std::lock_guard<std::mutex> lock(wordnet_mutex());
  if (wninit() != 0) {
    throw LmError("embedded LM: cannot open the WordNet dictionary (wninit failed; expected "
                  "Debian's wordnet in /usr/share/wordnet or $WNSEARCHDIR)");
  }
}

std::string WordNetLexicon::noun_lemma(const std::string& word) {
  std::lock_guard<std::mutex> lock(wordnet_mutex());
  auto forms = wn_base_forms(word, NOUN);
  return forms.empty() ? word : forms.front();
}

bool WordNetLexicon::sayable_name(const std::string& name) {
  std::string part;
  for (char c : name + "-") {
    if (std::isalpha(static_cast<unsigned char>(c))) {
      part.push_back(static_cast<char>(std::tolower(static_cast<unsigned char>(c))));
      continue;
    }
    if (part.size() >= 3 && knows(part)) return true;
    part.clear();
  }
  return false;
}

bool WordNetLexicon::knows(const std::string& word) {
  static std::unordered_map<std::string, bool> memo;
  std::lock_guard<std::mutex> lock(wordnet_mutex());
  if (auto it = memo.find(word); it != memo.end()) return it->second;
  bool known = false;
  for (int pos : {NOUN, VERB, ADJ, ADV}) known = known || wn_has(word, pos) || !wn_base_forms(word, pos).empty();
  memo.emplace(word, known);
  return known;
}

bool WordNetLexicon::names_place(const std::string& word) {
  static std::unordered_map<std::string, bool> memo;
  std::lock_guard<std::mutex> lock(wordnet_mutex());
  if (auto it = memo.find(word); it != memo.end()) return it->second;
  bool place = false;
  std::vector<std::string> forms = wn_base_forms(word, NOUN);
  forms.push_back(word);
  for (const std::string& f : forms) {
    std::string buf = f;
    SynsetPtr head = findtheinfo_ds(buf.data(), NOUN, HYPERPTR, 1);  // the dominant sense only
    // The whole hypernym tree of that sense (depth != 0: recursive).
    SynsetPtr tree = head != nullptr ? traceptrs_ds(head, HYPERPTR, NOUN, 1) : nullptr;
    std::vector<SynsetPtr> frontier;
    for (SynsetPtr h = tree; h != nullptr; h = h->nextss) frontier.push_back(h);
    for (int level = 0; level < 12 && !frontier.empty() && !place; ++level) {
      std::vector<SynsetPtr> next;
      for (SynsetPtr h : frontier) {
        for (int k = 0; k < h->wcount; ++k) {
          const std::string lemma = lower_word(h->words[k]);
          place = place || lemma == "area" || lemma == "location" || lemma == "region";
        }
        for (SynsetPtr g = h->ptrlist; g != nullptr; g = g->nextss) next.push_back(g);
      }
      frontier = std::move(next);
    }
    if (tree != nullptr) free_syns(tree);
    if (head != nullptr) free_syns(head);
    if (place || head != nullptr) break;
  }
  memo.emplace(word, place);
  return place;
}

WordNetLexicon::WordClass WordNetLexicon::word_class(const std::string& word) {
  // Memoised: training asks for every vocabulary word, twice, and each lookup
  // costs WordNet several seeks and reads of its index files.
  static std::unordered_map<std::string, WordClass> memo;
  std::lock_guard<std::mutex> lock(wordnet_mutex());
  if (auto it = memo.find(word); it != memo.end()) return it->second;
  auto senses = [&](int pos) {
    int best = 0;
    std::vector<std::string> forms = wn_base_forms(word, pos);
    forms.push_back(word);
    for (const std::string& f : forms) {
      std::string buf = f;
      IndexPtr idx = index_lookup(buf.data(), pos);
      if (idx != nullptr) {
        best = std::max(best, idx->off_cnt);
        free_index(idx);
      }
    }
    return best;
  };
  const int n = senses(NOUN);
  const int v = senses(VERB);
  WordClass c;
  c.noun_like = n >= v;
  c.verb_like = v >= n;
  const int a = senses(ADJ);
  c.adjective_like = a > n && a > v;
  memo.emplace(word, c);
  return c;
}

NounSenses WordNetLexicon::domain_noun_senses(const std::map<std::string, std::string>& parent_type,
                                              const std::vector<std::string>& types) {
  std::lock_guard<std::mutex> lock(wordnet_mutex());
  NounGraph graph;
  std::map<std::string, std::vector<long>> senses;
  auto senses_of = [&](const std::string& t) -> const std::vector<long>& {
    if (auto it = senses.find(t); it != senses.end()) return it->second;
    return senses.emplace(t, noun_sense_offsets(noun_lookup(t), kMaxDomainSenses)).first->second;
  };
  NounSenses out;
  for (const std::string& t : types) {
    const std::vector<long> mine = senses_of(t);
    if (mine.size() < 2) continue;
    // The context: the declared supertypes (the nearest weighs most) and the
    // types declared beside it, together as much as its parent.
    std::vector<std::pair<std::string, double>> context;
    std::string at = t;
    double weight = 1;
    for (int guard = 0; guard < 32; ++guard) {
      const auto it = parent_type.find(at);
      if (it == parent_type.end() || it->second == "object") break;
      at = it->second;
      context.emplace_back(at, weight);
      weight /= 2;
    }
    if (const auto it = parent_type.find(t); it != parent_type.end() && it->second != "object") {
      std::vector<std::string> siblings;
      for (const auto& [child, parent] : parent_type)
        if (parent == it->second && child != t) siblings.push_back(child);
      for (const std::string& sib : siblings) context.emplace_back(sib, 1.0 / static_cast<double>(siblings.size()));
    }
    std::vector<double> score(mine.size(), 0.0);
    std::set<int> context_kinds;
    double total = 0;
    for (const auto& [word, w] : context) {
      const std::vector<long> theirs = senses_of(word);
      if (theirs.empty()) continue;
      total += w;
      for (size_t j = 0; j < theirs.size() && j < kContextSenses; ++j) context_kinds.insert(graph.kind(theirs[j]));
      for (size_t i = 0; i < mine.size(); ++i) {
        // A context word's later senses count less: its first is what
        // the author most likely meant by it.
        double best = 0, rank_weight = 1;
        for (size_t j = 0; j < theirs.size() && j < kContextSenses; ++j, rank_weight *= kContextSenseDecay)
          best = std::max(best, rank_weight * graph.similarity(mine[i], theirs[j]));
        score[i] += w * best;
      }
    }
    if (total <= 0) continue;
    // A later sense must be of a kind the context has: near in the graph is
    // not enough when it is another sort of thing (garden supplies are
    // substances, and so, to WordNet, is the seed that is semen).
    for (size_t i = 1; i < mine.size(); ++i)
      if (context_kinds.count(graph.kind(mine[i])) == 0) score[i] = 0;
    const size_t pick = static_cast<size_t>(std::max_element(score.begin(), score.end()) - score.begin());
    // The first sense stays unless the domain clearly means another.
    if (pick != 0 && score[pick] > score[0] + kSenseMargin * total) out[t] = static_cast<int>(pick);
  }
  return out;
}

std::string WordNetLexicon::type_noun(const std::string& type) {
  std::lock_guard<std::mutex> lock(wordnet_mutex());
  const std::string lookup = noun_lookup(type);
  return wn_has(lookup, NOUN) ? lookup : std::string();
}

std::string WordNetLexicon::noun_gloss(const std::string& type, int sense) {
  std::lock_guard<std::mutex> lock(wordnet_mutex());
  const std::vector<long> offsets = noun_sense_offsets(noun_lookup(type), static_cast<size_t>(std::max(sense, 0)) + 1);
  if (sense < 0 || static_cast<size_t>(sense) >= offsets.size()) return {};
  std::string gloss;
  if (SynsetPtr s = read_synset(NOUN, offsets[static_cast<size_t>(sense)], nullptr)) {
    if (s->defn != nullptr) gloss = s->defn;
    free_synset(s);
  }
  // "(a gloss; \"an example\")": the gloss alone.
  if (const size_t cut = gloss.find(';'); cut != std::string::npos) gloss.erase(cut);
  if (!gloss.empty() && gloss.front() == '(') gloss.erase(gloss.begin());
  const auto count = [&](char c) { return std::count(gloss.begin(), gloss.end(), c); };
  while (!gloss.empty() && gloss.back() == ' ') gloss.pop_back();
  if (!gloss.empty() && gloss.back() == ')' && count(')') > count('(')) gloss.pop_back();
  return gloss;
}

WordDistribution WordNetLexicon::noun_base(const std::string& type, bool plural, int sense) {
  static std::map<std::tuple<std::string, bool, int>, WordDistribution> memo;
  std::lock_guard<std::mutex> lock(wordnet_mutex());
  auto key = std::make_tuple(type, plural, sense);
  if (auto it = memo.find(key); it != memo.end()) return it->second;

  Accum singular;  // weights over singular noun forms
  std::vector<std::string> parts = split_name(type, NOUN);
  std::string head = parts.back();
  std::string lookup = noun_lookup(type);
  // A name in the plural ("oats"): its lemma is the singular, and the things
  // are spoken of in the plural whatever their number.
  if (const std::string filed = filed_noun(head); filed != head) {
    head = filed;
    plural = true;
  }
  if (parts.size() == 2) {
    singular.add(head, 0.45);
    if (!is_function_word(parts[0])) singular.add(parts[0], 0.15);
  } else {
    singular.add(head, 0.6);
  }
  std::vector<std::string> syn, hyp;
  if (sense > 0) {
    // The domain's sense leads, with the first sense as the second.
    wn_related_senses(lookup, NOUN, {{sense, 2}, {0, 1}}, syn, hyp);
  } else {
    wn_related(lookup, NOUN, 2, 2, syn, hyp);
  }
  singular.spread(syn, 0.15);
  singular.spread(hyp, 0.1);
  // Pro-forms: "the blue one", "the red ones".
  singular.add("one", 0.05);

  Accum out;
  for (const auto& [word, weight] : singular.w) {
    if (word == "one") {
      out.add(plural ? "ones" : "one", weight);
      continue;
    }
    auto pl = plural_forms(word);
    const double share_plural = plural ? 0.85 : 0.05;
    out.add(word, weight * (1 - share_plural));
    for (const std::string& p : pl) out.add(p, weight * share_plural / static_cast<double>(pl.size()));
  }
  WordDistribution dist = out.normalised();
  memo[key] = dist;
  return dist;
}

namespace {

// Whether a noun synset is an instrumentality (tool, device, container,
// implement, ...): some hypernym path within 12 levels reaches it.
bool is_instrumentality(SynsetPtr s, int depth = 0) {
  if (s == nullptr || depth > 12) return false;
  for (int k = 0; k < s->wcount; ++k) {
    const std::string w = lower_word(s->words[k]);
    if (w == "instrumentality" || w == "instrumentation") return true;
  }
  for (int i = 0; i < s->ptrcount; ++i) {
    if (s->ptrtyp[i] != HYPERPTR) continue;
    SynsetPtr h = read_synset(s->ppos[i], s->ptroff[i], nullptr);
    const bool found = is_instrumentality(h, depth + 1);
    if (h != nullptr) free_synset(h);
    if (found) return true;
  }
  return false;
}

int sense_count(const std::string& word, int pos) {
  std::string buf = word;
  IndexPtr idx = index_lookup(buf.data(), pos);
  if (idx == nullptr) return 0;
  const int n = idx->off_cnt;
  free_index(idx);
  return n;
}

// More adjective senses than noun and verb senses ("sharp", "pointed").
bool adjective_dominant(const std::string& word) {
  const int a = sense_count(word, ADJ);
  return a > 0 && a > sense_count(word, NOUN) && a > sense_count(word, VERB);
}

std::vector<std::string> gloss_words(const char* defn) {
  std::vector<std::string> out;
  std::string cur;
  for (const char* c = defn; c != nullptr && *c != '\0' && *c != '"'; ++c) {
    const char ch = static_cast<char>(std::tolower(static_cast<unsigned char>(*c)));
    if (ch >= 'a' && ch <= 'z') {
      cur.push_back(ch);
    } else {
      if (!cur.empty()) out.push_back(cur);
      cur.clear();
      if (ch == ';') out.push_back(";");
    }
  }
  if (!cur.empty()) out.push_back(cur);
  return out;
}

}  // namespace

WordDistribution WordNetLexicon::function_words(const std::string& type) {
  static std::map<std::string, WordDistribution> memo;
  std::lock_guard<std::mutex> lock(wordnet_mutex());
  if (auto it = memo.find(type); it != memo.end()) return it->second;
  // Words that describe any object's size or shape are qualifier values,
  // not what the thing is for.
  static const std::set<std::string> plain = {"small", "large", "big", "little", "long", "short", "wide", "narrow",
                                              "heavy", "light", "tall", "high", "low", "thin", "thick", "open",
                                              "round", "flat", "shallow", "deep", "rigid", "other", "several"};
  // Verbs every gloss uses ("used to", "consisting of", "made of").
  static const std::set<std::string> generic = {"use", "make", "consist", "have", "be", "handle", "incorporate",
                                                "operate", "attach", "cover", "design", "include", "contain"};
  static const std::set<std::string> kinds = {"tool", "instrument", "utensil", "implement", "container",
                                              "vessel", "receptacle", "device", "used"};
  const std::string lookup = noun_lookup(type);
  Accum acc;
  auto add_verb = [&](const std::string& lemma, double weight) {
    if (lemma.find_first_of("_ -'.") != std::string::npos || is_function_word(lemma) || lemma == lookup ||
        generic.count(lemma))
      return;
    acc.add(lemma, weight);
    for (const std::string& f : verb_forms(lemma)) acc.add(f, weight * 0.5);
  };
  std::string buf = lookup;
  SynsetPtr head = findtheinfo_ds(buf.data(), NOUN, HYPERPTR, ALLSENSES);
  int used = 0, sense = 0;
  for (SynsetPtr s = head; s != nullptr && used < 2 && sense < 6; s = s->nextss, ++sense) {
    const std::vector<std::string> gloss = gloss_words(s->defn);
    bool kind = std::any_of(gloss.begin(), gloss.end(), [&](const std::string& w) { return kinds.count(w) != 0; });
    // Or a tool, container, ... by its hypernyms within three levels ("a sturdy hand shovel").
    std::vector<SynsetPtr> frontier;
    for (int i = 0; i < s->ptrcount; ++i)
      if (s->ptrtyp[i] == HYPERPTR) frontier.push_back(read_synset(s->ppos[i], s->ptroff[i], nullptr));
    for (int level = 0; level < 3 && !frontier.empty(); ++level) {
      std::vector<SynsetPtr> next;
      for (SynsetPtr h : frontier) {
        if (h == nullptr) continue;
        for (int k = 0; k < h->wcount; ++k) {
          const std::string hw = lower_word(h->words[k]);  // "edge_tool": its last part counts
          kind = kind || kinds.count(hw) != 0 || kinds.count(hw.substr(hw.rfind('_') + 1)) != 0;
        }
        for (int i = 0; i < h->ptrcount; ++i)
          if (h->ptrtyp[i] == HYPERPTR) next.push_back(read_synset(h->ppos[i], h->ptroff[i], nullptr));
        free_synset(h);
      }
      frontier = std::move(next);
    }
    for (SynsetPtr h : frontier)
      if (h != nullptr) free_synset(h);
    if (!kind || !is_instrumentality(s)) continue;
    ++used;
    // Verbs derived from the sense (spade -> spade), and their hypernyms (dig).
    for (int i = 0; i < s->ptrcount; ++i) {
      if (s->ptrtyp[i] != DERIVATION || s->ppos[i] != VERB) continue;
      SynsetPtr v = read_synset(VERB, s->ptroff[i], nullptr);
      if (v == nullptr) continue;
      for (int k = 0; k < v->wcount; ++k) add_verb(lower_word(v->words[k]), 1.0);
      for (int j = 0; j < v->ptrcount; ++j) {
        if (v->ptrtyp[j] != HYPERPTR) continue;
        SynsetPtr h = read_synset(VERB, v->ptroff[j], nullptr);
        if (h == nullptr) continue;
        for (int k = 0; k < h->wcount; ++k) add_verb(lower_word(h->words[k]), 0.5);
        free_synset(h);
      }
      free_synset(v);
    }
    // The gloss: purpose verbs ("used to measure", "for cutting") and
    // describing adjectives ("a sharp edge").
    for (size_t i = 0; i < gloss.size(); ++i) {
      const std::string& w = gloss[i];
      if (w == ";" || is_function_word(w) || plain.count(w) || w.size() < 3 || w == "used" || w == "such") continue;
      const bool after_to = i > 0 && gloss[i - 1] == "to";
      const bool gerund = w.size() > 4 && w.compare(w.size() - 3, 3, "ing") == 0;
      if (after_to || gerund) {
        std::vector<std::string> lemmas = wn_base_forms(w, VERB);
        if (lemmas.empty() && wn_has(w, VERB)) lemmas.push_back(w);
        if (!lemmas.empty()) {
          add_verb(lemmas.front(), 1.0);
          continue;
        }
      }
      if (adjective_dominant(w)) acc.add(w, 0.7);
    }
  }
  if (head != nullptr) free_syns(head);
  WordDistribution dist = acc.w.empty() ? WordDistribution{} : acc.normalised();
  memo[type] = dist;
  return dist;
}

WordDistribution WordNetLexicon::verb_base(const std::string& action, bool to_speaker) {
  static std::map<std::pair<std::string, bool>, WordDistribution> memo;
  std::lock_guard<std::mutex> lock(wordnet_mutex());
  auto key = std::make_pair(action, to_speaker);
  if (auto it = memo.find(key); it != memo.end()) return it->second;

  Accum lemmas;
  std::vector<std::string> parts = split_name(action, VERB);
  std::string lookup = action;
  if (parts.size() == 2) {
    const std::string compound = parts[0] + "_" + parts[1];
    lookup = wn_has(compound, VERB) ? compound : parts[0];
    lemmas.add(parts[0], 0.35);
    lemmas.add(parts[1], 0.15);  // particle ("up", "over"): allowed despite being a function word
  } else {
    lemmas.add(action, 0.5);
  }
  std::vector<std::string> syn, hyp;
  wn_related(lookup, VERB, 3, 1, syn, hyp);
  lemmas.spread(syn, 0.2);
  lemmas.spread(hyp, 0.15);

  Accum out;
  for (const auto& [word, weight] : lemmas.w) {
    auto forms = is_function_word(word) ? std::vector<std::string>{} : verb_forms(word);
    const double share = forms.empty() ? 0.0 : 0.3;
    out.add(word, weight * (1 - share));
    for (const std::string& f : forms) out.add(f, weight * share / static_cast<double>(forms.size()));
  }
  (void)to_speaker;  // the recipient ("me") is a mentionable unit of its own in the model
  WordDistribution dist = out.normalised();
  memo[key] = dist;
  return dist;
}

}  // namespace clips::lm

// ---- words for the generated corpus and for qualifier kinds ---------------------------

namespace clips::lm {
namespace {

// WordNet spells phrases with underscores ("pick_up").
std::string spaced(std::string w) {
  std::replace(w.begin(), w.end(), '_', ' ');
  return w;
}

bool plain_phrase(const std::string& w, size_t max_words) {
  if (w.empty() || w.front() == ' ' || w.back() == ' ') return false;
  size_t words = 1;
  for (char c : w) {
    if (c == ' ') ++words;
    else if (c < 'a' || c > 'z') return false;
  }
  return words <= max_words;
}

// Two spellings of one word ("color", "colour"; "gray", "grey").
bool spelling_variants(const std::string& a, const std::string& b) {
  if (a == b || a.size() < 3 || b.size() < 3) return false;
  if (a.size() == b.size()) {
    size_t diff = 0;
    for (size_t i = 0; i < a.size(); ++i) diff += a[i] != b[i];
    return diff == 1;
  }
  const std::string& l = a.size() > b.size() ? a : b;
  const std::string& s = a.size() > b.size() ? b : a;
  if (l.size() != s.size() + 1) return false;
  size_t i = 0;
  while (i < s.size() && l[i] == s[i]) ++i;
  return l.compare(i + 1, std::string::npos, s, i, std::string::npos) == 0;
}

void push_unique(std::vector<std::string>& out, const std::string& w) {
  if (!w.empty() && std::find(out.begin(), out.end(), w) == out.end()) out.push_back(w);
}

// Everyday verbs of a few action families. A family's verbs are offered for an
// action when one of its triggers is the action's own phrase or among the
// synonyms and direct hypernyms of its first two WordNet senses: WordNet
// relates "pick up" to "lift" and "hand over" to "give", but not to the
// colloquial "grab" or "bring" speakers actually use in requests.
struct VerbFamily {
  std::vector<std::string_view> triggers;
  std::vector<std::string_view> verbs;
};

const std::vector<VerbFamily>& verb_families() {
  static const std::vector<VerbFamily> families = {
      {{"get", "acquire", "take", "collect", "lift", "raise", "pick up", "fetch", "grab", "take hold"},
       {"get", "grab", "fetch", "take"}},
      {{"give", "pass", "hand", "deliver", "transfer", "hand over", "pass on"}, {"give", "hand", "pass", "bring"}},
      {{"put", "place", "set", "lay", "put down", "set down", "drop"}, {"put", "place", "set", "leave"}},
      {{"travel", "go", "move", "locomote", "walk"}, {"go", "move", "walk"}},
      {{"make", "create", "join", "build", "construct", "assemble"}, {"make", "build", "put together"}},
      {{"open", "unlock", "unfasten"}, {"open", "unlock"}},
      {{"close", "lock", "shut", "fasten"}, {"close", "lock", "shut"}},
      {{"clean", "wash", "wipe"}, {"clean", "wash", "wipe"}},
  };
  return families;
}

// A run-together or separated name as WordNet words ("pickup" -> "pick up").
std::vector<std::string> name_parts(const std::string& name, int pos) {
  std::vector<std::string> parts;
  std::string cur;
  for (char c : name) {
    if (c == '-' || c == '_' || c == ' ') {
      if (!cur.empty()) parts.push_back(cur);
      cur.clear();
    } else if (std::isalpha(static_cast<unsigned char>(c))) {
      cur.push_back(static_cast<char>(std::tolower(static_cast<unsigned char>(c))));
    }
  }
  if (!cur.empty()) parts.push_back(cur);
  if (parts.size() == 1) return split_name(parts[0], pos);
  return parts;
}

// Whether a synonym of `word` means it in one of its own first two senses:
// "board" (sense 2: a plank) may stand for "plank", but "cock" (a gun's hammer
// only in a late sense) may not stand for "hammer".
bool mutual_synonym(const std::string& synonym, const std::string& word, int pos) {
  std::vector<std::string> syn, hyp;
  std::string lookup = synonym;
  std::replace(lookup.begin(), lookup.end(), ' ', '_');
  wn_related(lookup, pos, 2, 0, syn, hyp);
  return std::find(syn.begin(), syn.end(), word) != syn.end();
}

std::string joined(const std::vector<std::string>& parts) {
  std::string out;
  for (const std::string& p : parts) out += (out.empty() ? "" : " ") + p;
  return out;
}

}  // namespace

std::vector<std::string> WordNetLexicon::qualifier_words(const std::string& predicate) {
  static std::map<std::string, std::vector<std::string>> memo;
  std::lock_guard<std::mutex> lock(wordnet_mutex());
  if (auto it = memo.find(predicate); it != memo.end()) return it->second;
  std::vector<std::string> parts;
  {
    std::string cur;
    for (char c : lower_word(predicate) + "-") {
      if (c == '-' || c == '_' || c == ' ') {
        if (!cur.empty() && cur != "is" && cur != "has" && cur != "of" && cur != "the") parts.push_back(cur);
        cur.clear();
      } else if (c >= 'a' && c <= 'z') {
        cur.push_back(c);
      }
    }
  }
  std::vector<std::string> out;
  if (!parts.empty()) {
    std::string kind = parts.back();
    for (std::string_view prefix : {"is", "has"}) {
      if (kind.size() > prefix.size() + 2 && kind.compare(0, prefix.size(), prefix) == 0 &&
          !wn_has(kind, NOUN) && wn_has(kind.substr(prefix.size()), NOUN)) {
        kind = kind.substr(prefix.size());
      }
    }
    if (wn_has(kind, NOUN)) {
      std::vector<std::string> variants = {kind}, syn, hyp;
      wn_related(kind, NOUN, 1, 0, syn, hyp);
      for (const std::string& s : syn)
        if (spelling_variants(kind, s)) push_unique(variants, s);
      for (const std::string& v : variants) {
        const std::string participle = v + (v.back() == 'e' ? "d" : "ed");
        if (wn_has(participle, ADJ)) push_unique(out, participle);
      }
      for (const std::string& v : variants) push_unique(out, v);
    }
  }
  memo.emplace(predicate, out);
  return out;
}

std::vector<std::pair<std::string, int>> WordNetLexicon::adjective_relatives(const std::string& value) {
  static std::map<std::string, std::vector<std::pair<std::string, int>>> memo;
  std::lock_guard<std::mutex> lock(wordnet_mutex());
  if (auto it = memo.find(value); it != memo.end()) return it->second;
  std::vector<std::pair<std::string, int>> out;
  // WordNet marks syntactic positions after adjectives ("metal(p)"): drop them.
  auto plain = [](const char* raw) {
    std::string w = lower_word(raw);
    if (const size_t paren = w.find('('); paren != std::string::npos) w.resize(paren);
    for (char c : w)
      if (c < 'a' || c > 'z') return std::string();
    return w;
  };
  auto add = [&](const std::string& w, int strength) {
    if (w.empty() || w == value) return;
    for (auto& [x, s] : out)
      if (x == w) {
        s = std::max(s, strength);
        return;
      }
    out.emplace_back(w, strength);
  };
  std::string buf = value;
  // The dominant sense only: later senses are figurative ("large" as in
  // "at large", "small" as in "small voice") and would map everyday words to
  // the wrong value.
  if (SynsetPtr head = findtheinfo_ds(buf.data(), ADJ, SIMPTR, 1); head != nullptr) {
    for (int k = 0; k < head->wcount; ++k) add(plain(head->words[k]), 3);
    for (SynsetPtr sim = head->ptrlist; sim != nullptr; sim = sim->nextss)
      for (int k = 0; k < sim->wcount; ++k) add(plain(sim->words[k]), 2);
    free_syns(head);
  }
  memo.emplace(value, out);
  return out;
}

std::vector<std::string> WordNetLexicon::verb_phrases(const std::string& action) {
  static std::map<std::string, std::vector<std::string>> memo;
  std::lock_guard<std::mutex> lock(wordnet_mutex());
  if (auto it = memo.find(action); it != memo.end()) return it->second;
  const std::vector<std::string> parts = name_parts(action, VERB);
  const std::string phrase = joined(parts);
  std::string lookup = phrase;
  std::replace(lookup.begin(), lookup.end(), ' ', '_');
  if (parts.size() > 1 && !wn_has(lookup, VERB)) lookup = parts.front();
  std::vector<std::string> first_syn, first_hyp, related, unused;
  wn_related(lookup, VERB, 1, 1, first_syn, first_hyp);
  wn_related(lookup, VERB, 2, 1, related, unused);
  for (const std::string& h : first_hyp) related.push_back(h);
  for (const std::string& h : unused) related.push_back(h);
  for (std::string& r : related) r = spaced(r);
  related.push_back(phrase);

  std::vector<std::string> out = {phrase};
  for (const VerbFamily& f : verb_families()) {
    const bool member = std::any_of(f.triggers.begin(), f.triggers.end(), [&](std::string_view t) {
      return std::find(related.begin(), related.end(), std::string(t)) != related.end();
    });
    if (member)
      for (std::string_view v : f.verbs) push_unique(out, std::string(v));
  }
  // The dominant sense's own synonyms (plain words or two-word phrasal verbs)
  // that mean the action in one of their own first senses; its hypernyms
  // ("raise" for "pick up") only choose the families above.
  for (const std::string& s : first_syn)
    if (plain_phrase(spaced(s), 2) && mutual_synonym(s, lookup, VERB)) push_unique(out, spaced(s));
  memo.emplace(action, out);
  return out;
}

std::vector<std::string> WordNetLexicon::noun_phrases(const std::string& type, int sense) {
  static std::map<std::pair<std::string, int>, std::vector<std::string>> memo;
  std::lock_guard<std::mutex> lock(wordnet_mutex());
  if (auto it = memo.find({type, sense}); it != memo.end()) return it->second;
  const std::vector<std::string> parts = name_parts(type, NOUN);
  std::string lookup = joined(parts);
  std::replace(lookup.begin(), lookup.end(), ' ', '_');
  std::vector<std::string> out;
  if (parts.size() > 1 && !wn_has(lookup, NOUN)) {
    lookup = parts.back();
    push_unique(out, parts.back());  // the head: "fork" for "cutleryfork"
    push_unique(out, joined(parts));
  } else {
    push_unique(out, joined(parts));
  }
  // A name in the plural is looked up by its lemma, which is not another name for it.
  if (parts.size() == 1) lookup = filed_noun(lookup);
  std::vector<std::string> syn, hyp;
  wn_related_senses(lookup, NOUN, {{std::max(sense, 0), 0}}, syn, hyp);
  for (const std::string& s : syn)
    if (plain_phrase(s, 1) && s != lookup && mutual_synonym(s, lookup, NOUN)) push_unique(out, s);
  memo.emplace(std::make_pair(type, sense), out);
  return out;
}

std::string WordNetLexicon::plural(const std::string& noun) {
  const size_t space = noun.rfind(' ');
  const std::string head = space == std::string::npos ? noun : noun.substr(space + 1);
  std::lock_guard<std::mutex> lock(wordnet_mutex());
  const std::vector<std::string> forms = plural_forms(head);
  return noun.substr(0, noun.size() - head.size()) + (forms.empty() ? head + "s" : forms.front());
}

}  // namespace clips::lm
