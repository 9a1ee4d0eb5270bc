#include "engine/options.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <functional>

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
  ParticleOption option;
  std::function<void(ParticleOptions&, const std::string&)> set;  // text already checked
  std::function<std::string(const ParticleOptions&)> get;
};

[[noreturn]] void refuse(const ParticleOption& o, const std::string& text) {
  throw InputError(o.name + " must be " + o.takes + ", got " + text);
}

// Digits only (no sign, no spaces) within [lo, hi].
template <typename T>
T parse_integer(const ParticleOption& o, const std::string& text, T lo, T hi) {
  T v{};
  const char* end = text.data() + text.size();
  if (text.empty() || text.find_first_not_of("0123456789") != std::string::npos) refuse(o, text);
  const auto [ptr, ec] = std::from_chars(text.data(), end, v);
  if (ec != std::errc() || ptr != end || v < lo || v > hi) refuse(o, text);
  return v;
}

double parse_real(const ParticleOption& o, const std::string& text, double lo, double hi) {
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
  ParticleOption o{std::move(name), ParticleOption::Kind::Integer, fmt::format("an integer from {} to {}", lo, hi),
                   std::move(brief), std::move(help), {}, static_cast<double>(lo), static_cast<double>(hi)};
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
  ParticleOption o{std::move(name),
                   ParticleOption::Kind::Choice,
                   one_of(table.names()),
                   std::move(brief),
                   lead + ": " + table.help_text() + " (default " + defaults.*field + ")",
                   table.names(),
                   {},
                   {}};
  return {o,
          [o, &table, field](ParticleOptions& p, const std::string& t) {
            if (!table.contains(t)) refuse(o, "'" + t + "'");
            p.*field = table.name(table.parse(t));
          },
          [field](const ParticleOptions& p) { return p.*field; }};
}

// Built at each use, so a choice registered at run time is listed (eight rows: cheap).
std::vector<Row> rows() {
  return [] {
    std::vector<Row> t;
    t.push_back(integer_row("particles", 0, kMaxParticles, "particles per filter (0: exact enumeration)",
                            "Particle inference with N particles per modality (sequential Monte Carlo over goal x "
                            "cost profile; only the hypotheses particles hold are refined). 0: exact enumeration "
                            "(default)",
                            &ParticleOptions::particles));
    {
      ParticleOption o{"particle_seed", ParticleOption::Kind::Integer, "an integer from 0 to 18446744073709551615",
                       "the particle filters' seed",
                       "Seed of the particle filters (default 1); results are a function of it", {}, 0.0, {}};
      t.push_back({o,
                   [o](ParticleOptions& p, const std::string& text) {
                     p.particle_seed = parse_integer<uint64_t>(o, text, 0, UINT64_MAX);
                   },
                   [](const ParticleOptions& p) { return std::to_string(p.particle_seed); }});
    }
    {
      ParticleOption o{"ess_threshold", ParticleOption::Kind::Real, "a number from 0 to 1",
                       "resample below this share of the particles",
                       "Resample when the effective sample size falls below this share of the particles (default "
                       "0.5; 1: every step)",
                       {}, 0.0, 1.0};
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
}

Row row(const std::string& name) {
  for (auto& r : rows())
    if (r.option.name == name) return r;
  std::string known;
  for (const auto& r : rows()) known += (known.empty() ? "" : ", ") + r.option.name;
  throw InputError("unknown particle option '" + name + "' (known: " + known + ")");
}

}  // namespace

std::vector<ParticleOption> particle_option_table() {
  std::vector<ParticleOption> t;
  for (const auto& r : rows()) t.push_back(r.option);
  return t;
}

std::string cli_flag(const ParticleOption& option) {
  std::string flag = "--" + option.name;
  std::replace(flag.begin(), flag.end(), '_', '-');
  return flag;
}

std::string particle_option_text(const ParticleOptions& o, const std::string& name) { return row(name).get(o); }

void set_particle_option(ParticleOptions& o, const std::string& name, const std::string& text) {
  row(name).set(o, text);
}

void check_particle_options(const ParticleOptions& o) {
  ParticleOptions scratch;
  for (const auto& r : rows()) r.set(scratch, r.get(o));
}

void apply_particle_options(const ParticleOptions& o, inference::InferenceOptions& io) {
  check_particle_options(o);
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
