// The Python module `clips` (pybind11): the session API of
// include/clips/session.hpp, plus a whole dataset plan (as `clips infer`) and
// a whole bench (as `clips bench`), all returning plain dicts and lists.
// C++ exceptions become clips.InputError (a ValueError),
// clips.InapplicableActionError (an InputError) and clips.LanguageModelError
// (a RuntimeError) with the same messages. Inference runs without the GIL.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <optional>

#include "clips/clips.hpp"
#include "data/dataset.hpp"
#include "eval/bench.hpp"
#include "inference/belief.hpp"
#include "language/listener.hpp"

namespace py = pybind11;

namespace {

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

clips::SessionOptions session_options(const std::string& method, const std::string& assistance, const std::string& lm,
                                      const std::string& lm_base_url, const std::string& lm_model, double lm_timeout,
                                      std::vector<std::string> goals, std::vector<std::string> cost_profiles,
                                      size_t max_nodes, int threads, int particles = 0,
                                      uint64_t particle_seed = 1, const clips::SessionOptions& tuning = {}) {
  clips::SessionOptions o;
  o.method = parse_method(method);
  o.assistance = parse_assistance(assistance);
  o.language_model.backend = lm;
  o.language_model.base_url = lm_base_url;
  o.language_model.model = lm_model;
  o.language_model.timeout_seconds = lm_timeout;
  o.goals = std::move(goals);
  o.cost_profiles = std::move(cost_profiles);
  o.max_nodes = max_nodes;
  o.threads = threads;
  if (particles < 0) throw clips::InputError("particles must be >= 0 (0: exact inference)");
  o.particles = particles;
  o.particle_seed = particle_seed;
  o.ess_threshold = tuning.ess_threshold;
  o.rejuvenation_moves = tuning.rejuvenation_moves;
  o.rejuvenate = tuning.rejuvenate;
  o.proposal_groups = tuning.proposal_groups;
  o.particle_filters = tuning.particle_filters;
  o.particle_estimate = tuning.particle_estimate;
  o.assistant_turns = tuning.assistant_turns;
  return o;
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
          [](const std::string& dataset, const std::string& problem, const std::string& method,
             const std::string& assistance, const std::string& lm, const std::string& lm_base_url,
             const std::string& lm_model, double lm_timeout, std::vector<std::string> goals,
             std::vector<std::string> cost_profiles, size_t max_nodes, int threads, int particles,
             uint64_t particle_seed, double ess_threshold, int rejuvenation_moves, const std::string& rejuvenate,
             int proposal_groups, const std::string& particle_filters, const std::string& particle_estimate,
             const std::string& assistant_turns) {
            clips::SessionOptions tuning;
            tuning.ess_threshold = ess_threshold;
            tuning.rejuvenation_moves = rejuvenation_moves;
            tuning.rejuvenate = rejuvenate;
            tuning.proposal_groups = proposal_groups;
            tuning.particle_filters = particle_filters;
            tuning.particle_estimate = particle_estimate;
            tuning.assistant_turns = assistant_turns;
            auto o = session_options(method, assistance, lm, lm_base_url, lm_model, lm_timeout, std::move(goals),
                                     std::move(cost_profiles), max_nodes, threads, particles, particle_seed, tuning);
            py::gil_scoped_release unlocked;
            return clips::Session::open_dataset(dataset, problem, std::move(o));
          },
          py::arg("dataset"), py::arg("problem"), py::kw_only(), py::arg("method") = "clips",
          py::arg("assistance") = "qmdp", py::arg("lm") = "embedded", py::arg("lm_base_url") = "",
          py::arg("lm_model") = "", py::arg("lm_timeout") = 120.0, py::arg("goals") = std::vector<std::string>{},
          py::arg("cost_profiles") = std::vector<std::string>{}, py::arg("max_nodes") = size_t{1} << 18,
          py::arg("threads") = 0, py::arg("particles") = 0, py::arg("particle_seed") = uint64_t{1},
          py::arg("ess_threshold") = 0.5, py::arg("rejuvenation_moves") = 2, py::arg("rejuvenate") = "evidence",
          py::arg("proposal_groups") = 8, py::arg("particle_filters") = "all", py::arg("particle_estimate") = "support",
          py::arg("assistant_turns") = "taken",
          "A dataset problem ('2') or plan ('2.1.keys': its goals and cost profiles, from the initial state); "
          "particles > 0: particle inference with that many particles instead of exact enumeration, tuned as "
          "clips infer's options of the same names (assistant_turns: 'taken' or 'all', as --assistant-turns)")
      .def_static(
          "open_domain",
          [](const std::string& domain_dir, const std::string& problem_file, const std::string& method,
             const std::string& assistance, const std::string& lm, std::vector<std::string> goals,
             std::vector<std::string> cost_profiles) {
            auto o = session_options(method, assistance, lm, "", "", 120.0, std::move(goals), std::move(cost_profiles),
                                     size_t{1} << 18, 0);
            py::gil_scoped_release unlocked;
            return clips::Session::open_domain(domain_dir, problem_file, std::move(o));
          },
          py::arg("domain_dir"), py::arg("problem_file"), py::kw_only(), py::arg("method") = "clips",
          py::arg("assistance") = "qmdp", py::arg("lm") = "embedded", py::arg("goals") = std::vector<std::string>{},
          py::arg("cost_profiles") = std::vector<std::string>{})
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
