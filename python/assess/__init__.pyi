# Type stub of the package assess (python/assess/__init__.py): signatures and
# return types; units in the docstrings (docs/user/python.md).
import os
from typing import Any, Dict, List, Optional, Sequence, Union

import numpy as np
import numpy.typing as npt

from . import records as records

__version__: str

PathLike = Union[str, "os.PathLike[str]"]
Json = Dict[str, Any]

class InputError(ValueError):
    """Bad input: the command line's message; ``file`` and ``path`` (JSON path) when it names them."""
    message: str
    file: Optional[str]
    path: Optional[str]

class AssessWarning(UserWarning): ...

def run(case: Union[PathLike, Json], *, keep_going: bool = ..., fragility: Optional[PathLike] = ...) -> Json: ...
def kinematic(case: Union[PathLike, Json]) -> Json: ...
def spectrum(
    site: Json,
    limit_state: Optional[str] = ...,
    periods: Optional[Sequence[float]] = ...,
    *,
    tr: Optional[float] = ...,
    damping: float = ...,
    q: Optional[float] = ...,
) -> Json: ...
def rocking(
    model: str,
    thickness: float,
    height: float,
    unit_weight: float,
    record: Union[PathLike, npt.ArrayLike],
    dt: Optional[float] = ...,
    unit: Optional[str] = ...,
    k: Optional[float] = ...,
    restitution: Union[None, str, float] = ...,
    one_sided: bool = ...,
    scale: float = ...,
    reverse: bool = ...,
    history: bool = ...,
    *,
    overturn_at: str = ...,
    stepper: str = ...,
    rtol: Optional[float] = ...,
    atol: Optional[float] = ...,
    tail: Optional[float] = ...,
    name: str = ...,
) -> Json: ...

class RockingModel:
    theta_cr: float
    theta_u: float
    theta_peak: float
    peak_moment: float
    capacity: float
    alpha: float
    weight: float
    restitution: float
    frequency_parameter: float
    def __init__(
        self,
        model: str,
        thickness: float,
        height: float,
        unit_weight: float,
        k: Optional[float] = ...,
        restitution: Union[None, str, float] = ...,
        one_sided: bool = ...,
    ) -> None: ...
    def moment(self, theta: npt.ArrayLike) -> Union[float, npt.NDArray[np.float64]]: ...
    def free(
        self,
        theta0: float,
        duration: float = ...,
        *,
        theta_dot0: float = ...,
        rtol: Optional[float] = ...,
        atol: Optional[float] = ...,
        history: bool = ...,
    ) -> Json: ...

def campaign(
    spec: Union[PathLike, Json],
    *,
    threads: Optional[int] = ...,
    out: Optional[PathLike] = ...,
    resume: bool = ...,
    limit: Optional[int] = ...,
    plots: bool = ...,
) -> Any: ...  # pandas.DataFrame when pandas imports, else a numpy structured array
def fragility(
    case: Union[PathLike, Json],
    *,
    mechanism: str = ...,
    stripes: Optional[Sequence[float]] = ...,
    ida: bool = ...,
    ida_levels: Optional[Sequence[float]] = ...,
    records: int = ...,
    bootstrap: int = ...,
    seed: int = ...,
    out: Optional[PathLike] = ...,
    threads: Optional[int] = ...,
    resume: bool = ...,
    plots: bool = ...,
) -> Json: ...
