#include "engine/options.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <functional>
#include <limits>
#include <mutex>
#include <regex>

#include <fmt/core.h>

#include "assist/assist.hpp"
#include "engine/methods.hpp"
#include "inference/belief.hpp"
#include "inference/particle_belief.hpp"
#include "language/listener.hpp"
#include "util/error.hpp"

namespace clips::engine {

namespace {

// More particles than this is a typo, not a setting: each particle costs a
// weight per step and the hypothesis spaces are far smaller.
constexpr long long kMaxParticles = 1'000'000;

struct Row {
  EngineOption option;
  std::function<void(ParticleOptions&, const std::string&)> set;  // text already checked
  std::function<std::string(const ParticleOptions&)> get;
};

[[noreturn]] void refuse(const EngineOption& o, const std::string& text) {
  throw InputError(o.name + " must be " + o.takes + ", got " + text);
}

// Digits only (no sign, no spaces) within [lo, hi].
template <typename T>
T parse_integer(const EngineOption& o, const std::string& text, T lo, T hi) {
  T v{};
  const char* end = text.data() + text.size();
  if (text.empty() || text.find_first_not_of("0123456789") != std::string::npos) refuse(o, text);
  const auto [ptr, ec] = std::from_chars(text.data(), end, v);
  if (ec != std::errc() || ptr != end || v < lo || v > hi) refuse(o, text);
  return v;
}

double parse_real(const EngineOption& o, const std::string& text, double lo, double hi) {
  char* end = nullptr;
  const double v = text.empty() ? NAN : std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size() || !(v >= lo && v <= hi)) refuse(o, text);  // NaN too
  return v;
}

std::string one_of(const std::vector<std::string>& choices) {
  std::string s = "one of ";
  for (size_t i = 0; i < choices.size(); ++i) s += (i ? ", " : "") + choices[i];
  return s;
}

template <typename T>
Row integer_row(std::string name, long long lo, long long hi, std::string brief, std::string help,
                T ParticleOptions::*field) {
  EngineOption o{std::move(name), EngineOption::Kind::Integer, fmt::format("an integer from {} to {}", lo, hi),
                   std::move(brief), std::move(help), {}, static_cast<double>(lo), static_cast<double>(hi), false, {}};
  return {o, [o, lo, hi, field](ParticleOptions& p, const std::string& t) {
            p.*field = static_cast<T>(parse_integer<long long>(o, t, lo, hi));
          },
          [field](const ParticleOptions& p) { return std::to_string(p.*field); }};
}

// The values, their help and the error's list come from the kind's one name
// table (util/choices.hpp), read when the table of options is built.
template <typename E>
Row choice_row(std::string name, const util::Choices<E>& table, std::string brief, const std::string& lead,
               std::string ParticleOptions::*field) {
  const ParticleOptions defaults;
  EngineOption o{std::move(name),
                   EngineOption::Kind::Choice,
                   one_of(table.names()),
                   std::move(brief),
                   lead + ": " + table.help_text() + " (default " + defaults.*field + ")",
                   table.names(),
                   {},
                   {},
                   false,
                   {}};
  return {o,
          [o, &table, field](ParticleOptions& p, const std::string& t) {
            if (!table.contains(t)) refuse(o, "'" + t + "'");
            p.*field = table.name(table.parse(t));
          },
          [field](const ParticleOptions& p) { return p.*field; }};
}

std::mutex& registered_mutex() {
  static std::mutex m;
  return m;
}
std::vector<EngineOption>& registered_table() {
  static std::vector<EngineOption> t;
  return t;
}

std::string bound_text(double v, EngineOption::Kind kind) {
  return kind == EngineOption::Kind::Integer ? std::to_string(static_cast<long long>(v)) : fmt::format("{}", v);
}

// "a number from 0 to 1", "an integer of at least 2", "one of low, high".
std::string takes_text(const EngineOption& o) {
  if (o.kind == EngineOption::Kind::Choice) return one_of(o.choices);
  std::string s = o.kind == EngineOption::Kind::Integer ? "an integer" : "a number";
  const auto k = o.kind;
  if (o.minimum && o.maximum) return s + " from " + bound_text(*o.minimum, k) + " to " + bound_text(*o.maximum, k);
  if (o.minimum) return s + " of at least " + bound_text(*o.minimum, k);
  if (o.maximum) return s + " of at most " + bound_text(*o.maximum, k);
  return s;
}

// The canonical text of a registered option's value (InputError when out of range).
std::string registered_value(const EngineOption& o, const std::string& text) {
  switch (o.kind) {
    case EngineOption::Kind::Integer: {
      long long v{};
      const char* end = text.data() + text.size();
      if (text.empty() || text.find_first_not_of("-0123456789") != std::string::npos) refuse(o, text);
      const auto [ptr, ec] = std::from_chars(text.data(), end, v);
      if (ec != std::errc() || ptr != end) refuse(o, text);
      if ((o.minimum && static_cast<double>(v) < *o.minimum) || (o.maximum && static_cast<double>(v) > *o.maximum))
        refuse(o, text);
      return std::to_string(v);
    }
    case EngineOption::Kind::Real: {
      const double v = parse_real(o, text, o.minimum.value_or(-HUGE_VAL), o.maximum.value_or(HUGE_VAL));
      if (!std::isfinite(v)) refuse(o, text);
      return fmt::format("{}", v);
    }
    case EngineOption::Kind::Choice:
      if (std::find(o.choices.begin(), o.choices.end(), text) == o.choices.end()) refuse(o, "'" + text + "'");
      return text;
    case EngineOption::Kind::Text:
    case EngineOption::Kind::List:
      break;  // not registrable
  }
  refuse(o, text);
}

Row registered_row(const EngineOption& o) {
  return {o, [o](ParticleOptions& p, const std::string& t) { p.registered_options[o.name] = registered_value(o, t); },
          [o](const ParticleOptions& p) {
            const auto it = p.registered_options.find(o.name);
            return it == p.registered_options.end() ? o.default_text : it->second;
          }};
}

// Built at each use, so a choice or an option registered at run time is listed (a few rows: cheap).
std::vector<Row> rows() {
  auto table = [] {
    std::vector<Row> t;
    t.push_back(integer_row("particles", 0, kMaxParticles, "particles per filter (0: exact enumeration)",
                            "Particle inference with N particles per modality (sequential Monte Carlo over goal x "
                            "cost profile; only the hypotheses particles hold are refined). 0: exact enumeration "
                            "(default)",
                            &ParticleOptions::particles));
    {
      EngineOption o{"particle_seed", EngineOption::Kind::Integer, "an integer from 0 to 18446744073709551615",
                       "the particle filters' seed",
                       "Seed of the particle filters (default 1); results are a function of it", {}, 0.0, {}, false, {}};
      t.push_back({o,
                   [o](ParticleOptions& p, const std::string& text) {
                     p.particle_seed = parse_integer<uint64_t>(o, text, 0, UINT64_MAX);
                   },
                   [](const ParticleOptions& p) { return std::to_string(p.particle_seed); }});
    }
    {
      EngineOption o{"ess_threshold", EngineOption::Kind::Real, "a number from 0 to 1",
                       "resample below this share of the particles",
                       "Resample when the effective sample size falls below this share of the particles (default "
                       "0.5; 1: every step)",
                       {}, 0.0, 1.0, false, {}};
      t.push_back({o, [o](ParticleOptions& p, const std::string& text) { p.ess_threshold = parse_real(o, text, 0, 1); },
                   [](const ParticleOptions& p) { return fmt::format("{}", p.ess_threshold); }});
    }
    t.push_back(integer_row("rejuvenation_moves", 0, 100, "Metropolis-Hastings sweeps after each resampling",
                            "Metropolis-Hastings sweeps over goals after each resampling (default 2; 0: none)",
                            &ParticleOptions::rejuvenation_moves));
    t.push_back(choice_row("rejuvenate", inference::rejuvenation_choices(), "when else the sweeps run",
                           "When the sweeps run besides after resampling", &ParticleOptions::rejuvenate));
    t.push_back(integer_row("proposal_groups", 1, 64, "exploring proposals per sweep",
                            "Independent exploring proposals per sweep: each sweep may bring in this many new "
                            "hypotheses per hypothesis held (default 8; fewer: cheaper, slower to find goals no "
                            "particle holds)",
                            &ParticleOptions::proposal_groups));
    t.push_back(choice_row("particle_filters", inference::particle_filters_choices(),
                           "one filter per method, or the CLIPS one only",
                           "Which posteriors get particles of their own", &ParticleOptions::particle_filters));
    t.push_back(choice_row("particle_estimate", inference::particle_estimate_choices(),
                           "exact weights on the held hypotheses, or weighted counts",
                           "How particles give the posterior", &ParticleOptions::particle_estimate));
    return t;
  }();
  std::lock_guard<std::mutex> lock(registered_mutex());
  for (const auto& o : registered_table()) table.push_back(registered_row(o));
  return table;
}

// The row named `name` of `table`; InputError listing the table's names.
template <typename R>
R find_row(std::vector<R> table, const std::string& name) {
  for (auto& r : table)
    if (r.option.name == name) return std::move(r);
  std::string known;
  for (const auto& r : table) known += (known.empty() ? "" : ", ") + r.option.name;
  throw InputError("unknown option '" + name + "' (known: " + known + ")");
}

Row row(const std::string& name) { return find_row(rows(), name); }

// ---- the session's own rows -------------------------------------------------

struct SessionRow {
  EngineOption option;
  std::function<void(SessionOptions&, const std::string&)> set;                     // every kind but List
  std::function<void(SessionOptions&, const std::vector<std::string>&)> set_list;   // List
  std::function<std::string(const SessionOptions&)> get;
};

EngineOption session_option(std::string name, EngineOption::Kind kind, std::string takes, std::string help,
                            std::vector<std::string> choices = {}, std::optional<double> lo = {},
                            std::optional<double> hi = {}) {
  EngineOption o{std::move(name), kind, std::move(takes), help, help, std::move(choices), lo, hi, false, {}};
  return o;
}

template <typename E>
SessionRow session_choice(std::string name, const util::Choices<E>& table, const std::string& lead,
                          E SessionOptions::*field) {
  EngineOption o = session_option(std::move(name), EngineOption::Kind::Choice, one_of(table.names()),
                                  lead + ": " + table.help_text(), table.names());
  return {o, [&table, field](SessionOptions& s, const std::string& t) { s.*field = table.parse(t); }, {},
          [&table, field](const SessionOptions& s) { return table.name(s.*field); }};
}

SessionRow session_list(std::string name, std::string help, std::vector<std::string> SessionOptions::*field) {
  return {session_option(std::move(name), EngineOption::Kind::List, "a list of strings", std::move(help)), {},
          [field](SessionOptions& s, const std::vector<std::string>& items) { s.*field = items; },
          [field](const SessionOptions& s) {
            std::string t;
            for (const auto& i : s.*field) t += (t.empty() ? "" : ", ") + i;
            return t;
          }};
}

// Built at each use: the choices of registered policies and options are listed.
std::vector<SessionRow> session_rows() {
  std::vector<SessionRow> t;
  t.push_back(session_choice("method", method_choices(), "the evidence the posterior uses and how the assistant decides",
                             &SessionOptions::method));
  t.push_back(session_choice("assistance", assistance_choices(), "how the assistant decides",
                             &SessionOptions::assistance));
  {
    const auto& table = language::language_model_choices();
    // The backend stays a name (LanguageModelOptions::backend), checked here.
    EngineOption o = session_option("lm", EngineOption::Kind::Choice, one_of(table.names()),
                                    "language model: " + table.help_text(), table.names());
    t.push_back({o, [&table](SessionOptions& s, const std::string& text) {
                   s.language_model.backend = table.name(table.parse(text));
                 },
                 {}, [](const SessionOptions& s) { return s.language_model.backend; }});
  }
  {
    EngineOption o = session_option("lm_base_url", EngineOption::Kind::Text, "a string",
                                    "openai: completions API base URL ('': $CLIPS_LM_BASE_URL, else OpenAI's)");
    t.push_back({o, [](SessionOptions& s, const std::string& text) { s.language_model.base_url = text; }, {},
                 [](const SessionOptions& s) { return s.language_model.base_url; }});
  }
  {
    EngineOption o = session_option("lm_model", EngineOption::Kind::Text, "a string",
                                    "openai: model name ('': $CLIPS_LM_MODEL, else davinci-002)");
    t.push_back({o, [](SessionOptions& s, const std::string& text) { s.language_model.model = text; }, {},
                 [](const SessionOptions& s) { return s.language_model.model; }});
  }
  {
    // At most a day: a longer wait is no timeout (and overflows libcurl's milliseconds).
    EngineOption o = session_option("lm_timeout", EngineOption::Kind::Real, "a number above 0 and at most 86400",
                                    "openai: seconds per request", {}, 0.0, 86400.0);
    t.push_back({o,
                 [o](SessionOptions& s, const std::string& text) {
                   const double v = parse_real(o, text, 0, 86400);
                   if (!(v > 0)) refuse(o, text);
                   s.language_model.timeout_seconds = v;
                 },
                 {}, [](const SessionOptions& s) { return fmt::format("{}", s.language_model.timeout_seconds); }});
  }
  t.push_back(session_list("goals", "candidate goals as PDDL conditions ([]: the domain pack's)", &SessionOptions::goals));
  t.push_back(session_list("cost_profiles", "candidate cost profiles ([]: the plan's or the pack's default)",
                           &SessionOptions::cost_profiles));
  {
    const long long hi = std::numeric_limits<long long>::max();
    EngineOption o = session_option("max_nodes", EngineOption::Kind::Integer, fmt::format("an integer from 1 to {}", hi),
                                    "expansions per lookahead search", {}, 1.0, {});
    t.push_back({o,
                 [o, hi](SessionOptions& s, const std::string& text) {
                   s.max_nodes = static_cast<size_t>(parse_integer<long long>(o, text, 1, hi));
                 },
                 {}, [](const SessionOptions& s) { return std::to_string(s.max_nodes); }});
  }
  {
    EngineOption o = session_option("threads", EngineOption::Kind::Integer, "an integer from 0 to 1024",
                                    "threads refining the hypotheses (0: all cores)", {}, 0.0, 1024.0);
    t.push_back({o,
                 [o](SessionOptions& s, const std::string& text) {
                   s.threads = static_cast<int>(parse_integer<long long>(o, text, 0, 1024));
                 },
                 {}, [](const SessionOptions& s) { return std::to_string(s.threads); }});
  }
  {
    EngineOption o = session_option("assist_max_nodes", EngineOption::Kind::Integer,
                                    fmt::format("an integer from 0 to {}", std::numeric_limits<long long>::max()),
                                    "expansions per search the assistant's decisions refine with (0: max_nodes)", {},
                                    0.0, {});
    t.push_back({o,
                 [o](SessionOptions& s, const std::string& text) {
                   s.assist_max_nodes = static_cast<size_t>(
                       parse_integer<long long>(o, text, 0, std::numeric_limits<long long>::max()));
                 },
                 {}, [](const SessionOptions& s) { return std::to_string(s.assist_max_nodes); }});
  }
  {
    const auto& table = assist::assist_rule_choices();
    std::vector<std::string> names = table.names();
    names.insert(names.begin(), "");
    EngineOption o = session_option("assist_rule", EngineOption::Kind::Choice, "'' or " + one_of(table.names()),
                                    "how Q_MDP breaks ties (as --assist-rule; '': the domain pack's): " +
                                        table.help_text(),
                                    names);
    t.push_back({o,
                 [&table](SessionOptions& s, const std::string& text) {
                   s.assist_rule = text.empty() ? text : table.name(table.parse(text));
                 },
                 {}, [](const SessionOptions& s) { return s.assist_rule; }});
  }
  {
    const auto& table = assist::qa_floor_choices();
    EngineOption o = session_option("qa_floor", EngineOption::Kind::Choice, one_of(table.names()),
                                    "which Q-values Q_MDP floors at waiting to the horizon (as --qa-floor): " +
                                        table.help_text(),
                                    table.names());
    t.push_back({o, [&table](SessionOptions& s, const std::string& text) { s.qa_floor = table.name(table.parse(text)); },
                 {}, [](const SessionOptions& s) { return s.qa_floor; }});
  }
  {
    EngineOption o = session_option("search_seconds", EngineOption::Kind::Real, "a number above 0 (inf: no limit)",
                                    "seconds per lookahead search (inf: none; a finite value makes results depend on "
                                    "the machine's speed)",
                                    {}, 0.0, {});
    t.push_back({o,
                 [o](SessionOptions& s, const std::string& text) {
                   char* end = nullptr;
                   const double v = text.empty() ? NAN : std::strtod(text.c_str(), &end);
                   if (text.empty() || end != text.c_str() + text.size() || !(v > 0)) refuse(o, text);  // NaN too
                   s.search_seconds = v;
                 },
                 {}, [](const SessionOptions& s) { return fmt::format("{}", s.search_seconds); }});
  }
  for (auto& r : rows())
    t.push_back({r.option, [set = r.set](SessionOptions& s, const std::string& text) { set(s, text); }, {},
                 [get = r.get](const SessionOptions& s) { return get(s); }});
  {
    const auto& table = inference::assistant_turns_choices();
    EngineOption o = session_option("assistant_turns", EngineOption::Kind::Choice, one_of(table.names()),
                                    "refinement at the assistant's turns (as --assistant-turns): " + table.help_text(),
                                    table.names());
    t.push_back({o, [&table](SessionOptions& s, const std::string& text) {
                   s.assistant_turns = table.name(table.parse(text));
                 },
                 {}, [](const SessionOptions& s) { return s.assistant_turns; }});
  }
  return t;
}

SessionRow session_row(const std::string& name) { return find_row(session_rows(), name); }

}  // namespace

std::vector<EngineOption> session_option_table() {
  std::vector<EngineOption> t;
  for (const auto& r : session_rows()) t.push_back(r.option);
  return t;
}

void set_session_option(SessionOptions& o, const std::string& name, const std::string& text) {
  const SessionRow r = session_row(name);
  if (r.option.kind == EngineOption::Kind::List) throw InputError(name + " must be a list of strings");
  r.set(o, text);
}

void set_session_option(SessionOptions& o, const std::string& name, const std::vector<std::string>& items) {
  const SessionRow r = session_row(name);
  if (r.option.kind != EngineOption::Kind::List) throw InputError(name + " must be " + r.option.takes + ", not a list");
  r.set_list(o, items);
}

std::string session_option_text(const SessionOptions& o, const std::string& name) { return session_row(name).get(o); }

std::string session_options_markdown() {
  const SessionOptions defaults;
  std::string md = "| option | takes | default | what it sets |\n|---|---|---|---|\n";
  for (const auto& r : session_rows()) {
    const std::string value = r.get(defaults);
    std::string shown;
    switch (r.option.kind) {
      case EngineOption::Kind::List: shown = value.empty() ? "`[]`" : "`[" + value + "]`"; break;
      case EngineOption::Kind::Choice:
      case EngineOption::Kind::Text: shown = "`'" + value + "'`"; break;
      default: shown = "`" + value + "`";
    }
    std::string help = r.option.help;
    std::replace(help.begin(), help.end(), '|', '/');  // a cell's text
    md += "| `" + r.option.name + "` | " + r.option.takes + " | " + shown + " | " + help + " |\n";
  }
  return md;
}

std::vector<EngineOption> option_table() {
  std::vector<EngineOption> t;
  for (const auto& r : rows()) t.push_back(r.option);
  return t;
}

std::string cli_flag(const EngineOption& option) {
  std::string flag = "--" + option.name;
  std::replace(flag.begin(), flag.end(), '_', '-');
  return flag;
}

std::string option_text(const ParticleOptions& o, const std::string& name) { return row(name).get(o); }

void set_option(ParticleOptions& o, const std::string& name, const std::string& text) {
  row(name).set(o, text);
}

void check_options(const ParticleOptions& o) {
  ParticleOptions scratch;
  const auto table = rows();
  for (const auto& r : table) r.set(scratch, r.get(o));
  for (const auto& [name, value] : o.registered_options)
    if (std::none_of(table.begin(), table.end(), [&](const Row& r) { return r.option.registered && r.option.name == name; }))
      row(name);  // the error naming the known options
}

const std::vector<std::string>& reserved_option_names() {
  // The arguments of Python's openers beside their keywords (dataset, ...).
  static const std::vector<std::string> names = {"dataset",     "problem",      "domain_dir", "problem_file",
                                                 "domain_text", "problem_text", "pack_text"};
  return names;
}

void register_option(EngineOption option) {
  static const std::regex word("[a-z][a-z0-9_]*");
  if (!std::regex_match(option.name, word))
    throw InputError("an option's name is lower-case letters, digits and '_' (the flag is --NAME with '-' for '_'), "
                     "got '" + option.name + "'");
  option.registered = true;
  if (option.kind == EngineOption::Kind::Text || option.kind == EngineOption::Kind::List)
    throw InputError("option '" + option.name + "': a registered option is an integer, a number or a choice");
  if (option.kind == EngineOption::Kind::Choice) {
    if (option.choices.empty()) throw InputError("option '" + option.name + "': a choice needs choices");
    option.minimum.reset();
    option.maximum.reset();
  } else {
    option.choices.clear();
    if ((option.minimum && !std::isfinite(*option.minimum)) || (option.maximum && !std::isfinite(*option.maximum)))
      throw InputError("option '" + option.name + "': its minimum and maximum are finite numbers (unset: unbounded)");
    if (option.minimum && option.maximum && *option.minimum > *option.maximum)
      throw InputError("option '" + option.name + "': its minimum is above its maximum");
  }
  option.takes = takes_text(option);
  if (option.brief.empty()) option.brief = option.help;
  option.default_text = registered_value(option, option.default_text);  // a default out of range says so now
  const auto& reserved = reserved_option_names();
  const auto table = session_rows();
  if (std::find(reserved.begin(), reserved.end(), option.name) != reserved.end() ||
      std::any_of(table.begin(), table.end(), [&](const SessionRow& r) { return r.option.name == option.name; })) {
    std::string taken;
    for (const auto& r : table) taken += (taken.empty() ? "" : ", ") + r.option.name;
    throw InputError("the option '" + option.name + "' is already taken (the session's options: " + taken +
                     "; and Python's openers' " + util::or_list(reserved) + ")");
  }
  std::lock_guard<std::mutex> lock(registered_mutex());
  registered_table().push_back(std::move(option));
}

void unregister_option(const std::string& name) {
  std::lock_guard<std::mutex> lock(registered_mutex());
  auto& t = registered_table();
  const auto it = std::find_if(t.begin(), t.end(), [&](const EngineOption& o) { return o.name == name; });
  if (it == t.end()) throw InputError("'" + name + "' is not an option registered with register_option");
  t.erase(it);
}

std::map<std::string, std::string> registered_option_values(const ParticleOptions& o) {
  std::map<std::string, std::string> values;
  for (const auto& r : rows())
    if (r.option.registered) values[r.option.name] = r.get(o);
  return values;
}

void apply_particle_options(const ParticleOptions& o, inference::InferenceOptions& io) {
  check_options(o);
  io.particles = o.particles;
  io.particle_seed = o.particle_seed;
  io.ess_threshold = o.ess_threshold;
  io.rejuvenation_moves = o.rejuvenation_moves;
  io.rejuvenate = inference::parse_rejuvenation(o.rejuvenate);
  io.proposal_groups = o.proposal_groups;
  io.particle_filters = inference::parse_particle_filters(o.particle_filters);
  io.particle_estimate = inference::parse_particle_estimate(o.particle_estimate);
}

}  // namespace clips::engine
