// Random Doors-Keys-Gems maps (Pack::generate_problem of the mDKG pack): the
// PDDL and the picture agree, gems sit behind doors that matter, the draw
// depends only on the seed, and impossible counts are clear errors.
#include "domains/builtin/packs.hpp"
#include "domains/dkg/dkg_generate.hpp"

#include <gtest/gtest.h>

#include <deque>
#include <set>

#include "domains/dkg/dkg_world.hpp"
#include "domains/pack.hpp"
#include "pddl/parser.hpp"
#include "test_paths.hpp"
#include "util/error.hpp"

namespace clips::domains::dkg {
namespace {

GenerateParams params(int w, int h, int gems, int keys, int doors) {
  GenerateParams p;
  p.width = w;
  p.height = h;
  p.counts = {{"gem", gems}, {"key", keys}, {"door", doors}};
  p.problem_name = "gen";
  return p;
}

// The first successful draw of a stream.
GeneratedProblem draw(const GenerateParams& p, uint64_t seed) {
  util::Rng rng(seed);
  for (int i = 0; i < 200; ++i)
    if (auto g = generate_dkg_problem(p, rng)) return *g;
  ADD_FAILURE() << "no map in 200 draws";
  return {};
}

struct Grounded {
  std::shared_ptr<const pddl::Task> task;
  explicit Grounded(const std::string& text) {
    auto d = std::make_shared<pddl::Domain>(pddl::load_domain(paths::source_dir() + "/data/domains/doors-keys-gems/domain.pddl"));
    auto p = std::make_shared<pddl::Problem>(pddl::parse_problem(*d, text, "gen.pddl"));
    auto pack = builtin_pack("doors-keys-gems");
    task = std::make_shared<const pddl::Task>(d, p, pack->spec().grounding);
    pack->check_problem(*task, "gen.pddl");
  }
};

// Cells the human reaches with the doors in `open` passable (others locked).
std::set<std::pair<int, int>> reach(const DkgWorld& w, const pddl::State& s, const std::set<pddl::ObjectId>& open) {
  std::set<std::pair<int, int>> blocked;
  for (auto d : w.doors())
    if (!open.count(d)) blocked.insert({w.pos(s, d).x, w.pos(s, d).y});
  const Cell h = w.pos(s, w.human());
  std::set<std::pair<int, int>> seen{{h.x, h.y}};
  std::deque<std::pair<int, int>> todo{{h.x, h.y}};
  while (!todo.empty()) {
    auto [x, y] = todo.front();
    todo.pop_front();
    for (auto [dx, dy] : {std::pair{1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
      const std::pair<int, int> n{x + dx, y + dy};
      if (w.wall(n.first, n.second) || blocked.count(n) || !seen.insert(n).second) continue;
      todo.push_back(n);
    }
  }
  return seen;
}

TEST(DkgGenerate, PictureIsTheStateAndObjectsFollowThePaperConventions) {
  for (uint64_t seed : {1u, 2u, 3u, 4u, 5u}) {
    const auto g = draw(params(9, 9, 4, 2, 2), seed);
    Grounded t(g.pddl);
    const DkgWorld w(*t.task);
    const pddl::State s0 = t.task->initial_state();
    EXPECT_EQ(w.ascii(s0), g.picture) << "seed " << seed;
    ASSERT_EQ(w.gems().size(), 4u);
    EXPECT_EQ(w.keys().size(), 2u);
    EXPECT_EQ(w.doors().size(), 2u);
    const char* colors[] = {"red", "yellow", "blue", "green"};
    for (size_t i = 0; i < w.gems().size(); ++i) EXPECT_EQ(w.color(w.gems()[i]), colors[i]);
    // Numbered in row-major scan order (spec 2.5).
    for (const auto* group : {&w.gems(), &w.keys(), &w.doors()})
      for (size_t i = 1; i < group->size(); ++i) {
        const Cell a = w.pos(s0, (*group)[i - 1]), b = w.pos(s0, (*group)[i]);
        EXPECT_LT(std::pair(a.y, a.x), std::pair(b.y, b.x)) << "seed " << seed;
      }
  }
}

TEST(DkgGenerate, EveryGemIsBehindADoorAndEveryDoorGuardsOne) {
  for (uint64_t seed : {11u, 12u, 13u, 14u, 15u, 16u}) {
    const auto g = draw(params(9, 9, 3, 2, 2), seed);
    Grounded t(g.pddl);
    const DkgWorld w(*t.task);
    const pddl::State s0 = t.task->initial_state();
    const auto locked = reach(w, s0, {});
    std::set<pddl::ObjectId> all(w.doors().begin(), w.doors().end());
    const auto open = reach(w, s0, all);
    for (auto gem : w.gems()) {
      const Cell c = w.pos(s0, gem);
      EXPECT_FALSE(locked.count({c.x, c.y})) << w.name(gem) << " is not behind a door, seed " << seed;
      EXPECT_TRUE(open.count({c.x, c.y})) << w.name(gem) << " is walled in, seed " << seed;
    }
    for (auto k : w.keys()) EXPECT_TRUE(locked.count({w.pos(s0, k).x, w.pos(s0, k).y})) << "keys start at home";
    for (auto d : w.doors()) {
      auto others = all;
      others.erase(d);
      const auto without = reach(w, s0, others);
      bool guards = false;
      for (auto gem : w.gems()) guards = guards || !without.count({w.pos(s0, gem).x, w.pos(s0, gem).y});
      EXPECT_TRUE(guards) << w.name(d) << " guards no gem, seed " << seed;
      bool has_key = false;
      for (auto k : w.keys()) has_key = has_key || w.color(k) == w.color(d);
      EXPECT_TRUE(has_key) << w.name(d) << " has no key of its colour";
    }
  }
}

TEST(DkgGenerate, TheSeedDecidesTheMap) {
  const auto p = params(9, 9, 4, 2, 2);
  EXPECT_EQ(draw(p, 7).pddl, draw(p, 7).pddl);
  EXPECT_NE(draw(p, 7).pddl, draw(p, 8).pddl);
  // Streams derived for different problems differ too.
  EXPECT_NE(util::Rng::derive(7, {1, 1}), util::Rng::derive(7, {1, 2}));
}

TEST(DkgGenerate, ImpossibleCountsAreClearErrors) {
  auto message = [](const GenerateParams& p) {
    try {
      util::Rng rng(1);
      generate_dkg_problem(p, rng);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(message(params(3, 3, 4, 5, 0)).find("need 11 cells, but a 3x3 map has only 9"), std::string::npos)
      << message(params(3, 3, 4, 5, 0));
  EXPECT_NE(message(params(30, 30, 65, 2, 2)).find("--gems 65: a doors-keys-gems map has 1 to 64 gems"),
            std::string::npos)
      << message(params(30, 30, 65, 2, 2));
  // 64 gems, 40 keys, 30 doors and the agents: 136 objects, over the heuristics' 128.
  EXPECT_NE(message(params(40, 40, 64, 40, 30)).find("at most 128"), std::string::npos)
      << message(params(40, 40, 64, 40, 30));
  EXPECT_NE(message(params(9, 9, 0, 2, 2)).find("--gems 0"), std::string::npos);
  EXPECT_NE(message(params(9, 9, 2, 0, 1)).find("--keys 0"), std::string::npos);
  EXPECT_NE(message(params(2, 9, 2, 1, 1)).find("--size 2x9"), std::string::npos);
  EXPECT_NE(message(params(41, 9, 2, 1, 1)).find("--size 41x9: a doors-keys-gems map is 3 to 40"), std::string::npos)
      << message(params(41, 9, 2, 1, 1));
  EXPECT_EQ(message(params(40, 40, 64, 2, 2)), "");  // the largest counts are accepted
  GenerateParams odd = params(9, 9, 2, 1, 1);
  odd.counts["chair"] = 1;
  EXPECT_NE(message(odd).find("'chair'"), std::string::npos);
}

TEST(DkgGenerate, SixtyFourGemsOnAFortyByFortyMapCycleTheFourColours) {
  const auto p = params(40, 40, 64, 2, 2);
  const GeneratedProblem g = draw(p, 5);
  EXPECT_EQ(g.pddl, draw(p, 5).pddl);  // the seed decides the map at this size too
  EXPECT_NE(g.pddl, draw(p, 6).pddl);
  Grounded gr(g.pddl);
  const pddl::Task& t = *gr.task;
  EXPECT_EQ(t.objects_of_type("gem").size(), 64u);
  const char* colours[] = {"red", "yellow", "blue", "green"};
  for (int i = 1; i <= 64; ++i) {
    const std::string gem = "gem" + std::to_string(i);
    EXPECT_TRUE(t.atom("iscolor", {gem, colours[(i - 1) % 4]}).value) << gem;
  }
  // The picture is the 40x40 grid.
  int rows = 0;
  for (char c : g.picture) rows += c == '\n';
  EXPECT_EQ(rows, 40);
  EXPECT_EQ(g.picture.find('\n'), 40u);
}

TEST(DkgGenerate, ManyGemsFillTheRoomsBehindDoorsInTurn) {
  // 30 gems behind two doors on an 11x11 map: when one room behind a door is
  // full the others take the remaining gems, rather than the draw failing.
  for (uint64_t seed : {3u, 4u, 5u}) {
    const GeneratedProblem g = draw(params(11, 11, 30, 2, 2), seed);
    Grounded gr(g.pddl);
    EXPECT_EQ(gr.task->objects_of_type("gem").size(), 30u);
  }
}

TEST(DkgGenerate, TooManyDoorsForTheGridFindNoLayout) {
  // A 3x3 grid has room for one wall at most.
  util::Rng rng(3);
  for (int i = 0; i < 20; ++i) EXPECT_FALSE(generate_dkg_problem(params(3, 3, 1, 3, 3), rng));
}

TEST(DkgGenerate, PacksWithoutGeneratorCodeSaySo) {
  util::Rng rng(1);
  auto vh = builtin_pack("virtual-home");
  EXPECT_TRUE(vh->generated_kinds().empty());
  try {
    vh->generate_problem(params(9, 9, 1, 1, 1), rng);
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("pack virtual-home cannot generate problems"), std::string::npos) << e.what();
  }
  EXPECT_EQ(builtin_pack("doors-keys-gems")->generated_kinds(), (std::vector<std::string>{"gem", "key", "door"}));
}

TEST(DkgGenerate, ShippedDomainIsTheExamplesDomain) {
  // `clips generate` copies data/domains/doors-keys-gems/domain.pddl into
  // its datasets; it must stay the domain the examples use.
  EXPECT_EQ(pddl::read_text_file(paths::source_dir() + "/data/domains/doors-keys-gems/domain.pddl"),
            pddl::read_text_file(paths::examples_dir() + "/doors-keys-gems/domain.pddl"));
}

}  // namespace
}  // namespace clips::domains::dkg
