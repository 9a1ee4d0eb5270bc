#include "inference/particle_test.hpp"

namespace clips::inference {
namespace particle_test {
TEST(ParticleFilter, SystematicInitialisationSpreadsParticlesEvenly) {
  ParticleFilter f(3, 2, popts(20));
  std::map<int, int> count;
  for (int h : f.particles()) ++count[h];
  ASSERT_EQ(count.size(), 6u);
  for (auto [h, c] : count) EXPECT_TRUE(c == 3 || c == 4) << "hypothesis " << h << ": " << c;
}

TEST(ParticleFilter, ResamplesExactlyWhenTheEssFallsBelowTheThreshold) {
  // 4 hypotheses × 25 particles; h0 has likelihood 1, the others e^-2.
  // ESS = (25 + 75 e^-2)^2 / (25 + 75 e^-4) ≈ 41.9 of 100.
  auto ll = [](int h) { return h == 0 ? 0.0 : -2.0; };
  const double w = std::exp(-2.0);
  const double expected = std::pow(25 + 75 * w, 2) / (25 + 75 * w * w);
  for (double threshold : {0.0, 0.40, 0.43, 1.0}) {
    ParticleFilter f(4, 1, popts(100, threshold));
    EXPECT_NEAR(f.ess([](int) { return 0.0; }), 100, 1e-9);
    EXPECT_NEAR(f.ess(ll), expected, 1e-9);
    const bool resampled = f.update(ll, kNoSync, kNone, /*evidence=*/false);  // sweeps only after resampling
    EXPECT_EQ(resampled, expected < threshold * 100) << threshold;
    EXPECT_EQ(f.stats().resamples, resampled ? 1 : 0);
    if (resampled) {
      EXPECT_NEAR(f.ess(ll), 100, 1e-9);  // equal weights after resampling (and MH moves)
    }
    double lm = 0;
    const auto p = f.posterior(ll, lm);
    EXPECT_NEAR(p[0], 1 / (1 + 3 * w), resampled ? 0.1 : 1e-12) << threshold;
    // The evidence estimate log mean w survives resampling.
    EXPECT_NEAR(lm, std::log((25 + 75 * w) / 100), 1e-9);
  }
}

TEST(ParticleFilter, RejuvenationRecoversAGoalNoParticleHeld) {
  // 8 goals, 4 particles: systematic sampling holds every other goal.
  const std::vector<int> start = ParticleFilter(8, 1, popts(4)).held();
  ASSERT_EQ(start.size(), 4u);
  const int target = start[0] == 0 ? 1 : 0;  // not held
  auto ll = [&](int h) { return h == target ? 0.0 : -30.0 - h; };
  for (int moves : {0, 40}) {
    ParticleFilter f(8, 1, popts(4, 1.0, moves));
    ASSERT_EQ(f.held(), start);
    std::vector<int> synced;
    f.update(ll, [&](const std::vector<int>& hs) { synced.insert(synced.end(), hs.begin(), hs.end()); }, kNone);
    double lm = 0;
    const auto p = f.posterior(ll, lm);
    if (moves == 0) {
      EXPECT_EQ(p[target], 0.0);
      EXPECT_TRUE(synced.empty());
    } else {
      EXPECT_GT(p[target], 0.99);
      EXPECT_GT(f.stats().accepted, 0);
      // The proposals were brought up to date before being read.
      EXPECT_NE(std::find(synced.begin(), synced.end(), target), synced.end());
    }
  }
}

TEST(ParticleFilter, RestartsFromThePriorWhenEveryParticleIsRuledOut) {
  ParticleFilter f(4, 1, popts(4));
  auto ll = [](int h) { return h == 2 ? 0.0 : kNegInf; };
  // Kill every held hypothesis but keep h2 unheld? With N = K all are held;
  // rule them all out instead: the posterior falls back to the prior.
  auto none = [](int) { return kNegInf; };
  std::vector<int> synced;
  EXPECT_FALSE(f.update(none, [&](const std::vector<int>& hs) { synced = hs; }, kNone));
  EXPECT_EQ(f.stats().restarts, 1);
  EXPECT_EQ(synced.size(), 4u);
  double lm = 0;
  for (double p : f.posterior(none, lm)) EXPECT_DOUBLE_EQ(p, 0.25);
  EXPECT_EQ(lm, kNegInf);
  // Once something explains the data, the restarted particles find it.
  f.update(ll, kNoSync, kNone);
  EXPECT_NEAR(f.posterior(ll, lm)[2], 1.0, 1e-12);
}

TEST(ParticleFilter, SupportEstimateWeighsTheHeldHypothesesExactly) {
  // 8 hypotheses, 4 particles resampled every step: the held set carries the
  // exact relative weights; the weighted counts come in quarters.
  auto ll = [](int h) { return -0.3 * h; };
  for (ParticleEstimate e : {ParticleEstimate::Support, ParticleEstimate::Weights}) {
    ParticleOptions o = popts(4, 1.0, 0);
    o.estimate = e;
    ParticleFilter f(8, 1, o);
    f.update(ll, kNoSync, kNone);
    EXPECT_EQ(f.stats().resamples, 1);
    const std::vector<int> held = f.support(ll);
    double z = 0;
    for (int h : held) z += std::exp(ll(h));
    double lm = 0;
    const auto p = f.posterior(ll, lm);
    double total = 0;
    for (int h = 0; h < 8; ++h) {
      total += p[h];
      const bool in = std::find(held.begin(), held.end(), h) != held.end();
      if (!in) {
        EXPECT_EQ(p[h], 0.0) << h;
      } else if (e == ParticleEstimate::Support) {
        EXPECT_NEAR(p[h], std::exp(ll(h)) / z, 1e-12) << h;
      }
      if (e == ParticleEstimate::Weights) {
        EXPECT_NEAR(p[h] * 4, std::round(p[h] * 4), 1e-12) << h;
      }
    }
    EXPECT_NEAR(total, 1.0, 1e-12);
  }
  EXPECT_EQ(parse_particle_estimate("weights"), ParticleEstimate::Weights);
  EXPECT_EQ(to_string(parse_particle_estimate("support")), "support");
  EXPECT_THROW(parse_particle_estimate("counts"), InputError);
}

TEST(ParticleFilter, SameSeedSameParticles) {
  auto ll = [](int h) { return -0.7 * h; };
  auto run = [&](uint64_t seed) {
    ParticleFilter f(16, 2, popts(10, 1.0, 3, seed));
    for (int i = 0; i < 5; ++i) f.update(ll, kNoSync, kNone);
    return f.particles();
  };
  EXPECT_EQ(run(7), run(7));
  bool differs = false;
  for (uint64_t s = 8; s < 12; ++s) differs = differs || run(s) != run(7);
  EXPECT_TRUE(differs);
}

TEST(ParticleFilter, BadOptionsAreRefused) {
  EXPECT_THROW(ParticleFilter(4, 1, popts(0)), InputError);
  EXPECT_THROW(ParticleFilter(4, 1, popts(-3)), InputError);
  EXPECT_THROW(ParticleFilter(4, 1, popts(8, 1.5)), InputError);
  EXPECT_THROW(ParticleFilter(4, 1, popts(8, std::nan(""))), InputError);
  EXPECT_THROW(ParticleFilter(4, 1, popts(8, 0.5, -1)), InputError);
  InferenceOptions o;
  o.particles = -1;
  EXPECT_THROW(check_options(o), InputError);
  o.particles = 10;
  o.ess_threshold = -0.1;
  EXPECT_THROW(check_options(o), InputError);
  o.ess_threshold = 0.5;
  o.rejuvenation_moves = -2;
  EXPECT_THROW(check_options(o), InputError);
  o.rejuvenation_moves = 0;
  EXPECT_NO_THROW(check_options(o));
}

TEST(ParticleBelief, ManyParticlesMatchExactOnTheCorridor) {
  auto task = corridor_task();
  ColourLm lm;
  Belief exact = corridor_belief(task, {});
  InferenceOptions po;
  po.particles = 400;  // 100 per hypothesis
  Belief particles = corridor_belief(task, po);
  ASSERT_TRUE(particles.particle_mode());
  ASSERT_FALSE(exact.particle_mode());
  const auto e = corridor_run(exact, *task, lm);
  const auto p = corridor_run(particles, *task, lm);
  ASSERT_EQ(e.size(), p.size());
  for (size_t t = 0; t < e.size(); ++t)
    for (Modality m : kModalities) {
      const double d = tv(e[t][m].goals, p[t][m].goals);
      EXPECT_LT(d, 0.05) << "step " << t << " " << to_string(m);
      EXPECT_LT(tv(e[t][m].profiles, p[t][m].profiles), 0.05) << "step " << t << " " << to_string(m);
      EXPECT_NEAR(e[t][m].log_marginal, p[t][m].log_marginal, 0.1) << "step " << t << " " << to_string(m);
    }
  // The same trace records: utterances with one entry per hypothesis.
  ASSERT_EQ(p[2].utterances.size(), 1u);
  EXPECT_EQ(p[2].utterances[0].hypotheses.size(), 4u);
  EXPECT_EQ(p.back().utterances.size(), 1u);
  // The utterance modality had no particles before the first utterance.
  EXPECT_EQ(p[1][Modality::UtteranceOnly].goals, e[1][Modality::UtteranceOnly].goals);
}

TEST(ParticleBelief, SupportEstimateIsTheExactPosteriorOnTheHeldHypotheses) {
  // Few particles, resampled every step: whatever set they hold, the default
  // estimate is the exact posterior renormalised on it; the weighted counts
  // are not.
  auto task = corridor_task();
  ColourLm lm;
  Belief exact = corridor_belief(task, {});
  const auto e = corridor_run(exact, *task, lm);
  double worst_weights = 0;
  for (ParticleEstimate est : {ParticleEstimate::Support, ParticleEstimate::Weights}) {
    InferenceOptions po;
    po.particles = 6;
    po.ess_threshold = 1;
    po.rejuvenation_moves = 0;
    po.particle_estimate = est;
    Belief particles = corridor_belief(task, po);
    const auto p = corridor_run(particles, *task, lm);
    ASSERT_EQ(e.size(), p.size());
    for (size_t t = 0; t < e.size(); ++t)
      for (Modality m : kModalities) {
        const auto& ph = p[t][m].hypotheses;
        const auto& eh = e[t][m].hypotheses;
        double z = 0;
        for (size_t h = 0; h < ph.size(); ++h)
          if (ph[h] > 0) z += eh[h];
        ASSERT_GT(z, 0) << "step " << t << " " << to_string(m);
        for (size_t h = 0; h < ph.size(); ++h) {
          const double want = ph[h] > 0 ? eh[h] / z : 0.0;
          if (est == ParticleEstimate::Support)
            EXPECT_NEAR(ph[h], want, 1e-9) << "step " << t << " " << to_string(m) << " h" << h;
          else
            worst_weights = std::max(worst_weights, std::abs(ph[h] - want));
        }
      }
  }
  EXPECT_GT(worst_weights, 1e-3);  // the counts carry sampling noise
}

TEST(ParticleBelief, HypothesesJoiningLateReplayToTheExactNumbers) {
  // One particle, resampled every step: it holds one hypothesis at a time
  // and rejuvenation brings in the others late. Once synced, every
  // hypothesis' likelihoods, temperatures and policy values must be exactly
  // those of exact enumeration.
  auto task = corridor_task();
  ColourLm lm;
  Belief exact = corridor_belief(task, {});
  InferenceOptions po;
  po.particles = 1;
  po.ess_threshold = 1.0;
  po.rejuvenation_moves = 1;
  po.proposal_groups = 1;
  Belief b = corridor_belief(task, po);
  corridor_run(exact, *task, lm);
  corridor_run(b, *task, lm);
  std::vector<int> all = {0, 1, 2, 3};
  // Some hypothesis is behind (its last events wait for a sync), and none
  // was refined more often than exact enumeration refines it.
  EXPECT_TRUE(std::any_of(all.begin(), all.end(), [&](int h) { return !b.current(h); }));
  EXPECT_LE(b.refinements(), exact.refinements());
  b.sync_policies(all);
  for (int h : all) {
    EXPECT_TRUE(b.current(h));
    EXPECT_EQ(b.action_log_likelihood(h), exact.action_log_likelihood(h)) << h;
    EXPECT_EQ(b.utterance_log_likelihood(h), exact.utterance_log_likelihood(h)) << h;
    EXPECT_EQ(b.temperature(h).weights(), exact.temperature(h).weights()) << h;
    const auto qa = b.policies()[h].q_values(b.state()), qb = exact.policies()[h].q_values(exact.state());
    ASSERT_EQ(qa.size(), qb.size());
    for (size_t i = 0; i < qa.size(); ++i) EXPECT_EQ(qa[i].q, qb[i].q) << h;
  }
  EXPECT_EQ(b.refinements(), exact.refinements());  // each refinement once, never twice
}

TEST(ParticleBelief, FixedSeedGivesTheSameRunAlsoOnTwoThreads) {
  auto task = corridor_task();
  ColourLm lm;
  auto run = [&](uint64_t seed, int threads) {
    InferenceOptions po;
    po.particles = 3;
    po.ess_threshold = 0.9;
    po.particle_seed = seed;
    po.threads = threads;
    Belief b = corridor_belief(task, po);
    std::vector<std::vector<double>> out;
    for (const auto& st : corridor_run(b, *task, lm))
      for (Modality m : kModalities) out.push_back(st[m].hypotheses);
    return out;
  };
  const auto a = run(5, 1);
  EXPECT_EQ(a, run(5, 1));
  EXPECT_EQ(a, run(5, 2));
}

TEST(ParticleBelief, AssistanceCopiesKeepFiltering) {
  // The online assistance adapter copies the belief and keeps observing.
  auto task = corridor_task();
  ColourLm lm;
  InferenceOptions po;
  po.particles = 8;
  Belief b = corridor_belief(task, po);
  corridor_run(b, *task, lm);
  Belief copy = b;
  copy.observe(*task->find_action("(wait robot)"));
  const StepRecord r = copy.observe(*task->find_action("(left human)"));
  double s = 0;
  for (double p : r[Modality::Both].goals) s += p;
  EXPECT_NEAR(s, 1.0, 1e-12);
  copy.sync_policies(Modality::Both);
  for (int h : copy.support(Modality::Both)) EXPECT_TRUE(copy.current(h));
  EXPECT_EQ(b.t() + 2, copy.t());
}

TEST(ParticleBelief, ClipsFilterAloneReweightsTheBaselinesFromItsParticles) {
  auto task = corridor_task();
  ColourLm lm;
  Belief exact = corridor_belief(task, {});
  const auto e = corridor_run(exact, *task, lm);
  InferenceOptions po;
  po.particles = 400;
  po.particle_filters = ParticleFilters::Clips;
  Belief one = corridor_belief(task, po);
  const auto p = corridor_run(one, *task, lm);
  // With every hypothesis held by ~100 particles, reweighting the CLIPS
  // particles gives every modality's posterior and evidence.
  for (size_t t = 0; t < e.size(); ++t)
    for (Modality m : kModalities) {
      EXPECT_LT(tv(e[t][m].goals, p[t][m].goals), 0.05) << "step " << t << " " << to_string(m);
      EXPECT_NEAR(e[t][m].log_marginal, p[t][m].log_marginal, 0.1) << "step " << t << " " << to_string(m);
    }
  EXPECT_NE(one.particle_stats(Modality::Both), nullptr);
  EXPECT_EQ(one.particle_stats(Modality::ActionOnly), nullptr);  // no filter of its own
  EXPECT_EQ(one.particle_stats(Modality::UtteranceOnly), nullptr);

  // With few particles the baselines can only weigh what CLIPS holds, and
  // only the CLIPS filter's hypotheses are refined.
  InferenceOptions few;
  few.particles = 1;
  few.ess_threshold = 1.0;
  few.rejuvenation_moves = 0;
  Belief all = corridor_belief(task, few);
  few.particle_filters = ParticleFilters::Clips;
  Belief clips_only = corridor_belief(task, few);
  corridor_run(all, *task, lm);
  const auto q = corridor_run(clips_only, *task, lm);
  EXPECT_LT(clips_only.refinements(), all.refinements());
  const auto both = clips_only.support(Modality::Both);
  for (Modality m : {Modality::ActionOnly, Modality::UtteranceOnly}) {
    for (int h : clips_only.support(m)) EXPECT_TRUE(std::binary_search(both.begin(), both.end(), h)) << h;
    double s = 0;
    for (double x : q.back()[m].goals) s += x;
    EXPECT_NEAR(s, 1.0, 1e-12) << to_string(m);
  }
  EXPECT_EQ(parse_particle_filters("clips"), ParticleFilters::Clips);
  EXPECT_EQ(to_string(parse_rejuvenation("utterances")), "utterances");
  EXPECT_THROW(parse_rejuvenation("always"), InputError);
  EXPECT_EQ(to_string(parse_particle_filters("all")), "all");
  EXPECT_THROW(parse_particle_filters("some"), InputError);
}

TEST(ParticleBelief, RejuvenationScheduleDecidesWhichStepsExplore) {
  // Never resampling (threshold 0), the sweeps run only where the schedule
  // says: never, after the two steps with utterances, or after every step
  // with a human action or an utterance.
  auto task = corridor_task();
  ColourLm lm;
  auto proposed = [&](Rejuvenation r) {
    InferenceOptions po;
    po.particles = 4;
    po.ess_threshold = 0;
    po.rejuvenate = r;
    po.particle_filters = ParticleFilters::Clips;
    Belief b = corridor_belief(task, po);
    corridor_run(b, *task, lm);
    return b.particle_stats(Modality::Both)->proposed;
  };
  const long never = proposed(Rejuvenation::Resampling), utterances = proposed(Rejuvenation::Utterances),
             evidence = proposed(Rejuvenation::Evidence);
  EXPECT_EQ(never, 0);
  EXPECT_GT(utterances, 0);
  EXPECT_GT(evidence, utterances);
}

}  // namespace particle_test

}  // namespace clips::inference
