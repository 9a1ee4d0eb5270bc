// `clips serve`: the assistant behind HTTP/JSON (or JSON lines on stdio) and a
// web page to play the human (docs/api.md).
#include <pthread.h>
#include <signal.h>

#include <cstdlib>
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <random>

#include "app/cli.hpp"
#include "app/exit_codes.hpp"
#include "app/particle_flags.hpp"
#include "language/listener.hpp"
#include "serve/frontends.hpp"
#include "serve/service.hpp"
#include "util/error.hpp"

namespace clips::app {

namespace {

std::string random_token() {
  std::random_device rd;
  std::string t;
  static const char* hex = "0123456789abcdef";
  for (int i = 0; i < 8; ++i) {
    uint32_t r = rd();
    for (int k = 0; k < 4; ++k, r >>= 8) {
      t += hex[(r >> 4) & 15];
      t += hex[r & 15];
    }
  }
  return t;
}

std::string read_token(const std::string& path) {
  std::ifstream f(path);
  std::string t;
  if (!f || !std::getline(f, t)) throw InputError(path + ": cannot read the owner token (--owner-token-file)");
  while (!t.empty() && (t.back() == '\r' || t.back() == ' ')) t.pop_back();
  if (t.size() < 16) throw InputError(path + ":1: the owner token must have at least 16 characters");
  for (unsigned char c : t)
    if (c <= 0x20 || c >= 0x7f) throw InputError(path + ":1: the owner token must be printable ASCII without spaces");
  return t;
}

}  // namespace

void register_serve(CLI::App& app) {
  auto* cmd = app.add_subcommand("serve", "Serve sessions over HTTP/JSON and a web page to play with the assistant");
  struct Opts {
    std::string host = "127.0.0.1";
    int port = 8080;
    std::vector<std::string> datasets;
    bool stdio = false;
    bool lm_on_demand = false;
    int threads = 8;
    double read_timeout = 10;
    int max_connections = 128;
    int max_client_connections = 64;
    std::vector<std::string> allow_origins;
    std::string owner_token_file;
    LmFlags lm;
    ParticleFlags particles;
    serve::ServiceLimits limits;
  };
  auto o = std::make_shared<Opts>();
  cmd->add_option("--host", o->host, "Address to listen on (default 127.0.0.1, loopback only)");
  cmd->add_option("--port", o->port, "TCP port (default 8080; 0 picks a free one)")->check(CLI::Range(0, 65535));
  cmd->add_option("--dataset", o->datasets,
                  "Dataset or domain folder to serve (repeatable; any pack, plans/ optional: every problem plays); "
                  "requests name a dataset by its folder's base name and never give paths (default: "
                  "$CLIPS_DATASET/doors-keys-gems and /virtual-home, else ../shared/dataset/...)");
  cmd->add_flag("--stdio", o->stdio, "Read one JSON request per line on stdin, answer one per line on stdout");
  cmd->add_flag("--lm-on-demand", o->lm_on_demand,
                "Build each dataset's language model at its first instruction instead of before serving (start-up "
                "is quicker, the first instruction on each domain slower: up to a minute for a new domain)");
  cmd->add_option("--threads", o->threads, "Session requests handled at once (default 8, at most 256)")
      ->check(CLI::Range(1, 256));
  cmd->add_option("--read-timeout", o->read_timeout,
                  "Seconds for a request (head and body) to arrive in full after its connection opens, and again for "
                  "its reply to be taken (default 10)")
      ->check(CLI::Range(0.01, 3600.0));
  cmd->add_option("--max-connections", o->max_connections, "Connections open at once (default 128; more: 503)")
      ->check(CLI::Range(1, 4096));
  cmd->add_option("--max-client-connections", o->max_client_connections,
                  "Connections open at once from one address (default 64; more: 503)")
      ->check(CLI::Range(1, 4096));
  cmd->add_option("--allow-origin", o->allow_origins,
                  "A web origin (e.g. https://example.org) whose pages may call the API, besides the page itself and "
                  "pages on loopback (repeatable; \"*\": any)");
  cmd->add_option("--owner-token-file", o->owner_token_file,
                  "File whose first line is the owner token (at least 16 characters) that lists and deletes every "
                  "session; default: a random token printed at start");
  cmd->add_option("--max-sessions", o->limits.max_sessions,
                  "Live sessions at most (default 64, at most 100000; when full, a new session replaces the idlest "
                  "of the client holding the most, if idle for --evict-idle seconds; else HTTP 503)")
      ->check(PositiveInteger)
      ->check(CLI::Range(1, 100000));
  cmd->add_option("--max-client-sessions", o->limits.max_client_sessions,
                  "Live sessions one client address may hold (default 16; 0: no limit of its own; more: HTTP 429). "
                  "Requests with the owner token are not counted")
      ->check(NonNegativeInteger)
      ->check(CLI::Range(0, 100000));
  cmd->add_option("--evict-idle", o->limits.evict_idle_seconds,
                  "Seconds a session must have been idle before a new session may replace it on a full server "
                  "(default 120; 0: never)")
      ->check(CLI::Range(0.0, 1e7));
  cmd->add_option("--max-body", o->limits.max_body_bytes, "Request body size limit in bytes (default 65536, at most 64 MiB)")
      ->check(PositiveInteger)
      ->check(CLI::Range(1, 64 << 20));
  cmd->add_option("--max-pddl-bytes", o->limits.max_pddl_bytes,
                  "Size limit of each PDDL or pack text of a session created from text (\"domain\", \"problem\", "
                  "\"pack\"), in bytes (default 32768, at most 16 MiB)")
      ->check(PositiveInteger)
      ->check(CLI::Range(1, 16 << 20));
  cmd->add_option("--idle-timeout", o->limits.idle_seconds,
                  "Seconds after which an unused session is deleted (default 1800, at most 1e7)")
      ->check(PositiveSeconds)
      ->check(CLI::Range(0.0, 1e7));
  cmd->add_option("--max-nodes", o->limits.play.inference_nodes,
                  "Expansion budget per A* search when updating a belief (default 2^18)")
      ->check(PositiveInteger)
      ->check(NodeBudget);
  cmd->add_option("--assist-nodes", o->limits.play.assist_nodes,
                  "Expansion budget per A* search of an assistance decision (default 2^16)")
      ->check(PositiveInteger)
      ->check(NodeBudget);
  cmd->add_option("--max-seconds", o->limits.play.search_seconds, "Time budget per A* search (default 5)")
      ->check(PositiveSeconds);
  cmd->add_option("--max-steps", o->limits.play.max_steps, "Actions per session at most (default 300, at most 100000)")
      ->check(PositiveInteger)
      ->check(CLI::Range(1, 100000));
  cmd->add_option("--session-threads", o->limits.play.belief_threads,
                  "Threads refining each session's belief (default 1, as sessions already run in parallel; 0: all "
                  "cores, for one player at a time; at most 64)")
      ->check(NonNegativeInteger)
      ->check(CLI::Range(0, 64));
  add_particle_options(cmd, o->particles);
  add_lm_options(cmd, o->lm);
  cmd->callback([o] {
    apply_particle_flags(o->particles, o->limits.play.belief);
    // Block the stop signals before any thread exists, so that only the
    // server's signal thread ever sees them.
    sigset_t stop;
    sigemptyset(&stop);
    sigaddset(&stop, SIGINT);
    sigaddset(&stop, SIGTERM);
    if (!o->stdio) {
      pthread_sigmask(SIG_BLOCK, &stop, nullptr);
      serve::load_http_module();
    }
    std::vector<std::string> dirs = o->datasets;
    if (dirs.empty()) {
      const char* env = std::getenv("CLIPS_DATASET");
      const std::string root = env && *env ? env : "../shared/dataset";
      // Every dataset folder there (one holding a domain.pddl), by name.
      std::error_code ec;
      for (const auto& e : std::filesystem::directory_iterator(root, ec))
        if (std::filesystem::exists(e.path() / "domain.pddl")) dirs.push_back(e.path().string());
      std::sort(dirs.begin(), dirs.end());
      if (dirs.empty()) throw InputError("no dataset found under " + root + "; give --dataset DIR");
    }
    auto lm = make_lm(o->lm);
    serve::Service service(dirs, o->limits, lm);
    // A domain without a hand-written corpus (the workshop, your own) gets the
    // embedded model trained on its own names, as `clips infer` gives it; the
    // paper's domains and other backends share the one model.
    service.set_domain_language_model([lm, flags = o->lm](const domains::Pack& pack, const pddl::Domain& domain,
                                                          const std::vector<const pddl::Problem*>& problems) {
      if (flags.kind != "embedded" || !pack.spec().embedded_corpus.empty()) return lm;
      return language::make_domain_language_model(flags.kind, lm_options(flags), pack, domain, problems);
    });
    service.set_dataset_language_model([lm, flags = o->lm](const data::Dataset& ds) {
      if (flags.kind != "embedded" || !ds.pack().spec().embedded_corpus.empty()) return lm;
      return language::make_dataset_language_model(flags.kind, lm_options(flags), ds);
    });
    if (!o->lm_on_demand) service.prepare_language_models(std::cerr);
    if (o->stdio) {
      g_exit_code = serve::run_stdio(service, std::cin, std::cout);
      return;
    }
    serve::HttpOptions ho;
    ho.host = o->host;
    ho.port = o->port;
    ho.threads = o->threads;
    ho.read_timeout = o->read_timeout;
    ho.max_connections = o->max_connections;
    ho.max_client_connections = o->max_client_connections;
    ho.allow_origins = o->allow_origins;
    ho.owner_token = o->owner_token_file.empty() ? random_token() : read_token(o->owner_token_file);
    const int code = serve::run_http(service, ho, std::cerr);
    g_exit_code = code == serve::kCannotListen ? kExitCannotListen : code;
  });
}

}  // namespace clips::app
