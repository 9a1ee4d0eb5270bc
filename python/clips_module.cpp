// The Python module `clips` (pybind11): the session API of
// include/clips/session.hpp, plus a whole dataset plan (as `clips infer`) and
// a whole bench (as `clips bench`), all returning plain dicts and lists.
// C++ exceptions become clips.InputError (a ValueError),
// clips.InapplicableActionError (an InputError) and clips.LanguageModelError
// (a RuntimeError) with the same messages. Inference runs without the GIL.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <functional>
#include <optional>

#include "clips/clips.hpp"
#include "data/dataset.hpp"
#include "eval/bench.hpp"
#include "inference/belief.hpp"
#include "language/listener.hpp"

namespace py = pybind11;

namespace {

// ---- session options: one table for every opener ---------------------------
//
// Session.open_dataset and Session.open_domain take the same keyword options,
// read by this one table (name, what it sets, its default from
// clips::SessionOptions{} itself), so that the openers cannot drift apart.

std::string type_name(py::handle v) { return py::str(py::type::handle_of(v).attr("__name__")); }

template <typename T>
T cast_option(const char* name, py::handle v, const char* expected) {
  try {
    return py::cast<T>(v);
  } catch (const py::cast_error&) {
    throw py::type_error(std::string("option '") + name + "': expected " + expected + ", got " + type_name(v));
  }
}

std::string text_option(const char* name, py::handle v) { return cast_option<std::string>(name, v, "str"); }

long long int_option(const char* name, py::handle v, long long lo) {
  if (py::isinstance<py::bool_>(v))
    throw py::type_error(std::string("option '") + name + "': expected int, got bool");
  const long long x = cast_option<long long>(name, v, "int");
  if (x < lo) throw clips::InputError(std::string(name) + " must be >= " + std::to_string(lo) + ", got " + std::to_string(x));
  return x;
}

double float_option(const char* name, py::handle v) {
  if (py::isinstance<py::bool_>(v))
    throw py::type_error(std::string("option '") + name + "': expected float, got bool");
  return cast_option<double>(name, v, "float");
}

std::vector<std::string> list_option(const char* name, py::handle v) {
  if (py::isinstance<py::str>(v))
    throw py::type_error(std::string("option '") + name + "': expected a list of str, got one str");
  return cast_option<std::vector<std::string>>(name, v, "a list of str");
}

clips::Method parse_method(const std::string& m) {
  if (m == "clips" || m == "both") return clips::Method::Clips;
  if (m == "language" || m == "language-only" || m == "utterance") return clips::Method::LanguageOnly;
  if (m == "action" || m == "action-only") return clips::Method::ActionOnly;
  throw clips::InputError("unknown method '" + m + "' (expected clips, language or action)");
}

clips::Assistance parse_assistance(const std::string& a) {
  if (a == "qmdp") return clips::Assistance::QMdp;
  if (a == "pibar") return clips::Assistance::PiBar;
  throw clips::InputError("unknown assistance '" + a + "' (expected qmdp or pibar)");
}

struct SessionOption {
  const char* name;
  const char* help;
  std::function<void(clips::SessionOptions&, py::handle)> set;
  std::function<std::string(const clips::SessionOptions&)> show;  // the default, as Python would write it
};

std::string quoted(const std::string& s) { return "'" + s + "'"; }
std::string number(double v) { return py::str(py::float_(v)); }

const std::vector<SessionOption>& session_option_table() {
  using O = clips::SessionOptions;
  static const std::vector<SessionOption> table = {
      {"method", "clips, language or action: the evidence the posterior and the assistance use",
       [](O& o, py::handle v) { o.method = parse_method(text_option("method", v)); },
       [](const O&) { return quoted("clips"); }},
      {"assistance", "qmdp or pibar",
       [](O& o, py::handle v) { o.assistance = parse_assistance(text_option("assistance", v)); },
       [](const O&) { return quoted("qmdp"); }},
      {"lm", "language model: embedded (offline) or openai",
       [](O& o, py::handle v) { o.language_model.backend = text_option("lm", v); },
       [](const O& o) { return quoted(o.language_model.backend); }},
      {"lm_base_url", "openai: completions API base URL ('': $CLIPS_LM_BASE_URL, else OpenAI's)",
       [](O& o, py::handle v) { o.language_model.base_url = text_option("lm_base_url", v); },
       [](const O& o) { return quoted(o.language_model.base_url); }},
      {"lm_model", "openai: model name ('': $CLIPS_LM_MODEL, else davinci-002)",
       [](O& o, py::handle v) { o.language_model.model = text_option("lm_model", v); },
       [](const O& o) { return quoted(o.language_model.model); }},
      {"lm_timeout", "openai: seconds per request",
       [](O& o, py::handle v) {
         o.language_model.timeout_seconds = float_option("lm_timeout", v);
         if (!(o.language_model.timeout_seconds > 0)) throw clips::InputError("lm_timeout must be > 0");
       },
       [](const O& o) { return number(o.language_model.timeout_seconds); }},
      {"goals", "candidate goals as PDDL conditions ([]: the domain pack's)",
       [](O& o, py::handle v) { o.goals = list_option("goals", v); }, [](const O&) { return std::string("[]"); }},
      {"cost_profiles", "candidate cost profiles ([]: the plan's or the pack's default)",
       [](O& o, py::handle v) { o.cost_profiles = list_option("cost_profiles", v); },
       [](const O&) { return std::string("[]"); }},
      {"max_nodes", "expansions per lookahead search",
       [](O& o, py::handle v) { o.max_nodes = static_cast<size_t>(int_option("max_nodes", v, 1)); },
       [](const O& o) { return std::to_string(o.max_nodes); }},
      {"threads", "threads refining the hypotheses (0: all cores)",
       [](O& o, py::handle v) { o.threads = static_cast<int>(int_option("threads", v, 0)); },
       [](const O& o) { return std::to_string(o.threads); }},
      {"particles", "particle inference with this many particles (0: exact enumeration)",
       [](O& o, py::handle v) { o.particles = static_cast<int>(int_option("particles", v, 0)); },
       [](const O& o) { return std::to_string(o.particles); }},
      {"particle_seed", "the particle filter's seed",
       [](O& o, py::handle v) {
         if (py::isinstance<py::bool_>(v)) throw py::type_error("option 'particle_seed': expected int, got bool");
         o.particle_seed = cast_option<uint64_t>("particle_seed", v, "an int from 0 to 2**64-1");
       },
       [](const O& o) { return std::to_string(o.particle_seed); }},
      {"ess_threshold", "resample below this share of the particles, in [0, 1]",
       [](O& o, py::handle v) { o.ess_threshold = float_option("ess_threshold", v); },
       [](const O& o) { return number(o.ess_threshold); }},
      {"rejuvenation_moves", "Metropolis-Hastings sweeps after each resampling",
       [](O& o, py::handle v) { o.rejuvenation_moves = static_cast<int>(int_option("rejuvenation_moves", v, 0)); },
       [](const O& o) { return std::to_string(o.rejuvenation_moves); }},
      {"rejuvenate", "when else the sweeps run: evidence, utterances or resampling",
       [](O& o, py::handle v) { o.rejuvenate = text_option("rejuvenate", v); },
       [](const O& o) { return quoted(o.rejuvenate); }},
      {"proposal_groups", "exploring proposals per sweep",
       [](O& o, py::handle v) { o.proposal_groups = static_cast<int>(int_option("proposal_groups", v, 1)); },
       [](const O& o) { return std::to_string(o.proposal_groups); }},
      {"particle_filters", "all (one filter per method) or clips",
       [](O& o, py::handle v) { o.particle_filters = text_option("particle_filters", v); },
       [](const O& o) { return quoted(o.particle_filters); }},
      {"particle_estimate", "support or weights",
       [](O& o, py::handle v) { o.particle_estimate = text_option("particle_estimate", v); },
       [](const O& o) { return quoted(o.particle_estimate); }},
      {"assistant_turns", "refinement at the assistant's turns: taken or all (as --assistant-turns)",
       [](O& o, py::handle v) { o.assistant_turns = text_option("assistant_turns", v); },
       [](const O& o) { return quoted(o.assistant_turns); }},
  };
  return table;
}

// The options named in `kwargs`; `taken` lists keywords the opener reads
// itself. An unknown keyword is a TypeError, as for any Python function.
clips::SessionOptions session_options(const py::kwargs& kwargs, const char* opener,
                                      std::initializer_list<const char*> taken = {}) {
  clips::SessionOptions o;
  const auto& table = session_option_table();
  for (auto item : kwargs) {
    const std::string key = py::str(item.first);
    if (std::any_of(taken.begin(), taken.end(), [&](const char* t) { return key == t; })) continue;
    auto it = std::find_if(table.begin(), table.end(), [&](const SessionOption& so) { return key == so.name; });
    if (it == table.end())
      throw py::type_error(std::string(opener) + "() got an unexpected keyword argument '" + key + "'");
    if (item.second.is_none()) continue;  // None: the default
    it->set(o, item.second);
  }
  return o;
}

std::string options_doc() {
  std::string d = "Keyword options (shared by open_dataset and open_domain; None keeps the default):\n";
  const clips::SessionOptions defaults;
  for (const auto& so : session_option_table())
    d += std::string("  ") + so.name + "=" + so.show(defaults) + ": " + so.help + "\n";
  return d;
}

// A str or os.PathLike (pathlib.Path) as a path.
std::string path_arg(const char* name, py::handle v) {
  if (py::isinstance<py::str>(v)) return py::cast<std::string>(v);
  if (py::hasattr(v, "__fspath__")) return py::cast<std::string>(py::module_::import("os").attr("fspath")(v));
  throw py::type_error(std::string("argument '") + name + "': expected str or os.PathLike, got " + type_name(v));
}

py::dict to_dict(const clips::Posterior& p) {
  py::dict goals, profiles;
  for (size_t g = 0; g < p.goals.size(); ++g) goals[py::str(p.goals[g])] = p.goal_probabilities[g];
  for (size_t c = 0; c < p.cost_profiles.size(); ++c)
    profiles[py::str(p.cost_profiles[c])] = p.cost_profile_probabilities[c];
  py::list hyps;
  for (const auto& h : p.hypotheses) {
    py::dict d;
    d["goal"] = h.goal;
    d["cost_profile"] = h.cost_profile;
    d["weight"] = h.weight;
    hyps.append(d);
  }
  py::dict d;
  d["goals"] = goals;
  d["cost_profiles"] = profiles;
  d["hypotheses"] = hyps;
  d["log_marginal_likelihood"] = p.log_marginal_likelihood;
  return d;
}

py::dict to_dict(const clips::Step& s) {
  py::dict d;
  d["t"] = s.t;
  d["action"] = s.action;
  d["agent"] = s.agent;
  d["evidence"] = s.evidence;
  d["utterances"] = s.utterances;
  d["posterior"] = to_dict(s.posterior);
  d["seconds"] = s.seconds;
  return d;
}

py::dict to_dict(const clips::AssistDecision& a) {
  py::dict d;
  d["assistant_turn"] = a.assistant_turn;
  d["action"] = a.assistant_turn ? py::object(py::str(a.action)) : py::object(py::none());
  d["id"] = a.id;
  py::list cands;
  for (const auto& c : a.candidates) {
    py::dict cd;
    cd["id"] = c.id;
    cd["action"] = c.action;
    cd["value"] = c.value;
    cands.append(cd);
  }
  d["candidates"] = cands;
  d["unanimous"] = a.unanimous;
  py::dict weights;
  for (size_t g = 0; g < a.goals.size(); ++g) weights[py::str(a.goals[g])] = a.goal_weights[g];
  d["goal_weights"] = weights;
  return d;
}

// One dataset plan, as `clips infer --json` (every step, all three methods).
py::dict run_plan(const std::string& dataset, const std::string& plan_id, const std::string& lm_kind, int threads) {
  std::optional<clips::inference::InferenceRun> run;
  {
    py::gil_scoped_release unlocked;
    auto ds = clips::data::Dataset::load(dataset);
    const auto& plan = ds.plan(plan_id);
    auto lm = clips::language::make_language_model(lm_kind);
    clips::inference::InferenceOptions o;
    o.threads = threads;
    run = clips::inference::run_inference(ds, plan, *lm, o);
  }
  py::dict d;
  d["plan"] = run->plan_id;
  d["goals"] = run->goals;
  d["true_goal"] = run->true_goal >= 0 ? py::object(py::str(run->goals[run->true_goal])) : py::object(py::none());
  d["cost_profiles"] = run->profiles;
  py::list steps;
  for (const auto& st : run->steps) {
    py::dict s;
    s["t"] = st.t;
    s["action"] = st.action;
    py::list us;
    for (const auto& u : st.utterances) us.append(u.text);
    s["utterances"] = us;
    for (auto m : clips::inference::kModalities) {
      const char* name = m == clips::inference::Modality::Both          ? "clips"
                         : m == clips::inference::Modality::UtteranceOnly ? "language"
                                                                          : "action";
      s[name] = st[m].goals;
    }
    s["log_marginal_likelihood"] = st[clips::inference::Modality::Both].log_marginal;
    s["seconds"] = st.seconds;
    steps.append(s);
  }
  d["steps"] = steps;
  d["seconds"] = run->seconds;
  return d;
}

// A whole bench, as `clips bench`: one row per plan and method (ready for
// pandas.DataFrame) and the aggregated summary.
py::dict run_bench(const std::string& dataset, std::vector<std::string> methods, std::vector<std::string> plans,
                   int jobs, uint64_t seed, const std::string& lm_kind) {
  clips::eval::BenchReport rep;
  {
    py::gil_scoped_release unlocked;
    clips::eval::BenchOptions o;
    o.dataset = dataset;
    o.jobs = jobs;
    o.experiment.methods = std::move(methods);
    o.experiment.seed = seed;
    o.lm = lm_kind;
    o.plans = std::move(plans);
    o.progress = false;
    rep = clips::eval::run_bench(o);
  }
  py::list rows;
  for (const auto& p : rep.plans) {
    if (!p.error.empty()) {
      py::dict r;
      r["plan"] = p.plan_id;
      r["error"] = p.error;
      rows.append(r);
      continue;
    }
    for (const auto& m : p.methods) {
      py::dict r;
      r["domain"] = rep.domain;
      r["plan"] = p.plan_id;
      r["method"] = m.method;
      r["p_true_goal"] = m.p_true_goal ? py::object(py::float_(*m.p_true_goal)) : py::object(py::none());
      r["precision"] = m.precision;
      r["recall"] = m.recall;
      r["plan_length"] = m.plan_length;
      r["human_cost"] = m.human_cost;
      r["plan_cost"] = m.plan_cost;
      r["goal_success"] = m.goal_success;
      r["rel_plan_length"] = m.has_relative ? py::object(py::float_(m.rel_plan_length)) : py::object(py::none());
      r["rel_human_cost"] = m.has_relative ? py::object(py::float_(m.rel_human_cost)) : py::object(py::none());
      r["seconds"] = m.seconds;
      r["error"] = m.error;
      rows.append(r);
    }
  }
  py::dict summary;
  for (const auto& ms : rep.summary) {
    py::dict metrics;
    for (const auto& [name, v] : ms.metrics) {
      py::dict x;
      x["mean"] = v.mean;
      x["se"] = v.se;
      x["n"] = v.n;
      metrics[py::str(name)] = x;
    }
    summary[py::str(ms.method)] = metrics;
  }
  py::dict d;
  d["domain"] = rep.domain;
  d["lm"] = rep.lm;
  d["rows"] = rows;
  d["summary"] = summary;
  d["wall_seconds"] = rep.wall_seconds;
  d["failed_plans"] = rep.failed_plans;
  return d;
}

}  // namespace

PYBIND11_MODULE(clips, m) {
  m.doc() = "Goal inference from a human's actions and instructions, and assistance (CLIPS)";
  m.attr("__version__") = clips::library_version();

  auto& input_error = py::register_exception<clips::InputError>(m, "InputError", PyExc_ValueError);
  py::register_exception<clips::InapplicableActionError>(m, "InapplicableActionError", input_error.ptr());
  auto& lm_error = py::register_exception<clips::LanguageModelError>(m, "LanguageModelError", PyExc_RuntimeError);
  // Internal language-model failures reach Python as the same type.
  static PyObject* lm_error_type = lm_error.ptr();
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const clips::lm::LmError& e) {
      PyErr_SetString(lm_error_type, e.what());
    }
  });

  py::class_<clips::Session>(m, "Session",
                             "A live inference session; open it with Session.open_dataset or Session.open_domain")
      .def_static(
          "open_dataset",
          [](py::object dataset, const std::string& problem, const py::kwargs& kwargs) {
            const std::string dir = path_arg("dataset", dataset);
            auto o = session_options(kwargs, "open_dataset");
            py::gil_scoped_release unlocked;
            return clips::Session::open_dataset(dir, problem, std::move(o));
          },
          py::arg("dataset"), py::arg("problem"),
          ("open_dataset(dataset, problem, **options)\n\n"
           "A dataset problem ('2') or plan ('2.1.keys': its goals and cost profiles, from the initial state); the "
           "folder may have no plans/. particles > 0: particle inference with that many particles instead of exact "
           "enumeration, tuned as clips infer's options of the same names.\n\n" +
           options_doc())
              .c_str())
      .def_static(
          "open_domain",
          [](py::object domain_dir, py::object problem_file, const py::kwargs& kwargs) {
            auto text = [&](const char* key) -> std::optional<std::string> {
              if (!kwargs.contains(key) || kwargs[key].is_none()) return std::nullopt;
              return text_option(key, kwargs[key]);
            };
            const auto domain_text = text("domain_text"), problem_text = text("problem_text"),
                       pack_text = text("pack_text");
            auto o = session_options(kwargs, "open_domain", {"domain_text", "problem_text", "pack_text"});
            const bool from_text = domain_text || problem_text || pack_text;
            if (from_text) {
              if (!domain_dir.is_none() || !problem_file.is_none())
                throw clips::InputError(
                    "open_domain: give domain_dir and problem_file (paths), or domain_text and problem_text "
                    "(PDDL text, with pack_text), not both");
              if (!domain_text || !problem_text)
                throw clips::InputError(std::string("open_domain: ") + (domain_text ? "problem_text" : "domain_text") +
                                        " is missing (PDDL text comes as both domain_text and problem_text)");
              py::gil_scoped_release unlocked;
              return clips::Session::open_domain_text(*domain_text, *problem_text, pack_text.value_or(""), std::move(o));
            }
            if (domain_dir.is_none() || problem_file.is_none())
              throw clips::InputError(std::string("open_domain: ") + (domain_dir.is_none() ? "domain_dir" : "problem_file") +
                                      " is missing (give domain_dir and problem_file, or domain_text and problem_text)");
            const std::string dir = path_arg("domain_dir", domain_dir), file = path_arg("problem_file", problem_file);
            py::gil_scoped_release unlocked;
            return clips::Session::open_domain(dir, file, std::move(o));
          },
          py::arg("domain_dir") = py::none(), py::arg("problem_file") = py::none(),
          ("open_domain(domain_dir=None, problem_file=None, *, domain_text=None, problem_text=None, pack_text=None, "
           "**options)\n\n"
           "A domain folder (holding domain.pddl, and pack.json if the domain has one) and a problem file; or the "
           "domain and the problem as PDDL text (domain_text, problem_text), with the pack as JSON text (pack_text; "
           "None: the pack the domain's name finds). The candidate goals follow the pack's rule for the problem.\n\n" +
           options_doc())
              .c_str())
      .def(
          "observe",
          [](clips::Session& s, const std::string& action) {
            const clips::Step* st;
            {
              py::gil_scoped_release unlocked;
              st = &s.observe(action);
            }
            return to_dict(*st);
          },
          py::arg("action"), "An action of either agent, as PDDL text; returns the step's record")
      .def(
          "observe",
          [](clips::Session& s, int id) {
            const clips::Step* st;
            {
              py::gil_scoped_release unlocked;
              st = &s.observe(id);
            }
            return to_dict(*st);
          },
          py::arg("action_id"))
      .def(
          "hear",
          [](clips::Session& s, const std::string& utterance) {
            const clips::Step* st;
            {
              py::gil_scoped_release unlocked;
              st = &s.hear(utterance);
            }
            return to_dict(*st);
          },
          py::arg("utterance"))
      .def(
          "posterior",
          [](const clips::Session& s, std::optional<std::string> method) {
            return to_dict(method ? s.posterior(parse_method(*method)) : s.posterior());
          },
          py::arg("method") = py::none(), "Goal and cost-profile probabilities, per-hypothesis weights")
      .def(
          "assist",
          [](clips::Session& s) {
            clips::AssistDecision d;
            {
              py::gil_scoped_release unlocked;
              d = s.assist();
            }
            return to_dict(d);
          },
          "The assistant's next action, the candidates' values and the goal weights behind them")
      .def("state", &clips::Session::state)
      .def("__str__", &clips::Session::state)
      .def("trace",
           [](const clips::Session& s) {
             py::list out;
             for (const auto& st : s.trace()) out.append(to_dict(st));
             return out;
           })
      .def_property_readonly("t", &clips::Session::t)
      .def_property_readonly("domain", &clips::Session::domain)
      .def_property_readonly("active_agent", &clips::Session::active_agent)
      .def_property_readonly("assistant_turn", &clips::Session::assistant_turn)
      .def("applicable_actions",
           [](const clips::Session& s) {
             py::list out;
             for (const auto& a : s.applicable_actions()) {
               py::dict d;
               d["id"] = a.id;
               d["action"] = a.action;
               out.append(d);
             }
             return out;
           })
      .def("action_name", &clips::Session::action_name);

  m.def("run_plan", &run_plan, py::arg("dataset"), py::arg("plan"), py::kw_only(), py::arg("lm") = "embedded",
        py::arg("threads") = 0,
        "Goal inference over one dataset plan, as `clips infer`: every step's goal posterior for the clips, "
        "language and action methods");
  m.def("run_bench", &run_bench, py::arg("dataset"), py::kw_only(), py::arg("methods") = std::vector<std::string>{},
        py::arg("plans") = std::vector<std::string>{}, py::arg("jobs") = 0, py::arg("seed") = 1,
        py::arg("lm") = "embedded",
        "Every plan x method of a dataset, as `clips bench`: {'rows': [...], 'summary': {...}, ...}");
  m.def("data_directory", &clips::data_directory);
}
