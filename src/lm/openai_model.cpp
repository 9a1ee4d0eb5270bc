#include "lm/openai_model.hpp"

#include <algorithm>
#include <cctype>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <utility>

namespace clips::lm {

using nlohmann::json;

namespace detail {

std::size_t utf8_length(const std::string& text) {
  return static_cast<std::size_t>(std::count_if(text.begin(), text.end(), [](char c) {
    return (static_cast<unsigned char>(c) & 0xC0) != 0x80;  // skip continuation bytes
  }));
}

namespace {

bool looks_special(const std::string& token) {
  return token.size() >= 3 && token.front() == '<' && token.back() == '>';
}

long long offset_at(const json& offsets, std::size_t i, const std::string& where) {
  const json& o = offsets[i];
  if (!o.is_number_integer() && !o.is_number_unsigned()) {
    throw LmError(where + ".text_offset[" + std::to_string(i) + "] is not an integer");
  }
  return o.get<long long>();
}

}  // namespace

// Servers compute log-probabilities in float precision; anything above this
// is not a rounding of 0 but a broken reply.
constexpr double kMaxRoundedLogprob = 1e-4;

double sum_continuation_logprobs(const json& logprobs, const std::string& prompt,
                                 const std::string& continuation, const std::string& where) {
  if (!logprobs.is_object()) throw LmError(where + " missing (server ignored logprobs?)");
  auto offsets_it = logprobs.find("text_offset");
  if (offsets_it == logprobs.end() || offsets_it->is_null()) throw LmError(where + ".text_offset missing");
  if (!offsets_it->is_array()) throw LmError(where + ".text_offset is not an array");
  auto lps_it = logprobs.find("token_logprobs");
  if (lps_it == logprobs.end() || lps_it->is_null()) throw LmError(where + ".token_logprobs missing");
  if (!lps_it->is_array()) throw LmError(where + ".token_logprobs is not an array");
  const json& offsets = *offsets_it;
  const json& lps = *lps_it;
  const std::size_t n = lps.size();
  if (offsets.size() != n) {
    throw LmError(where + ".text_offset has " + std::to_string(offsets.size()) +
                  " entries but token_logprobs has " + std::to_string(n));
  }
  if (n == 0) throw LmError(where + ".token_logprobs is empty");

  const auto p = static_cast<long long>(utf8_length(prompt));
  const auto f = p + static_cast<long long>(utf8_length(continuation));

  long long shift = 0;
  if (auto tokens = logprobs.find("tokens"); tokens != logprobs.end() && tokens->is_array() &&
                                             tokens->size() == n && n >= 2 && lps[0].is_null() &&
                                             (*tokens)[0].is_string()) {
    const auto first = (*tokens)[0].get<std::string>();
    const long long first_len = static_cast<long long>(utf8_length(first));
    if (looks_special(first) && prompt.rfind(first, 0) != 0 &&
        offset_at(offsets, 1, where) - offset_at(offsets, 0, where) == first_len) {
      shift = offset_at(offsets, 0, where) + first_len;
    }
  }

  double sum = 0.0;
  std::size_t counted = 0;
  bool saw_prompt_token = (p == 0);
  long long previous = std::numeric_limits<long long>::min();
  for (std::size_t i = 0; i < n; ++i) {
    const long long raw = offset_at(offsets, i, where);
    if (raw < previous) {
      throw LmError(where + ".text_offset[" + std::to_string(i) + "] decreases (" +
                    std::to_string(raw) + " after " + std::to_string(previous) + ")");
    }
    previous = raw;
    const long long start = raw - shift;
    const long long end =
        (i + 1 < n) ? offset_at(offsets, i + 1, where) - shift : std::numeric_limits<long long>::max();
    if (start < p) saw_prompt_token = true;
    const bool inside = start >= p && start < f;
    const bool straddles = start < p && end > p && p < f;
    if (!inside && !straddles) continue;

    const json& lp = lps[i];
    if (lp.is_null()) {
      throw LmError(where + ".token_logprobs[" + std::to_string(i) + "] is null" +
                    (i == 0 ? " (the continuation starts at the first token: empty prompt?)" : ""));
    }
    if (!lp.is_number()) {
      throw LmError(where + ".token_logprobs[" + std::to_string(i) + "] is not a number");
    }
    // A log-probability is at most 0; allow float rounding, not a positive score.
    if (const double v = lp.get<double>(); v > kMaxRoundedLogprob) {
      throw LmError(where + ".token_logprobs[" + std::to_string(i) + "] is " + json(v).dump() +
                    ", but a log-probability cannot be positive");
    }
    sum += lp.get<double>();
    ++counted;
  }
  // With the token strings we can also check that the echo reaches the end of
  // the continuation: a reply cut short would silently score a prefix.
  if (auto tokens = logprobs.find("tokens"); tokens != logprobs.end() && tokens->is_array() &&
                                             tokens->size() == n && (*tokens)[n - 1].is_string()) {
    const long long end = offset_at(offsets, n - 1, where) - shift +
                          static_cast<long long>(utf8_length((*tokens)[n - 1].get<std::string>()));
    if (end < f) {
      throw LmError(where + ": the echoed tokens end at character " + std::to_string(end) +
                    ", before the end of the continuation (character " + std::to_string(f) +
                    "); the reply does not cover the whole text");
    }
  }
  if (!saw_prompt_token) {
    throw LmError(where + ".text_offset: no token lies inside the prompt (first offset " +
                  std::to_string(offset_at(offsets, 0, where)) +
                  "); the server does not seem to echo the prompt");
  }
  if (counted == 0) {
    throw LmError(where + ".text_offset: no token starts inside the continuation (characters " +
                  std::to_string(p) + ".." + std::to_string(f) +
                  "); the server does not seem to echo the prompt");
  }
  return sum;
}

double sum_prompt_logprobs(const json& prompt_logprobs, const std::string& prompt,
                           const std::string& continuation, const std::string& where) {
  if (!prompt_logprobs.is_array()) throw LmError(where + " is not an array");
  const std::string text = prompt + continuation;
  std::size_t end = text.size();  // where the token being read ends, in bytes
  double sum = 0;
  bool covered = false;
  for (std::size_t k = prompt_logprobs.size(); k-- > 0 && end > prompt.size();) {
    const std::string at = where + "[" + std::to_string(k) + "]";
    const json& entry = prompt_logprobs[k];
    if (entry.is_null())
      throw LmError(at + " is null inside the continuation (only the first prompt token has no log-prob)");
    if (!entry.is_object() || entry.empty()) throw LmError(at + " is not a non-empty object");
    // The prompt's own token: the one of highest rank (the other, if any, is the top alternative).
    const json* token = nullptr;
    long long best_rank = std::numeric_limits<long long>::min();
    for (const auto& [id, lp] : entry.items()) {
      if (!lp.is_object()) throw LmError(at + "[\"" + id + "\"] is not an object");
      const auto rank = lp.find("rank");
      const long long r = rank != lp.end() && rank->is_number_integer() ? rank->get<long long>() : 1;
      if (token == nullptr || r > best_rank) {
        token = &lp;
        best_rank = r;
      }
    }
    const auto decoded = token->find("decoded_token");
    if (decoded == token->end() || !decoded->is_string())
      throw LmError(at + ".decoded_token missing: the tokens cannot be placed in the text");
    const auto lp = token->find("logprob");
    if (lp == token->end() || !lp->is_number()) throw LmError(at + ".logprob missing or not a number");
    const double v = lp->get<double>();
    if (v > kMaxRoundedLogprob) throw LmError(at + ".logprob is " + json(v).dump() + ", above 0");
    const std::string& piece = decoded->get_ref<const std::string&>();
    if (piece.size() > end || text.compare(end - piece.size(), piece.size(), piece) != 0)
      throw LmError(where + ": the decoded tokens do not spell the prompt (token " + std::to_string(k) + ", " +
                    json(piece).dump() + ", is not the text before byte " + std::to_string(end) +
                    "); the server tokenised something else");
    sum += v;
    end -= piece.size();
    covered = true;
  }
  if (!covered) throw LmError(where + " covers none of the continuation");
  if (end > prompt.size())
    throw LmError(where + ": the tokens end " + std::to_string(end - prompt.size()) +
                  " bytes into the continuation; the prompt was not scored whole");
  return sum;
}

std::vector<double> parse_completions_reply(const std::string& body,
                                            const std::vector<const ScoreRequest*>& chunk,
                                            double temperature, const std::string& context) {
  const json j = parse_choices_reply(body, context);
  const auto choices = j.find("choices");
  if (choices->size() != chunk.size()) {
    throw LmError(context + "choices has " + std::to_string(choices->size()) + " entries, expected " +
                  std::to_string(chunk.size()) + " (one per prompt)");
  }

  std::vector<double> scores(chunk.size());
  std::vector<bool> filled(chunk.size(), false);
  for (std::size_t pos = 0; pos < choices->size(); ++pos) {
    const json& choice = (*choices)[pos];
    const std::string where = "choices[" + std::to_string(pos) + "]";
    if (!choice.is_object()) throw LmError(context + where + " is not an object");
    // Servers may answer a batch out of order; `index` says which prompt it is.
    std::size_t index = pos;
    if (auto idx = choice.find("index"); idx != choice.end() && !idx->is_null()) {
      if (!idx->is_number_integer() && !idx->is_number_unsigned()) {
        throw LmError(context + where + ".index is not an integer");
      }
      const auto v = idx->get<long long>();
      if (v < 0 || static_cast<std::size_t>(v) >= chunk.size()) {
        throw LmError(context + where + ".index " + std::to_string(v) + " out of range");
      }
      index = static_cast<std::size_t>(v);
    }
    if (filled[index]) {
      throw LmError(context + where + ".index " + std::to_string(index) + " repeats an earlier choice");
    }
    filled[index] = true;
    // vLLM's prompt_logprobs when the reply has them, else echo + logprobs.
    if (auto plp = choice.find("prompt_logprobs"); plp != choice.end() && !plp->is_null()) {
      try {
        scores[index] = sum_prompt_logprobs(*plp, chunk[index]->prompt, chunk[index]->continuation,
                                            where + ".prompt_logprobs") /
                        temperature;
      } catch (const LmError& e) {
        throw LmError(context + e.what());
      }
      continue;
    }
    auto lp = choice.find("logprobs");
    if (lp == choice.end() || lp->is_null()) throw LmError(context + where + ".logprobs missing");
    try {
      const double total = sum_continuation_logprobs(*lp, chunk[index]->prompt,
                                                     chunk[index]->continuation, where + ".logprobs");
      scores[index] = total / temperature;
    } catch (const LmError& e) {
      throw LmError(context + e.what());
    }
  }
  return scores;
}

}  // namespace detail

namespace {

std::string lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

bool mentions(const std::string& text, const char* phrase) { return lower(text).find(phrase) != std::string::npos; }

bool mentions_max_tokens(const std::string& text) {
  return mentions(text, "max_tokens") || mentions(text, "max tokens");
}

// Ollama's /v1 (Go): "json: cannot unmarshal array into Go struct field
// CompletionRequest.prompt of type string".
bool refuses_array_prompt(const std::string& why) {
  return mentions(why, "unmarshal array") || (mentions(why, "prompt") && mentions(why, "array") && mentions(why, "string"));
}

bool truthy(std::string v) {
  v = lower(std::move(v));
  return v == "1" || v == "true" || v == "yes" || v == "on";
}

// What every "cannot score" line ends with: which servers can, and the offline way.
constexpr const char* kWhatWorks =
    "Scoring needs the log-probabilities of the prompt's own tokens: vLLM gives them (echo + logprobs, or "
    "prompt_logprobs), as do OpenAI-compatible /v1/completions servers that echo the prompt with logprobs "
    "(OpenAI's davinci-002 and babbage-002, llama-cpp-python); llama.cpp's server and Ollama do not. "
    "The embedded model (--lm embedded) needs no server.";

// llama.cpp's own /completion endpoint: {"content": ..} (or an array of them), no "choices".
bool looks_like_llama_native(const json& j) {
  const json* first = j.is_array() && !j.empty() ? &j[0] : &j;
  return first->is_object() && !first->contains("choices") &&
         (first->contains("content") || first->contains("completion_probabilities") || first->contains("tokens"));
}

// Which server a failed check was talking to, when the reply says so ("" when unknown).
std::string server_hint(const json& reply, const std::string& why) {
  if (mentions(why, "only no echo")) return ", as llama.cpp's server does";
  if (mentions(why, "go struct") || (reply.is_object() && reply.value("system_fingerprint", json()) == "fp_ollama"))
    return ", as Ollama does";
  if (reply.is_object() && reply.contains("choices") && reply["choices"].is_array() && !reply["choices"].empty()) {
    const json& c = reply["choices"][0];
    if (c.is_object() && c.contains("logprobs") && c["logprobs"].is_object() && c["logprobs"].contains("content"))
      return ", as llama.cpp's server does";
  }
  return "";
}

}  // namespace

OpenAiCompletionsModel::OpenAiCompletionsModel(OpenAiCompletionsOptions options)
    : options_(std::move(options)), http_(options_.http) {
  std::string base = options_.base_url.empty()
                         ? env_or("CLIPS_LM_BASE_URL", env_or("OPENAI_BASE_URL", "https://api.openai.com/v1"))
                         : options_.base_url;
  if (const std::string why = base_url_problem(base); !why.empty())
    throw LmError("base URL " + why + (options_.base_url.empty() ? " ($CLIPS_LM_BASE_URL)" : ""));
  endpoint_ = join_url(base, "/completions");
  model_ = options_.model.empty() ? env_or("CLIPS_LM_MODEL", "davinci-002") : options_.model;
  api_key_ = options_.api_key ? *options_.api_key : env_or("OPENAI_API_KEY", "");
  if (!(options_.temperature > 0.0)) {
    throw LmError("openai completions: temperature must be > 0 (scores are divided by it), got " +
                  std::to_string(options_.temperature));
  }
  if (options_.batch_size == 0) options_.batch_size = 1;
  fallback_ = !options_.try_max_tokens_zero;
  if (options_.prompt_logprobs) {
    prompt_logprobs_ = *options_.prompt_logprobs;
    prompt_logprobs_chosen_ = true;
  } else {
    const std::string v = env_or("CLIPS_LM_PROMPT_LOGPROBS", "");
    prompt_logprobs_ = truthy(v);
    prompt_logprobs_chosen_ = !v.empty();
  }
}

std::string OpenAiCompletionsModel::name() const { return "openai:" + model_; }

std::vector<double> OpenAiCompletionsModel::score(const std::vector<ScoreRequest>& batch) {
  // Identical pairs are common (one utterance, repeated commands): send each once.
  std::map<std::pair<std::string, std::string>, std::size_t> slot_of;
  std::vector<const ScoreRequest*> unique;
  std::vector<std::size_t> slot(batch.size());
  for (std::size_t i = 0; i < batch.size(); ++i) {
    auto [it, added] = slot_of.try_emplace({batch[i].prompt, batch[i].continuation}, unique.size());
    if (added) unique.push_back(&batch[i]);
    slot[i] = it->second;
  }

  std::vector<double> unique_scores;
  unique_scores.reserve(unique.size());
  const std::size_t per_request = options_.single_prompt ? 1 : options_.batch_size;
  for (std::size_t start = 0; start < unique.size(); start += per_request) {
    std::size_t stop = std::min(unique.size(), start + per_request);
    std::vector<const ScoreRequest*> chunk(unique.begin() + static_cast<std::ptrdiff_t>(start),
                                           unique.begin() + static_cast<std::ptrdiff_t>(stop));
    for (double s : score_chunk(chunk)) unique_scores.push_back(s);
  }

  std::vector<double> out(batch.size());
  for (std::size_t i = 0; i < batch.size(); ++i) out[i] = unique_scores[slot[i]];
  return out;
}

HttpResponse OpenAiCompletionsModel::post_chunk(const std::vector<const ScoreRequest*>& chunk) {
  json prompts = json::array();
  for (const auto* r : chunk) prompts.push_back(r->prompt + r->continuation);
  std::vector<std::string> headers;
  if (!api_key_.empty()) headers.push_back("Authorization: Bearer " + api_key_);

  for (;;) {
    const bool fallback = fallback_.load();
    json body = {{"model", model_},
                 {"prompt", options_.single_prompt && prompts.size() == 1 ? prompts[0] : prompts},
                 {"max_tokens", fallback ? 1 : 0},
                 {"temperature", options_.temperature}};
    if (prompt_logprobs_) {
      // vLLM: the prompt tokens' log-probs (and the top alternative) without echo.
      body["prompt_logprobs"] = 1;
    } else {
      body["echo"] = true;
      body["logprobs"] = options_.logprobs;
    }
    HttpResponse reply = http_.post_json(endpoint_, body.dump(), headers);
    if (reply.status >= 200 && reply.status < 300) return reply;
    const std::string why = server_error_text(reply.body);
    // vLLM: 400 "max_tokens must be at least 1"; pydantic-based servers: 422.
    if (!fallback && (reply.status == 400 || reply.status == 422) &&
        (mentions_max_tokens(why) || mentions_max_tokens(reply.body))) {
      fallback_ = true;
      continue;
    }
    return reply;
  }
}

std::vector<double> OpenAiCompletionsModel::score_chunk(const std::vector<const ScoreRequest*>& chunk) {
  const HttpResponse reply = post_chunk(chunk);
  if (reply.status < 200 || reply.status >= 300)
    throw LmError("POST " + endpoint_ + ": HTTP " + std::to_string(reply.status) + ": " + server_error_text(reply.body));
  return detail::parse_completions_reply(reply.body, chunk, options_.temperature,
                                         "reply from " + endpoint_ + ": ");
}

ScoringCheck OpenAiCompletionsModel::check_scoring() {
  const ScoreRequest probe{"Input: (pickup you key1)\nOutput:", " Get the key.\n"};
  const std::vector<const ScoreRequest*> chunk{&probe};
  const std::string who = "language model " + endpoint_ + " (model " + model_ + ")";
  const bool prompt_logprobs_before = prompt_logprobs_;
  std::string echo_problem;  // why echo failed, while prompt_logprobs is tried instead
  auto cannot = [&](const std::string& why) {
    prompt_logprobs_ = prompt_logprobs_before;
    return ScoringCheck{false, who + " cannot score a given text: " + why + ". " + kWhatWorks};
  };
  // Each round changes one thing (array -> single prompt, echo -> prompt_logprobs), so a few suffice.
  for (int round = 0; round < 4; ++round) {
    const HttpResponse reply = post_chunk(chunk);
    const json j = json::parse(reply.body, nullptr, /*allow_exceptions=*/false);
    const std::string why = server_error_text(reply.body);
    const std::string status = "HTTP " + std::to_string(reply.status) + " \"" + why + "\"";
    if (reply.status >= 200 && reply.status < 300) {
      try {
        detail::parse_completions_reply(reply.body, chunk, 1.0, "");
      } catch (const LmError& e) {
        if (!j.is_discarded() && looks_like_llama_native(j))
          return cannot("the reply has no choices but llama.cpp's own fields (content): this is llama.cpp's native "
                        "completion endpoint, whose log-probabilities cover generated tokens only (its /v1 "
                        "endpoint cannot score either)");
        if (j.is_discarded() || !j.is_object() || !j.contains("choices") || !j["choices"].is_array())
          return ScoringCheck{false, who + ": the reply is not an OpenAI completions reply (" + e.what() + ")"};
        const std::string problem = "it ignores echo: the reply's log-probabilities do not cover the prompt (" +
                                    std::string(e.what()) + ")" + server_hint(j, why);
        if (!prompt_logprobs_ && !prompt_logprobs_chosen_) {
          echo_problem = problem;
          prompt_logprobs_ = true;
          continue;
        }
        return cannot(echo_problem.empty() ? problem : echo_problem);
      }
      const json& first = j["choices"][0];
      const bool read_prompt_logprobs = first.contains("prompt_logprobs") && !first["prompt_logprobs"].is_null();
      std::string how = read_prompt_logprobs ? "vLLM's prompt_logprobs" : "echo + logprobs";
      if (!echo_problem.empty()) how += " (echo did not work)";
      if (options_.single_prompt) how += ", one prompt per request";
      if (fallback_) how += ", max_tokens=1";
      return ScoringCheck{true, who + " scores given text with " + how};
    }
    if (!options_.single_prompt && refuses_array_prompt(why)) {
      options_.single_prompt = true;
      continue;
    }
    // prompt_logprobs, tried because echo failed, is refused too: echo's failure is the reason.
    if (!echo_problem.empty()) return cannot(echo_problem);
    if (!prompt_logprobs_ && mentions(why, "echo")) {
      const std::string problem = "it refuses echo (" + status + ")" + server_hint(j, why);
      if (!prompt_logprobs_chosen_) {
        echo_problem = problem;
        prompt_logprobs_ = true;
        continue;
      }
      return cannot(problem);
    }
    if (prompt_logprobs_ && mentions(why, "prompt_logprobs")) return cannot("it refuses prompt_logprobs (" + status + ")");
    if (reply.status == 401 || reply.status == 403)
      return ScoringCheck{false, who + " refused the request (" + status + "): check $OPENAI_API_KEY"};
    if (reply.status == 404)
      return ScoringCheck{false, who + ": " + status +
                                     ": no completions endpoint there (an OpenAI-compatible base URL usually ends in /v1)"};
    return ScoringCheck{false, who + ": the scoring request failed: " + status};
  }
  return cannot("it refused every form of request tried");
}

}  // namespace clips::lm
