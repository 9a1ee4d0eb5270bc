#include "engine/runs.hpp"
#include "studies/particle_eval.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "data/dataset.hpp"
#include "engine/options.hpp"
#include "inference/belief.hpp"
#include "lm/cached_model.hpp"
#include "util/error.hpp"

namespace clips::studies {

namespace {

double tv(const std::vector<double>& p, const std::vector<double>& q) {
  double s = 0;
  for (size_t i = 0; i < p.size() && i < q.size(); ++i) s += std::abs(p[i] - q[i]);
  return s / 2;
}

// Nearest-rank quantile of sorted values.
double quantile(const std::vector<double>& sorted, double q) {
  const size_t n = sorted.size();
  const size_t rank = static_cast<size_t>(std::ceil(q * static_cast<double>(n)));
  return sorted[std::min(n - 1, rank == 0 ? 0 : rank - 1)];
}

}  // namespace

Distribution distribution(std::vector<double> xs) {
  Distribution d;
  if (xs.empty()) return d;
  std::sort(xs.begin(), xs.end());
  double s = 0;
  for (double x : xs) s += x;
  d.mean = s / static_cast<double>(xs.size());
  d.min = xs.front();
  d.max = xs.back();
  d.median = xs.size() % 2 ? xs[xs.size() / 2] : (xs[xs.size() / 2 - 1] + xs[xs.size() / 2]) / 2;
  d.p90 = quantile(xs, 0.9);
  return d;
}

ParticleEvalReport run_particle_eval(const ParticleEvalOptions& o) {
  if (!o.language_model) throw InputError("particle evaluation needs a language model");
  if (o.particles.empty()) throw InputError("particle evaluation needs at least one particle count");
  for (int n : o.particles)
    if (n < 1) throw InputError(fmt::format("particle counts must be positive, not {}", n));
  if (o.seeds < 1) throw InputError("particle evaluation needs at least one seed");
  const data::Dataset ds = data::Dataset::load(o.dataset);
  ParticleEvalReport rep;
  rep.dataset = o.dataset;
  rep.lm = o.language_model->name();
  rep.settings = {{"ess_threshold", engine::option_text(o.tuning, "ess_threshold")},
                  {"rejuvenation_moves", engine::option_text(o.tuning, "rejuvenation_moves")},
                  {"rejuvenate", engine::option_text(o.tuning, "rejuvenate")},
                  {"proposal_groups", engine::option_text(o.tuning, "proposal_groups")},
                  {"particle_filters", engine::option_text(o.tuning, "particle_filters")},
                  {"particle_estimate", engine::option_text(o.tuning, "particle_estimate")},
                  {"assistant_turns", inference::to_string(o.assistant_turns)}};
  std::vector<const data::PlanRecord*> todo;
  for (const auto& p : ds.plans()) {
    const bool wanted = o.plans.empty() ? p.evaluated : std::find(o.plans.begin(), o.plans.end(), p.id) != o.plans.end();
    if (wanted) todo.push_back(&p);
  }
  if (!o.plans.empty() && todo.size() != o.plans.size())
    throw InputError("--plans names a plan that is not in " + o.dataset);
  if (todo.empty()) throw InputError("no plans to evaluate in " + o.dataset);

  inference::InferenceOptions base;
  base.threads = 1;  // comparable single-core times
  base.utterance.speaker_rule = o.speaker_rule;
  base.utterance.plans = o.speaker_plans;
  base.utterance_timing = o.utterance_timing;
  base.assistant_turns = o.assistant_turns;
  {
    ParticleOptions tuning = o.tuning;
    tuning.particles = 0;  // the exact run; the particle runs set their count and seed below
    engine::apply_particle_options(tuning, base);
  }
  // Every timed run starts with an empty score cache: otherwise the runs
  // after the first would find the exact run's language-model scores there
  // and look cheaper than they are.
  auto cold = [cache = dynamic_cast<lm::CachedLanguageModel*>(o.language_model.get())] {
    if (cache) cache->clear();
  };
  size_t done = 0;
  for (const data::PlanRecord* p : todo) {
    ++done;
    try {
      cold();
      const inference::InferenceRun exact = engine::run_inference(ds, *p, *o.language_model, base);
      ++rep.plans;
      for (int n : o.particles)
        for (int s = 1; s <= o.seeds; ++s) {
          inference::InferenceOptions io = base;
          io.particles = n;
          io.particle_seed = static_cast<uint64_t>(s);
          cold();
          const inference::InferenceRun run = engine::run_inference(ds, *p, *o.language_model, io);
          ParticleEvalRow r;
          r.plan = p->id;
          r.goals = static_cast<int>(exact.goals.size());
          r.hypotheses = static_cast<int>(exact.belief->hypotheses().size());
          r.steps = static_cast<int>(exact.steps.size()) - 1;
          r.particles = n;
          r.seed = io.particle_seed;
          using inference::Modality;
          r.tv_final = tv(exact.final_posterior(Modality::Both).goals, run.final_posterior(Modality::Both).goals);
          r.tv_action_final =
              tv(exact.final_posterior(Modality::ActionOnly).goals, run.final_posterior(Modality::ActionOnly).goals);
          double sum = 0;
          for (size_t t = 0; t < exact.steps.size(); ++t) {
            const double d = tv(exact.steps[t][Modality::Both].goals, run.steps[t][Modality::Both].goals);
            sum += d;
            r.tv_steps_max = std::max(r.tv_steps_max, d);
          }
          r.tv_steps_mean = sum / static_cast<double>(exact.steps.size());
          r.exact_seconds = exact.seconds;
          r.particle_seconds = run.seconds;
          r.exact_refinements = exact.belief->refinements();
          r.particle_refinements = run.belief->refinements();
          if (const auto* st = run.belief->particle_stats(Modality::Both)) r.resamples = st->resamples;
          rep.rows.push_back(std::move(r));
        }
    } catch (const InputError& e) {
      rep.failed.push_back(p->id + ": " + e.what());
    }
    if (o.progress) fmt::print(stderr, "\rbench particles: {}/{} plans", done, todo.size());
  }
  if (o.progress) fmt::print(stderr, "\n");

  for (int n : o.particles) {
    ParticleEvalSummary s;
    s.particles = n;
    std::vector<double> fin, steps, ratios;
    double ps = 0, es = 0, pr = 0, er = 0;
    for (const auto& r : rep.rows) {
      if (r.particles != n) continue;
      ++s.runs;
      fin.push_back(r.tv_final);
      steps.push_back(r.tv_steps_mean);
      if (r.exact_seconds > 0) ratios.push_back(r.particle_seconds / r.exact_seconds);
      ps += r.particle_seconds;
      es += r.exact_seconds / o.seeds;  // each plan's exact run counts once per count
      pr += static_cast<double>(r.particle_refinements);
      er += static_cast<double>(r.exact_refinements) / o.seeds;
    }
    s.tv_final = distribution(fin);
    s.tv_steps = distribution(steps);
    s.time_ratio = es > 0 ? ps / o.seeds / es : 0;
    s.time_ratio_median = distribution(ratios).median;
    s.refinement_ratio = er > 0 ? pr / o.seeds / er : 0;
    rep.summary.push_back(s);
  }
  return rep;
}

std::string format_particle_eval(const ParticleEvalReport& rep) {
  std::string out = fmt::format("particle vs exact inference on {} ({} plans, {}; CLIPS goal posterior)\n",
                                rep.dataset, rep.plans, rep.lm);
  std::string settings;
  for (const auto& [k, v] : rep.settings) settings += (settings.empty() ? "" : ", ") + k + " " + v;
  if (!settings.empty()) out += "settings: " + settings + "\n";
  out += fmt::format("{:>6} {:>5}  {:>33}  {:>6}  {:>7} {:>7} {:>7}\n", "N", "runs",
                     "TV final: mean min med p90 max", "TV/step", "time", "t med", "refine");
  for (const auto& s : rep.summary)
    out += fmt::format("{:>6} {:>5}  {:>6.4f} {:>6.4f} {:>6.4f} {:>6.4f} {:>6.4f}  {:>7.4f}  {:>7.3f} {:>7.3f} {:>7.3f}\n",
                       s.particles, s.runs, s.tv_final.mean, s.tv_final.min, s.tv_final.median, s.tv_final.p90,
                       s.tv_final.max, s.tv_steps.mean, s.time_ratio, s.time_ratio_median, s.refinement_ratio);
  out += "TV/step: mean over plans of the per-step TV averaged over steps; time, refine: particle / exact totals "
         "(t med: median per-run ratio)\n";
  for (const auto& f : rep.failed) out += "failed: " + f + "\n";
  return out;
}

nlohmann::json to_json(const ParticleEvalReport& rep) {
  auto dist = [](const Distribution& d) {
    return nlohmann::json{{"mean", d.mean}, {"min", d.min}, {"median", d.median}, {"p90", d.p90}, {"max", d.max}};
  };
  nlohmann::json j;
  j["dataset"] = rep.dataset;
  j["lm"] = rep.lm;
  j["plans"] = rep.plans;
  j["settings"] = nlohmann::json::object();
  for (const auto& [k, v] : rep.settings) j["settings"][k] = v;
  j["failed"] = rep.failed;
  j["summary"] = nlohmann::json::array();
  for (const auto& s : rep.summary)
    j["summary"].push_back({{"particles", s.particles},
                            {"runs", s.runs},
                            {"tv_final", dist(s.tv_final)},
                            {"tv_steps_mean", dist(s.tv_steps)},
                            {"time_ratio", s.time_ratio},
                            {"time_ratio_median", s.time_ratio_median},
                            {"refinement_ratio", s.refinement_ratio}});
  j["runs"] = nlohmann::json::array();
  for (const auto& r : rep.rows)
    j["runs"].push_back({{"plan", r.plan},
                         {"goals", r.goals},
                         {"hypotheses", r.hypotheses},
                         {"steps", r.steps},
                         {"particles", r.particles},
                         {"seed", r.seed},
                         {"tv_final", r.tv_final},
                         {"tv_steps_mean", r.tv_steps_mean},
                         {"tv_steps_max", r.tv_steps_max},
                         {"tv_action_final", r.tv_action_final},
                         {"exact_seconds", r.exact_seconds},
                         {"particle_seconds", r.particle_seconds},
                         {"exact_refinements", r.exact_refinements},
                         {"particle_refinements", r.particle_refinements},
                         {"resamples", r.resamples}});
  return j;
}

}  // namespace clips::studies
