#include "lm/embedded_model_test.hpp"

namespace clips::lm {
namespace embedded_model_test {
TEST(EmbeddedSnapshot, LoadedModelScoresBitForBitLikeTheTrainedOne) {
  EmbeddedLanguageModel trained(with_cache("off"));
  EXPECT_TRUE(trained.cache_dir().empty());
  auto m = trained.model_for_prompt(literal_prompt("(pickup you key1)"));
  const std::string bytes = m->save();
  auto loaded = AlignmentModel::load(bytes);
  EXPECT_EQ(loaded->vocabulary_size(), m->vocabulary_size());
  EXPECT_EQ(loaded->save(), bytes);
  for (const auto& r : probe_batch()) {
    if (r.prompt == "\n") continue;
    const std::string cmd = split_prompt(r.prompt).second;
    const bool complete = r.continuation.back() == '\n';
    EXPECT_EQ(loaded->log_prob(*loaded->bind(cmd), loaded->encode(r.continuation), complete),
              m->log_prob(*m->bind(cmd), m->encode(r.continuation), complete))
        << cmd << " /" << r.continuation;
  }
  EXPECT_EQ(loaded->log_prob_unprimed(loaded->encode(" Hello there.\n"), true),
            m->log_prob_unprimed(m->encode(" Hello there.\n"), true));
}

TEST(EmbeddedSnapshot, DamagedSnapshotsAreRejected) {
  EmbeddedLanguageModel trained(with_cache("off"));
  const std::string bytes = trained.model_for_prompt("\n")->save();
  EXPECT_THROW(AlignmentModel::load(""), LmError);
  EXPECT_THROW(AlignmentModel::load("not a snapshot at all"), LmError);
  for (size_t cut : {size_t{8}, size_t{9}, bytes.size() / 3, bytes.size() / 2, bytes.size() - 1})
    EXPECT_THROW(AlignmentModel::load(bytes.substr(0, cut)), LmError) << "cut at " << cut;
  EXPECT_THROW(AlignmentModel::load(bytes + "x"), LmError);
  std::string wrong_magic = bytes;
  wrong_magic[7] = '9';
  EXPECT_THROW(AlignmentModel::load(wrong_magic), LmError);
  // A length field blown up to more than the file holds.
  std::string huge = bytes;
  const uint64_t big = uint64_t{1} << 40;
  std::memcpy(huge.data() + 8, &big, sizeof(big));
  EXPECT_THROW(AlignmentModel::load(huge), LmError);
  // One flipped bit anywhere in the parameters.
  for (size_t at : {bytes.size() / 4, bytes.size() / 2, bytes.size() - 20}) {
    std::string flipped = bytes;
    flipped[at] = static_cast<char>(flipped[at] ^ 0x10);
    EXPECT_THROW(AlignmentModel::load(flipped), LmError) << "bit flipped at " << at;
  }
}

TEST(EmbeddedCache, SecondInstanceLoadsWhatTheFirstTrainedAndScoresAlike) {
  const auto dir = fresh_dir("clips_lm_cache_test");
  const auto batch = probe_batch();
  const std::vector<double> reference = EmbeddedLanguageModel(with_cache("off")).score(batch);

  EmbeddedLanguageModel first(with_cache(dir.string()));
  ASSERT_EQ(first.cache_dir(), dir.string());
  EXPECT_EQ(first.score(batch), reference);
  EXPECT_EQ(first.cache_hits(), 0u);
  size_t files = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir)) files += e.path().extension() == ".bin";
  EXPECT_EQ(files, first.trained_blocks());  // literal, pragmatic, VH and empty blocks

  EmbeddedLanguageModel second(with_cache(dir.string()));
  EXPECT_EQ(second.score(batch), reference);
  EXPECT_EQ(second.cache_hits(), second.trained_blocks());

  // A damaged entry is trained again and rewritten, with the same scores.
  for (const auto& e : std::filesystem::directory_iterator(dir)) std::filesystem::resize_file(e.path(), 100);
  EmbeddedLanguageModel third(with_cache(dir.string()));
  EXPECT_EQ(third.score(batch), reference);
  EXPECT_EQ(third.cache_hits(), 0u);
  EmbeddedLanguageModel fourth(with_cache(dir.string()));
  EXPECT_EQ(fourth.score(batch), reference);
  EXPECT_EQ(fourth.cache_hits(), fourth.trained_blocks());
  std::filesystem::remove_all(dir);
}

// Cached models are shared by every build with the same training version,
// so the version must move whenever training produces another model. The
// scores a small reference training gives, recorded for the version: when
// they change, bump kEmbeddedTrainingVersion and record the new ones.
TEST(EmbeddedCache, TheTrainingVersionGoesWithWhatTrainingProduces) {
  const std::map<int, std::vector<double>> recorded = {
      {1, {-38.15526606519726, -31.461070506912517, -23.598095674832585, -35.386005874968397}},
      // 2: the snapshot keeps which qualifiers are bags of words (no bag here).
      {2, {-38.15526606519726, -31.461070506912517, -23.598095674832585, -35.386005874968397}},
      // 3: "it" may point back to a noun-less "one" (no such sentence here).
      {3, {-38.15526606519726, -31.461070506912517, -23.598095674832585, -35.386005874968397}},
  };
  const auto batch = probe_batch();
  const std::vector<ScoreRequest> probes = {batch[0], batch[3], batch[10], batch.back()};
  const std::vector<double> scores = EmbeddedLanguageModel(with_cache("off")).score(probes);
  const auto it = recorded.find(kEmbeddedTrainingVersion);
  ASSERT_NE(it, recorded.end()) << "record the scores of training version " << kEmbeddedTrainingVersion;
  ASSERT_EQ(scores.size(), it->second.size());
  for (size_t i = 0; i < scores.size(); ++i)
    EXPECT_NEAR(scores[i], it->second[i], 1e-6 * std::max(1.0, std::abs(it->second[i])))
        << "probe " << i << ": training changed what it produces (score " << std::setprecision(12) << scores[i]
        << "); bump kEmbeddedTrainingVersion (src/lm/embedded_model.hpp) and record the new scores";
}

TEST(EmbeddedCache, DifferentTrainingDataGetsItsOwnEntry) {
  const auto dir = fresh_dir("clips_lm_cache_iter_test");
  const std::string prompt = literal_prompt("(pickup you key1)");
  EmbeddedModelOptions a = with_cache(dir.string());
  EmbeddedModelOptions b = a;
  b.em_iterations = a.em_iterations - 1;
  const double sa = EmbeddedLanguageModel(a).score({{prompt, " Get the key.\n"}})[0];
  EmbeddedLanguageModel mb(b);
  const double sb = mb.score({{prompt, " Get the key.\n"}})[0];
  EXPECT_EQ(mb.cache_hits(), 0u);  // not served a's model
  EXPECT_NE(sa, sb);
  // An unwritable cache directory only means training every time.
  const auto file = dir / "plain-file";
  std::ofstream(file) << "x";
  EmbeddedLanguageModel blocked(with_cache((file / "sub").string()));
  EXPECT_EQ(blocked.score({{prompt, " Get the key.\n"}})[0], sa);
  EXPECT_EQ(blocked.cache_hits(), 0u);
  std::filesystem::remove_all(dir);
}

TEST(EmbeddedCache, DirectoryKeepsTheNewestSnapshots) {
  const auto dir = fresh_dir("clips_lm_cache_bound_test");
  std::filesystem::create_directories(dir);
  for (int i = 0; i < 70; ++i) std::ofstream(dir / ("embedded-old" + std::to_string(i) + ".bin")) << "stale";
  std::ofstream(dir / "notes.txt") << "not ours";
  EmbeddedLanguageModel m(with_cache(dir.string()));
  m.score({{"\n", " Hello.\n"}});
  size_t snapshots = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir))
    snapshots += e.path().extension() == ".bin";
  EXPECT_EQ(snapshots, 64u);
  EXPECT_TRUE(std::filesystem::exists(dir / "notes.txt"));  // other files are left alone
  EmbeddedLanguageModel again(with_cache(dir.string()));
  again.score({{"\n", " Hello.\n"}});
  EXPECT_EQ(again.cache_hits(), 1u);  // the new snapshot survived the pruning
  std::filesystem::remove_all(dir);
}

TEST(EmbeddedCache, OffByEnvironment) {
  const char* old = std::getenv("CLIPS_LM_CACHE_DIR");
  const std::string saved = old ? old : "";
  ::setenv("CLIPS_LM_CACHE_DIR", "off", 1);
  EXPECT_TRUE(EmbeddedLanguageModel().cache_dir().empty());
  ::setenv("CLIPS_LM_CACHE_DIR", "/tmp/clips-cache-env-test", 1);
  EXPECT_EQ(EmbeddedLanguageModel().cache_dir(), "/tmp/clips-cache-env-test");
  if (old) ::setenv("CLIPS_LM_CACHE_DIR", saved.c_str(), 1);
  else ::unsetenv("CLIPS_LM_CACHE_DIR");
}

}  // namespace embedded_model_test

}  // namespace clips::lm
