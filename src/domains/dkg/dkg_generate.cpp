#include "domains/dkg/dkg_generate.hpp"

#include <algorithm>
#include <array>
#include <deque>
#include <sstream>
#include <string>
#include <vector>

#include "domains/dkg/dkg_mask.hpp"
#include "util/error.hpp"

namespace clips::domains::dkg {

namespace {

// The map analysis keeps three num_cells^2 tables of 16-bit distances
// (dkg_map.hpp): 15 MB at 40x40, 4 MB at 30x30.
constexpr int kMinSide = 3, kMaxSide = 40;
constexpr int kMaxGems = 64;
// The heuristics index agents, items and doors in 128-bit masks (dkg_mask.hpp).
constexpr int kMaxObjects = kObjMaskBits;
// Key and door colours of the paper's dataset; gems take theirs by number,
// cycling through the four gem colours (gem5 is red again, as gem1).
constexpr std::array<const char*, 3> kDoorColors = {"red", "yellow", "blue"};
constexpr std::array<const char*, 4> kGemColors = {"red", "yellow", "blue", "green"};
constexpr int kColorDraws = 10;  // door colourings tried before the layout is given up

char key_letter(const std::string& color) { return color[0] == 'r' ? 'r' : color[0] == 'y' ? 'y' : 'b'; }

int count(const GenerateParams& p, const char* kind) {
  auto it = p.counts.find(kind);
  return it == p.counts.end() ? 0 : it->second;
}

struct Room {
  int x0, y0, x1, y1;  // inclusive, 1-based
  int width() const { return x1 - x0 + 1; }
  int height() const { return y1 - y0 + 1; }
};

// The grid while it is drawn: walls, gaps (door or open) and the rooms left
// to divide.
class Layout {
 public:
  Layout(int w, int h) : w_(w), h_(h), wall_(static_cast<size_t>(w * h), false), gap_(wall_.size(), false) {
    rooms_.push_back({1, 1, w, h});
  }

  int width() const { return w_; }
  int height() const { return h_; }
  int cell(int x, int y) const { return (y - 1) * w_ + (x - 1); }
  int x_of(int c) const { return c % w_ + 1; }
  int y_of(int c) const { return c / w_ + 1; }
  bool wall(int c) const { return wall_[static_cast<size_t>(c)]; }
  bool gap(int c) const { return gap_[static_cast<size_t>(c)]; }
  const std::vector<int>& gaps() const { return gaps_; }

  // One more wall across a room, with one gap; false when no room can be
  // divided any more.
  bool divide(util::Rng& rng) {
    std::vector<double> weight;  // larger rooms first, so rooms stay alike in size
    for (const Room& r : rooms_)
      weight.push_back(can_split(r.x0, r.x1) || can_split(r.y0, r.y1) ? double(r.width() * r.height()) : 0.0);
    if (std::none_of(weight.begin(), weight.end(), [](double v) { return v > 0; })) return false;
    const size_t i = rng.weighted(weight);
    const Room r = rooms_[i];
    const bool can_v = can_split(r.x0, r.x1), can_h = can_split(r.y0, r.y1);
    // Split across the longer side; a square room either way.
    const bool vertical =
        can_v && (!can_h || r.width() > r.height() || (r.width() == r.height() && rng.index(2) == 0));
    const int at = vertical ? split_line(r.x0, r.x1, rng) : split_line(r.y0, r.y1, rng);
    const int open = vertical ? odd_in(r.y0, r.y1, rng) : odd_in(r.x0, r.x1, rng);
    if (vertical) {
      for (int y = r.y0; y <= r.y1; ++y) wall_[static_cast<size_t>(cell(at, y))] = y != open;
      mark_gap(cell(at, open));
      rooms_[i] = {r.x0, r.y0, at - 1, r.y1};
      rooms_.push_back({at + 1, r.y0, r.x1, r.y1});
    } else {
      for (int x = r.x0; x <= r.x1; ++x) wall_[static_cast<size_t>(cell(x, at))] = x != open;
      mark_gap(cell(open, at));
      rooms_[i] = {r.x0, r.y0, r.x1, at - 1};
      rooms_.push_back({r.x0, at + 1, r.x1, r.y1});
    }
    return true;
  }

  // Cells reachable from `from` through floor and the gaps not in `closed`.
  std::vector<bool> reachable(int from, const std::vector<bool>& closed) const {
    std::vector<bool> seen(wall_.size(), false);
    std::deque<int> todo{from};
    seen[static_cast<size_t>(from)] = true;
    while (!todo.empty()) {
      const int c = todo.front();
      todo.pop_front();
      const int x = x_of(c), y = y_of(c);
      const int nx[4] = {x, x, x - 1, x + 1}, ny[4] = {y - 1, y + 1, y, y};
      for (int k = 0; k < 4; ++k) {
        if (nx[k] < 1 || ny[k] < 1 || nx[k] > w_ || ny[k] > h_) continue;
        const int n = cell(nx[k], ny[k]);
        if (seen[static_cast<size_t>(n)] || wall(n) || closed[static_cast<size_t>(n)]) continue;
        seen[static_cast<size_t>(n)] = true;
        todo.push_back(n);
      }
    }
    return seen;
  }

 private:
  // A wall on an even line strictly inside [lo, hi]; gaps on odd lines.
  static bool can_split(int lo, int hi) { return first_even_after(lo) < hi; }
  static int first_even_after(int lo) { return lo % 2 == 0 ? lo + 1 + 1 : lo + 1; }
  static int split_line(int lo, int hi, util::Rng& rng) {
    std::vector<int> lines, roomy;  // roomy: both sides at least two wide
    for (int v = first_even_after(lo); v < hi; v += 2) {
      lines.push_back(v);
      if (v - lo >= 2 && hi - v >= 2) roomy.push_back(v);
    }
    const auto& from = roomy.empty() ? lines : roomy;
    return from[rng.index(from.size())];
  }
  static int odd_in(int lo, int hi, util::Rng& rng) {
    std::vector<int> odd;
    for (int v = lo; v <= hi; ++v)
      if (v % 2 == 1) odd.push_back(v);
    return odd[rng.index(odd.size())];
  }
  void mark_gap(int c) {
    gap_[static_cast<size_t>(c)] = true;
    gaps_.push_back(c);
  }

  int w_, h_;
  std::vector<bool> wall_, gap_;
  std::vector<int> gaps_;
  std::vector<Room> rooms_;
};

struct Placed {
  int cell;
  char kind;  // 'h' human, 'm' robot, 'k' key, 'g' gem, 'd' door
  std::string color;
};

std::string problem_text(const GenerateParams& params, const Layout& map, std::vector<Placed> objects) {
  // Row-major scan order numbers the objects of each kind, as in the paper's maps.
  std::stable_sort(objects.begin(), objects.end(), [](const Placed& a, const Placed& b) { return a.cell < b.cell; });
  std::vector<std::string> doors, keys, gems;
  std::ostringstream facts;
  std::string human, robot;
  for (const Placed& o : objects) {
    auto at = [&](const std::string& name) {
      return "(= (xloc " + name + ") " + std::to_string(map.x_of(o.cell)) + ") (= (yloc " + name + ") " +
             std::to_string(map.y_of(o.cell)) + ")";
    };
    if (o.kind == 'd') {
      doors.push_back("door" + std::to_string(doors.size() + 1));
      facts << "         " << at(doors.back()) << " (iscolor " << doors.back() << " " << o.color << ") (locked "
            << doors.back() << ")\n";
    } else if (o.kind == 'k') {
      keys.push_back("key" + std::to_string(keys.size() + 1));
      facts << "         " << at(keys.back()) << " (iscolor " << keys.back() << " " << o.color << ")\n";
    } else if (o.kind == 'g') {
      gems.push_back("gem" + std::to_string(gems.size() + 1));
      facts << "         " << at(gems.back()) << " (iscolor " << gems.back() << " " << kGemColors[(gems.size() - 1) % kGemColors.size()]
            << ") (forbidden robot " << gems.back() << ")\n";
    } else {
      (o.kind == 'h' ? human : robot) = at(o.kind == 'h' ? "human" : "robot");
    }
  }
  auto names = [](const std::vector<std::string>& v, const char* type) {
    std::string out;
    for (const auto& n : v) out += n + " ";
    return v.empty() ? std::string() : out + "- " + type + "\n            ";
  };
  std::ostringstream o;
  o << "(define (problem " << params.problem_name << ") (:domain doors-keys-gems)\n"
    << "  (:objects " << names(doors, "door") << names(keys, "key") << names(gems, "gem")
    << "red yellow blue green - color robot - robot human - human)\n"
    << "  (:init (= (walls) (new-bit-matrix false " << map.height() << " " << map.width() << "))\n";
  for (int y = 1; y <= map.height(); ++y)
    for (int x = 1; x <= map.width(); ++x)
      if (map.wall(map.cell(x, y))) o << "         (= (walls) (set-index walls true " << y << " " << x << "))\n";
  o << facts.str() << "         " << human << " " << robot << "\n"
    << "         (active human) (next-turn human robot) (next-turn robot human))\n"
    // A placeholder, as in the paper's problems: the true goal comes from the plans.
    << "  (:goal (has human " << gems.back() << ")))\n";
  return o.str();
}

// The map as the paper's .txt pictures draw it.
std::string picture(const Layout& map, const std::vector<Placed>& objects) {
  std::vector<std::string> rows(static_cast<size_t>(map.height()), std::string(static_cast<size_t>(map.width()), '.'));
  for (int c = 0; c < map.width() * map.height(); ++c)
    if (map.wall(c)) rows[static_cast<size_t>(map.y_of(c) - 1)][static_cast<size_t>(map.x_of(c) - 1)] = 'W';
  for (const Placed& o : objects) {
    char ch = o.kind;
    if (o.kind == 'k') ch = key_letter(o.color);
    if (o.kind == 'd') ch = static_cast<char>(key_letter(o.color) - 'a' + 'A');
    rows[static_cast<size_t>(map.y_of(o.cell) - 1)][static_cast<size_t>(map.x_of(o.cell) - 1)] = ch;
  }
  std::string out;
  for (const auto& r : rows) out += r + "\n";
  return out;
}

// `n` distinct cells drawn from `pool` (removed from it); false if too few.
bool take_cells(std::vector<int>& pool, int n, util::Rng& rng, std::vector<int>& out) {
  if (static_cast<int>(pool.size()) < n) return false;
  for (int i = 0; i < n; ++i) {
    const size_t j = rng.index(pool.size());
    out.push_back(pool[j]);
    pool.erase(pool.begin() + static_cast<std::ptrdiff_t>(j));
  }
  return true;
}

}  // namespace

void check_dkg_generate_params(const GenerateParams& p) {
  for (const auto& [kind, n] : p.counts)
    if (kind != "gem" && kind != "key" && kind != "door")
      throw InputError("doors-keys-gems maps have gems, keys and doors, not '" + kind + "'");
  const int gems = count(p, "gem"), keys = count(p, "key"), doors = count(p, "door");
  const std::string size = std::to_string(p.width) + "x" + std::to_string(p.height);
  if (p.width < kMinSide || p.height < kMinSide || p.width > kMaxSide || p.height > kMaxSide)
    throw InputError("--size " + size + ": a doors-keys-gems map is " + std::to_string(kMinSide) + " to " +
                     std::to_string(kMaxSide) + " cells wide and high");
  if (gems < 1 || gems > kMaxGems)
    throw InputError("--gems " + std::to_string(gems) + ": a doors-keys-gems map has 1 to " +
                     std::to_string(kMaxGems) + " gems");
  if (keys < 0 || doors < 0) throw InputError("--keys and --doors cannot be negative");
  if (doors > 0 && keys == 0)
    throw InputError("--doors " + std::to_string(doors) +
                     " with --keys 0: every gem stands behind a locked door, and a door opens only with a key");
  const int objects = gems + keys + doors + 2;
  if (objects > p.width * p.height)
    throw InputError(std::to_string(gems) + " gems, " + std::to_string(keys) + " keys, " + std::to_string(doors) +
                     " doors and the two agents need " + std::to_string(objects) + " cells, but a " + size +
                     " map has only " + std::to_string(p.width * p.height));
  if (objects > kMaxObjects)
    throw InputError(std::to_string(objects) + " objects (gems, keys, doors and the two agents): the grid "
                     "heuristics handle at most " + std::to_string(kMaxObjects));
}

std::optional<GeneratedProblem> generate_dkg_problem(const GenerateParams& params, util::Rng& rng) {
  check_dkg_generate_params(params);
  const int gems = count(params, "gem"), keys = count(params, "key"), doors = count(params, "door");
  Layout map(params.width, params.height);
  // One wall per door, and now and then one with an open gap.
  const int walls = doors + (doors > 0 ? static_cast<int>(rng.index(2)) : 0);
  for (int i = 0; i < walls; ++i)
    if (!map.divide(rng)) {
      if (i < doors) return std::nullopt;  // no room left for another door
      break;
    }
  std::vector<int> gap_order = map.gaps();
  rng.shuffle(gap_order);
  const std::vector<int> door_cells(gap_order.begin(), gap_order.begin() + doors);
  const int cells = params.width * params.height;
  std::vector<bool> is_door(static_cast<size_t>(cells), false);
  for (int c : door_cells) is_door[static_cast<size_t>(c)] = true;

  // Rooms with every door locked, numbered in scan order; objects stand on
  // floor that is not a gap, so no chokepoint is blocked.
  std::vector<int> room(static_cast<size_t>(cells), -1);
  std::vector<std::vector<int>> floor;  // per room, in scan order
  for (int c = 0; c < cells; ++c) {
    if (map.wall(c) || is_door[static_cast<size_t>(c)] || room[static_cast<size_t>(c)] >= 0) continue;
    const auto seen = map.reachable(c, is_door);
    floor.emplace_back();
    for (int d = 0; d < cells; ++d)
      if (seen[static_cast<size_t>(d)]) {
        room[static_cast<size_t>(d)] = static_cast<int>(floor.size()) - 1;
        if (!map.gap(d)) floor.back().push_back(d);
      }
  }
  size_t home = 0;
  for (size_t r = 1; r < floor.size(); ++r)
    if (floor[r].size() > floor[home].size()) home = r;
  std::vector<size_t> behind;  // rooms behind at least one door
  for (size_t r = 0; r < floor.size(); ++r)
    if (r != home) behind.push_back(r);
  rng.shuffle(behind);

  std::vector<Placed> objects;
  std::vector<int> gem_cells;
  for (int g = 0, turn = 0; g < gems; ++g) {
    // Round robin over the rooms behind doors, so each gets a gem while there
    // are gems; a room that is full is passed over (many gems on a small map).
    size_t r = home;
    for (size_t tried = 0; !behind.empty() && tried < behind.size(); ++tried, ++turn) {
      r = behind[static_cast<size_t>(turn) % behind.size()];
      if (!floor[r].empty()) break;
    }
    ++turn;
    auto& pool = floor[r];
    std::vector<int> got;
    if (!take_cells(pool, 1, rng, got)) return std::nullopt;
    gem_cells.push_back(got[0]);
    objects.push_back({got[0], 'g', ""});
  }
  std::vector<int> home_cells;
  if (!take_cells(floor[home], keys + 2, rng, home_cells)) return std::nullopt;
  const int human = home_cells[0];
  objects.push_back({human, 'h', ""});
  objects.push_back({home_cells[1], 'm', ""});

  // The doors between the human and each gem: those whose closing alone
  // cuts the gem off. A door that cuts off no gem does not matter: redraw.
  std::vector<std::vector<int>> doors_to_gem(static_cast<size_t>(gems));
  for (int d = 0; d < doors; ++d) {
    std::vector<bool> closed(static_cast<size_t>(cells), false);
    closed[static_cast<size_t>(door_cells[static_cast<size_t>(d)])] = true;
    const auto seen = map.reachable(human, closed);
    bool matters = false;
    for (int g = 0; g < gems; ++g)
      if (!seen[static_cast<size_t>(gem_cells[static_cast<size_t>(g)])]) {
        doors_to_gem[static_cast<size_t>(g)].push_back(d);
        matters = true;
      }
    if (!matters) return std::nullopt;
  }

  // Door colours such that the keys can cover every gem's doors; keys are
  // used up, so a gem behind two red doors needs two red keys.
  std::vector<int> door_color(static_cast<size_t>(doors));
  std::array<int, kDoorColors.size()> need{};
  bool covered = false;
  for (int draw = 0; draw < kColorDraws && !covered; ++draw) {
    for (int& c : door_color) c = static_cast<int>(rng.index(kDoorColors.size()));
    need.fill(0);
    for (const auto& path : doors_to_gem) {
      std::array<int, kDoorColors.size()> n{};
      for (int d : path) ++n[static_cast<size_t>(door_color[static_cast<size_t>(d)])];
      for (size_t c = 0; c < n.size(); ++c) need[c] = std::max(need[c], n[c]);
    }
    int total = 0;
    for (int n : need) total += n;
    covered = total <= keys;
  }
  if (!covered) return std::nullopt;
  std::vector<int> key_color;
  for (size_t c = 0; c < need.size(); ++c) key_color.insert(key_color.end(), static_cast<size_t>(need[c]), static_cast<int>(c));
  while (static_cast<int>(key_color.size()) < keys) key_color.push_back(static_cast<int>(rng.index(kDoorColors.size())));
  rng.shuffle(key_color);
  for (int k = 0; k < keys; ++k)
    objects.push_back({home_cells[static_cast<size_t>(k) + 2], 'k', kDoorColors[static_cast<size_t>(key_color[static_cast<size_t>(k)])]});
  for (int d = 0; d < doors; ++d)
    objects.push_back({door_cells[static_cast<size_t>(d)], 'd', kDoorColors[static_cast<size_t>(door_color[static_cast<size_t>(d)])]});

  GeneratedProblem out;
  out.pddl = problem_text(params, map, objects);
  out.picture = picture(map, objects);
  return out;
}

}  // namespace clips::domains::dkg
