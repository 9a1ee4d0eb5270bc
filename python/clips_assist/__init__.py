"""clips-assist: goal inference from a human's actions and instructions, and assistance.

A C++ implementation of CLIPS (cooperative language-guided inverse plan search;
Zhi-Xuan et al., AAMAS 2024). Open a :class:`Session` on a PDDL problem, feed it
what the human (and the assistant) did and said, read the goal posterior and ask
for the assistant's next action::

    import clips_assist

    s = clips_assist.Session.open_dataset(clips_assist.example_dataset(), "e1")
    s.observe("(left human)")
    s.hear("Can you get me the yellow key?")
    print(clips_assist.goal_probabilities(s.posterior()), s.assist()["action"])

Posteriors, steps and decisions are the engine's JSON form as plain dicts, the
same the server and ``clips infer --json`` write (docs/api.md); their keys are
typed by the TypedDicts of :mod:`clips_assist.results` (Posterior, Step,
Decision, ...). In Jupyter a session shows its scene and goal posterior.

Long calls run without the GIL; Ctrl-C interrupts them (KeyboardInterrupt) and
leaves the session as it was. observe, hear and assist also take
time_limit=SECONDS: past it they raise TimeLimitError, and the session is as it
was before the call. Session.cancel(), from another thread, stops the running
call the same way (CancelledError).
"""
import atexit as _atexit
import os as _os

from ._core import (
    CancelledError,
    InapplicableActionError,
    InputError,
    LanguageModelError,
    Session,
    TimeLimitError,
    MemoryLimitError,
    __version__,
    choices,
    data_directory,
    options,
    register_option,
    register_policy,
    run_bench,
    run_plan,
    unregister_option,
    unregister_policy,
)
from ._core import _join_abandoned
from . import _display  # noqa: F401  (Session._repr_png_ and _repr_html_)
from .results import Decision, Posterior, Step

__all__ = [
    "CancelledError",
    "Decision",
    "InapplicableActionError",
    "InputError",
    "LanguageModelError",
    "Session",
    "TimeLimitError",
    "MemoryLimitError",
    "Posterior",
    "Step",
    "__version__",
    "choices",
    "data_directory",
    "example_dataset",
    "goal_probabilities",
    "options",
    "register_option",
    "register_policy",
    "run_bench",
    "run_plan",
    "unregister_option",
    "unregister_policy",
]

# Calls interrupted by Ctrl-C finish on their own threads; wait for them
# before the interpreter is torn down.
_atexit.register(_join_abandoned)


def example_dataset(name: str = "doors-keys-gems") -> str:
    """The folder of an example dataset installed with the data (``examples/<name>``).

    The project's own small Doors-Keys-Gems dataset: problems ``e1`` and ``e2``
    and plans ``e1.1.keys``, ``e1.2.keys``, ``e2.1.doors``, ``e2.2.keys``.
    Raises InputError when it is not there.
    """
    if not isinstance(name, str):
        raise TypeError(f"example_dataset(): expected the name as str, got {type(name).__name__}")
    root = data_directory()
    path = _os.path.join(root, "examples", name)
    if not _os.path.isfile(_os.path.join(path, "domain.pddl")):
        raise InputError(f"no example dataset '{name}' in {_os.path.join(root, 'examples')} "
                         "(set CLIPS_DATA_DIR to the installed share/clips-assist folder)")
    return path


def goal_probabilities(posterior: Posterior) -> "dict[str, float]":
    """{goal label: probability} of a posterior dict (its ``goals`` list), in the goals' order."""
    return {g["goal"]: g["p"] for g in posterior["goals"]}
