#include "serve/service.hpp"

#include <fcntl.h>
#include <malloc.h>
#include <sys/random.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <filesystem>
#include <regex>
#include <set>
#include <system_error>

#include <fmt/core.h>
#include <nlohmann/json.hpp>
#include <ostream>

#include "engine/methods.hpp"
#include "engine/options.hpp"
#include "serve/api_schema.hpp"
#include "language/listener.hpp"
#include "util/error.hpp"
#include "util/program_name.hpp"

namespace clips::serve {

using nlohmann::json;

namespace {

// Set while a request works on a problem sent as PDDL text (creating its
// session, or any request on it).
thread_local bool t_text_problem = false;

// A request error with its HTTP status.
struct HttpError : std::runtime_error {
  int status;
  HttpError(int s, const std::string& what) : std::runtime_error(what), status(s) {}
};

// Invalid UTF-8 can only come from a request echoed in an error message: it
// is replaced, never allowed to make the reply itself fail.
Reply json_reply(int status, const json& j) {
  return {status, j.dump(-1, ' ', false, json::error_handler_t::replace), "application/json", {}};
}
Reply error_reply(int status, const std::string& message) {
  return json_reply(status, json{{"error", message}, {"status", status}});
}

// The body as a JSON object whose keys are all in `allowed`; an empty body is {}.
json parse_body(const std::string& body, std::initializer_list<const char*> allowed) {
  json j;
  if (body.find_first_not_of(" \t\r\n") == std::string::npos) {
    j = json::object();
  } else {
    try {
      j = parse_json_unique(body);
    } catch (const json::exception& e) {  // parse_error, or out_of_range for a number too large
      throw HttpError(400, "malformed JSON body: " + json_error_text(e));
    } catch (const std::invalid_argument& e) {  // a repeated key
      throw HttpError(400, std::string("malformed JSON body: ") + e.what());
    }
  }
  if (!j.is_object()) throw HttpError(400, "body: expected a JSON object");
  std::set<std::string> ok(allowed.begin(), allowed.end());
  for (auto it = j.begin(); it != j.end(); ++it)
    if (!ok.count(it.key())) {
      std::string names;
      for (const auto& n : ok) names += (names.empty() ? "" : ", ") + n;
      throw HttpError(400, "unknown field '" + echo(it.key()) + "' (allowed: " + (names.empty() ? "none" : names) + ")");
    }
  return j;
}

// The server's play limits with a session's "inference" object applied: its
// particle options, read by the engine's one table (engine/options.hpp) as
// `clips serve --particles ...` and Python's keywords are.
PlayLimits with_inference(PlayLimits play, const json& j) {
  if (!j.contains("inference")) return play;
  const json& inf = j["inference"];
  if (!inf.is_object()) throw HttpError(400, "field 'inference': expected an object of particle options");
  try {
    for (auto it = inf.begin(); it != inf.end(); ++it) {
      const std::string& name = it.key();
      const json& value = it.value();
      // A choice is a JSON string; a number is read from its JSON text.
      const auto& table = engine::option_table();
      const bool choice = std::any_of(table.begin(), table.end(), [&](const engine::EngineOption& o) {
        return o.name == name && o.kind == engine::EngineOption::Kind::Choice;
      });
      engine::set_option(play.belief, name, choice && value.is_string() ? value.get<std::string>() : value.dump());
    }
  } catch (const InputError& e) {
    throw HttpError(400, std::string("field 'inference': ") + e.what());
  }
  if (play.belief.particles > kMaxSessionParticles)
    throw HttpError(400, "field 'inference': particles must be at most " + std::to_string(kMaxSessionParticles) +
                             " on this server, got " + std::to_string(play.belief.particles));
  return play;
}

std::string string_field(const json& j, const char* name, bool required, const std::string& fallback = "") {
  if (!j.contains(name)) {
    if (required) throw HttpError(400, std::string("field '") + name + "' is required");
    return fallback;
  }
  if (!j[name].is_string()) throw HttpError(400, std::string("field '") + name + "': expected a string");
  return j[name].get<std::string>();
}

bool bool_field(const json& j, const char* name, bool fallback) {
  if (!j.contains(name)) return fallback;
  if (!j[name].is_boolean()) throw HttpError(400, std::string("field '") + name + "': expected true or false");
  return j[name].get<bool>();
}

// Whether `method` is one of the comma-separated names of `allow`.
bool method_in(const std::string& method, const std::string& allow) {
  size_t i = 0;
  while (i < allow.size()) {
    size_t j = allow.find(',', i);
    if (j == std::string::npos) j = allow.size();
    std::string_view name(allow.data() + i, j - i);
    while (!name.empty() && name.front() == ' ') name.remove_prefix(1);
    if (name == method) return true;
    i = j + 1;
  }
  return false;
}

std::vector<std::string> split_path(const std::string& path) {
  std::vector<std::string> parts;
  const std::string p = path.substr(0, path.find('?'));
  size_t i = 0;
  while (i < p.size()) {
    size_t j = p.find('/', i);
    if (j == std::string::npos) j = p.size();
    if (j > i) parts.push_back(p.substr(i, j - i));
    i = j + 1;
  }
  return parts;
}

}  // namespace

void os_random_bytes(void* out, size_t n) {
  auto* bytes = static_cast<unsigned char*>(out);
  size_t got = 0;
  while (got < n) {
    const ssize_t r = getrandom(bytes + got, n - got, 0);
    if (r > 0) {
      got += static_cast<size_t>(r);
    } else if (r < 0 && errno == ENOSYS) {
      break;  // a kernel without getrandom: its device instead
    } else if (r < 0 && errno != EINTR) {
      throw std::system_error(errno, std::generic_category(), "getrandom");
    }
  }
  if (got == n) return;
  const int fd = ::open("/dev/urandom", O_RDONLY | O_CLOEXEC);
  if (fd < 0) throw std::system_error(errno, std::generic_category(), "/dev/urandom");
  while (got < n) {
    const ssize_t r = ::read(fd, bytes + got, n - got);
    if (r > 0) {
      got += static_cast<size_t>(r);
    } else if (r == 0 || errno != EINTR) {
      const int err = r == 0 ? EIO : errno;
      ::close(fd);
      throw std::system_error(err, std::generic_category(), "/dev/urandom");
    }
  }
  ::close(fd);
}

std::string json_error_text(const std::exception& e) {
  const std::string what = e.what();
  // "[json.exception.parse_error.101] parse error at line 1, column 5: syntax
  // error while parsing object key - invalid literal; last read: '{x';
  // expected string literal": where, what was read, what was wrong.
  static const std::regex parse(
      R"(parse error at line (\d+), column (\d+): syntax error while parsing [^-]*- ([^;]*)(?:; last read: '(.*?)'(?=;|$))?(?:; expected (.*))?)");
  std::smatch m;
  if (std::regex_search(what, m, parse)) {
    std::string out = "not valid JSON at line " + m[1].str() + ", column " + m[2].str();
    if (m[4].matched && !m[4].str().empty()) {
      std::string read = m[4].str();
      if (read.size() > 24) read = "..." + read.substr(read.size() - 24);
      out += " (after '" + read + "')";
    }
    out += ": " + m[3].str();
    if (m[5].matched) out += "; expected " + m[5].str();
    return echo(out, 300);
  }
  static const std::regex overflow(R"(number overflow parsing '(.*)')");
  if (std::regex_search(what, m, overflow))
    return "the number " + echo(m[1].str(), 40) + " is too large for a double";
  const size_t tag = what.find("] ");
  return echo(what.rfind("[json.exception.", 0) == 0 && tag != std::string::npos ? what.substr(tag + 2) : what, 300);
}

json parse_json_unique(const std::string& text) {
  // One set of keys per object being read, innermost last.
  std::vector<std::set<std::string>> open;
  json::parser_callback_t check = [&open](int, json::parse_event_t event, json& parsed) {
    if (event == json::parse_event_t::object_start) {
      open.emplace_back();
    } else if (event == json::parse_event_t::object_end) {
      if (!open.empty()) open.pop_back();
    } else if (event == json::parse_event_t::key && !open.empty()) {
      const std::string& key = parsed.get_ref<const std::string&>();
      if (!open.back().insert(key).second) throw std::invalid_argument("duplicate key '" + echo(key) + "'");
    }
    return true;
  };
  return json::parse(text, check);
}

namespace {

// Each problem's candidate goals: those of its first recorded plan, or the
// pack's rule for the problem; none when they cannot be found (a session on
// the problem then says why).
std::map<std::string, std::vector<std::string>> goals_by_problem(const data::Dataset& ds) {
  std::map<std::string, const data::PlanRecord*> first;
  for (const auto& p : ds.plans()) first.emplace(p.problem_id, &p);
  std::map<std::string, std::vector<std::string>> out;
  for (const std::string& id : ds.problem_ids()) {
    data::PlanRecord only;
    only.id = only.problem_id = id;
    const auto it = first.find(id);
    auto& labels = out[id];
    try {
      for (const auto& g : ds.candidate_goals(it != first.end() ? *it->second : only)) labels.push_back(g.label);
    } catch (const InputError&) {
      labels.clear();
    }
  }
  return out;
}

}  // namespace

Service::Service(const std::vector<std::string>& dataset_dirs, ServiceLimits limits,
                 std::shared_ptr<lm::LanguageModel> lm, std::function<Clock::time_point()> now)
    : limits_(limits), lm_(std::move(lm)), now_(std::move(now)) {
  for (const auto& dir : dataset_dirs) {
    std::string name = std::filesystem::path(dir).lexically_normal().filename().string();
    if (name.empty()) name = std::filesystem::path(dir).lexically_normal().parent_path().filename().string();
    if (datasets_.count(name)) throw InputError("--dataset " + dir + ": a dataset named '" + name + "' is already served");
    // A domain folder with problems but no recorded plans is served too.
    Served& served = datasets_[name];
    served.dataset = std::make_shared<const data::Dataset>(data::Dataset::load(dir, false));
    served.problem_goals = goals_by_problem(*served.dataset);
  }
}

std::string Service::new_id() {
  static const char* hex = "0123456789abcdef";
  unsigned char bytes[16];
  random_(bytes, sizeof bytes);
  std::string id;
  for (unsigned char b : bytes) {
    id += hex[b >> 4];
    id += hex[b & 15];
  }
  return id;
}

size_t Service::live_sessions() const {
  std::lock_guard lock(mutex_);
  return sessions_.size();
}

size_t Service::expire_locked(int64_t now) {
  const auto idle = std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(limits_.idle_seconds));
  size_t n = 0;
  for (auto it = sessions_.begin(); it != sessions_.end();) {
    Entry& e = *it->second;
    std::unique_lock busy(e.mutex, std::try_to_lock);  // a session in use is not idle
    if (busy.owns_lock() && now - e.last_used.load() > idle.count()) {
      busy.unlock();
      it = sessions_.erase(it);
      ++n;
    } else {
      ++it;
    }
  }
  return n;
}

size_t Service::expire_idle() {
  size_t n = 0;
  {
    std::lock_guard lock(mutex_);
    n = expire_locked(now_().time_since_epoch().count());
  }
  if (n > 0) malloc_trim(0);
  return n;
}

std::shared_ptr<Service::Entry> Service::evict_locked(int64_t now) {
  if (!(limits_.evict_idle_seconds > 0)) return nullptr;
  const auto least = std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(limits_.evict_idle_seconds));
  std::map<std::string, size_t> held;  // sessions per client
  for (const auto& [id, e] : sessions_) ++held[e->client];
  auto victim = sessions_.end();
  std::pair<size_t, int64_t> worst{0, 0};  // (the client's sessions, idle ticks)
  for (auto it = sessions_.begin(); it != sessions_.end(); ++it) {
    Entry& e = *it->second;
    const int64_t idle = now - e.last_used.load();
    if (idle < least.count()) continue;
    std::unique_lock busy(e.mutex, std::try_to_lock);  // a session in use stays
    if (!busy.owns_lock()) continue;
    const std::pair<size_t, int64_t> rank{held[e.client], idle};
    if (victim == sessions_.end() || rank > worst) {
      victim = it;
      worst = rank;
    }
  }
  if (victim == sessions_.end()) return nullptr;
  auto gone = std::move(victim->second);
  sessions_.erase(victim);
  return gone;
}

std::shared_ptr<Service::Entry> Service::find(const std::string& id) {
  std::lock_guard lock(mutex_);
  expire_locked(now_().time_since_epoch().count());
  auto it = sessions_.find(id);
  if (it == sessions_.end()) throw HttpError(404, "no session '" + echo(id) + "' (it may have expired or been deleted)");
  return it->second;
}

Reply Service::datasets() const {
  json out = json::array();
  for (const auto& [name, served] : datasets_) {
    const data::Dataset& ds = *served.dataset;
    std::map<std::string, std::vector<std::string>> plans;
    for (const auto& p : ds.plans()) plans[p.problem_id].push_back(p.id);
    json problems = json::array();
    for (const auto& pid : ds.problem_ids()) {
      const auto goals = served.problem_goals.find(pid);
      problems.push_back({{"id", pid},
                          {"plans", plans[pid]},
                          {"goals", goals != served.problem_goals.end() ? json(goals->second) : json::array()}});
    }
    out.push_back({{"name", name},
                   {"domain", ds.pack().name()},
                   {"scene", domains::to_string(ds.pack().spec().scene)},
                   {"problems", std::move(problems)}});
  }
  return json_reply(200, json{{"datasets", std::move(out)},
                              {"methods", play_methods()},
                              {"assistance", assistance_names()},
                              {"limits",
                               {{"utterance_bytes", limits_.play.max_utterance_bytes},
                                {"pddl_bytes", limits_.max_pddl_bytes},
                                {"body_bytes", limits_.max_body_bytes}}}});
}

std::shared_ptr<lm::LanguageModel> Service::dataset_lm(Served& served) {
  if (!dataset_lm_) return lm_;
  std::lock_guard lock(served.lm_mutex);
  if (!served.lm) served.lm = dataset_lm_(*served.dataset);
  return served.lm;
}

void Service::prepare_language_models(std::ostream& log) {
  size_t k = 0;
  for (auto& [name, served] : datasets_) {
    ++k;
    const auto t0 = Clock::now();
    log << util::program_name() << " serve: preparing the language model of " << name << " (" << k << " of "
        << datasets_.size() << ")..." << std::flush;
    language::warm_up_language_model(*dataset_lm(served), *served.dataset, served.dataset->problem_ids());
    log << " ready in " << fmt::format("{:.1f}", std::chrono::duration<double>(Clock::now() - t0).count()) << " s\n"
        << std::flush;
  }
}

std::shared_ptr<lm::LanguageModel> Service::text_lm(const PlaySetup& setup, const std::string& key) {
  if (!domain_lm_) return lm_;
  std::lock_guard lock(lm_mutex_);
  for (auto& [k, m] : text_lms_)
    if (k == key) return m;
  auto m = domain_lm_(*setup.pack, setup.task->domain(), {&setup.task->problem()});
  text_lms_.emplace_back(key, m);
  if (text_lms_.size() > 8) text_lms_.erase(text_lms_.begin());  // the oldest goes
  return m;
}

Reply Service::create(const std::string& body, const std::string& client) {
  const json j = parse_body(body, {"assistance", "dataset", "domain", "goal", "inference", "method", "pack", "plan",
                                   "problem"});
  // The player's goal: absent, the reference plan's true goal; null, none.
  std::optional<std::optional<std::string>> player_goal;
  if (j.contains("goal")) {
    if (j["goal"].is_null()) player_goal.emplace(std::nullopt);
    else if (j["goal"].is_string()) player_goal.emplace(j["goal"].get<std::string>());
    else throw HttpError(400, "field 'goal': expected a candidate goal's label (a string) or null");
  }
  PlayLimits play = with_inference(limits_.play, j);
  // How the assistant decides (the engine's one name table).
  if (j.contains("assistance")) try {
      play.belief.assistance = parse_assistance(string_field(j, "assistance", true));
    } catch (const InputError& e) {
      throw HttpError(400, std::string("field 'assistance': ") + e.what());
    }
  // The engine's method table, its older spellings too (as POST .../method reads them).
  std::string method = string_field(j, "method", false, method_name(Method::Clips));
  try {
    method = method_name(parse_method(method));
  } catch (const InputError&) {
    throw HttpError(400, "field 'method': " + engine::method_choices().unknown(echo(method)));
  }
  const bool from_text = j.contains("domain");
  t_text_problem = from_text;
  std::string dataset, problem, plan, domain_text, pack_text;
  Served* served = nullptr;
  if (from_text) {
    // A session on PDDL text: "domain" and "problem" are PDDL, "pack" the pack (JSON text or object).
    if (j.contains("dataset"))
      throw HttpError(400, "field 'dataset': give either 'dataset' (a served dataset's problem id) or 'domain' "
                           "and 'problem' (PDDL text), not both");
    if (j.contains("plan")) throw HttpError(400, "field 'plan': a session from PDDL text has no recorded plan");
    domain_text = string_field(j, "domain", true);
    problem = string_field(j, "problem", true);
    if (j.contains("pack")) {
      if (j["pack"].is_object()) pack_text = j["pack"].dump();
      else if (j["pack"].is_string()) pack_text = j["pack"].get<std::string>();
      else throw HttpError(400, "field 'pack': expected a JSON object or a string holding one");
    }
    for (const auto& [name, text] : {std::pair<const char*, const std::string*>{"domain", &domain_text},
                                     {"problem", &problem}, {"pack", &pack_text}})
      if (text->size() > limits_.max_pddl_bytes)
        throw HttpError(400, std::string("field '") + name + "': " + std::to_string(text->size()) +
                                 " bytes exceeds the limit of " + std::to_string(limits_.max_pddl_bytes) +
                                 " bytes (--max-pddl-bytes)");
  } else {
    if (j.contains("pack")) throw HttpError(400, "field 'pack': only with 'domain' (PDDL text)");
    if (!j.contains("dataset"))
      throw HttpError(400, "field 'dataset' is required (or 'domain' and 'problem' as PDDL text)");
    dataset = string_field(j, "dataset", true);
    problem = string_field(j, "problem", true);
    plan = string_field(j, "plan", false);
    auto ds = datasets_.find(dataset);
    if (ds == datasets_.end()) throw HttpError(400, "field 'dataset': no served dataset '" + echo(dataset) + "'");
    served = &ds->second;
  }
  std::shared_ptr<Entry> evicted;  // dropped outside the lock
  {
    std::lock_guard lock(mutex_);
    const int64_t now = now_().time_since_epoch().count();
    expire_locked(now);
    if (!client.empty() && limits_.max_client_sessions > 0) {
      size_t mine = pending_by_client_[client];
      for (const auto& [id, e] : sessions_) mine += e->client == client;
      if (mine >= limits_.max_client_sessions)
        throw HttpError(429, "too many sessions from " + echo(client) + ": " + std::to_string(mine) + " of at most " +
                                 std::to_string(limits_.max_client_sessions) +
                                 " per client (--max-client-sessions); delete one (DELETE /api/sessions/ID) first");
    }
    if (sessions_.size() + pending_ >= limits_.max_sessions && !(evicted = evict_locked(now)))
      throw HttpError(503, "the server is full: " + std::to_string(limits_.max_sessions) +
                               " live sessions, none idle long enough to make room; delete one or try later");
    ++pending_;
    ++pending_by_client_[client];
  }
  if (evicted) {
    std::lock_guard wait_for_requests(evicted->mutex);
    evicted->session.reset();
    evicted.reset();
    malloc_trim(0);
  }
  // The slot is held until the session is in the table (or its creation failed).
  const auto release_pending = [this, &client] {
    --pending_;
    if (--pending_by_client_[client] == 0) pending_by_client_.erase(client);
  };
  auto entry = std::make_shared<Entry>();
  try {
    if (from_text) {
      PlaySetup setup = text_setup(domain_text, problem, pack_text, limits_.play);
      auto lm = text_lm(setup, domain_text + '\0' + pack_text + '\0' + problem);
      entry->session = std::make_unique<PlaySession>(std::move(setup), method, std::move(lm), play);
    } else {
      PlaySetup setup = dataset_setup(served->dataset, dataset, problem, plan);
      auto lm = dataset_lm(*served);
      entry->session = std::make_unique<PlaySession>(std::move(setup), method, std::move(lm), play);
    }
    if (player_goal) try {
        entry->session->set_player_goal(*player_goal);
      } catch (const InputError& e) {
        throw HttpError(400, std::string("field 'goal': ") + e.what());
      }
  } catch (...) {
    {
      std::lock_guard lock(mutex_);
      release_pending();
    }
    malloc_trim(0);  // a refused problem may have grounded a large task: its pages go back now
    throw;
  }
  entry->last_used = now_().time_since_epoch().count();
  entry->created = entry->last_used;
  entry->dataset = dataset;
  entry->client = client;
  entry->problem = from_text ? entry->session->state().value("problem", "") : problem;
  json state = entry->session->state();
  std::string id;
  {
    std::lock_guard lock(mutex_);
    release_pending();
    do id = new_id();
    while (sessions_.count(id));
    sessions_[id] = entry;
  }
  state["id"] = id;
  return json_reply(201, state);
}

Reply Service::on_session(const std::string& method, const std::string& id, const std::string& op,
                          const std::string& body) {
  if (method == "DELETE" && op.empty()) {
    std::shared_ptr<Entry> gone;
    {
      std::lock_guard lock(mutex_);
      auto it = sessions_.find(id);
      if (it == sessions_.end()) throw HttpError(404, "no session '" + echo(id) + "'");
      gone = std::move(it->second);
      sessions_.erase(it);
    }
    {
      std::lock_guard wait_for_requests(gone->mutex);  // a request in flight finishes first
      gone->session.reset();
    }
    malloc_trim(0);  // hand the session's pages back, so RSS follows the live sessions
    return json_reply(200, json{{"deleted", id}});
  }
  auto entry = find(id);
  t_text_problem = entry->dataset.empty();
  std::lock_guard busy(entry->mutex);
  if (!entry->session) throw HttpError(404, "no session '" + echo(id) + "' (deleted)");
  entry->last_used = now_().time_since_epoch().count();
  PlaySession& s = *entry->session;
  auto with_id = [&](json j) {
    j["id"] = id;
    return json_reply(200, j);
  };
  if (method == "GET") {
    if (op.empty()) return with_id(s.state());
    if (op == "posterior") return json_reply(200, s.posterior());
    if (op == "trace") return json_reply(200, s.trace());
  } else if (method == "POST") {
    if (op == "act") {
      const json j = parse_body(body, {"action"});
      s.act(string_field(j, "action", true));
      return with_id(s.state());
    }
    if (op == "hear") {
      const json j = parse_body(body, {"utterance"});
      s.hear(string_field(j, "utterance", true));
      return with_id(s.state());
    }
    if (op == "assist") {
      const json j = parse_body(body, {"apply"});
      json d = s.assist(bool_field(j, "apply", false));
      return json_reply(200, json{{"decision", std::move(d)}, {"state", [&] {
                                                                  json st = s.state();
                                                                  st["id"] = id;
                                                                  return st;
                                                                }()}});
    }
    if (op == "undo" || op == "reset") {
      parse_body(body, {});
      op == "undo" ? s.undo() : s.reset();
      return with_id(s.state());
    }
    if (op == "goal_holds") {
      const json j = parse_body(body, {"goal"});
      const std::string goal = string_field(j, "goal", true);
      return json_reply(200, json{{"goal", goal}, {"holds", s.goal_holds(goal)}, {"t", s.steps()}});
    }
    if (op == "method") {
      const json j = parse_body(body, {"method"});
      s.set_method(string_field(j, "method", true));
      return with_id(s.state());
    }
  }
  throw HttpError(404, "no route " + echo(method, 16) + " /api/sessions/" + echo(id) + (op.empty() ? "" : "/" + echo(op)));
}

Reply Service::list_sessions() {
  const int64_t now = now_().time_since_epoch().count();
  const auto seconds = [](int64_t ticks) {
    return std::chrono::duration<double>(Clock::duration(ticks)).count();
  };
  json out = json::array();
  {
    std::lock_guard lock(mutex_);
    expire_locked(now);
    for (const auto& [id, e] : sessions_) {
      std::unique_lock busy(e->mutex, std::try_to_lock);
      json s = {{"id", id},
                {"dataset", e->dataset.empty() ? json(nullptr) : json(e->dataset)},
                {"problem", e->problem},
                {"age_seconds", seconds(now - e->created)},
                {"idle_seconds", seconds(now - e->last_used.load())},
                {"busy", !busy.owns_lock()}};
      if (busy.owns_lock() && e->session) s["method"] = e->session->method();
      out.push_back(std::move(s));
    }
  }
  return json_reply(200, json{{"sessions", std::move(out)}, {"max_sessions", limits_.max_sessions}});
}

Reply Service::delete_all_sessions() {
  std::map<std::string, std::shared_ptr<Entry>> gone;
  {
    std::lock_guard lock(mutex_);
    gone.swap(sessions_);
  }
  json ids = json::array();
  for (auto& [id, e] : gone) {
    std::lock_guard wait_for_requests(e->mutex);  // a request in flight finishes first
    e->session.reset();
    ids.push_back(id);
  }
  gone.clear();
  malloc_trim(0);
  return json_reply(200, json{{"deleted", std::move(ids)}});
}

std::string Service::allowed_methods(const std::string& path) {
  const auto parts = split_path(path);
  if (parts.empty() || parts[0] != "api") {
    const auto& assets = web_assets();
    if (parts.size() <= 1 && assets.count(parts.empty() ? "/index.html" : "/" + parts.back())) return "GET, HEAD";
    return "";
  }
  if (parts.size() == 2 && (parts[1] == "health" || parts[1] == "datasets" || parts[1] == "openapi.json"))
    return "GET, HEAD";
  if (parts.size() == 2 && parts[1] == "sessions") return "GET, HEAD, POST, DELETE";
  if (parts.size() == 3 && parts[1] == "sessions") return "GET, HEAD, DELETE";
  if (parts.size() == 4 && parts[1] == "sessions") {
    const std::string& op = parts[3];
    if (op == "posterior" || op == "trace") return "GET, HEAD";
    if (op == "act" || op == "hear" || op == "assist" || op == "undo" || op == "reset" || op == "method" ||
        op == "goal_holds")
      return "POST";
  }
  return "";
}

Reply Service::handle(const Request& request) {
  Reply r = respond(request);
  if (exchange_log_) exchange_log_->exchange(request.method, request.path, request.body, r.status, r.content_type, r.body);
  return r;
}

Reply Service::respond(const Request& request) {
  t_text_problem = false;
  const std::string method = request.method == "HEAD" ? "GET" : request.method;  // the front end drops the body
  const std::string& path = request.path;
  const std::string& body = request.body;
  try {
    if (body.size() > limits_.max_body_bytes)
      throw HttpError(413, "request body of " + std::to_string(body.size()) + " bytes exceeds the limit of " +
                               std::to_string(limits_.max_body_bytes) + " bytes (--max-body)");
    const std::string allow = allowed_methods(path);
    if (allow.empty()) throw HttpError(404, "no route " + echo(method, 16) + " " + echo(path));
    if (!method_in(method, allow)) {
      Reply r = error_reply(405, echo(method, 16) + " " + echo(path) + ": allowed methods are " + allow);
      r.headers.emplace_back("Allow", allow);
      return r;
    }
    const auto parts = split_path(path);
    if (parts.empty() || parts[0] != "api") {
      const auto& it = web_assets().find(parts.empty() ? "/index.html" : "/" + parts.back());
      return {200, std::string(it->second.body), it->second.content_type, {}};
    }
    if (parts.size() == 2 && parts[1] == "health") {
      std::lock_guard lock(mutex_);
      return json_reply(200, json{{"sessions", sessions_.size()}, {"max_sessions", limits_.max_sessions}});
    }
    if (parts.size() == 2 && parts[1] == "datasets") return datasets();
    if (parts.size() == 2 && parts[1] == "openapi.json")
      return {200, served_api_document().dump(1) + "\n", "application/json", {}};
    if (parts.size() == 2 && parts[1] == "sessions") {
      // The owner's sessions are not counted against a client's quota.
      if (method == "POST") return create(body, request.owner ? "" : request.client);
      if (!request.owner) {
        Reply r = error_reply(401, "listing or deleting every session needs the owner token "
                                   "(header 'Authorization: Bearer TOKEN'; " + util::program_name() +
                                       " serve prints it at start)");
        r.headers.emplace_back("WWW-Authenticate", "Bearer");
        return r;
      }
      return method == "GET" ? list_sessions() : delete_all_sessions();
    }
    return on_session(method, parts[2], parts.size() == 4 ? parts[3] : "", body);
  } catch (const HttpError& e) {
    return error_reply(e.status, e.what());
  } catch (const ConflictError& e) {
    return error_reply(409, e.what());
  } catch (const InputError& e) {
    return error_reply(400, e.what());
  } catch (const MemoryLimitError& e) {
    // Memory this server would not have: not the client's fault, and trying
    // later or smaller may work.
    return error_reply(503, e.what());
  } catch (const std::bad_alloc&) {
    return error_reply(503, "the server ran out of memory for this request; try a smaller problem or later");
  } catch (const CallStoppedError& e) {
    // A request past the server's time limits (grounding a problem sent as text).
    return error_reply(422, std::string("the problem exceeds a limit of this server: ") + e.what());
  } catch (const std::length_error& e) {
    // A size limit of the planner's tables (e.g. more than 65,535 actions
    // applicable in one state): the problem is too large for this server.
    return error_reply(422, std::string("the problem exceeds a limit of this server: ") + e.what());
  } catch (const lm::LmError& e) {
    // The language model is another server behind this one: a gateway error.
    const bool timed_out = std::string_view(e.what()).find("timed out") != std::string_view::npos;
    return error_reply(timed_out ? 504 : 502, std::string("language model failed: ") + e.what());
  } catch (const std::system_error& e) {
    if (e.code() != std::errc::resource_unavailable_try_again)
      return error_reply(500, std::string("internal error: ") + e.what());
    return error_reply(503, std::string("the server is out of resources: ") + e.what());
  } catch (const std::exception& e) {
    // A problem sent as PDDL text is the client's: whatever the planner
    // throws on it is a limit the problem exceeds, not the server's fault.
    if (t_text_problem) return error_reply(422, std::string("the problem exceeds a limit of this server: ") + e.what());
    return error_reply(500, std::string("internal error: ") + e.what());
  }
}

}  // namespace clips::serve
