#include "domains/dkg/dkg_world.hpp"

#include <stdexcept>

namespace clips::domains::dkg {

using pddl::ObjectId;

DkgWorld::DkgWorld(const pddl::Task& task) : task_(&task) {
  auto w = task.fluent("walls", {});
  if (!w.matrix) throw InputError("Doors-Keys-Gems task has no static (walls) bit-matrix");
  walls_ = w.matrix;
  width_ = walls_->cols;
  height_ = walls_->rows;
  auto humans = task.objects_of_type("human");
  auto robots = task.objects_of_type("robot");
  if (humans.size() != 1 || robots.size() != 1) throw InputError("Doors-Keys-Gems needs exactly one human and one robot");
  human_ = humans[0];
  robot_ = robots[0];
  agents_ = {human_, robot_};
  keys_ = task.objects_of_type("key");
  doors_ = task.objects_of_type("door");
  gems_ = task.objects_of_type("gem");
  int n = task.num_objects();
  x_.resize(n);
  y_.resize(n);
  color_.resize(n);
  auto colors = task.objects_of_type("color");
  for (ObjectId o = 0; o < n; ++o) {
    if (!task.object_is_a(o, "physical")) continue;
    x_[o] = task.fluent("xloc", {task.object_name(o)});
    y_[o] = task.fluent("yloc", {task.object_name(o)});
    for (ObjectId c : colors)
      if (task.atom("iscolor", {task.object_name(o), task.object_name(c)}).value) color_[o] = task.object_name(c);
  }
}

bool DkgWorld::wall(int x, int y) const {
  if (x < 1 || y < 1 || x > width_ || y > height_) return true;
  return walls_->get(y - 1, x - 1);
}

std::string DkgWorld::color(ObjectId o) const { return color_[o]; }

Cell DkgWorld::pos(const pddl::State& s, ObjectId o) const {
  int x = static_cast<int>(task_->value(s, x_[o]));
  int y = static_cast<int>(task_->value(s, y_[o]));
  if (x < 1 || y < 1) return Cell{};
  return Cell{x, y};
}

bool DkgWorld::has(const pddl::State& s, ObjectId agent, ObjectId item) const {
  return task_->test(s, task_->atom(*task_->domain().find_predicate("has"), {agent, item}));
}

std::optional<ObjectId> DkgWorld::holder(const pddl::State& s, ObjectId i) const {
  for (ObjectId a : agents_)
    if (has(s, a, i)) return a;
  return std::nullopt;
}

bool DkgWorld::locked(const pddl::State& s, ObjectId door) const {
  return task_->test(s, task_->atom(*task_->domain().find_predicate("locked"), {door}));
}

bool DkgWorld::active(const pddl::State& s, ObjectId agent) const {
  return task_->test(s, task_->atom(*task_->domain().find_predicate("active"), {agent}));
}

ObjectId DkgWorld::active_agent(const pddl::State& s) const { return active(s, human_) ? human_ : robot_; }

bool DkgWorld::picked_up_by(const pddl::State& s, ObjectId agent, ObjectId item) const {
  return task_->test(s, task_->atom(*task_->domain().find_predicate("pickedup-by"), {agent, item}));
}

bool DkgWorld::unlocked_by(const pddl::State& s, ObjectId agent, ObjectId door) const {
  return task_->test(s, task_->atom(*task_->domain().find_predicate("unlocked-by"), {agent, door}));
}

namespace {
char color_letter(const std::string& c) {
  if (c == "red") return 'r';
  if (c == "yellow") return 'y';
  if (c == "blue") return 'b';
  if (c == "green") return 'e';
  if (c == "pink") return 'p';
  return 'k';
}
}  // namespace

std::string DkgWorld::ascii(const pddl::State& s) const {
  std::vector<std::string> rows(height_, std::string(width_, '.'));
  for (int y = 1; y <= height_; ++y)
    for (int x = 1; x <= width_; ++x)
      if (wall(x, y)) rows[y - 1][x - 1] = 'W';
  auto put = [&](Cell c, char ch) {
    if (c.on_grid() && c.x <= width_ && c.y <= height_) rows[c.y - 1][c.x - 1] = ch;
  };
  for (ObjectId d : doors_)
    put(pos(s, d), locked(s, d) ? static_cast<char>(std::toupper(color_letter(color_[d]))) : '_');
  for (ObjectId k : keys_) put(pos(s, k), color_letter(color_[k]));
  for (ObjectId g : gems_) put(pos(s, g), 'g');
  Cell h = pos(s, human_), m = pos(s, robot_);
  put(h, 'h');
  put(m, 'm');
  if (h == m) put(h, '@');
  std::string out;
  for (auto& r : rows) out += r + "\n";
  return out;
}

std::string DkgWorld::describe(const pddl::State& s) const {
  std::string out = "active: " + name(active_agent(s)) + "\n";
  for (ObjectId a : agents_) {
    Cell c = pos(s, a);
    out += name(a) + " at (" + std::to_string(c.x) + "," + std::to_string(c.y) + ") holds:";
    bool any = false;
    for (ObjectId i : keys_)
      if (has(s, a, i)) out += " " + name(i) + "(" + color_[i] + ")", any = true;
    for (ObjectId i : gems_)
      if (has(s, a, i)) out += " " + name(i) + "(" + color_[i] + ")", any = true;
    out += any ? "\n" : " nothing\n";
  }
  for (ObjectId d : doors_) {
    Cell c = pos(s, d);
    out += name(d) + " (" + color_[d] + ") at (" + std::to_string(c.x) + "," + std::to_string(c.y) + ") " +
           (locked(s, d) ? "locked" : "unlocked") + "\n";
  }
  for (ObjectId k : keys_) {
    Cell c = pos(s, k);
    auto h = holder(s, k);
    out += name(k) + " (" + color_[k] + ") ";
    if (c.on_grid()) out += "at (" + std::to_string(c.x) + "," + std::to_string(c.y) + ")\n";
    else if (h) out += "held by " + name(*h) + "\n";
    else out += "used\n";
  }
  for (ObjectId g : gems_) {
    Cell c = pos(s, g);
    out += name(g) + " (" + color_[g] + ") ";
    out += c.on_grid() ? "at (" + std::to_string(c.x) + "," + std::to_string(c.y) + ")\n" : "picked up\n";
  }
  return out;
}

}  // namespace clips::domains::dkg
