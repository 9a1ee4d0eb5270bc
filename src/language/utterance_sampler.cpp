#include "language/utterance_sampler.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <limits>
#include <set>

#include "commands/fewshot.hpp"
#include "language/listener.hpp"
#include "lm/domain_corpus.hpp"
#include "language/lm_domain.hpp"
#include "util/error.hpp"

namespace clips::language {

namespace {

std::string lower(std::string s) {
  for (auto& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// A command's shape: its prompt form with the qualifier values blanked out,
// and those values in order.
struct Shape {
  std::string key;
  std::vector<std::string> values;
};

std::optional<Shape> shape_of(const std::string& form, const commands::LanguageConfig& config) {
  const size_t where = form.find(" where ");
  Shape s;
  try {
    const auto actions = commands::parse_terms(form.substr(0, where));
    s.key = commands::to_pddl(actions);
    if (where == std::string::npos) return s;
    auto predicates = commands::parse_terms(form.substr(where + 7));
    const size_t value_at = config.qualifier_object_arg == 1 ? 1 : 0;
    for (auto& p : predicates)
      if (config.is_qualifier(p.name) && p.args.size() == 2) {
        s.values.push_back(p.args[value_at]);
        p.args[value_at] = "$";
      }
    s.key += " where " + commands::to_pddl(predicates);
  } catch (const std::invalid_argument&) {
    return std::nullopt;  // not a command of this grammar
  }
  return s;
}

// The action names a command text uses.
std::vector<std::string> action_names(const std::string& form) {
  std::vector<std::string> out;
  try {
    for (const auto& t : commands::parse_terms(form.substr(0, form.find(" where ")))) out.push_back(t.name);
  } catch (const std::invalid_argument&) {
  }
  return out;
}

// command<TAB>utterance lines; '#' starts a comment line.
std::vector<std::pair<std::string, std::string>> read_corpus(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(SourceLoc{path, 0, 0}, "cannot open the corpus file");
  std::vector<std::pair<std::string, std::string>> out;
  std::string line;
  while (std::getline(in, line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty() || line[0] == '#') continue;
    const size_t tab = line.find('\t');
    if (tab == std::string::npos) continue;
    out.push_back({line.substr(0, tab), line.substr(tab + 1)});
  }
  return out;
}

}  // namespace

struct UtteranceSampler::Entry {
  Shape shape;
  std::string utterance;
};

UtteranceSampler::UtteranceSampler(domains::PackPtr pack, std::shared_ptr<const pddl::Domain> domain,
                                   lm::LanguageModel& lm, const std::string& language_dir)
    : pack_(std::move(pack)), domain_(std::move(domain)), lm_(lm) {
  const std::string dir = language_dir.empty() ? language_data_dir() : language_dir;
  pragmatic_ = pack_->fewshot(/*literal=*/false, language_dir);
  literal_ = pack_->fewshot(/*literal=*/true, language_dir);
  std::vector<std::pair<std::string, std::string>> pairs;
  for (const auto& file : pack_->spec().embedded_corpus)
    for (auto& p : read_corpus(dir + "/" + file)) pairs.push_back(std::move(p));
  for (const auto* examples : {&pragmatic_, &literal_})
    for (const auto& e : *examples) pairs.push_back({e.command, e.utterance});
  corpus_ = entries_of(pairs);
  for (const auto& e : corpus_)
    for (const auto& v : e.shape.values) value_words_.insert(lower(v));
}

UtteranceSampler::~UtteranceSampler() = default;

std::vector<UtteranceSampler::Entry> UtteranceSampler::entries_of(
    const std::vector<std::pair<std::string, std::string>>& pairs) const {
  std::vector<Entry> out;
  for (const auto& [command, utterance] : pairs) {
    // Only commands over this domain's actions (a pack may train on other domains' corpora too).
    const auto names = action_names(command);
    if (names.empty() || std::any_of(names.begin(), names.end(),
                                     [&](const std::string& n) { return domain_->find_action(n) < 0; }))
      continue;
    if (auto s = shape_of(command, pack_->language())) out.push_back({std::move(*s), utterance});
  }
  return out;
}

const std::vector<UtteranceSampler::Entry>& UtteranceSampler::generated_entries(const pddl::Problem& problem) {
  auto it = generated_.find(problem.name);
  if (it != generated_.end()) return it->second;
  const auto& config = pack_->language();
  std::vector<std::pair<std::string, std::string>> pairs;
  for (const auto& p : lm::generate_domain_corpus(describe_for_language_model(*domain_, problem, config, config.qualifiers())))
    pairs.push_back({p.command, p.utterance});
  return generated_[problem.name] = entries_of(pairs);
}

Realisation UtteranceSampler::realise(const commands::Command* command, bool literal, const pddl::Problem& problem,
                                      util::Rng& rng, const commands::Command* listener_part) {
  Realisation r;
  std::set<std::string> pool;  // ordered: the draw must not depend on hash order
  std::string prompt(commands::kEmptyCommandPrompt);
  std::set<std::string> allowed_values;  // the command's qualifier values, lower case
  if (command) {
    r.command = command->llm_form();
    prompt = commands::build_prompt(literal ? literal_ : pragmatic_, r.command);
    auto collect = [&](const std::vector<Entry>& entries, const commands::Command* wanted_command) {
      if (!wanted_command) return;
      const auto wanted = shape_of(wanted_command->llm_form(), pack_->language());
      if (!wanted) return;
      for (const auto& e : entries)
        if (e.shape.key == wanted->key)
          if (auto text = rename_values(e.utterance, e.shape.values, wanted->values)) pool.insert(*text);
    };
    if (const auto own = shape_of(r.command, pack_->language()))
      for (const auto& v : own->values) allowed_values.insert(lower(v));
    collect(corpus_, command);
    r.pool = "corpus";
    if (pool.empty()) {
      collect(corpus_, listener_part);
      r.pool = "listener part";
    }
    if (pool.empty()) {
      collect(generated_entries(problem), command);
      if (pool.empty()) collect(generated_entries(problem), listener_part);
      r.pool = "generated";
    }
  }
  if (pool.empty()) {
    // No colour (or other value) the command does not name.
    auto foreign = [&](const std::string& text) {
      std::string word;
      for (size_t i = 0; i <= text.size(); ++i) {
        if (i < text.size() && std::isalnum(static_cast<unsigned char>(text[i]))) {
          word += static_cast<char>(std::tolower(static_cast<unsigned char>(text[i])));
          continue;
        }
        if (!word.empty() && value_words_.count(word) && !allowed_values.count(word)) return true;
        word.clear();
      }
      return false;
    };
    for (const auto& e : corpus_)
      if (!foreign(e.utterance)) pool.insert(e.utterance);
    if (pool.empty())
      for (const auto& e : corpus_) pool.insert(e.utterance);
    r.pool = "any";
  }
  if (pool.empty()) throw InputError("no phrasing to draw an utterance from (pack " + pack_->name() + " has no corpus)");

  const std::vector<std::string> texts(pool.begin(), pool.end());
  std::vector<lm::ScoreRequest> batch;
  for (const auto& t : texts) batch.push_back({prompt, commands::utterance_continuation(t)});
  const std::vector<double> scores = lm_.score(batch);
  if (scores.size() != texts.size()) throw lm::LmError(lm_.name() + ": wrong number of scores");
  double best = -std::numeric_limits<double>::infinity();
  for (double s : scores)
    if (!std::isnan(s)) best = std::max(best, s);
  std::vector<double> weight(texts.size(), 1.0);  // every score -inf: a uniform draw
  if (std::isfinite(best))
    for (size_t i = 0; i < texts.size(); ++i) weight[i] = std::isnan(scores[i]) ? 0.0 : std::exp(scores[i] - best);
  double total = 0;
  for (double w : weight) total += w;
  const size_t pick = rng.weighted(weight);
  r.text = texts[pick];
  r.candidates = texts.size();
  r.probability = weight[pick] / total;
  return r;
}

std::optional<commands::Command> listener_part(const commands::Command& command,
                                               const commands::LanguageConfig& config,
                                               const commands::QualifierLookup& qualifier_of,
                                               const commands::TypeLookup& type_of) {
  std::vector<commands::Term> ground;
  bool speaker_acts = false;
  for (const auto& t : commands::substitute(command.actions, command.binding)) {
    const commands::Term named = commands::to_agent_names(t, config);
    const commands::SalientActionRule* rule = config.salient_rule(named.name);
    const size_t agent = rule ? static_cast<size_t>(rule->agent_arg - 1) : 0;
    if (agent < named.args.size() && named.args[agent] == config.speaker) {
      speaker_acts = true;
      continue;
    }
    ground.push_back(named);
  }
  if (!speaker_acts || ground.empty()) return std::nullopt;
  return commands::lift_command(commands::extract_salient(ground, config, qualifier_of), config, type_of);
}

std::optional<std::string> rename_values(const std::string& text, const std::vector<std::string>& from,
                                         const std::vector<std::string>& to) {
  if (from.size() != to.size()) return std::nullopt;
  std::map<std::string, std::string> forward, backward;
  for (size_t i = 0; i < from.size(); ++i) {
    const std::string f = lower(from[i]), t = lower(to[i]);
    auto [fi, fresh_f] = forward.emplace(f, t);
    auto [bi, fresh_b] = backward.emplace(t, f);
    if ((!fresh_f && fi->second != t) || (!fresh_b && bi->second != f)) return std::nullopt;
  }
  std::string out;
  size_t i = 0;
  while (i < text.size()) {
    if (!std::isalnum(static_cast<unsigned char>(text[i]))) {
      out += text[i++];
      continue;
    }
    size_t j = i;
    while (j < text.size() && std::isalnum(static_cast<unsigned char>(text[j]))) ++j;
    std::string word = text.substr(i, j - i);
    auto it = forward.find(lower(word));
    if (it != forward.end()) {
      std::string repl = it->second;
      if (std::isupper(static_cast<unsigned char>(word[0])) && !repl.empty())
        repl[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(repl[0])));
      word = repl;
    }
    out += word;
    i = j;
  }
  return out;
}

}  // namespace clips::language
