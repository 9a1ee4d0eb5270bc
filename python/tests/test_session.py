"""The Python package clips_assist: the session API, dataset plans, errors."""
import json
import os
import pathlib
import subprocess
import threading

import pytest

import clips_assist

ROOT = pathlib.Path(__file__).resolve().parents[2]
EXAMPLES = ROOT / "data" / "examples" / "doors-keys-gems"
SHARED = pathlib.Path(os.environ.get("CLIPS_DATASET", ROOT.parent / "shared" / "dataset")) / "doors-keys-gems"
BINARY_DIR = pathlib.Path(os.environ.get("CLIPS_BINARY_DIR", ROOT / "build"))


def plan_lines(dataset, plan):
    """(actions, {index: [utterances]}) of an observed plan file."""
    actions, said = [], {}
    for line in (pathlib.Path(dataset) / "plans" / "observed" / f"{plan}.pddl").read_text().splitlines():
        line = line.strip()
        if line.startswith(";"):
            said.setdefault(len(actions), []).append(line[1:].strip())
        elif line:
            actions.append(line)
    return actions, said


def replay(dataset, plan):
    """Goal posteriors of a Session replaying a plan, at the points `clips infer` reports them."""
    actions, said = plan_lines(dataset, plan)
    s = clips_assist.Session.open_dataset(str(dataset), plan)
    T = len(actions)
    out = []
    for t in range(T + 1):
        if t > 0:
            s.observe(actions[t - 1])
        # `clips infer` scores utterances said after t actions in step t + 1,
        # except at the start and the end.
        if t in (0, T):
            for u in said.get(t, []):
                s.hear(u)
        out.append([g["p"] for g in s.posterior()["goals"]])
        if t not in (0, T):
            for u in said.get(t, []):
                s.hear(u)
    return out


def check_against_cli(dataset, plan):
    cli = BINARY_DIR / "clips"
    if not cli.exists():
        pytest.skip(f"no CLI at {cli}")
    infer = json.loads(subprocess.run([str(cli), "infer", "--json", "--dataset", str(dataset), "--plan", plan],
                                      check=True, capture_output=True, text=True).stdout)
    got = replay(dataset, plan)
    assert len(got) == len(infer["steps"])
    for t, (mine, theirs) in enumerate(zip(got, infer["steps"])):
        assert mine == pytest.approx([g["p"] for g in theirs["posterior"]["goals"]], abs=1e-9), f"{plan} t={t}"
    # run_plan gives the same numbers without a session.
    run = clips_assist.run_plan(str(dataset), plan)
    assert len(run["steps"]) == len(infer["steps"])
    for mine, theirs in zip(run["steps"], infer["steps"]):
        assert [g["p"] for g in mine["posterior"]["clips"]["goals"]] == pytest.approx(
            [g["p"] for g in theirs["posterior"]["goals"]], abs=1e-9)
        assert mine["posterior"]["clips"].keys() == theirs["posterior"].keys()  # one JSON form


def test_session_reproduces_clips_infer_on_the_papers_dataset():
    if not (SHARED / "domain.pddl").exists():
        pytest.skip(f"no shared dataset at {SHARED}")
    check_against_cli(SHARED, "2.1.keys")


def test_session_reproduces_clips_infer_on_a_repo_example():
    check_against_cli(EXAMPLES, "e2.2.keys")


def test_posterior_assist_and_trace_are_plain_python_values():
    s = clips_assist.Session.open_dataset(str(EXAMPLES), "e1")
    step = s.observe("(left human)")
    assert step["agent"] == "human" and step["evidence"] is True
    s.observe("(wait robot)")
    s.hear("Can you get me the yellow key?")
    s.observe("(left human)")
    post = s.posterior()
    goals = clips_assist.goal_probabilities(post)
    assert sum(goals.values()) == pytest.approx(1.0)
    assert max(goals, key=goals.get) == "gem3"  # the yellow key's side (problems/e1.txt)
    assert len(post["hypotheses"]) == 8
    assert sum(h["p"] for h in post["hypotheses"]) == pytest.approx(1.0)
    assert post["method"] == "clips" and post["log_marginal_likelihood"] < 0
    decision = s.assist()
    assert decision["assistant_turn"] and "robot" in decision["action"]
    assert dict(zip(decision["goals"], decision["goal_weights"])) == goals
    assert decision["action"] in [c["action"] for c in decision["candidates"]]
    assert [st["t"] for st in s.trace()] == [0, 1, 2, 3]
    assert s.trace()[2]["utterances"] == ["Can you get me the yellow key?"]
    assert "h" in str(s)
    json.dumps(s.trace())  # plain values all the way down


def test_errors_map_to_python_exceptions_with_the_same_messages():
    s = clips_assist.Session.open_dataset(str(EXAMPLES), "e1")
    s.observe("(left human)")
    before = s.posterior()
    with pytest.raises(clips_assist.InapplicableActionError, match=r"\(left human\)"):
        s.observe("(left human)")  # the robot is to move
    assert issubclass(clips_assist.InapplicableActionError, clips_assist.InputError)
    assert issubclass(clips_assist.InputError, ValueError)
    with pytest.raises(clips_assist.InputError, match="fly"):
        s.observe("(fly human)")
    with pytest.raises(clips_assist.InputError):
        s.hear("")
    assert s.t == 1 and s.posterior() == before
    with pytest.raises(clips_assist.InputError, match="unknown method"):
        clips_assist.Session.open_dataset(str(EXAMPLES), "e1", method="telepathy")
    with pytest.raises(clips_assist.InputError, match="no problem or plan 'zz'"):
        clips_assist.Session.open_dataset(str(EXAMPLES), "zz")


def test_particle_sessions_are_seeded_and_close_to_exact():
    def run(**kw):
        s = clips_assist.Session.open_dataset(str(EXAMPLES), "e1", **kw)
        s.observe("(left human)")
        s.observe("(wait robot)")
        s.hear("Can you get me the yellow key?")
        return clips_assist.goal_probabilities(s.posterior())

    exact = run()
    many = run(particles=2000, particle_seed=3)
    assert sum(many.values()) == pytest.approx(1.0)
    assert sum(abs(many[g] - exact[g]) for g in exact) / 2 < 0.05
    assert run(particles=2000, particle_seed=3) == many  # a function of the seed
    one = run(particles=1)
    assert sorted(one.values())[-1] == pytest.approx(1.0)  # a single particle sits on one goal
    with pytest.raises(clips_assist.InputError, match="particles"):
        clips_assist.Session.open_dataset(str(EXAMPLES), "e1", particles=-1)
    # The tuning options reach the filter: one CLIPS filter resampling every
    # step, read by its weighted counts, is another estimate than the default
    # (which weighs the hypotheses the particles hold exactly), still close.
    tuned = run(particles=2000, particle_seed=3, ess_threshold=1.0, particle_filters="clips",
                rejuvenate="utterances", particle_estimate="weights")
    assert tuned != many
    assert sum(abs(tuned[g] - exact[g]) for g in exact) / 2 < 0.05
    with pytest.raises(clips_assist.InputError, match="particle_estimate must be one of support, weights, got 'counts'"):
        clips_assist.Session.open_dataset(str(EXAMPLES), "e1", particles=10, particle_estimate="counts")
    with pytest.raises(clips_assist.InputError, match="particle_filters must be one of all, clips, got 'some'"):
        clips_assist.Session.open_dataset(str(EXAMPLES), "e1", particles=10, particle_filters="some")
    with pytest.raises(clips_assist.InputError, match="ess_threshold must be a number from 0 to 1, got 2.0"):
        clips_assist.Session.open_dataset(str(EXAMPLES), "e1", particles=10, ess_threshold=2.0)


def test_assistant_turns_option():
    """Refining only toward the assistant's action leaves the posterior as the
    spec's refinement of every successor gives it; a bad value is refused."""
    def run(**kw):
        s = clips_assist.Session.open_dataset(str(EXAMPLES), "e1", **kw)
        for action in ("(left human)", "(left robot)", "(left human)", "(right robot)"):
            s.observe(action)
        s.hear("Can you get me the yellow key?")
        return clips_assist.goal_probabilities(s.posterior())

    taken, every = run(), run(assistant_turns="all")
    assert taken.keys() == every.keys()
    for g in taken:
        assert taken[g] == pytest.approx(every[g], abs=1e-9)
    with pytest.raises(clips_assist.InputError, match="assistant-turn refinement 'some'"):
        clips_assist.Session.open_dataset(str(EXAMPLES), "e1", assistant_turns="some")


def test_inference_releases_the_gil():
    # Two sessions on two Python threads: with the GIL released during
    # inference they run concurrently and still agree with one thread.
    def run(out, i):
        s = clips_assist.Session.open_dataset(str(EXAMPLES), "e1.1.keys")
        for a in ["(left human)", "(wait robot)", "(left human)"]:
            s.observe(a)
        out[i] = s.posterior()["goals"]

    out = [None, None]
    threads = [threading.Thread(target=run, args=(out, i)) for i in range(2)]
    for th in threads:
        th.start()
    for th in threads:
        th.join()
    alone = [None]
    run(alone, 0)
    assert out[0] == alone[0] and out[1] == alone[0]


def test_run_bench_returns_rows_per_plan_and_method():
    rep = clips_assist.run_bench(str(EXAMPLES), methods=["clips"], plans=["e1.1.keys"], jobs=1)
    assert [(r["plan"], r["method"]) for r in rep["rows"]] == [("e1.1.keys", "clips")]
    assert 0 <= rep["rows"][0]["p_true_goal"] <= 1
    assert "clips" in rep["summary"]


# ---- open_domain: every option of open_dataset, and PDDL as text ------------

WORKSHOP = ROOT / "data" / "datasets" / "workshop"

# A value other than the default for every keyword option, and one the option refuses.
OPTIONS = {
    "method": ("action", "telepathy"),
    "assistance": ("pibar", "oracle"),
    "lm": ("embedded", "nope"),
    "lm_base_url": ("http://127.0.0.1:9/v1", 3),
    "lm_model": ("some-model", 3),
    "lm_timeout": (5.0, -1.0),
    "goals": (["(made table)", "(made stool)"], "(made table)"),
    "cost_profiles": (["unit"], ["no-such-profile"]),
    "max_nodes": (5000, 0),
    "threads": (1, -1),
    "assist_max_nodes": (1000, -1),
    "assist_rule": ("request", "sometimes"),
    "qa_floor": ("horizon", "never"),
    "search_seconds": (30.0, 0.0),
    "particles": (64, -1),
    "particle_seed": (7, "seven"),
    "ess_threshold": (0.9, 2.0),
    "rejuvenation_moves": (1, -1),
    "rejuvenate": ("utterances", "sometimes"),
    "proposal_groups": (2, 0),
    "particle_filters": ("clips", "some"),
    "particle_estimate": ("weights", "counts"),
    "assistant_turns": ("all", "some"),
}


def documented_options(opener):
    doc = opener.__doc__
    block = doc[doc.index("Keyword options"):].splitlines()[1:]
    return [line.split("=")[0].strip() for line in block if line.startswith("  ") and "=" in line]


def docs_example_files():
    text = (ROOT / "docs" / "domains.md").read_text(encoding="utf-8")
    import re
    return dict(re.findall(r"<!-- file: (\S+) -->\s*\n```[a-z]*\n(.*?)```", text, re.S))


def test_both_openers_take_every_option():
    """open_dataset and open_domain read one option table: the same names, the same checks."""
    assert documented_options(clips_assist.Session.open_dataset) == list(OPTIONS)
    assert documented_options(clips_assist.Session.open_domain) == list(OPTIONS)
    opened = [lambda **kw: clips_assist.Session.open_dataset(str(WORKSHOP), "1", **kw),
              lambda **kw: clips_assist.Session.open_domain(str(WORKSHOP), str(WORKSHOP / "problems" / "1.pddl"), **kw)]
    for name, (_, bad) in OPTIONS.items():
        errors = []
        for open_ in opened:
            with pytest.raises((clips_assist.InputError, TypeError)) as e:
                s = open_(**{name: bad}, particles=8) if name not in ("particles", "particle_seed") else open_(**{name: bad})
                s.observe("(move human bench rack)")
                s.hear("Can you bring the big plank?")
            errors.append((type(e.value), str(e.value)))
        assert errors[0] == errors[1], name
    for open_ in opened:
        with pytest.raises(TypeError, match="unexpected keyword argument 'colour'"):
            open_(colour="red")


def test_open_domain_options_reach_the_session():
    path = dict(domain_dir=WORKSHOP, problem_file=WORKSHOP / "problems" / "1.pddl")  # pathlib paths are fine
    good = {name: value for name, (value, _) in OPTIONS.items() if not name.startswith("lm_")}
    s = clips_assist.Session.open_domain(**path, **good)
    s.observe("(move human bench rack)")
    post = s.posterior()
    assert [g["goal"] for g in post["goals"]] == ["(made table)", "(made stool)"]  # goals
    assert [c["cost_profile"] for c in post["cost_profiles"]] == ["unit"]  # cost_profiles
    assert sum(g["p"] for g in post["goals"]) == pytest.approx(1.0)
    again = clips_assist.Session.open_domain(**path, **good)
    again.observe("(move human bench rack)")
    assert again.posterior() == post  # particles are a function of particle_seed
    d = s.assist()  # pibar: the candidates' values are the mixture of policies' probabilities
    assert d["assistant_turn"] and d["action"].startswith("(") and "robot" in d["action"]
    assert sum(c["value"] for c in d["candidates"]) == pytest.approx(1.0)
    assert all(0 <= c["value"] <= 1 for c in d["candidates"])
    # Exact inference agrees between open_dataset and open_domain on the same problem and options.
    exact = dict(goals=["(made table)", "(made stool)"], max_nodes=5000, threads=1, assistant_turns="all")
    a = clips_assist.Session.open_dataset(WORKSHOP, "1", **exact)
    b = clips_assist.Session.open_domain(**path, **exact)
    for s_ in (a, b):
        s_.observe("(move human bench rack)")
        s_.hear("Can you bring the big plank over to the bench?")
    assert a.posterior() == b.posterior()
    # None keeps an option's default.
    assert clips_assist.Session.open_domain(**path, max_nodes=None, particles=None).posterior()["goals"]


def test_open_domain_from_pddl_text_matches_the_files(tmp_path):
    files = docs_example_files()
    pack = json.loads(files["kitchen/pack.json"])
    pack.pop("fewshot")  # a pack as text has no folder beside it
    folder = tmp_path / "kitchen"
    (folder / "problems").mkdir(parents=True)
    (folder / "domain.pddl").write_text(files["kitchen/domain.pddl"])
    (folder / "pack.json").write_text(json.dumps(pack))
    (folder / "problems" / "1.pddl").write_text(files["kitchen/problems/1.pddl"])

    def play(s):
        s.observe("(take cook flour1 pantry)")
        s.hear("Can you fetch the milk?")
        return s.posterior()

    from_text = clips_assist.Session.open_domain(domain_text=files["kitchen/domain.pddl"],
                                          problem_text=files["kitchen/problems/1.pddl"], pack_text=json.dumps(pack),
                                          threads=1)
    assert from_text.domain == "kitchen"
    post = play(from_text)
    assert post == play(clips_assist.Session.open_domain(folder, folder / "problems" / "1.pddl", threads=1))
    goals = clips_assist.goal_probabilities(post)
    assert max(goals, key=goals.get) == "cake"  # flour and milk (docs/domains.md)
    # A folder without plans/ opens as a dataset too.
    assert play(clips_assist.Session.open_dataset(folder, "1", threads=1)) == post


def test_open_domain_text_errors_name_the_input():
    files = docs_example_files()
    domain, problem = files["kitchen/domain.pddl"], files["kitchen/problems/1.pddl"]
    pack = json.dumps({k: v for k, v in json.loads(files["kitchen/pack.json"]).items() if k != "fewshot"})
    with pytest.raises(clips_assist.InputError, match=r"<domain text>:1:\d+"):
        clips_assist.Session.open_domain(domain_text="(define (domain kitchen", problem_text=problem, pack_text=pack)
    with pytest.raises(clips_assist.InputError, match=r"<problem text>:\d+:\d+: .*'plank'"):
        clips_assist.Session.open_domain(domain_text=domain, pack_text=pack,
                                  problem_text="(define (problem p) (:domain kitchen) (:objects x - plank))")
    with pytest.raises(clips_assist.InputError, match="<pack text>"):
        clips_assist.Session.open_domain(domain_text=domain, problem_text=problem, pack_text="{")
    with pytest.raises(clips_assist.InputError, match="problem_text is missing"):
        clips_assist.Session.open_domain(domain_text=domain)
    with pytest.raises(clips_assist.InputError, match="not both"):
        clips_assist.Session.open_domain(str(WORKSHOP), problem_text=problem)
    with pytest.raises(clips_assist.InputError, match="domain_dir is missing"):
        clips_assist.Session.open_domain()
    with pytest.raises(TypeError, match="domain_text"):
        clips_assist.Session.open_domain(domain_text=3, problem_text=problem)


def test_the_package_under_test_is_the_expected_one():
    """pip_install_venv runs these tests against the installed package; the
    in-tree run against build/python."""
    expected = os.environ.get("CLIPS_ASSIST_EXPECTED_DIR") or str(BINARY_DIR / "python" / "clips_assist")
    assert pathlib.Path(clips_assist.__file__).resolve().parent == pathlib.Path(expected).resolve()


def test_one_method_name_table():
    """issue 44: the method keyword reads the one table (clips, lang_only, action_only,
    literal) and the older spellings (language, action, both, utterance) alike."""
    def final(method):
        s = clips_assist.Session.open_dataset(EXAMPLES, "e1", method=method)
        s.observe("(left human)")
        s.hear("Can you get me the yellow key?")
        return s.posterior()

    assert final("lang_only") == final("language") == final("utterance")
    assert final("action_only") == final("action")
    assert final("clips") == final("both")
    assert final("lang_only")["method"] == "lang_only" and final("action")["method"] == "action_only"
    # The literal listener's posterior is the CLIPS one, under its own name.
    literal = final("literal")
    assert literal["method"] == "literal"
    assert {**literal, "method": "clips"} == final("clips")
    assert final("lang_only") != final("action_only")
    with pytest.raises(clips_assist.InputError, match="lang_only"):
        clips_assist.Session.open_dataset(EXAMPLES, "e1", method="lang-only-please")


def test_a_time_limit_stops_a_call_and_leaves_the_session_unchanged():
    """issue 44: a call past its time_limit raises TimeLimitError; the session is as before it,
    and the next call gives what a session that never saw the stopped one gives."""
    s = clips_assist.Session.open_dataset(EXAMPLES, "e1")
    s.observe("(left human)")
    before = (s.t, s.posterior(), [st["posterior"] for st in s.trace()])
    assert issubclass(clips_assist.TimeLimitError, RuntimeError)
    with pytest.raises(clips_assist.TimeLimitError, match="time limit of 0 s"):
        s.observe("(wait robot)", time_limit=0)
    with pytest.raises(clips_assist.TimeLimitError):
        s.hear("Can you get me the yellow key?", time_limit=0)
    assert (s.t, s.posterior(), [st["posterior"] for st in s.trace()]) == before
    s.observe("(wait robot)", time_limit=600)
    s.observe("(left human)")
    with pytest.raises(clips_assist.TimeLimitError):
        s.assist(time_limit=0)
    reference = clips_assist.Session.open_dataset(EXAMPLES, "e1")
    for a in ["(left human)", "(wait robot)", "(left human)"]:
        reference.observe(a)
    assert s.posterior() == reference.posterior()
    assert s.assist(time_limit=600) == reference.assist()
    with pytest.raises(clips_assist.InputError, match="time_limit"):
        s.observe("(wait robot)", time_limit=-1)


def test_hear_flags_an_utterance_the_model_cannot_read():
    # As `clips infer` warns on stderr: the step says why the words counted
    # for little, and a readable instruction carries no warning.
    s = clips_assist.Session.open_dataset(str(EXAMPLES), "e1")
    s.observe("(left human)")
    s.observe("(wait robot)")
    step = s.hear("Kannst du mir den roten Schlüssel geben?")
    assert len(step["utterance_warnings"]) == 1
    assert "Kannst du mir" in step["utterance_warnings"][0]
    assert s.trace()[-1]["utterance_warnings"] == step["utterance_warnings"]
    readable = s.hear("Can you get me the yellow key?")
    assert readable["utterance_warnings"] == step["utterance_warnings"]  # the same step: only the first is flagged
