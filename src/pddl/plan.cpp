#include "pddl/plan.hpp"

#include "pddl/parser.hpp"

namespace clips::pddl {

namespace {
std::string strip(const std::string& s) {
  size_t a = s.find_first_not_of(" \t\r\n");
  if (a == std::string::npos) return "";
  size_t b = s.find_last_not_of(" \t\r\n");
  return s.substr(a, b - a + 1);
}

// Plan text quoted in an error message: escaped, and cut if very long.
std::string quoted(const std::string& text) { return printable(text, 200); }
}  // namespace

PlanFile parse_plan(const std::string& text, const std::string& path) {
  PlanFile pf;
  pf.path = path;
  int line_no = 0;
  size_t pos = text.compare(0, 3, "\xEF\xBB\xBF") == 0 ? 3 : 0;  // skip a byte-order mark
  while (pos <= text.size()) {
    size_t nl = text.find('\n', pos);
    std::string raw = text.substr(pos, nl == std::string::npos ? std::string::npos : nl - pos);
    ++line_no;
    std::string line = strip(raw);
    if (!line.empty()) {
      SourceLoc loc{path, line_no, static_cast<int>(raw.find_first_not_of(" \t\r\n")) + 1};
      if (line[0] == ';') {
        pf.utterances.push_back({strip(line.substr(1)), static_cast<int>(pf.actions.size()), loc});
      } else {
        pf.actions.push_back({line, loc});
      }
    }
    if (nl == std::string::npos) break;
    pos = nl + 1;
  }
  return pf;
}

PlanFile load_plan(const std::string& path) { return parse_plan(read_text_file(path), path); }

ActionId resolve_step(const Task& task, const PlanLine& line, const State& s) {
  SExpr e;
  try {
    e = read_one_sexpr(line.text, line.loc);
  } catch (const SyntaxError& err) {
    throw InputError(err.loc, "malformed action '" + quoted(line.text) + "': " + err.message);
  }
  if (!e.is_list || e.items.empty() || e.items[0].is_list)
    throw InputError(line.loc, "expected an action term like (name arg ...), found '" + quoted(line.text) + "'");
  const Domain& d = task.domain();
  int schema = d.find_action(e.head());
  if (schema < 0) throw InputError(line.loc, "unknown action '" + printable(e.head()) + "' in " + quoted(line.text));
  const ActionSchema& sc = d.actions[schema];
  if (e.items.size() - 1 != sc.param_types.size())
    throw InputError(line.loc, "arity mismatch: '" + sc.name + "' takes " + std::to_string(sc.param_types.size()) +
                                   " argument(s), given " + std::to_string(e.items.size() - 1) + " in " + quoted(line.text));
  std::vector<ObjectId> args;
  for (size_t i = 1; i < e.items.size(); ++i) {
    const SExpr& a = e.items[i];
    auto o = a.is_list ? std::nullopt : task.find_object(a.atom);
    if (!o) throw InputError(line.loc, "unknown object '" + quoted(a.str()) + "' in " + quoted(line.text));
    args.push_back(*o);
  }
  auto id = task.find_action(schema, args);
  if (id && task.applicable(*id, s.data())) return *id;
  std::string why = task.explain_inapplicable(schema, args, s);
  if (why.empty()) why = "its precondition is false";
  throw InputError(line.loc, "action " + quoted(line.text) + " is not applicable: " + printable(why));
}

Simulation simulate(const Task& task, const State& start, const PlanFile& plan) {
  Simulation sim;
  sim.states.push_back(start);
  for (const PlanLine& line : plan.actions) {
    ActionId a = resolve_step(task, line, sim.states.back());
    sim.actions.push_back(a);
    sim.cost += task.action(a).cost;
    sim.states.push_back(task.apply(sim.states.back(), a));
  }
  return sim;
}

Simulation simulate(const Task& task, const State& start, const std::vector<ActionId>& actions) {
  Simulation sim;
  sim.states.push_back(start);
  for (size_t i = 0; i < actions.size(); ++i) {
    ActionId a = actions[i];
    if (!task.applicable(a, sim.states.back().data()))
      throw InputError("step " + std::to_string(i + 1) + ": action " + task.action_name(a) + " is not applicable: " +
                       task.explain_inapplicable(task.action(a).schema, task.action(a).args, sim.states.back()));
    sim.actions.push_back(a);
    sim.cost += task.action(a).cost;
    sim.states.push_back(task.apply(sim.states.back(), a));
  }
  return sim;
}

}  // namespace clips::pddl
