# Type stubs of the package pgm, for editors and type checkers (PEP 561: py.typed beside it).
# python/tests/test_stubs.py checks that every public function and method here has the
# parameters, defaults and keyword-only marks of the code.

import math
import os
from collections.abc import Iterable, Mapping, Sequence
from typing import Any, Literal, Optional, Union

import numpy as np
import pandas as pd
from matplotlib.axes import Axes
from matplotlib.figure import Figure

__version__: str
ENGINES: tuple[str, ...]

_Path = Union[str, os.PathLike[str]]
_Names = Union[str, Sequence[str]]
_Edges = Union[str, Iterable[tuple[str, str]]]
_Assignment = Union[str, Mapping[str, Union[str, float]]]
_Evidence = Mapping[str, Union[str, int]]
_Likelihoods = Mapping[str, Sequence[float]]
_Missing = Literal["error", "drop", "available", "em"]
_MissingRule = Literal["error", "drop", "available"]
_IntervalEdges = Union[Mapping[str, Sequence[float]], _Path]

class Error(ValueError): ...

class Network:
    def __init__(self, handle: Any) -> None: ...
    @property
    def variables(self) -> list[str]: ...
    @property
    def edges(self) -> list[tuple[str, str]]: ...
    @property
    def free_parameters(self) -> int: ...
    @property
    def success(self) -> Optional[str]: ...
    @property
    def notes(self) -> list[str]: ...
    @property
    def has_counts(self) -> bool: ...
    def states(self, name: str) -> list[str]: ...
    def parents(self, name: str) -> list[str]: ...
    def interval_edges(self, name: str) -> Optional[list[float]]: ...
    def cpt(self, name: str) -> pd.DataFrame: ...
    def write(self, path: _Path) -> None: ...
    def update(self, data: pd.DataFrame, decay: float = 1.0, *, threads: int = 0) -> Network: ...
    def to_dot(self, success: Optional[_Names] = None, controllable: Optional[_Names] = None) -> str: ...
    def draw(
        self, path: Optional[_Path] = None, *, success: Optional[_Names] = None, controllable: Optional[_Names] = None
    ) -> Optional[str]: ...
    def plot_table(
        self,
        node: str,
        x: str,
        y: str,
        *,
        given: Optional[_Assignment] = None,
        average: bool = False,
        state: Optional[str] = None,
        counts: bool = False,
        path: Optional[_Path] = None,
        ax: Optional[Axes] = None,
    ) -> Figure: ...
    def to_pgmpy(self) -> Any: ...
    def _repr_html_(self) -> str: ...
    def _repr_svg_(self) -> Optional[str]: ...

class MarkovNetwork:
    memory_limit: int
    def __init__(
        self, variables: Mapping[str, Sequence[str]], factors: Sequence[tuple[Any, Any]], *, memory_limit: int = 4096
    ) -> None: ...
    @property
    def variables(self) -> list[str]: ...
    def states(self, variable: str) -> list[str]: ...
    @property
    def factors(self) -> list[tuple[tuple[str, ...], np.ndarray]]: ...
    def write(self, path: _Path) -> None: ...
    def log_partition_function(self, evidence: Optional[_Evidence] = None, engine: str = "auto") -> float: ...
    def marginals(self, evidence: Optional[_Evidence] = None, engine: str = "auto") -> dict[str, pd.Series]: ...
    def map(self, evidence: Optional[_Evidence] = None, engine: str = "auto") -> dict[str, str]: ...
    def to_pgmpy(self) -> Any: ...

class DecisionSolution:
    meu: float
    policies: dict[str, pd.DataFrame]
    local_optimum: bool
    start_expected_utility: float
    rounds: int

class InfluenceDiagram:
    def __init__(self, handle: Any) -> None: ...
    @classmethod
    def read(cls, path: _Path) -> InfluenceDiagram: ...
    @property
    def decisions(self) -> list[str]: ...
    @property
    def chance_variables(self) -> list[str]: ...
    @property
    def utilities(self) -> list[str]: ...
    def states(self, variable: str) -> list[str]: ...
    def solve(self, evidence: Optional[_Evidence] = None, limited_memory: bool = False) -> DecisionSolution: ...
    def value_of_information(
        self, variable: str, before: str, evidence: Optional[_Evidence] = None, limited_memory: bool = False
    ) -> float: ...
    def write(self, path: _Path) -> None: ...

class DynamicNetwork:
    @property
    def variables(self) -> list[str]: ...
    def states(self, variable: str) -> list[str]: ...
    @property
    def initial(self) -> Network: ...
    @property
    def transition_edges(self) -> list[tuple[str, str]]: ...
    def unroll(self, steps: int) -> Network: ...
    @property
    def has_counts(self) -> bool: ...
    def update(self, data: pd.DataFrame, decay: float = 1.0, *, threads: int = 0) -> DynamicNetwork: ...
    def filter(
        self, data: pd.DataFrame, predict: int = 0, do: Optional[Mapping[str, str]] = None
    ) -> pd.DataFrame: ...
    def smooth(self, data: pd.DataFrame, do: Optional[Mapping[str, str]] = None) -> pd.DataFrame: ...
    def most_probable_sequence(self, data: pd.DataFrame, do: Optional[Mapping[str, str]] = None) -> pd.DataFrame: ...
    def to_pgmpy(self, state_names: bool = True) -> Any: ...
    def write(self, path: _Path) -> None: ...

class InferenceEngine:
    def __init__(
        self,
        network: Union[Network, MarkovNetwork],
        engine: str = "auto",
        *,
        samples: int = 100_000,
        seed: int = 1,
        burn_in: int = 1_000,
        threads: int = 0,
    ) -> None: ...
    @property
    def name(self) -> str: ...
    @property
    def note(self) -> str: ...
    def set_evidence(self, evidence: Optional[_Evidence] = None) -> None: ...
    def set_soft_evidence(self, evidence: Optional[_Likelihoods] = None) -> None: ...
    def set_interventions(self, do: Optional[_Evidence] = None) -> None: ...
    def marginal(self, variable: str) -> pd.Series: ...
    def joint(self, variables: _Names) -> pd.Series: ...
    def marginals(self) -> dict[str, pd.Series]: ...
    def mpe(self, variables: Optional[_Names] = None) -> tuple[dict[str, str], float]: ...
    def probability_of_evidence(self) -> float: ...
    def log_probability_of_evidence(self) -> float: ...
    def log_partition_function(self) -> float: ...

def read_network(path: _Path) -> Union[Network, MarkovNetwork, DynamicNetwork]: ...
def from_pgmpy(model: Any) -> Union[Network, MarkovNetwork, DynamicNetwork]: ...
def backends() -> list[str]: ...
def fit(
    data: pd.DataFrame,
    edges: _Edges,
    estimator: Literal["mle", "bayes"] = "mle",
    prior: str = "bdeu",
    ess: float = 1.0,
    prior_model: Optional[Network] = None,
    strategy: Optional[str] = None,
    map: Optional[str] = None,
    w_prior: Union[float, Literal["auto"], None] = None,
    *,
    alpha: float = 1.0,
    intervals: Optional[_IntervalEdges] = None,
    empty: str = "uniform",
    success: Optional[str] = None,
    match: Optional[str] = None,
    threads: int = 0,
    missing: _Missing = "error",
    latent: Optional[Mapping[str, Union[int, Sequence[str]]]] = None,
    restarts: int = 1,
    seed: int = 0,
    max_iterations: int = 100,
    tolerance: float = 1e-6,
    hard: bool = False,
    keep_counts: bool = False,
    states: Optional[Mapping[str, Sequence[Union[str, int]]]] = None,
) -> Network: ...
def fit_dynamic(
    data: pd.DataFrame,
    edges: Optional[_Edges] = None,
    estimator: Literal["mle", "bayes"] = "mle",
    prior: str = "bdeu",
    ess: float = 1.0,
    prior_model: Optional[Network] = None,
    strategy: Optional[str] = None,
    map: Optional[str] = None,
    w_prior: Optional[float] = None,
    *,
    model: Optional[DynamicNetwork] = None,
    alpha: float = 1.0,
    initial_map: Optional[str] = None,
    initial_strategy: Optional[str] = None,
    empty: str = "uniform",
    missing: Literal["error", "available", "em"] = "error",
    latent: Optional[Mapping[str, Union[int, Sequence[str]]]] = None,
    restarts: int = 1,
    seed: int = 0,
    max_iterations: int = 100,
    tolerance: float = 1e-6,
    keep_counts: bool = False,
    threads: int = 0,
) -> DynamicNetwork: ...
def query(
    network: Network,
    variables: _Names,
    evidence: Optional[_Evidence] = None,
    *,
    do: Optional[_Evidence] = None,
    engine: str = "auto",
    soft_evidence: Optional[_Likelihoods] = None,
) -> pd.Series: ...
def mpe(
    network: Network,
    evidence: Optional[_Evidence] = None,
    *,
    variables: Optional[_Names] = None,
    do: Optional[_Evidence] = None,
    engine: str = "auto",
    soft_evidence: Optional[_Likelihoods] = None,
) -> tuple[dict[str, str], float]: ...
def d_separated(network: Network, x: _Names, y: _Names, given: Optional[_Names] = None) -> bool: ...
def intervene(network: Network, do: _Evidence) -> Network: ...
def counterfactual(
    model: Union[Network, _Path],
    variables: _Names,
    evidence: Optional[_Evidence] = None,
    *,
    do: _Evidence,
    assume: Optional[str] = None,
) -> pd.Series: ...
def backdoor_sets(network: Network, x: _Names, y: _Names, *, limit: int = 100_000) -> tuple[list[list[str]], bool]: ...
def check(
    network: Network,
    data: pd.DataFrame,
    test: str = "chi2",
    alpha: float = 0.05,
    *,
    threads: int = 0,
) -> pd.DataFrame: ...
def predict(
    network: Network, assign: _Assignment, success: Optional[str] = None, marginalize: bool = False
) -> float: ...
def prevent(
    network: Network,
    assign: _Assignment,
    controllable: Optional[_Names] = None,
    epsilon: float = 0.8,
    success: Optional[str] = None,
    distance: str = "steps",
    marginalize: bool = False,
    *,
    reward: Optional[float] = None,
    move_cost: Optional[Mapping[str, float]] = None,
    per: str = "steps",
) -> dict[str, Any]: ...
def learn_structure(
    data: pd.DataFrame,
    test: str = "chi2",
    alpha: float = 0.01,
    tiers: Union[str, Sequence[Sequence[str]], None] = None,
    forbid: Optional[_Edges] = None,
    require: Optional[_Edges] = None,
    *,
    max_cond: int = 3,
    threads: int = 0,
    missing: _MissingRule = "error",
    algorithm: str = "pc",
    score: str = "bic",
    max_parents: float = math.inf,
    tabu: int = 10,
    max_tabu: int = 10,
    restarts: int = 0,
    perturb: int = 1,
    seed: int = 1,
    start: Union[Network, _Edges, Literal["pc"], None] = None,
    prior_model: Optional[Network] = None,
    map: Optional[str] = None,
    prior_weight: float = 5.0,
) -> list[tuple[str, str]]: ...
def score(
    network: Network,
    data: pd.DataFrame,
    score: str = "bic",
    *,
    by_node: bool = False,
    threads: int = 0,
    missing: _MissingRule = "error",
) -> Union[float, dict[str, float]]: ...
def discretize(
    data: pd.DataFrame,
    bins: int = 5,
    columns: Optional[_Names] = None,
    *,
    method: Literal["quantile", "width"] = "quantile",
    edges: Optional[_IntervalEdges] = None,
    missing: _MissingRule = "error",
) -> tuple[pd.DataFrame, dict[str, list[float]]]: ...
def simulate(
    task: str,
    rows: int,
    seed: int = 0,
    backend: str = "analytic",
    variant: Literal["sim", "reality"] = "sim",
    *,
    threads: int = 0,
    tasks_dir: Optional[_Path] = None,
    long_form: bool = False,
) -> pd.DataFrame: ...
def experiment(
    scenario: str,
    reps: Optional[int] = None,
    seed: int = 1,
    backend: str = "analytic",
    *,
    threads: int = 0,
    distance: str = "steps",
    auto: bool = True,
    tasks_dir: Optional[_Path] = None,
) -> pd.DataFrame: ...
