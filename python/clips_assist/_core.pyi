"""Type stubs of clips_assist._core (python/core_module.cpp)."""
import os
from typing import Any, Optional, Sequence, Union

__version__: str

StrPath = Union[str, "os.PathLike[str]"]

class InputError(ValueError): ...
class InapplicableActionError(InputError): ...
class LanguageModelError(RuntimeError): ...
class TimeLimitError(RuntimeError): ...
class MemoryLimitError(MemoryError): ...

class Session:
    @staticmethod
    def open_dataset(
        dataset: StrPath,
        problem: str,
        *,
        method: Optional[str] = ...,
        assistance: Optional[str] = ...,
        lm: Optional[str] = ...,
        lm_base_url: Optional[str] = ...,
        lm_model: Optional[str] = ...,
        lm_timeout: Optional[float] = ...,
        goals: Optional[Sequence[str]] = ...,
        cost_profiles: Optional[Sequence[str]] = ...,
        max_nodes: Optional[int] = ...,
        threads: Optional[int] = ...,
        particles: Optional[int] = ...,
        particle_seed: Optional[int] = ...,
        ess_threshold: Optional[float] = ...,
        rejuvenation_moves: Optional[int] = ...,
        rejuvenate: Optional[str] = ...,
        proposal_groups: Optional[int] = ...,
        particle_filters: Optional[str] = ...,
        particle_estimate: Optional[str] = ...,
        assistant_turns: Optional[str] = ...,
    ) -> Session: ...
    @staticmethod
    def open_domain(
        domain_dir: Optional[StrPath] = ...,
        problem_file: Optional[StrPath] = ...,
        *,
        domain_text: Optional[str] = ...,
        problem_text: Optional[str] = ...,
        pack_text: Optional[str] = ...,
        method: Optional[str] = ...,
        assistance: Optional[str] = ...,
        lm: Optional[str] = ...,
        lm_base_url: Optional[str] = ...,
        lm_model: Optional[str] = ...,
        lm_timeout: Optional[float] = ...,
        goals: Optional[Sequence[str]] = ...,
        cost_profiles: Optional[Sequence[str]] = ...,
        max_nodes: Optional[int] = ...,
        threads: Optional[int] = ...,
        particles: Optional[int] = ...,
        particle_seed: Optional[int] = ...,
        ess_threshold: Optional[float] = ...,
        rejuvenation_moves: Optional[int] = ...,
        rejuvenate: Optional[str] = ...,
        proposal_groups: Optional[int] = ...,
        particle_filters: Optional[str] = ...,
        particle_estimate: Optional[str] = ...,
        assistant_turns: Optional[str] = ...,
    ) -> Session: ...
    def observe(self, action: Union[str, int], *, time_limit: Optional[float] = None) -> dict[str, Any]: ...
    def hear(self, utterance: str, *, time_limit: Optional[float] = None) -> dict[str, Any]: ...
    def posterior(self, method: Optional[str] = None) -> dict[str, Any]: ...
    def assist(self, *, time_limit: Optional[float] = None) -> dict[str, Any]: ...
    def state(self) -> str: ...
    def scene_png(self) -> bytes: ...
    def trace(self) -> list[dict[str, Any]]: ...
    @property
    def t(self) -> int: ...
    @property
    def domain(self) -> str: ...
    @property
    def active_agent(self) -> str: ...
    @property
    def assistant_turn(self) -> bool: ...
    def applicable_actions(self) -> list[dict[str, Any]]: ...
    def action_name(self, action_id: int) -> str: ...
    def __getstate__(self) -> tuple[Any, ...]: ...
    def __setstate__(self, state: tuple[Any, ...]) -> None: ...

def run_plan(dataset: str, plan: str, *, lm: str = "embedded", threads: int = 0) -> dict[str, Any]: ...
def run_bench(
    dataset: str,
    *,
    methods: Sequence[str] = ...,
    plans: Sequence[str] = ...,
    jobs: int = 0,
    seed: int = 1,
    lm: str = "embedded",
) -> dict[str, Any]: ...
def data_directory() -> str: ...
def _join_abandoned() -> None: ...
def _abandoned_running() -> int: ...
