"""clips_assist as a Python package: argument checks, reprs, docstrings, stubs,
pickling, Ctrl-C, and run_plan's per-step records."""
import ast
import copy
import math
import os
import pathlib
import pickle
import signal
import socket
import threading
import time

import pytest

import clips_assist
from clips_assist import _core

ROOT = pathlib.Path(__file__).resolve().parents[2]
EXAMPLES = ROOT / "data" / "examples" / "doors-keys-gems"
GARDEN = ROOT / "data" / "datasets" / "garden"


def without_seconds(trace):
    return [{k: v for k, v in step.items() if k != "seconds"} for step in trace]


def test_observe_takes_text_or_an_id_but_not_a_bool():
    s = clips_assist.Session.open_dataset(EXAMPLES, "e1")
    for bad in (True, False, 1.0, None, b"(left human)"):
        with pytest.raises(TypeError, match="observe"):
            s.observe(bad)
    with pytest.raises(TypeError, match="hear"):
        s.hear(3)
    with pytest.raises(TypeError, match="action_name"):
        s.action_name(True)
    assert s.t == 0
    ids = {a["action"]: a["id"] for a in s.applicable_actions()}
    by_id = s.observe(ids["(left human)"])
    other = clips_assist.Session.open_dataset(EXAMPLES, "e1")
    by_text = other.observe("(left human)")
    assert by_id["action"] == "(left human)"
    assert without_seconds([by_id]) == without_seconds([by_text])
    with pytest.raises(clips_assist.InputError, match="unknown action id"):
        s.observe(10**12)


@pytest.mark.parametrize("option,value", [
    ("threads", -3), ("threads", 1025), ("threads", 10**30),
    ("max_nodes", 0), ("max_nodes", -1), ("max_nodes", 2**64),
    ("lm_timeout", -1.0), ("lm_timeout", 0.0), ("lm_timeout", math.nan), ("lm_timeout", math.inf),
    ("lm_timeout", 1e9),
    ("particles", -1), ("particles", 2**40), ("ess_threshold", math.nan), ("rejuvenation_moves", 2**31),
])
def test_numeric_options_out_of_range_or_nan_are_value_errors(option, value):
    with pytest.raises(ValueError, match=option) as e:
        clips_assist.Session.open_dataset(EXAMPLES, "e1", **{option: value})
    assert isinstance(e.value, clips_assist.InputError)


@pytest.mark.parametrize("option,value", [("threads", True), ("threads", 2.0), ("lm_timeout", "5")])
def test_numeric_options_of_the_wrong_type_are_type_errors(option, value):
    with pytest.raises(TypeError, match=option):
        clips_assist.Session.open_dataset(EXAMPLES, "e1", **{option: value})


def test_run_plan_and_run_bench_check_their_thread_counts():
    with pytest.raises(ValueError, match="threads"):
        clips_assist.run_plan(str(EXAMPLES), "e1.1.keys", threads=-3)
    with pytest.raises(ValueError, match="jobs"):
        clips_assist.run_bench(str(EXAMPLES), plans=["e1.1.keys"], jobs=5000)


def test_run_plan_keeps_each_steps_action_text():
    """issue 44: the action-only posterior used to overwrite steps[t]["action"]."""
    run = clips_assist.run_plan(str(EXAMPLES), "e1.1.keys")
    observed = [line.strip() for line in (EXAMPLES / "plans" / "observed" / "e1.1.keys.pddl").read_text().splitlines()
                if line.strip() and not line.strip().startswith(";")]
    assert [st["action"] for st in run["steps"]] == [""] + observed
    for st in run["steps"]:
        assert set(st["posterior"]) == {"clips", "lang_only", "action_only"}  # the method names
        for method, post in st["posterior"].items():
            assert post["method"] == method
            assert [g["goal"] for g in post["goals"]] == run["goals"]
            assert sum(g["p"] for g in post["goals"]) == pytest.approx(1.0)


def test_repr_names_the_session():
    s = clips_assist.Session.open_dataset(EXAMPLES, "e1")
    s.observe("(left human)")
    r = repr(s)
    assert r.startswith("<clips_assist.Session ") and r.endswith(">")
    assert "domain='doors-keys-gems'" in r and "problem='e1'" in r and "t=1" in r and "to move='robot'" in r
    assert repr(clips_assist.InputError("x")) == "InputError('x')"
    assert clips_assist.InputError.__module__ == "clips_assist"


def test_every_public_name_has_a_docstring_and_a_stub():
    stub = ast.parse((pathlib.Path(_core.__file__).parent / "_core.pyi").read_text())
    stub_names = {n.name for n in stub.body if isinstance(n, (ast.FunctionDef, ast.ClassDef))}
    stub_names |= {t.id for n in stub.body if isinstance(n, ast.AnnAssign) for t in [n.target]}
    session_stub = next(n for n in stub.body if isinstance(n, ast.ClassDef) and n.name == "Session")
    stub_methods = {n.name for n in session_stub.body if isinstance(n, ast.FunctionDef)}

    public = [n for n in dir(_core) if not n.startswith("__")] + ["__version__"]
    assert sorted(set(public) - stub_names) == []
    assert sorted(stub_names - set(public) - {"StrPath"}) == []
    methods = [n for n in dir(_core.Session) if not n.startswith("_")]
    assert sorted(set(methods) - stub_methods) == []
    for name in methods:
        doc = getattr(_core.Session, name).__doc__ or ""
        # pybind11 writes the signature first; the description must follow.
        assert len(doc.strip().splitlines()) > 1 or not doc.startswith(name), name
        assert doc.strip(), name
    for name in ("run_plan", "run_bench", "data_directory", "example_dataset"):
        assert len(getattr(clips_assist, name).__doc__.strip().splitlines()) > 1, name
    assert (pathlib.Path(clips_assist.__file__).parent / "py.typed").exists()
    assert clips_assist.Session.__doc__ and "pickles" in clips_assist.Session.__doc__


def played(s):
    s.observe("(left human)")
    s.observe("(wait robot)")
    s.hear("Can you get me the yellow key?")
    s.observe("(left human)")  # now the robot is to move
    return s


def test_a_session_pickles_and_copies_as_its_problem_options_and_trace(tmp_path, monkeypatch):
    s = played(clips_assist.Session.open_dataset(EXAMPLES, "e1", threads=1, assistance="pibar"))
    blob = pickle.dumps(s)
    monkeypatch.chdir(tmp_path)  # the dataset path was made absolute
    for again in (pickle.loads(blob), copy.copy(s), copy.deepcopy(s)):
        assert repr(again) == repr(s)
        assert again.posterior() == s.posterior()
        assert without_seconds(again.trace()) == without_seconds(s.trace())
        assert again.assist()["action"] == s.assist()["action"]
        # The options came along: pibar values are probabilities.
        assert sum(c["value"] for c in again.assist()["candidates"]) == pytest.approx(1.0)
        # And both go on the same way.
        action = s.assist()["action"]
        assert without_seconds([again.observe(action)]) == without_seconds([copy.copy(s).observe(action)])
    # A copy is independent.
    c = copy.copy(s)
    c.observe(s.assist()["action"])
    assert c.t == 4 and s.t == 3


def test_a_session_from_text_pickles_too():
    domain = (EXAMPLES / "domain.pddl").read_text()
    problem = (EXAMPLES / "problems" / "e1.pddl").read_text()
    s = played(clips_assist.Session.open_domain(domain_text=domain, problem_text=problem, threads=1))
    again = pickle.loads(pickle.dumps(s))
    assert "from text" in repr(again) and again.posterior() == s.posterior()


def test_a_bad_pickle_state_is_refused():
    state = clips_assist.Session.open_dataset(EXAMPLES, "e1").__getstate__()

    def load(st):  # as pickle does
        obj = clips_assist.Session.__new__(clips_assist.Session)
        obj.__setstate__(st)
        return obj

    assert load(state).t == 0
    with pytest.raises(clips_assist.InputError, match="version 1"):
        load((2,) + state[1:])
    with pytest.raises(clips_assist.InputError, match="unknown opener"):
        load(state[:1] + ("socket",) + state[2:])
    with pytest.raises(clips_assist.InapplicableActionError):
        load(state[:6] + ([("observe", "(wait robot)")],))  # the human is to move first


def interrupt_after(seconds):
    timer = threading.Timer(seconds, os.kill, args=(os.getpid(), signal.SIGINT))
    timer.start()
    return timer


class SilentServer:
    """A language-model server that holds every request unanswered until
    released, then refuses each one with HTTP 400 (not retried): a call that
    waits on it is long for as long as the test wants, whatever the machine."""

    def __init__(self):
        self.sock = socket.socket()
        self.sock.bind(("127.0.0.1", 0))
        self.sock.listen(16)
        self.sock.settimeout(0.05)
        self.url = "http://127.0.0.1:%d/v1" % self.sock.getsockname()[1]
        self.held, self.released, self.stopped = [], threading.Event(), threading.Event()
        self.thread = threading.Thread(target=self._serve, daemon=True)
        self.thread.start()

    def _refuse(self, conn):
        try:
            conn.sendall(b"HTTP/1.1 400 Bad Request\r\nContent-Length: 0\r\nConnection: close\r\n\r\n")
        except OSError:
            pass
        conn.close()

    def _serve(self):
        while not self.stopped.is_set():
            if self.released.is_set():
                while self.held:
                    self._refuse(self.held.pop())
            try:
                conn, _ = self.sock.accept()
            except socket.timeout:
                continue
            self.held.append(conn)

    def release(self):
        self.released.set()

    def close(self):
        self.release()
        time.sleep(0.1)
        self.stopped.set()
        self.thread.join()
        self.sock.close()


@pytest.fixture
def silent_lm(monkeypatch):
    server = SilentServer()
    monkeypatch.setenv("CLIPS_LM_BASE_URL", server.url)
    monkeypatch.setenv("OPENAI_API_KEY", "test-key")
    yield server
    server.close()


def test_ctrl_c_interrupts_a_long_call_and_leaves_the_session_as_it_was(silent_lm):
    s = clips_assist.Session.open_dataset(GARDEN, "1.1.plant-tulips", threads=1, lm="openai", lm_timeout=60)
    s.observe("(pickup human key1 patio)")
    s.observe("(wait robot)")
    before, trace = s.posterior(), without_seconds(s.trace())
    timer = interrupt_after(0.2)
    with pytest.raises(KeyboardInterrupt):
        s.hear("Could you bring the compost over?")  # waits on the server until released
    timer.join()
    # Raised while the call was still running: the interruption was prompt.
    assert _core._abandoned_running() >= 1
    assert s.t == 2 and s.posterior() == before and without_seconds(s.trace()) == trace
    silent_lm.release()
    _core._join_abandoned()
    assert _core._abandoned_running() == 0
    # The session goes on as one that was never interrupted.
    step = s.observe("(unlock human key1 shed patio)")
    fresh = clips_assist.Session.open_dataset(GARDEN, "1.1.plant-tulips", threads=1)
    for a in ("(pickup human key1 patio)", "(wait robot)"):
        fresh.observe(a)
    assert step["posterior"] == fresh.observe("(unlock human key1 shed patio)")["posterior"]


def test_ctrl_c_interrupts_run_plan(silent_lm):
    timer = interrupt_after(0.3)
    with pytest.raises(KeyboardInterrupt):
        clips_assist.run_plan(str(GARDEN), "1.1.plant-tulips", lm="openai", threads=1)  # its instruction waits
    timer.join()
    assert _core._abandoned_running() >= 1
    silent_lm.release()
    _core._join_abandoned()
    assert _core._abandoned_running() == 0


def test_a_live_session_draws_its_scene_as_png_bytes():
    s = clips_assist.Session.open_dataset(EXAMPLES, "e1", threads=1)
    before = s.scene_png()
    assert isinstance(before, bytes) and before.startswith(b"\x89PNG\r\n\x1a\n") and len(before) > 1000
    s.observe("(left human)")
    after = s.scene_png()
    assert after.startswith(b"\x89PNG") and after != before  # the human moved
    # A text scene has no picture.
    garden = clips_assist.Session.open_dataset(GARDEN, "1.1.plant-tulips", threads=1)
    with pytest.raises(clips_assist.InputError, match="scene is text"):
        garden.scene_png()


# ---- parity with the C++ Session: undo, reset, goal_holds, cancel (issue 44) ----

def whole_plan(plan):
    """The observed actions, then the rest of the plan to the goal."""
    return [line.strip() for part in ("observed", "completed")
            for line in (EXAMPLES / "plans" / part / f"{plan}.pddl").read_text().splitlines()
            if line.strip() and not line.strip().startswith(";")]


def test_undo_takes_back_the_humans_latest_move_or_instruction_with_what_followed():
    s = clips_assist.Session.open_dataset(EXAMPLES, "e1")
    start = (s.posterior(), without_seconds(s.trace()))
    assert s.undo() is False and s.t == 0  # nothing to take back
    s.observe("(left human)")
    s.observe("(wait robot)")
    after_two = (s.posterior(), without_seconds(s.trace()))
    s.observe("(left human)")
    after_three = (s.posterior(), without_seconds(s.trace()))
    s.hear("Can you get me the yellow key?")
    s.observe("(wait robot)")
    # The instruction goes with the robot's wait after it; the move before it stays.
    assert s.undo() is True
    assert s.t == 3 and s.active_agent == "robot"
    assert (s.posterior(), without_seconds(s.trace())) == after_three
    # Then the human's last action.
    assert s.undo() is True
    assert s.t == 2 and s.active_agent == "human"
    assert (s.posterior(), without_seconds(s.trace())) == after_two
    # The replay log follows: a copy (pickled log, replayed) is the same session.
    again = pickle.loads(pickle.dumps(s))
    assert again.t == 2 and again.posterior() == s.posterior()
    with pytest.raises(clips_assist.TimeLimitError):
        s.undo(time_limit=0)
    assert s.t == 2 and s.posterior() == after_two[0]
    # The human's first action goes with the robot's wait after it.
    assert s.undo() is True
    assert s.t == 0 and (s.posterior(), without_seconds(s.trace())) == start


def test_reset_goes_back_to_the_start():
    s = clips_assist.Session.open_dataset(EXAMPLES, "e1")
    start = (s.posterior(), without_seconds(s.trace()))
    s.observe("(left human)")
    s.hear("Can you get me the yellow key?")
    assert s.reset() is None
    assert s.t == 0 and (s.posterior(), without_seconds(s.trace())) == start
    assert pickle.loads(pickle.dumps(s)).t == 0  # the log is empty too
    s.observe("(left human)")
    assert s.t == 1


def test_goal_holds_names_a_candidate_goal():
    plan = whole_plan("e1.1.keys")
    s = clips_assist.Session.open_dataset(EXAMPLES, "e1.1.keys")
    labels = [g["goal"] for g in s.posterior()["goals"]]
    assert "gem3" in labels
    for a in plan[:-1]:
        s.observe(a)
    assert not any(s.goal_holds(g) for g in labels)
    s.observe(plan[-1])  # (pickup human gem3)
    assert [g for g in labels if s.goal_holds(g)] == ["gem3"]
    with pytest.raises(clips_assist.InputError, match="no candidate goal 'gem9'"):
        s.goal_holds("gem9")
    with pytest.raises(TypeError):
        s.goal_holds(3)


def test_cancel_from_another_thread_stops_a_long_call_and_leaves_the_session_as_it_was(silent_lm):
    s = clips_assist.Session.open_dataset(GARDEN, "1.1.plant-tulips", threads=1, lm="openai", lm_timeout=60)
    s.observe("(pickup human key1 patio)")
    s.observe("(wait robot)")
    before, trace = s.posterior(), without_seconds(s.trace())
    assert s.cancel() is False  # no call is running
    assert issubclass(clips_assist.CancelledError, RuntimeError)
    cancelled = []

    def controller():
        # Until the call is running (hear waits on the silent server), then stop it.
        deadline = time.monotonic() + 120
        while not s.cancel():
            assert time.monotonic() < deadline, "hear() never started"
            time.sleep(0.01)
        cancelled.append(True)
        silent_lm.release()  # the model's request fails now; the cancellation is what is reported

    thread = threading.Thread(target=controller)
    thread.start()
    with pytest.raises(clips_assist.CancelledError, match="cancelled"):
        s.hear("Could you bring the compost over?")
    thread.join()
    assert cancelled == [True]
    assert s.t == 2 and s.posterior() == before and without_seconds(s.trace()) == trace
    assert s.cancel() is False
    # The next call works, as on a session that never saw the cancelled one.
    step = s.observe("(unlock human key1 shed patio)")
    fresh = clips_assist.Session.open_dataset(GARDEN, "1.1.plant-tulips", threads=1)
    for a in ("(pickup human key1 patio)", "(wait robot)"):
        fresh.observe(a)
    assert step["posterior"] == fresh.observe("(unlock human key1 shed patio)")["posterior"]


def test_choices_are_the_name_tables_the_docs_list():
    """issue 63: choices() is the one catalogue; docs/cli.md's table (checked
    against the C++ tables by test_eval) and the keywords' help agree with it."""
    catalogue = clips_assist.choices()
    rows = []
    page = (ROOT / "docs" / "cli.md").read_text(encoding="utf-8")
    table = page.split("<!-- choices: begin (generated) -->\n", 1)[1].split("<!-- choices: end -->", 1)[0]
    for line in table.splitlines()[2:]:
        kind, name = (cell.strip() for cell in line.split("|")[1:3])
        rows.append((kind.strip("`"), name.split("`")[1]))
    assert rows == [(k, c["name"]) for k, cs in catalogue.items() for c in cs]
    doc = clips_assist.Session.open_dataset.__doc__
    for kind in ("method", "assistance", "assistant_turns", "rejuvenate", "particle_filters", "particle_estimate"):
        for c in catalogue[kind]:
            assert c["name"] in doc, (kind, c["name"])
    assert {c["name"] for c in catalogue["assistance"]} == {"qmdp", "pibar"}
    with pytest.raises(clips_assist.InputError, match=r"known: qmdp, pibar"):
        clips_assist.Session.open_dataset(EXAMPLES, "e1", assistance="oracle")


# The catalogue's kinds by the front end that takes them: a keyword of
# Session.open_dataset/open_domain, a part of run_bench's method names, or a
# flag of the CLI alone (docs/cli.md). A new kind must be placed here.
KEYWORD_KINDS = {"method", "assistance", "assistant_turns", "rejuvenate", "particle_filters", "particle_estimate", "lm"}
BENCH_KINDS = {"assist", "literal_method", "baseline"}
CLI_ONLY_KINDS = {"modality", "speaker_rule", "speaker_plans", "utterance_timing", "qa_floor", "assist_rule",
                  "heuristic", "bench_assist", "planner"}


def test_every_catalogue_kind_is_reachable_from_python_or_said_to_be_cli_only():
    """issue 63: each kind of choices() is reachable by its keyword (each name and
    alias is taken; a bad one is refused with the names), or by run_bench's
    method names, or is one of the CLI's own flags."""
    catalogue = clips_assist.choices()
    assert set(catalogue) == KEYWORD_KINDS | BENCH_KINDS | CLI_ONLY_KINDS
    doc = clips_assist.Session.open_dataset.__doc__
    for kind in sorted(KEYWORD_KINDS):
        assert kind + "=" in doc, kind
        for c in catalogue[kind]:
            for spelling in [c["name"]] + c["aliases"]:
                # Taken: the session fails on the missing folder, not on the name.
                with pytest.raises(clips_assist.InputError, match="dataset directory"):
                    clips_assist.Session.open_dataset("/nonexistent-clips-dataset", "1", **{kind: spelling})
        with pytest.raises(clips_assist.InputError) as bad:
            clips_assist.Session.open_dataset(EXAMPLES, "e1", **{kind: "oracle"})
        assert "oracle" in str(bad.value), kind
        for c in catalogue[kind]:
            assert c["name"] in str(bad.value), (kind, c["name"], str(bad.value))
    with pytest.raises(clips_assist.InputError) as bad:
        clips_assist.run_bench(str(EXAMPLES), methods=["oracle"])
    valid = str(bad.value).split("valid methods: ", 1)[1].split(", ")
    default, *others = [c["name"] for c in catalogue["assist"]]
    assert "clips" in valid and "clips/" + default not in valid  # the default policy leaves the name bare
    assert all("clips/" + p in valid for p in others)
    assert all(c["name"] in valid for c in catalogue["baseline"])
    assert any(c["name"] in valid for c in catalogue["literal_method"])  # the pack says which it runs


def test_a_policy_registered_in_python_decides_sessions_and_bench_episodes():
    """A decision policy is one registration, from Python too: the keyword
    assistance=, choices() (the CLI's and server's table) and run_bench's
    methods take it, and the engine calls it at the assistant's turns."""
    views = []

    def idle(view):
        views.append(view)
        return view["wait"], "this policy only waits"

    clips_assist.register_policy("py_idle", "waits, whatever it hears", idle)
    try:
        with pytest.raises(ValueError, match="already registered"):
            clips_assist.register_policy("py_idle", "again", idle)
        with pytest.raises(ValueError, match="one word"):
            clips_assist.register_policy("py/idle", "", idle)
        catalogue = clips_assist.choices()
        assert {"name": "py_idle", "help": "waits, whatever it hears", "aliases": []} in catalogue["assistance"]
        assert "py_idle" in [c["name"] for c in catalogue["assist"]]

        s = played(clips_assist.Session.open_dataset(EXAMPLES, "e1", threads=1, assistance="py_idle"))
        d = s.assist()
        view = views[-1]
        assert d["action"] == view["wait"] and d["reason"] == "this policy only waits"
        assert d["action"] in view["actions"] and len(view["actions"]) > 1
        assert sum(g["p"] for g in view["goals"]) == pytest.approx(1.0)
        # The goals as PDDL formulas, with the posterior's weights.
        assert [g["p"] for g in view["goals"]] == pytest.approx([g["p"] for g in s.posterior()["goals"]])
        assert all(g["goal"].startswith("(") for g in view["goals"])
        assert any("key" in a["command"] for a in view["asked"])  # "Can you get me the yellow key?"
        helpful = played(clips_assist.Session.open_dataset(EXAMPLES, "e1", threads=1)).assist()
        assert helpful["action"] != d["action"]  # Q_MDP moves to fetch the key

        rep = clips_assist.run_bench(str(EXAMPLES), methods=["clips", "clips/py_idle"], plans=["e1.1.keys"], jobs=1)
        rows = {r["method"]: r for r in rep["rows"]}
        assert rows["clips/py_idle"]["human_cost"] > rows["clips"]["human_cost"]  # the human did it all

        clips_assist.register_policy("py_bad", "names an action that is not there", lambda view: "(fly robot)")
        bad = played(clips_assist.Session.open_dataset(EXAMPLES, "e1", threads=1, assistance="py_bad"))
        with pytest.raises(clips_assist.InputError, match=r"'py_bad' returned '\(fly robot\)', which is not an applicable"):
            bad.assist()

        def raises(view):
            raise RuntimeError("no plan today")

        clips_assist.register_policy("py_raises", "raises", raises)
        broken = played(clips_assist.Session.open_dataset(EXAMPLES, "e1", threads=1, assistance="py_raises"))
        with pytest.raises(clips_assist.InputError, match="'py_raises' raised .*no plan today"):
            broken.assist()
        broken.observe(helpful["action"])
    finally:
        for name in ("py_idle", "py_bad", "py_raises"):
            if name in [c["name"] for c in clips_assist.choices()["assistance"]]:
                clips_assist.unregister_policy(name)
    assert "py_idle" not in [c["name"] for c in clips_assist.choices()["assistance"]]
    with pytest.raises(ValueError, match="not a policy registered with register_policy"):
        clips_assist.unregister_policy("qmdp")


def test_an_option_registered_in_python_is_a_keyword_and_what_the_policy_sees():
    """An option is one registration too: a keyword of the openers (checked
    as the built-in ones are), listed by options(), and its value (typed as
    its kind) in the view of a registered policy, in sessions and bench
    episodes alike."""
    seen = []

    def careful(view):
        seen.append(view["options"])
        return view["wait"]

    own = [o["name"] for o in clips_assist.options()]
    clips_assist.register_option("py_caution", "how sure before moving", "float", 0.8, minimum=0, maximum=1)
    clips_assist.register_option("py_mood", "a choice", "choice", "calm", choices=["calm", "eager"])
    clips_assist.register_policy("py_careful", "waits, noting its options", careful)
    try:
        # Every keyword the openers already take is refused as a name.
        for name in own:
            with pytest.raises(ValueError, match="already taken"):
                clips_assist.register_option(name, "clash", "int", 1)
        with pytest.raises(ValueError, match="from 0 to 1"):
            clips_assist.register_option("py_far", "out of range", "float", 2.0, minimum=0, maximum=1)
        with pytest.raises(ValueError, match="kind must be"):
            clips_assist.register_option("py_text", "no such kind", "text", "x")
        with pytest.raises(ValueError, match="finite"):
            clips_assist.register_option("py_nan", "a NaN bound", "float", 0.5, minimum=math.nan)
        with pytest.raises(ValueError, match="minimum is above its maximum"):
            clips_assist.register_option("py_upside", "bounds upside down", "int", 1, minimum=5, maximum=0)
        with pytest.raises(ValueError, match="a choice needs choices"):
            clips_assist.register_option("py_empty", "no choices", "choice", "a", choices=[])
        with pytest.raises(TypeError, match="default must be a number"):
            clips_assist.register_option("py_bool", "a bool default", "int", True)
        listed = {o["name"]: o for o in clips_assist.options()}
        assert listed["py_caution"]["default"] == "0.8" and listed["py_mood"]["default"] == "'calm'"
        assert "how sure before moving" in listed["py_caution"]["help"]

        s = played(clips_assist.Session.open_dataset(EXAMPLES, "e1", threads=1, assistance="py_careful",
                                                     py_caution=0.25, py_mood="eager"))
        s.assist()
        assert seen[-1] == {"py_caution": 0.25, "py_mood": "eager"}
        played(clips_assist.Session.open_dataset(EXAMPLES, "e1", threads=1, assistance="py_careful")).assist()
        assert seen[-1] == {"py_caution": 0.8, "py_mood": "calm"}  # the defaults
        with pytest.raises(ValueError, match="py_caution must be a number from 0 to 1, got 2.0"):
            clips_assist.Session.open_dataset(EXAMPLES, "e1", py_caution=2.0)
        with pytest.raises(ValueError, match="py_mood must be one of calm, eager, got 'sleepy'"):
            clips_assist.Session.open_dataset(EXAMPLES, "e1", py_mood="sleepy")

        seen.clear()
        rep = clips_assist.run_bench(str(EXAMPLES), methods=["clips/py_careful"], plans=["e1.1.keys"], jobs=1)
        assert rep["rows"] and seen and all(v == {"py_caution": 0.8, "py_mood": "calm"} for v in seen)
        # run_bench takes the engine's options as `clips bench` its flags.
        seen.clear()
        clips_assist.run_bench(str(EXAMPLES), methods=["clips/py_careful"], plans=["e1.1.keys"], jobs=1,
                               py_caution=0.3, py_mood="eager")
        assert seen and all(v == {"py_caution": 0.3, "py_mood": "eager"} for v in seen)
        with pytest.raises(ValueError, match="py_caution must be a number from 0 to 1, got 7.0"):
            clips_assist.run_bench(str(EXAMPLES), methods=["clips/py_careful"], plans=["e1.1.keys"], py_caution=7.0)
        with pytest.raises(TypeError, match="unexpected keyword argument 'threads'"):
            clips_assist.run_bench(str(EXAMPLES), plans=["e1.1.keys"], threads=1)
    finally:
        clips_assist.unregister_policy("py_careful")
        for name in ("py_caution", "py_mood"):
            clips_assist.unregister_option(name)
    assert "py_caution" not in [o["name"] for o in clips_assist.options()]
    with pytest.raises(TypeError, match="unexpected keyword argument 'py_caution'"):
        clips_assist.Session.open_dataset(EXAMPLES, "e1", py_caution=0.5)
    with pytest.raises(ValueError, match="not an option registered with register_option"):
        clips_assist.unregister_option("particles")
