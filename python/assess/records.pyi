# Type stub of assess.records (python/assess/records.py).
import builtins
import os
from typing import Any, Dict, Optional, Sequence, Union

PathLike = Union[str, "os.PathLike[str]"]
Json = Dict[str, Any]
Strings = Union[None, str, Sequence[str]]

def list(
    *,
    mw_min: Optional[float] = ...,
    mw_max: Optional[float] = ...,
    r_min: Optional[float] = ...,
    r_max: Optional[float] = ...,
    site_class: Strings = ...,
    country: Strings = ...,
    all: bool = ...,
    catalogue: Optional[PathLike] = ...,
) -> builtins.list[Json]: ...
def select(
    site: Json,
    limit_state: str = ...,
    *,
    count: int = ...,
    t_min: float = ...,
    t_max: float = ...,
    max_scale: float = ...,
    max_mean_scale: float = ...,
    max_pga_ratio: float = ...,
    max_misfit: float = ...,
    per_event: int = ...,
    per_station: int = ...,
    near_fault: str = ...,
    near_fault_km: float = ...,
    mw_min: Optional[float] = ...,
    mw_max: Optional[float] = ...,
    r_min: Optional[float] = ...,
    r_max: Optional[float] = ...,
    site_class: Strings = ...,
    country: Strings = ...,
    relax: bool = ...,
    catalogue: Optional[PathLike] = ...,
) -> Json: ...
def read(path: PathLike, dt: Optional[float] = ..., unit: Optional[str] = ...) -> Json: ...
