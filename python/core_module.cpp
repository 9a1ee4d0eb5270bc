// clips_assist._core (pybind11), the extension of the Python package
// clips_assist (python/clips_assist/): the session API of
// include/clips/session.hpp, plus a whole dataset plan (as `clips infer`) and
// a whole bench (as `clips bench`), all returning plain dicts and lists.
// C++ exceptions become clips_assist.InputError (a ValueError),
// InapplicableActionError (an InputError) and LanguageModelError (a
// RuntimeError) with the same messages. Inference runs without the GIL, on a
// worker thread, while the calling thread watches for signals: Ctrl-C raises
// KeyboardInterrupt at once and leaves the session as it was (see
// interruptible() below). A session pickles as its opener, options and the
// actions and utterances it was given, replayed on load.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <climits>
#include <cmath>
#include <filesystem>
#include <functional>
#include <future>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>

#include "clips/clips.hpp"
#include "data/dataset.hpp"
#include "api/session_internals.hpp"
#include "eval/bench.hpp"
#include "scenes/scenes.hpp"
#include "domains/dkg/dkg_world.hpp"
#include "domains/vh/vh_world.hpp"
#include "render/render.hpp"
#include "engine/json.hpp"
#include "engine/methods.hpp"
#include "eval/choices.hpp"
#include "inference/belief.hpp"
#include "engine/options.hpp"
#include "engine/runs.hpp"
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

// A str argument as UTF-8. `what` names it ("hear(): utterance"). A str that
// UTF-8 cannot encode (a lone surrogate, '\ud800') is a ValueError naming it,
// not pybind11's "Unable to cast".
std::string text_arg(const std::string& what, py::handle v) {
  if (!py::isinstance<py::str>(v)) throw py::type_error(what + ": expected str, got " + type_name(v));
  Py_ssize_t n = 0;
  const char* bytes = PyUnicode_AsUTF8AndSize(v.ptr(), &n);
  if (!bytes) {
    PyErr_Clear();
    throw clips::InputError(what + ": the text holds a lone surrogate (such as '\\ud800'), which is not a character "
                                   "and cannot be encoded as UTF-8");
  }
  return std::string(bytes, static_cast<size_t>(n));
}

// An int argument (anything with __index__ but a bool) as a C++ int; an int
// beyond that range, however large, is `out_of_range`'s ValueError.
int index_arg(const std::string& what, py::handle v, const std::string& out_of_range) {
  if (py::isinstance<py::bool_>(v) || !py::hasattr(v, "__index__"))
    throw py::type_error(what + ": expected an int, got " + type_name(v));
  const py::object i = v.attr("__index__")();
  int overflow = 0;
  const long long x = PyLong_AsLongLongAndOverflow(i.ptr(), &overflow);
  if (x == -1 && PyErr_Occurred()) throw py::error_already_set();
  if (overflow != 0 || x < INT_MIN || x > INT_MAX)
    throw clips::InputError(out_of_range + " " + std::string(py::str(i)));
  return static_cast<int>(x);
}

std::string text_option(const char* name, py::handle v) {
  if (!py::isinstance<py::str>(v))
    throw py::type_error(std::string("option '") + name + "': expected str, got " + type_name(v));
  return text_arg(std::string("option '") + name + "'", v);
}

// A finite float option in [lo, hi] (NaN and infinities are refused).
double float_option(const char* name, py::handle v, double lo = -HUGE_VAL, double hi = HUGE_VAL) {
  if (py::isinstance<py::bool_>(v))
    throw py::type_error(std::string("option '") + name + "': expected float, got bool");
  const double x = cast_option<double>(name, v, "float");
  const std::string got = py::str(py::float_(x));
  if (!std::isfinite(x)) throw clips::InputError(std::string(name) + " must be a finite number, got " + got);
  if (x < lo || x > hi)
    throw clips::InputError(std::string(name) + " must be in [" + std::string(py::str(py::float_(lo))) + ", " +
                            std::string(py::str(py::float_(hi))) + "], got " + got);
  return x;
}

std::vector<std::string> list_option(const char* name, py::handle v) {
  if (py::isinstance<py::str>(v))
    throw py::type_error(std::string("option '") + name + "': expected a list of str, got one str");
  if (!py::isinstance<py::sequence>(v))
    throw py::type_error(std::string("option '") + name + "': expected a list of str, got " + type_name(v));
  std::vector<std::string> out;
  for (py::handle item : py::reinterpret_borrow<py::sequence>(v))
    out.push_back(text_arg(std::string("option '") + name + "' item", item));
  return out;
}



// ---- decision policies written in Python -------------------------------------
//
// register_policy(name, help, decide) is the library's clips::register_policy
// (clips/policy.hpp) with a Python callable: the keyword assistance=,
// choices() and run_bench's "clips/NAME" take it. The callables are kept in a
// dict that is never destroyed (their one strong reference, so no Python
// object is released after the interpreter is gone); the registered function
// holds them borrowed.

// Set on the thread that runs a Python policy: a call on a session from inside
// the policy would wait for the call that is running it.
thread_local bool inside_python_policy = false;

py::dict& python_policies() {
  static auto* held = new py::dict();  // never destroyed: the interpreter owns its items
  return *held;
}

// The Python callable's choice for one view (clips/policy.hpp), with the GIL
// held: its exceptions become C++ ones carrying their Python message.
clips::PolicyChoice choose_in_python(const std::string& name, PyObject* fn, const clips::PolicyView& v) {
  py::gil_scoped_acquire gil;
  py::dict view;
  view["actions"] = v.actions;
  view["wait"] = v.wait;
  py::list goals, asked;
  for (size_t i = 0; i < v.goals.size(); ++i)
    goals.append(py::dict(py::arg("goal") = v.goals[i], py::arg("p") = v.goal_weights[i]));
  for (size_t i = 0; i < v.asked.size(); ++i)
    asked.append(py::dict(py::arg("command") = v.asked[i], py::arg("p") = v.asked_weights[i]));
  view["goals"] = goals;
  view["asked"] = asked;
  view["state"] = v.state;
  view["t"] = v.t;
  view["stalled"] = v.stalled;
  // The registered options' values, typed as their kinds.
  py::dict options;
  for (const auto& o : clips::engine::option_table()) {
    const auto it = v.options.find(o.name);
    if (!o.registered || it == v.options.end()) continue;
    using Kind = clips::engine::EngineOption::Kind;
    if (o.kind == Kind::Integer) options[py::str(o.name)] = py::int_(std::stoll(it->second));
    else if (o.kind == Kind::Real) options[py::str(o.name)] = py::float_(std::stod(it->second));
    else options[py::str(o.name)] = py::str(it->second);
  }
  view["options"] = options;
  struct Inside {
    Inside() { inside_python_policy = true; }
    ~Inside() { inside_python_policy = false; }
  };
  clips::PolicyChoice choice;
  try {
    const Inside inside;
    const py::object r = py::reinterpret_borrow<py::object>(fn)(view);
    if (py::isinstance<py::tuple>(r) && py::len(r) == 2) {
      choice.action = py::cast<std::string>(r.cast<py::tuple>()[0]);
      choice.reason = py::cast<std::string>(r.cast<py::tuple>()[1]);
    } else {
      choice.action = py::cast<std::string>(r);
    }
  } catch (py::error_already_set& e) {
    throw std::runtime_error(e.what());  // read while the GIL is held
  } catch (const py::cast_error&) {
    throw clips::InputError("assistance policy '" + name +
                            "' must return an action's name (a str) or (action, reason), as in view['actions']");
  }
  return choice;
}

void register_policy(const std::string& name, const std::string& help, py::function decide) {
  const py::str key(name);
  if (python_policies().contains(key))
    throw clips::InputError("the assistance policy '" + name + "' is already registered");
  python_policies()[key] = decide;
  PyObject* fn = decide.ptr();
  try {
    clips::register_policy(name, help,
                           [name, fn](const clips::PolicyView& v) { return choose_in_python(name, fn, v); });
  } catch (...) {
    PyDict_DelItem(python_policies().ptr(), key.ptr());
    throw;
  }
}

void unregister_policy(const std::string& name) {
  clips::unregister_policy(name);  // InputError for a name it did not register
  const py::str key(name);
  if (python_policies().contains(key)) PyDict_DelItem(python_policies().ptr(), key.ptr());
}

// register_option(name, help, kind, default, ...) is the library's
// clips::register_option: kind 'int', 'float' or 'choice'; the default as a
// value of that kind (a float's repr is the text the table parses).
void register_option(const std::string& name, const std::string& help, const std::string& kind, py::handle fallback,
                     py::handle minimum, py::handle maximum, py::handle choices) {
  clips::OptionSpec spec;
  spec.name = name;
  spec.help = help;
  if (kind == "int") {
    spec.kind = clips::OptionSpec::Kind::Integer;
  } else if (kind == "float") {
    spec.kind = clips::OptionSpec::Kind::Real;
  } else if (kind == "choice") {
    spec.kind = clips::OptionSpec::Kind::Choice;
  } else {
    throw clips::InputError("option '" + name + "': kind must be 'int', 'float' or 'choice', got '" + kind + "'");
  }
  if (spec.kind == clips::OptionSpec::Kind::Choice) {
    spec.default_value = text_option("default", fallback);
    if (choices.is_none()) throw clips::InputError("option '" + name + "': a choice needs choices=[...]");
    spec.choices = list_option("choices", choices);
  } else {
    if (!choices.is_none()) throw clips::InputError("option '" + name + "': choices= is for kind 'choice'");
    if (py::isinstance<py::bool_>(fallback) || !(py::isinstance<py::int_>(fallback) || py::isinstance<py::float_>(fallback)))
      throw py::type_error("option '" + name + "': default must be a number, got " + type_name(fallback));
    spec.default_value = spec.kind == clips::OptionSpec::Kind::Integer
                             ? std::string(py::str(fallback))
                             : std::string(py::repr(py::float_(py::reinterpret_borrow<py::object>(fallback))));
    if (!minimum.is_none()) spec.minimum = cast_option<double>("minimum", minimum, "float");
    if (!maximum.is_none()) spec.maximum = cast_option<double>("maximum", maximum, "float");
  }
  clips::register_option(spec);
}

// Every named choice (eval/choices.hpp) as {id: [{'name', 'help', 'aliases'}]}:
// the same tables the CLI's flags and the server's fields read.
py::dict choices() {
  py::dict out;
  for (const auto& [id, kind] : clips::eval::choice_catalogue()) {
    py::list l;
    for (const auto& c : kind.choices) {
      py::dict d;
      d["name"] = c.name;
      d["help"] = c.help;
      d["aliases"] = c.aliases;
      l.append(d);
    }
    out[py::str(id)] = l;
  }
  return out;
}

constexpr long long kMaxThreads = 1024;

struct SessionOption {
  std::string name;
  std::string help;
  std::function<void(clips::SessionOptions&, py::handle)> set;
  std::function<std::string(const clips::SessionOptions&)> show;  // the default, as Python would write it
};

std::string quoted(const std::string& s) { return "'" + s + "'"; }

// A session option of the engine's table (engine/options.hpp) as Python
// passes it: an int, a float or a str, turned into the text the table parses,
// so that a bad value gives the CLI's and the server's message.
std::string python_option_text(const clips::engine::EngineOption& po, py::handle v) {
  const char* name = po.name.c_str();
  using Kind = clips::engine::EngineOption::Kind;
  if (po.kind == Kind::Choice || po.kind == Kind::Text) return text_option(name, v);
  if (py::isinstance<py::bool_>(v))
    throw py::type_error(std::string("option '") + name + "': expected " + (po.kind == Kind::Real ? "float" : "int") +
                         ", got bool");
  if (po.kind == Kind::Integer) {
    if (!py::isinstance<py::int_>(v) && !py::hasattr(v, "__index__"))
      throw py::type_error(std::string("option '") + name + "': expected int, got " + type_name(v));
    return py::str(py::int_(py::reinterpret_borrow<py::object>(v)));
  }
  return py::repr(py::float_(cast_option<double>(name, v, "float")));
}

// The keywords of Python's sessions: the engine's session option table (the
// session's own options, the particle settings and options registered at
// run time), read at each use, so an option registered after import is a
// keyword.
std::vector<SessionOption> session_option_table() {
  using Kind = clips::engine::EngineOption::Kind;
  std::vector<SessionOption> rows;
  for (const auto& po : clips::engine::session_option_table()) {
    std::string help = po.kind == Kind::Choice ? po.help : po.brief;
    if (po.kind == Kind::Integer || po.kind == Kind::Real) help += "; " + po.takes;
    rows.push_back({po.name, help,
                    [po](clips::SessionOptions& o, py::handle v) {
                      if (po.kind == Kind::List)
                        clips::engine::set_session_option(o, po.name, list_option(po.name.c_str(), v));
                      else
                        clips::engine::set_session_option(o, po.name, python_option_text(po, v));
                    },
                    [name = po.name, kind = po.kind](const clips::SessionOptions& o) {
                      const std::string text = clips::engine::session_option_text(o, name);
                      switch (kind) {
                        case Kind::Choice:
                        case Kind::Text: return quoted(text);
                        case Kind::List: return text.empty() ? std::string("[]") : "[" + text + "]";
                        case Kind::Real: return std::string(py::str(py::float_(std::stod(text))));
                        case Kind::Integer: break;
                      }
                      return text;
                    }});
  }
  return rows;
}

// The options named in `kwargs`; `taken` lists keywords the opener reads
// itself. An unknown keyword is a TypeError, as for any Python function.
clips::SessionOptions session_options(const py::kwargs& kwargs, const char* opener,
                                      std::initializer_list<const char*> taken = {}) {
  clips::SessionOptions o;
  const auto table = session_option_table();
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
  if (py::isinstance<py::str>(v)) return text_arg(std::string("argument '") + name + "'", v);
  if (py::hasattr(v, "__fspath__"))
    return text_arg(std::string("argument '") + name + "'", py::module_::import("os").attr("fspath")(v));
  throw py::type_error(std::string("argument '") + name + "': expected str or os.PathLike, got " + type_name(v));
}

// The engine's one JSON form (src/engine/json.hpp) as Python objects: the
// Python dicts are that JSON, so they cannot drift from the server's or the
// CLI's (null, e.g. an impossible observation's log marginal, is None).
py::object from_json(const nlohmann::json& j) {
  switch (j.type()) {
    case nlohmann::json::value_t::null: return py::none();
    case nlohmann::json::value_t::boolean: return py::bool_(j.get<bool>());
    case nlohmann::json::value_t::number_integer: return py::int_(j.get<int64_t>());
    case nlohmann::json::value_t::number_unsigned: return py::int_(j.get<uint64_t>());
    case nlohmann::json::value_t::number_float: return py::float_(j.get<double>());
    case nlohmann::json::value_t::string: return py::str(j.get_ref<const std::string&>());
    case nlohmann::json::value_t::array: {
      py::list l;
      for (const auto& x : j) l.append(from_json(x));
      return l;
    }
    case nlohmann::json::value_t::object: {
      py::dict d;
      for (const auto& [k, v] : j.items()) d[py::str(k)] = from_json(v);
      return d;
    }
    default: break;
  }
  throw std::logic_error("from_json: unexpected JSON value");
}

py::object to_py(const clips::Posterior& p, clips::Method m) { return from_json(clips::engine::to_json(p, m)); }
py::object to_py(const clips::Step& s, clips::Method m) { return from_json(clips::engine::to_json(s, m)); }
py::object to_py(const clips::AssistDecision& a) { return from_json(clips::engine::to_json(a)); }

// ---- long calls: off the calling thread, interruptible ------------------------
//
// A long call runs on a worker thread, so that Ctrl-C returns at once
// (the engine notices its cancellation flag only at its next check), holding
// everything it uses (shared_ptr, copies), while the calling thread
// waits without the GIL and checks for signals every 20 ms. On Ctrl-C (any
// signal handler raising) the caller raises at once and the worker is left to
// finish on its own state, its result dropped: a session interrupted in a call
// replays its log into a fresh engine before its next use, so it is as it was
// before the call. Left workers are joined at exit (clips_assist registers
// _join_abandoned with atexit), so none runs while the process is torn down.

struct Abandoned {
  std::thread worker;
  std::shared_ptr<std::atomic<bool>> finished;
};
std::mutex abandoned_mutex;
std::vector<Abandoned>& abandoned() {
  static auto* left = new std::vector<Abandoned>();  // never destroyed: joined by _join_abandoned
  return *left;
}

template <typename F>
auto interruptible(F f) -> decltype(f()) {
  using R = decltype(f());
  auto task = std::make_shared<std::packaged_task<R()>>(std::move(f));
  auto finished = std::make_shared<std::atomic<bool>>(false);
  std::future<R> done = task->get_future();
  std::thread worker([task, finished] {
    (*task)();
    *finished = true;
  });
  for (;;) {
    bool ready;
    {
      py::gil_scoped_release unlocked;
      ready = done.wait_for(std::chrono::milliseconds(20)) == std::future_status::ready;
    }
    if (ready) break;
    if (PyErr_CheckSignals() != 0) {
      std::lock_guard<std::mutex> lock(abandoned_mutex);
      abandoned().push_back(Abandoned{std::move(worker), finished});
      throw py::error_already_set();
    }
  }
  worker.join();
  return done.get();  // the worker's exception, if any, is rethrown here
}

void join_abandoned() {
  std::vector<Abandoned> left;
  {
    std::lock_guard<std::mutex> lock(abandoned_mutex);
    left.swap(abandoned());
  }
  py::gil_scoped_release unlocked;
  for (auto& a : left) a.worker.join();
}

// How many interrupted calls are still running (for the tests).
int abandoned_running() {
  std::lock_guard<std::mutex> lock(abandoned_mutex);
  return static_cast<int>(std::count_if(abandoned().begin(), abandoned().end(),
                                        [](const Abandoned& a) { return !*a.finished; }));
}

// ---- the Python session --------------------------------------------------------

// How a session was opened, to open it again (pickling, recovery).
struct Opener {
  std::string kind;  // "dataset", "domain" or "text"
  std::string a, b, c;  // dataset dir + problem; domain dir + problem file; domain, problem and pack text
};

// One call that changed the session: an action (PDDL text) or an utterance.
struct Event {
  bool utterance = false;
  std::string text;
};

// The state as `clips render` draws it, PNG-encoded.
std::string scene_png(const clips::domains::Pack& pack, const clips::pddl::Task& task, const clips::pddl::State& s) {
  switch (pack.spec().scene) {
    case clips::domains::SceneKind::Grid:
      return clips::render::encode_png(clips::render::render_png(clips::scenes::dkg_scene(clips::domains::dkg::DkgWorld(task), s)));
    case clips::domains::SceneKind::Cards:
      return clips::render::encode_png(
          clips::render::render_png(clips::scenes::vh_scene(pack, clips::domains::vh::VhWorld(task), s)));
    case clips::domains::SceneKind::Text: break;
  }
  throw clips::InputError("the " + pack.name() + " pack's scene is text: there is no picture (print the session)");
}

struct PySession {
  Opener opener;
  py::dict options;  // the keyword options as given (None values dropped)
  clips::SessionOptions parsed;
  std::vector<Event> log;
  // Null after an interrupted call; rebuilt from opener + options + log.
  std::shared_ptr<clips::Session> engine;
  // The running call's cancellation flag (null between calls): cancel(),
  // from another Python thread, raises it. Read and written under the GIL.
  std::shared_ptr<std::atomic<bool>> cancel_flag;
  // Held for the whole of every call but cancel(): calls from several
  // threads run one after the other (the engine is not thread-safe, and
  // calls release the GIL while they run).
  std::shared_ptr<std::timed_mutex> busy = std::make_shared<std::timed_mutex>();
  std::shared_ptr<std::atomic<std::thread::id>> busy_owner = std::make_shared<std::atomic<std::thread::id>>();
};

// `self` of a Session method. Session.__new__(Session) alone (as pickle does
// before __setstate__) makes an object whose C++ part was never built, which
// pybind11 would hand over as uninitialised memory: every method takes
// `self` as a handle and checks it here.
PySession& opened(py::handle self) {
  if (!py::isinstance<PySession>(self))
    throw py::type_error("expected a clips_assist.Session, got " + type_name(self));
  auto* inst = reinterpret_cast<py::detail::instance*>(self.ptr());
  const py::detail::value_and_holder vh = inst->get_value_and_holder(py::detail::get_type_info(typeid(PySession)));
  if (!vh.holder_constructed())
    throw py::type_error("this Session was never opened: make sessions with Session.open_dataset(...) or "
                         "Session.open_domain(...) (Session.__new__ alone makes an empty shell)");
  return *vh.value_ptr<PySession>();
}

// An opened session, held for one call: a call from another thread waits
// (without the GIL, Ctrl-C still interrupting it) until this one is done.
class Held {
 public:
  explicit Held(py::handle self) : ps_(&opened(self)), busy_(ps_->busy), owner_(ps_->busy_owner) {
    if (inside_python_policy)
      throw clips::InputError("a Python assistance policy cannot call a session: it runs inside a session's call");
    if (owner_->load() == std::this_thread::get_id())
      throw py::value_error("this Session is already running a call on this thread (a call from inside a call)");
    while (!busy_->try_lock()) {
      bool got;
      {
        py::gil_scoped_release unlocked;
        got = busy_->try_lock_for(std::chrono::milliseconds(20));
      }
      if (got) break;
      if (PyErr_CheckSignals() != 0) throw py::error_already_set();
    }
    owner_->store(std::this_thread::get_id());
  }
  ~Held() {
    owner_->store(std::thread::id());
    busy_->unlock();
  }
  Held(const Held&) = delete;
  Held& operator=(const Held&) = delete;
  PySession& operator*() const { return *ps_; }

 private:
  PySession* ps_;
  std::shared_ptr<std::timed_mutex> busy_;
  std::shared_ptr<std::atomic<std::thread::id>> owner_;
};

std::shared_ptr<clips::Session> open_engine(const Opener& op, const clips::SessionOptions& o) {
  if (op.kind == "dataset") return std::make_shared<clips::Session>(clips::Session::open_dataset(op.a, op.b, o));
  if (op.kind == "domain") return std::make_shared<clips::Session>(clips::Session::open_domain(op.a, op.b, o));
  return std::make_shared<clips::Session>(clips::Session::open_domain_text(op.a, op.b, op.c, o));
}

void apply(clips::Session& s, const Event& e, const clips::CallLimits& limits = {}) {
  if (e.utterance)
    s.hear(e.text, limits);
  else
    s.observe(e.text, limits);
}

// A call's time_limit keyword (None: no limit) as the engine's CallLimits.
clips::CallLimits call_limits(const py::object& time_limit) {
  clips::CallLimits limits;
  if (!time_limit.is_none()) limits.seconds = float_option("time_limit", time_limit, 0, 1e9);
  return limits;
}

// The session's engine, replayed first if a call on it was interrupted.
clips::Session& engine(PySession& ps) {
  if (!ps.engine) {
    ps.engine = interruptible([op = ps.opener, o = ps.parsed, log = ps.log] {
      auto s = open_engine(op, o);
      for (const auto& e : log) apply(*s, e);
      return s;
    });
  }
  return *ps.engine;
}

PySession open_session(Opener op, py::dict options, clips::SessionOptions parsed, std::vector<Event> log = {}) {
  PySession ps{std::move(op), std::move(options), std::move(parsed), std::move(log), nullptr, nullptr};
  engine(ps);
  return ps;
}

std::string absolute(const std::string& path) { return std::filesystem::absolute(path).lexically_normal().string(); }

py::dict given_options(const py::kwargs& kwargs, std::initializer_list<const char*> taken = {}) {
  py::dict d;
  for (auto item : kwargs) {
    const std::string key = py::str(item.first);
    if (item.second.is_none()) continue;
    if (std::any_of(taken.begin(), taken.end(), [&](const char* t) { return key == t; })) continue;
    d[item.first] = item.second;
  }
  return d;
}

// One call on the session's engine, off the calling thread, with a fresh
// cancellation flag that cancel() raises. On Ctrl-C the flag is raised too
// (the abandoned worker stops at its next check) and the engine is dropped,
// to be replayed from the log before the next call.
template <typename F>
auto session_call(PySession& ps, clips::CallLimits limits, F f) -> decltype(f(std::declval<clips::Session&>(), limits)) {
  engine(ps);
  auto shared = ps.engine;
  auto flag = std::make_shared<std::atomic<bool>>(false);
  limits.cancel = flag.get();
  ps.cancel_flag = flag;
  struct Done {
    PySession& ps;
    ~Done() { ps.cancel_flag.reset(); }
  } done{ps};
  try {
    return interruptible([shared, flag, limits, f] { return f(*shared, limits); });
  } catch (py::error_already_set&) {
    flag->store(true);
    ps.engine.reset();
    throw;
  }
}

// One call that changes the session (observe, hear). A call stopped by its
// time limit or cancelled leaves the session (and its log) as it was.
py::object step_call(PySession& ps, Event e, clips::CallLimits limits = {}) {
  clips::Step st = session_call(ps, limits, [e](clips::Session& s, const clips::CallLimits& l) {
    apply(s, e, l);
    return s.trace().back();
  });
  if (!e.utterance) e.text = st.action;  // an id becomes its action's text
  ps.log.push_back(std::move(e));
  return to_py(st, ps.parsed.method);
}

// A dataset plan, as `clips infer --json` (every step, all three methods):
// steps[t]["action"] is the action observed at t ("" at t = 0) and
// steps[t]["posterior"] each inference method's posterior by its name.
py::dict run_plan(const std::string& dataset, const std::string& plan_id, const std::string& lm_kind, long long threads) {
  if (threads < 0 || threads > kMaxThreads)
    throw clips::InputError("threads must be an int in [0, " + std::to_string(kMaxThreads) + "], got " +
                            std::to_string(threads));
  auto run = interruptible([dataset, plan_id, lm_kind, threads] {
    auto ds = clips::data::Dataset::load(dataset);
    const auto& plan = ds.plan(plan_id);
    auto lm = clips::language::make_dataset_language_model(lm_kind, {}, ds);  // the model `clips infer` hears with
    clips::inference::InferenceOptions o;
    o.threads = static_cast<int>(threads);
    return clips::engine::run_observations(ds, plan, *lm, o, /*known_truth=*/true);
  });
  py::dict d;
  d["plan"] = run.plan_id;
  d["goals"] = run.goals;
  d["true_goal"] = run.true_goal >= 0 ? py::object(py::str(run.goals[run.true_goal])) : py::object(py::none());
  d["cost_profiles"] = run.profiles;
  py::list steps;
  for (const auto& st : run.steps) {
    py::dict s;
    s["t"] = st.t;
    s["action"] = st.action;
    py::list us;
    for (const auto& u : st.utterances) us.append(u.text);
    s["utterances"] = us;
    // Each inference method's posterior, keyed by its name, in the engine's JSON form.
    py::dict posterior;
    for (auto m : {clips::Method::Clips, clips::Method::LanguageOnly, clips::Method::ActionOnly})
      posterior[py::str(clips::method_name(m))] = to_py(clips::engine::posterior_of(run, st, m), m);
    s["posterior"] = posterior;
    s["seconds"] = st.seconds;
    steps.append(s);
  }
  d["steps"] = steps;
  d["seconds"] = run.seconds;
  return d;
}

// A whole bench, as `clips bench`: one row per plan and method (ready for
// pandas.DataFrame) and the aggregated summary.
py::dict run_bench(const std::string& dataset, std::vector<std::string> methods, std::vector<std::string> plans,
                   long long jobs, uint64_t seed, const std::string& lm_kind, const py::kwargs& options) {
  if (jobs < 0 || jobs > kMaxThreads)
    throw clips::InputError("jobs must be an int in [0, " + std::to_string(kMaxThreads) + "], got " + std::to_string(jobs));
  clips::eval::BenchOptions o;
  // The engine's option table (`clips bench`'s flags of the same names): the
  // particle settings and options registered with register_option.
  const auto table = clips::engine::option_table();
  for (auto item : options) {
    const std::string key = py::str(item.first);
    const auto it = std::find_if(table.begin(), table.end(), [&](const auto& po) { return po.name == key; });
    if (it == table.end()) throw py::type_error("run_bench() got an unexpected keyword argument '" + key + "'");
    if (item.second.is_none()) continue;  // None: the default
    clips::engine::set_option(o.experiment.particles, key, python_option_text(*it, item.second));
  }
  o.dataset = dataset;
  o.jobs = static_cast<int>(jobs);
  o.experiment.methods = std::move(methods);
  o.experiment.seed = seed;
  o.lm = lm_kind;
  o.plans = std::move(plans);
  o.progress = false;
  const clips::eval::BenchReport rep = interruptible([o] { return clips::eval::run_bench(o); });
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
      // instructions.tsv's explicit request and whether this method's assistant did it (None: nothing asked).
      r["requested"] = p.requested;
      r["request_done"] = m.request_done ? py::object(py::bool_(*m.request_done)) : py::object(py::none());
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

PYBIND11_MODULE(_core, m) {
  m.doc() =
      "clips_assist._core: the compiled part of clips_assist (import clips_assist, not this module).\n\n"
      "Goal inference from a human's actions and instructions, and assistance (CLIPS).";
  m.attr("__version__") = clips::library_version();

  auto& input_error = py::register_exception<clips::InputError>(m, "InputError", PyExc_ValueError);
  input_error.attr("__doc__") = "Bad input (a file, an option, an action or an utterance); a ValueError naming it.";
  auto& inapplicable =
      py::register_exception<clips::InapplicableActionError>(m, "InapplicableActionError", input_error.ptr());
  inapplicable.attr("__doc__") = "An action whose precondition is false in the current state (an InputError).";
  auto& lm_error = py::register_exception<clips::LanguageModelError>(m, "LanguageModelError", PyExc_RuntimeError);
  lm_error.attr("__doc__") = "The language model failed (e.g. the completions server did not answer).";
  auto& time_limit_error = py::register_exception<clips::TimeLimitError>(m, "TimeLimitError", PyExc_RuntimeError);
  time_limit_error.attr("__doc__") =
      "A call's time_limit passed before it was done; the session is exactly as it was before the call.";
  auto& cancelled_error = py::register_exception<clips::CancelledError>(m, "CancelledError", PyExc_RuntimeError);
  cancelled_error.attr("__doc__") =
      "A call stopped by Session.cancel() (from another thread); the session is exactly as it was before the call.";
  auto& memory_limit_error =
      py::register_exception<clips::MemoryLimitError>(m, "MemoryLimitError", PyExc_MemoryError);
  memory_limit_error.attr("__doc__") =
      "Refused before memory ran out: e.g. a problem with more ground actions than this process has memory for.";
  for (py::handle e :
       std::initializer_list<py::handle>{input_error, inapplicable, lm_error, time_limit_error, cancelled_error,
                                        memory_limit_error})
    e.attr("__module__") = "clips_assist";
  // Internal language-model failures reach Python as the same type.
  static PyObject* lm_error_type = lm_error.ptr();
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const clips::lm::LmError& e) {
      PyErr_SetString(lm_error_type, e.what());
    }
  });

  py::class_<PySession>(m, "Session",
                        "A live inference session: observe() the agents' actions, hear() the human's utterances, read "
                        "posterior() and ask assist() for the assistant's next action.\n\n"
                        "Open it with Session.open_dataset or Session.open_domain. A session pickles (and copies) as "
                        "its problem, options and the actions and utterances it was given, replayed on load. Ctrl-C "
                        "during a call raises KeyboardInterrupt and leaves the session as it was.")
      .def_static(
          "open_dataset",
          [](py::object dataset, py::object problem_arg, const py::kwargs& kwargs) {
            const std::string dir = absolute(path_arg("dataset", dataset));
            const std::string problem = text_arg("open_dataset(): problem", problem_arg);
            auto o = session_options(kwargs, "open_dataset");
            return open_session(Opener{"dataset", dir, problem, ""}, given_options(kwargs), std::move(o));
          },
          py::arg("dataset"), py::arg("problem"),
          ("open_dataset(dataset, problem, **options)\n\n"
           "A dataset problem ('2') or plan ('2.1.keys': its goals and cost profiles, from the initial state); the "
           "folder may have no plans/. particles > 0: particle inference with that many particles instead of exact "
           "enumeration, tuned as clips infer's options of the same names. clips_assist.example_dataset() is the "
           "installed example.\n\n" +
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
            py::dict given = given_options(kwargs, {"domain_text", "problem_text", "pack_text"});
            const bool from_text = domain_text || problem_text || pack_text;
            if (from_text) {
              if (!domain_dir.is_none() || !problem_file.is_none())
                throw clips::InputError(
                    "open_domain: give domain_dir and problem_file (paths), or domain_text and problem_text "
                    "(PDDL text, with pack_text), not both");
              if (!domain_text || !problem_text)
                throw clips::InputError(std::string("open_domain: ") + (domain_text ? "problem_text" : "domain_text") +
                                        " is missing (PDDL text comes as both domain_text and problem_text)");
              return open_session(Opener{"text", *domain_text, *problem_text, pack_text.value_or("")}, given,
                                  std::move(o));
            }
            if (domain_dir.is_none() || problem_file.is_none())
              throw clips::InputError(std::string("open_domain: ") + (domain_dir.is_none() ? "domain_dir" : "problem_file") +
                                      " is missing (give domain_dir and problem_file, or domain_text and problem_text)");
            const std::string dir = absolute(path_arg("domain_dir", domain_dir)),
                              file = absolute(path_arg("problem_file", problem_file));
            return open_session(Opener{"domain", dir, file, ""}, given, std::move(o));
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
          [](py::handle self, py::object action, py::object time_limit) {
            Held held(self);
            PySession& ps = *held;
            const clips::CallLimits limits = call_limits(time_limit);
            // A str is PDDL text, an int (not a bool) an id of applicable_actions().
            if (py::isinstance<py::str>(action))
              return step_call(ps, Event{false, text_arg("observe(): action", action)}, limits);
            if (py::isinstance<py::bool_>(action) || !py::hasattr(action, "__index__"))
              throw py::type_error("observe(): expected the action as PDDL text (str) or an action id (int), got " +
                                   type_name(action));
            const int id = index_arg("observe(): action", action, "observe(): action: unknown action id");
            const std::string text = engine(ps).action_name(id);
            return step_call(ps, Event{false, text}, limits);
          },
          py::arg("action"), py::kw_only(), py::arg("time_limit") = py::none(),
          "observe(action, *, time_limit=None) -> dict\n\n"
          "An action of either agent in the current state: PDDL text ('(left human)') or an id of "
          "applicable_actions(). Returns the new step (as trace()[-1]). Raises InputError for text naming no action "
          "or an unknown id, InapplicableActionError when its precondition is false, TimeLimitError when the call "
          "takes longer than time_limit seconds; the session is then unchanged.")
      .def(
          "hear",
          [](py::handle self, py::object utterance, py::object time_limit) {
            Held held(self);
            PySession& ps = *held;
            if (!py::isinstance<py::str>(utterance))
              throw py::type_error("hear(): expected the utterance as str, got " + type_name(utterance));
            return step_call(ps, Event{true, text_arg("hear(): utterance", utterance)}, call_limits(time_limit));
          },
          py::arg("utterance"), py::kw_only(), py::arg("time_limit") = py::none(),
          "hear(utterance, *, time_limit=None) -> dict\n\n"
          "An utterance heard in the current state (the human's instruction to the assistant). Returns the current "
          "step with the new posterior. Raises InputError for empty text, LanguageModelError when the model fails, "
          "TimeLimitError when the call takes longer than time_limit seconds (the session is then unchanged).")
      .def(
          "posterior",
          [](py::handle self, py::object method) {
            Held held(self);
            PySession& ps = *held;
            clips::Session& s = engine(ps);
            const clips::Method m =
                method.is_none() ? ps.parsed.method : clips::parse_method(text_arg("posterior(): method", method));
            return to_py(s.posterior(m), m);
          },
          py::arg("method") = py::none(),
          "posterior(method=None) -> dict\n\n"
          "The posterior in the engine's JSON form (as `clips infer --json` and the server write it): {'method', "
          "'modality', 'goals': [{'goal', 'p'}], 'cost_profiles': [{'cost_profile', 'p'}], 'hypotheses': [{'goal', "
          "'cost_profile', 'p'}], 'log_marginal_likelihood': float, None when nothing explains the observations}, "
          "under the session's method or another with a posterior of its own (choices()['method'] lists the "
          "methods).")
      .def(
          "assist",
          [](py::handle self, py::object time_limit) {
            Held held(self);
            PySession& ps = *held;
            return to_py(session_call(ps, call_limits(time_limit),
                                      [](clips::Session& s, const clips::CallLimits& l) { return s.assist(l); }));
          },
          py::kw_only(), py::arg("time_limit") = py::none(),
          "assist(*, time_limit=None) -> dict\n\n"
          "The assistant's next action under the session's assistance rule, in the engine's JSON form: {'method', "
          "'assistant_turn', 'action' (None when the human is to move), 'id', 'reason', 'unanimous', 'candidates': "
          "[{'id', 'action', 'value'}], 'goals', 'goal_weights'} (+ 'command', 'command_probability' for literal). "
          "The posterior is not changed. TimeLimitError when the decision takes longer than time_limit seconds.")
      .def(
          "undo",
          [](py::handle self, py::object time_limit) {
            Held held(self);
            PySession& ps = *held;
            const bool undone = session_call(ps, call_limits(time_limit),
                                             [](clips::Session& s, const clips::CallLimits& l) { return s.undo(l); });
            if (undone) {
              ps.log.clear();
              for (const auto& [utterance, text] : clips::SessionInternals::events(*ps.engine))
                ps.log.push_back(Event{utterance, text});
            }
            return undone;
          },
          py::kw_only(), py::arg("time_limit") = py::none(),
          "undo(*, time_limit=None) -> bool\n\n"
          "Takes back the human's latest move or instruction with everything after it (the assistant's actions): "
          "an instruction heard after the last move goes alone; "
          "False, and nothing changes, when there is none. The posterior is recomputed by replaying what is left: "
          "TimeLimitError past time_limit, CancelledError on cancel(), the session then unchanged.")
      .def(
          "reset",
          [](py::handle self) {
            Held held(self);
            PySession& ps = *held;
            session_call(ps, {}, [](clips::Session& s, const clips::CallLimits&) {
              s.reset();
              return true;
            });
            ps.log.clear();
          },
          "reset() -> None\n\nBack to the initial state with nothing observed or heard (t = 0).")
      .def(
          "goal_holds",
          [](py::handle self, py::object goal) {
            Held held(self);
            PySession& ps = *held;
            if (!py::isinstance<py::str>(goal))
              throw py::type_error("goal_holds(): expected the goal's label as str, got " + type_name(goal));
            return engine(ps).goal_holds(text_arg("goal_holds(): goal", goal));
          },
          py::arg("goal"),
          "goal_holds(goal) -> bool\n\nWhether the candidate goal with this label (e.g. 'gem2', as posterior()'s "
          "goals name it) holds in the current state; InputError for a label that is not a candidate.")
      .def(
          "cancel",
          [](py::handle self) {
            // Not held: it reaches the call that holds the session now.
            PySession& ps = opened(self);
            if (!ps.cancel_flag) return false;
            ps.cancel_flag->store(true);
            return true;
          },
          "cancel() -> bool\n\nAsks the call running on this session (observe, hear, assist, undo), from another "
          "thread, to stop: it raises CancelledError and leaves the session exactly as it was before it. True when "
          "a call was running; a call started afterwards is not affected.")
      .def(
          "state", [](py::handle self) { return engine(*Held(self)).state(); },
          "state() -> str\n\nThe current state, printable (an ASCII map for Doors-Keys-Gems).")
      .def(
          "scene_png",
          [](py::handle self) {
            Held held(self);
            PySession& ps = *held;
            const clips::Session& s = engine(ps);
            const std::string png = scene_png(clips::SessionInternals::pack(s), clips::SessionInternals::task(s),
                                              clips::SessionInternals::state(s));
            return py::bytes(png);
          },
          "scene_png() -> bytes\n\nThe current state drawn as a PNG image (the grid of Doors-Keys-Gems, the "
          "fixtures of a card scene), as `clips render` draws it. A pack whose scene is text has no picture: "
          "InputError (print the session instead).")
      .def("__str__", [](py::handle self) { return engine(*Held(self)).state(); })
      .def("__repr__",
           [](py::handle self) {
             Held held(self);
             PySession& ps = *held;
             const clips::Session& s = engine(ps);
             std::string where = ps.opener.kind == "dataset" ? "problem=" + std::string(py::repr(py::str(ps.opener.b)))
                                 : ps.opener.kind == "domain"
                                     ? "problem_file=" + std::string(py::repr(py::str(ps.opener.b)))
                                     : std::string("from text");
             return "<clips_assist.Session domain=" + std::string(py::repr(py::str(s.domain()))) + " " + where +
                    " t=" + std::to_string(s.t()) + " to move=" + std::string(py::repr(py::str(s.active_agent()))) +
                    ">";
           })
      .def(
          "trace",
          [](py::handle self) {
            Held held(self);
            PySession& ps = *held;
            py::list out;
            for (const auto& st : engine(ps).trace()) out.append(to_py(st, ps.parsed.method));
            return out;
          },
          "trace() -> list[dict]\n\n"
          "Every step so far: trace()[t] after t actions, with 't', 'action', 'agent', 'evidence', 'utterances', "
          "'posterior' and 'seconds'.")
      .def_property_readonly(
          "t", [](py::handle self) { return engine(*Held(self)).t(); }, "Actions observed so far.")
      .def_property_readonly(
          "domain", [](py::handle self) { return engine(*Held(self)).domain(); }, "The PDDL domain's name.")
      .def_property_readonly(
          "active_agent", [](py::handle self) { return engine(*Held(self)).active_agent(); }, "Who is to move.")
      .def_property_readonly(
          "assistant_turn", [](py::handle self) { return engine(*Held(self)).assistant_turn(); },
          "True when the assistant is to move.")
      .def(
          "applicable_actions",
          [](py::handle self) {
            Held held(self);
            PySession& ps = *held;
            py::list out;
            for (const auto& a : engine(ps).applicable_actions()) {
              py::dict d;
              d["id"] = a.id;
              d["action"] = a.action;
              out.append(d);
            }
            return out;
          },
          "applicable_actions() -> list[dict]\n\nThe active agent's actions applicable now: [{'id', 'action'}].")
      .def(
          "action_name",
          [](py::handle self, py::object id) {
            Held held(self);
            PySession& ps = *held;
            if (py::isinstance<py::bool_>(id) || !py::hasattr(id, "__index__"))
              throw py::type_error("action_name(): expected an action id (int), got " + type_name(id));
            return engine(ps).action_name(index_arg("action_name(): action_id", id, "unknown action id"));
          },
          py::arg("action_id"), "action_name(action_id) -> str\n\nThe PDDL text of an action id.")
      .def(py::pickle(
          [](py::handle self) {
            Held held(self);
            const PySession& ps = *held;
            py::list log;
            for (const auto& e : ps.log) log.append(py::make_tuple(e.utterance ? "hear" : "observe", e.text));
            return py::make_tuple(1, ps.opener.kind, ps.opener.a, ps.opener.b, ps.opener.c, ps.options, log);
          },
          [](const py::tuple& st) {
            if (st.size() != 7 || !py::isinstance<py::int_>(st[0]) || py::cast<int>(st[0]) != 1)
              throw clips::InputError("not a pickled clips_assist.Session (version 1)");
            Opener op{py::cast<std::string>(st[1]), py::cast<std::string>(st[2]), py::cast<std::string>(st[3]),
                      py::cast<std::string>(st[4])};
            if (op.kind != "dataset" && op.kind != "domain" && op.kind != "text")
              throw clips::InputError("pickled clips_assist.Session: unknown opener '" + op.kind + "'");
            py::dict options = py::cast<py::dict>(st[5]);
            py::kwargs kw;
            for (auto item : options) kw[item.first] = item.second;
            auto o = session_options(kw, "Session");
            std::vector<Event> log;
            for (py::handle e : py::cast<py::list>(st[6])) {
              auto pair = py::cast<std::pair<std::string, std::string>>(e);
              log.push_back(Event{pair.first == "hear", pair.second});
            }
            return open_session(std::move(op), std::move(options), std::move(o), std::move(log));
          }));

  m.def("run_plan", &run_plan, py::arg("dataset"), py::arg("plan"), py::kw_only(), py::arg("lm") = "embedded",
        py::arg("threads") = 0,
        "run_plan(dataset, plan, *, lm='embedded', threads=0) -> dict\n\n"
        "Goal inference over one dataset plan, as `clips infer`: {'plan', 'goals', 'true_goal', 'cost_profiles', "
        "'steps', 'seconds'}; steps[t] has 't', 'action' (the action observed at t, '' at t = 0), 'utterances', "
        "'posterior' ({method: posterior} for each method with a posterior of its own, as posterior() gives it) "
        "and 'seconds'.");
  m.def("run_bench", &run_bench, py::arg("dataset"), py::kw_only(), py::arg("methods") = std::vector<std::string>{},
        py::arg("plans") = std::vector<std::string>{}, py::arg("jobs") = 0, py::arg("seed") = 1,
        py::arg("lm") = "embedded",
        "run_bench(dataset, *, methods=[], plans=[], jobs=0, seed=1, lm='embedded', **options) -> dict\n\n"
        "Every plan x method of a dataset, as `clips bench`: {'domain', 'lm', 'rows': [one dict per plan and "
        "method], 'summary': {method: {metric: {'mean', 'se', 'n'}}}, 'wall_seconds', 'failed_plans'}. options: "
        "the engine's options as `clips bench`'s flags of the same names take them (particles, particle_seed, "
        "..., and options registered with register_option, which registered policies read in the episodes).");
  m.def("choices", &choices,
        "choices() -> dict\n\nEvery named choice of the options and methods (the keyword 'method', "
        "'assistance', 'rejuvenate', ...; run_bench's methods), by kind: {kind: [{'name', 'help', 'aliases'}]}. "
        "The same name tables the CLI's flags and the server's fields read (docs/cli.md, \"Named choices\").");
  m.def("register_option", &register_option, py::arg("name"), py::arg("help"), py::arg("kind"), py::arg("default"),
        py::kw_only(), py::arg("minimum") = py::none(), py::arg("maximum") = py::none(),
        py::arg("choices") = py::none(),
        "register_option(name, help, kind, default, *, minimum=None, maximum=None, choices=None) -> None\n\n"
        "An option of your own, for a policy registered with register_policy to read (view['options'][name], "
        "typed as its kind): kind is 'int', 'float' or 'choice'. It is then a keyword of open_dataset and "
        "open_domain (checked as the built-in ones), and of the engine's option table that the CLI's flags and "
        "the server's 'inference' fields are built from. InputError for a malformed or taken name (the built-in "
        "keywords included) or a default out of range.");
  m.def(
      "options",
      [] {
        py::list out;
        const clips::SessionOptions defaults;
        for (const auto& so : session_option_table())
          out.append(py::dict(py::arg("name") = so.name, py::arg("help") = so.help,
                              py::arg("default") = so.show(defaults)));
        return out;
      },
      "options() -> list\n\nThe keywords of open_dataset and open_domain, each {'name', 'help', 'default'} (the "
      "default as Python writes it): this module's own, the engine's option table's (particle settings) and the "
      "options registered with register_option.");
  m.def("unregister_option", [](const std::string& name) { clips::unregister_option(name); }, py::arg("name"),
        "unregister_option(name) -> None\n\nTakes back an option register_option registered.");
  m.def("register_policy", &register_policy, py::arg("name"), py::arg("help"), py::arg("decide"),
        "register_policy(name, help, decide) -> None\n\n"
        "Registers a decision policy written in Python, in the same table as the built-in ones: sessions take "
        "assistance=name, choices()['assistance'] lists it, run_bench(methods=['clips/' + name]) runs its "
        "episodes. decide(view) is called at each of the assistant's turns with a dict: 'actions' (the "
        "applicable actions' names), 'wait' (the assistant's no-op), 'goals' ([{'goal', 'p'}]: each goal's PDDL formula and its posterior probability), "
        "'asked' ([{'command', 'p'}], what the last instruction asked for), 'state' (its atoms, as text), 't', "
        "'stalled' (a round of waits just ended). It returns an action of view['actions'], or (action, "
        "reason). It runs on a worker thread with the GIL held, and must not call a session.");
  m.def("unregister_policy", &unregister_policy, py::arg("name"),
        "unregister_policy(name) -> None\n\nTakes back a policy register_policy registered.");
  m.def("data_directory", &clips::data_directory,
        "data_directory() -> str\n\nWhere the library reads its data: $CLIPS_DATA_DIR, else the data installed "
        "with the package (or under the prefix), else the source tree it was built from.");
  m.def("_join_abandoned", &join_abandoned, "Waits for the calls Ctrl-C interrupted to finish (run at exit).");
  m.def("_abandoned_running", &abandoned_running, "How many calls Ctrl-C interrupted are still running.");
}
