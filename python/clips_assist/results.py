"""The shapes of what a session returns, as TypedDicts.

Posteriors, steps and decisions stay plain dicts at run time (the engine's one
JSON form, the same the server and ``clips infer --json`` write: docs/api.md),
so ``step["posterior"]["goals"]`` and ``json.dumps(step)`` keep working; these
types let a type checker or an editor know every key. ``Session.observe`` is
typed ``-> Step``, ``Session.assist`` ``-> Decision`` and so on (_core.pyi).
"""
from typing import Dict, List, Optional, TypedDict

__all__ = [
    "ActionChoice",
    "BenchReport",
    "Candidate",
    "CostProfileProbability",
    "Decision",
    "GoalProbability",
    "HypothesisProbability",
    "MetricSummary",
    "PlanRun",
    "PlanStep",
    "Posterior",
    "Step",
]


class GoalProbability(TypedDict):
    goal: str
    p: float


class CostProfileProbability(TypedDict):
    cost_profile: str
    p: float


class HypothesisProbability(TypedDict):
    goal: str
    cost_profile: str
    p: float


class Posterior(TypedDict):
    """A goal posterior: per goal, per cost profile, per (goal, cost profile) hypothesis."""
    method: str  # clips, lang_only, action_only, literal
    modality: str  # both, utterance, action: the evidence it uses
    goals: List[GoalProbability]
    cost_profiles: List[CostProfileProbability]
    hypotheses: List[HypothesisProbability]
    log_marginal_likelihood: Optional[float]  # None when nothing explains the observations


class Step(TypedDict):
    """One observed action (or the start, t = 0) with what was heard after it."""
    t: int
    action: str  # "" at t = 0
    agent: str  # who acted ("" at t = 0)
    evidence: bool  # whether the action was evidence (the human's) or an intervention
    utterances: List[str]
    utterance_warnings: List[str]
    posterior: Posterior
    seconds: float


class Candidate(TypedDict):
    id: int
    action: str
    value: Optional[float]  # expected value; None for a dead end


class _DecisionBase(TypedDict):
    method: str
    assistant_turn: bool
    action: Optional[str]  # None when the human is to move
    id: int  # -1 on the human's turn
    reason: str
    unanimous: bool
    candidates: List[Candidate]
    goals: List[str]
    goal_weights: List[float]


class Decision(_DecisionBase, total=False):
    """The assistant's next action; command and command_probability for the literal listener only."""
    command: str
    command_probability: float


class ActionChoice(TypedDict):
    id: int
    action: str


class PlanStep(TypedDict):
    t: int
    action: str
    utterances: List[str]
    posterior: Dict[str, Posterior]  # by method name: clips, lang_only, action_only
    seconds: float


class PlanRun(TypedDict):
    """run_plan(): a recorded plan's posteriors, step by step."""
    plan: str
    goals: List[str]
    true_goal: Optional[str]
    cost_profiles: List[str]
    steps: List[PlanStep]
    seconds: float


class MetricSummary(TypedDict):
    mean: float
    se: float
    n: int


class BenchReport(TypedDict):
    """run_bench(): one row per plan and method (pandas.DataFrame(rows)), and the means by method and metric."""
    domain: str
    lm: str
    rows: List[Dict[str, object]]
    summary: Dict[str, Dict[str, MetricSummary]]
    wall_seconds: float
    failed_plans: int
