#include "engine/options.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <functional>
#include <mutex>
#include <regex>

#include <fmt/core.h>

#include "inference/belief.hpp"
#include "inference/particle_belief.hpp"
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

Row row(const std::string& name) {
  for (auto& r : rows())
    if (r.option.name == name) return r;
  std::string known;
  for (const auto& r : rows()) known += (known.empty() ? "" : ", ") + r.option.name;
  throw InputError("unknown option '" + name + "' (known: " + known + ")");
}

}  // namespace

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
  // Python's own session keywords and its openers' arguments
  // (python/tests checks the keywords are all here), and the session's
  // other fields.
  static const std::vector<std::string> names = {
      "method", "assistance", "lm", "lm_base_url", "lm_model", "lm_timeout", "goals", "cost_profiles", "max_nodes",
      "threads", "assistant_turns", "dataset", "problem", "domain_dir", "problem_file", "domain_text",
      "problem_text", "pack_text", "assist_max_nodes", "assist_rule", "qa_floor", "search_seconds",
      "language_model", "registered_options"};
  return names;
}

void register_option(EngineOption option) {
  static const std::regex word("[a-z][a-z0-9_]*");
  if (!std::regex_match(option.name, word))
    throw InputError("an option's name is lower-case letters, digits and '_' (the flag is --NAME with '-' for '_'), "
                     "got '" + option.name + "'");
  option.registered = true;
  if (option.kind == EngineOption::Kind::Choice) {
    if (option.choices.empty()) throw InputError("option '" + option.name + "': a choice needs choices");
    option.minimum.reset();
    option.maximum.reset();
  } else {
    option.choices.clear();
    if (option.minimum && option.maximum && *option.minimum > *option.maximum)
      throw InputError("option '" + option.name + "': its minimum is above its maximum");
  }
  option.takes = takes_text(option);
  if (option.brief.empty()) option.brief = option.help;
  registered_value(option, option.default_text);  // a default out of range says so now
  const auto& reserved = reserved_option_names();
  const auto table = rows();
  if (std::find(reserved.begin(), reserved.end(), option.name) != reserved.end() ||
      std::any_of(table.begin(), table.end(), [&](const Row& r) { return r.option.name == option.name; })) {
    std::string taken;
    for (const auto& r : table) taken += (taken.empty() ? "" : ", ") + r.option.name;
    throw InputError("the option '" + option.name + "' is already taken (the table's: " + taken +
                     "; and the front ends' " + util::or_list(reserved) + ")");
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
