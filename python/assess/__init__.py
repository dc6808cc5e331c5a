"""libassess from Python: out-of-plane seismic assessment of masonry walls.

The same results as the command line ``assess``, each call a thin layer over
the C++ library (no second implementation): ``assess.run(case)`` returns the
dict that ``assess run CASE --json`` prints, ``assess.rocking(...)`` the one of
``assess rocking ... --json``, and so on. Units are those of the command line
and the case files: m, kN/m^3, g or m/s^2 as each key or argument names, s,
rad, kJ/m for energies per unit length of wall.

Functions
---------
run(case)            the façade assessment (or a whole building): site, kinematic
                     checks of NTC 2008 / 2018, dynamic rocking analysis, D/C side by side
kinematic(case)      linear and non-linear kinematic analysis and the code checks
spectrum(site, ...)  NTC 2018 elastic spectra of a site, with numpy arrays
rocking(...)         one rocking analysis of a wall under a record (path or array)
RockingModel(...)    the wall's rocking model: moment-rotation curve, capacity, free rocking
records.list(...)    the record library, filtered
records.select(...)  records compatible with a site's spectrum
records.read(path)   one record file as a numpy array
campaign(spec, ...)  a parametric study: the rows as a DataFrame (or structured array)
fragility(case, ...) fragility curves and the annual risk of overturning

Errors: bad input raises :class:`InputError` (a ``ValueError``) with the command
line's message; ``err.file`` and ``err.path`` name the file and the JSON path
when the message has them. A failure of the machine (a full disk) raises
``OSError``. Warnings of the input (plausibility) are issued as
:class:`AssessWarning`. Long calls release the GIL: threads run analyses in
parallel. See docs/user/python.md.
"""

import os as _os
import warnings as _warnings

from . import _assess
from ._assess import InputError, __version__

__all__ = [
    "__version__",
    "InputError",
    "AssessWarning",
    "run",
    "kinematic",
    "spectrum",
    "rocking",
    "RockingModel",
    "records",
    "campaign",
    "fragility",
]


class AssessWarning(UserWarning):
    """A warning of the input or of the analysis (the command line prints it as ``assess: warning: ...``)."""


def _warn(messages, stacklevel=3):
    for m in messages:
        _warnings.warn(m, AssessWarning, stacklevel=stacklevel)


def run(case, *, keep_going=False, fragility=None):
    """The façade assessment of a case: what ``assess run CASE --json`` prints.

    Parameters
    ----------
    case : str, os.PathLike or dict
        A case file (docs/user/case-file.md) or its content as a dict (relative
        record paths are then taken from the working directory). A building case
        (key ``"walls"``) gives the building's result (``assess run BUILDING --json``).
    keep_going : bool
        Go on with the readable records when some cannot be read (``--keep-going``).
    fragility : str or os.PathLike, optional
        A directory written by ``assess fragility`` (or :func:`fragility`) for this
        case (``--fragility DIR``); a case file also picks up ``CASE.fragility`` in
        the working directory, as the command line does.

    Returns
    -------
    dict
        The keys of ``assess run --json``: ``"site"``, ``"kinematic"``, ``"checks"``,
        ``"dynamic"``, ``"comparison"`` (D/C of every approach), ``"verdict"``,
        ``"safety_indices"`` and, when present, ``"ties"`` and ``"fragility"``;
        ``"assess_version"`` and ``"schema_version"``. Accelerations in g or m/s^2
        and lengths in m as each key names.

    Raises
    ------
    InputError
        Bad input: the message names the file, the JSON path, what was expected and its unit.
    """
    result, warnings = _assess._run(case, keep_going, fragility)
    _warn(warnings)
    return result


def kinematic(case):
    """The kinematic analysis of a case: what ``assess kinematic CASE --json`` prints.

    Linear and non-linear kinematic analysis of the case's mechanism (alpha0, M*,
    e*, a0* in m/s^2, d0*, du* in m, Ts in s, ...) and every code check of NTC 2008
    and NTC 2018, with the tie rods when the case has them.

    Parameters
    ----------
    case : str, os.PathLike or dict
        A single-mechanism case file or its content as a dict.
    """
    result, warnings = _assess._kinematic(case)
    _warn(warnings)
    return result


_SPECTRUM_KEYS = ("T", "Se_g", "SDe_m", "Sve_g", "Sd_g")


def _spectrum_arrays(column):
    import numpy as np

    points = column.get("spectrum")
    if isinstance(points, list):
        keys = [k for k in _SPECTRUM_KEYS if k in points[0]] if points else list(_SPECTRUM_KEYS[:4])
        column["spectrum"] = {k: np.array([p[k] for p in points], dtype=float) for k in keys}
    return column


def spectrum(site, limit_state="SLV", periods=None, *, tr=None, damping=5.0, q=None):
    """NTC 2018 elastic spectra of a site (§3.2.3): what ``assess spectrum --json`` prints.

    Parameters
    ----------
    site : dict
        The case file's ``"site"`` block: where, ``{"lat": 43.44, "lon": 12.64}``,
        ``{"comune": "L'Aquila"}``, ``{"island": "Lipari"}`` or ``{"hazard": {"SLV":
        {"ag_g": ..., "F0": ..., "Tc_star": ...}}}``, with the soil class ``"soil"``
        (A..E, required) and optionally ``"topography"`` (T1..T4), ``"h_over_H"``,
        ``"VN_years"``, ``"use_class"`` or ``"CU"`` (docs/user/case-file.md).
    limit_state : str or None
        ``"SLO"``, ``"SLD"``, ``"SLV"`` (default) or ``"SLC"``; None: all four.
    periods : sequence of float, optional
        Periods T (s, >= 0); default the command line's 13 periods from 0 to 4 s.
    tr : float, optional
        A return period (years) instead of a limit state (``limit_state=None``).
    damping : float
        Viscous damping (%, default 5).
    q : float, optional
        Behaviour factor: also the design spectrum Sd.

    Returns
    -------
    dict
        The keys of ``assess spectrum --json`` (ag_g in g, F0, Tc_star, TB, TC, TD in s,
        S, ...), with ``"spectrum"`` as a dict of numpy arrays: ``T`` (s), ``Se_g`` (g),
        ``SDe_m`` (m), ``Sve_g`` (g) and with q ``Sd_g`` (g). With ``limit_state=None``:
        ``"site"``, ``"VR"`` (years) and ``"limit_states"``, one such dict per state.
    """
    if tr is not None and limit_state == "SLV":
        limit_state = None
    result, warnings = _assess._spectrum(site, limit_state, None if periods is None else list(periods), tr,
                                         damping, q)
    _warn(warnings)
    if "limit_states" in result:
        for c in result["limit_states"]:
            _spectrum_arrays(c)
    else:
        _spectrum_arrays(result)
    return result


def rocking(model, thickness, height, unit_weight, record, dt=None, unit=None, k=None, restitution=None,
            one_sided=False, scale=1.0, reverse=False, history=False, *, overturn_at="theta_u", stepper="rk8pd",
            rtol=None, atol=None, tail=None, name="record"):
    """One rocking analysis of a wall under a record: what ``assess rocking ... --json`` prints.

    The smooth block on a no-tension Winkler foundation (Lipo & de Felice 2017, Eq. 1)
    or Housner's rigid block, two- or one-sided, integrated with GSL's rk8pd with
    exact event handling (docs/theory/rocking.md). The arguments are the command
    line's options.

    Parameters
    ----------
    model : str
        ``"smooth"`` (Winkler foundation, needs ``k``) or ``"rigid"`` (Housner).
    thickness, height : float
        Full thickness 2b and height 2h of the wall (m).
    unit_weight : float
        Unit weight (kN/m^3).
    record : str, os.PathLike or array_like
        A record file (PEER AT2, ESM/ITACA ASCII, .cor.acc; a plain file with ``dt``
        or ``unit``), or the accelerations as a one-dimensional array at time step
        ``dt`` in ``unit`` (default g).
    dt : float, optional
        Time step (s) of a plain file or of an array (required with an array).
    unit : str, optional
        ``"g"``, ``"m/s^2"`` or ``"cm/s^2"`` of a plain file or an array (default g).
    k : float, optional
        Winkler modulus (kN/m^3), smooth model only.
    restitution : str or float, optional
        A coefficient in [-1, 1], ``"housner"`` (default), ``"one-sided-theory"``
        (default with ``one_sided``) or ``"none"``.
    one_sided : bool
        One-sided rocking (a façade against its side walls).
    scale : float
        Factor on the record (-, in (0, 100]).
    reverse : bool
        Flip the record's polarity.
    history : bool
        Also return the history: numpy arrays ``t`` (s), ``theta`` (rad), ``theta_dot`` (rad/s).
    overturn_at : str
        ``"theta_u"`` (default) or ``"half_pi"``.
    stepper : str
        ``"rk8pd"`` (default), ``"rkck"`` or ``"rkf45"``.
    rtol, atol : float, optional
        Local error tolerances per step, relative (-) and absolute (rad, rad/s);
        default the library's 1e-7 and 1e-9.
    tail : float, optional
        Cap on the free motion after the record (s, default 30).
    name : str
        The array record's name in the result and in messages.

    Returns
    -------
    dict
        theta_max, theta_u, theta_cr, alpha (rad), t_theta_max, t_end (s), overturned,
        impacts, energy_demand, capacity, kinetic_energy_overturn (kJ/m), dc (-), d_max (m),
        termination, end, the record's name, npts, dt (s), pga_g (g), scale, reverse;
        with ``history=True`` also ``"t"``, ``"theta"``, ``"theta_dot"`` (numpy arrays).

    Raises
    ------
    InputError
        A bad option or record (the command line's message, naming the option or the
        file and line), or an analysis that failed (never reported as a result).
    """
    result, h = _assess._rocking(model, thickness, height, unit_weight, record, dt, unit or "", k, restitution,
                                 one_sided, scale, reverse, history, overturn_at, stepper, rtol, atol, tail, name)
    if h is not None:
        result["t"], result["theta"], result["theta_dot"] = h
    return result


class RockingModel:
    """The rocking model of a rectangular wall (seed Eq. 1; docs/theory/rocking.md).

    ``RockingModel("smooth", 0.25, 3.0, 12.06, k=1e6)`` is the wall of the seed's
    Fig. 2 on a Winkler foundation of 1e6 kN/m^3. The arguments are those of
    :func:`rocking` (thickness and height in m, unit weight and k in kN/m^3).

    Attributes
    ----------
    theta_cr : float    end of full contact W/(2 b^2 k) (rad; 0 for a rigid base)
    theta_u : float     ultimate rotation, where the restoring moment vanishes (rad)
    theta_peak : float  rotation of the peak restoring moment (rad)
    peak_moment : float peak restoring moment (kN m/m)
    capacity : float    energy capacity, the area under M(theta) up to theta_u (kJ/m)
    alpha : float       slenderness (rad)
    weight : float      weight W per unit length (kN/m)
    restitution : float coefficient of restitution e applied at each impact (-)
    frequency_parameter : float  p = sqrt(W R / I0) (rad/s)
    """

    def __init__(self, model, thickness, height, unit_weight, k=None, restitution=None, one_sided=False):
        self._m = _assess._RockingModel(model, thickness, height, unit_weight, k, restitution, one_sided)

    theta_cr = property(lambda self: self._m.theta_cr, doc="end of full contact W/(2 b^2 k) (rad; 0 for a rigid base)")
    theta_u = property(lambda self: self._m.theta_u, doc="ultimate rotation, where the restoring moment vanishes (rad)")
    theta_peak = property(lambda self: self._m.theta_peak, doc="rotation of the peak restoring moment (rad)")
    peak_moment = property(lambda self: self._m.peak_moment, doc="peak restoring moment (kN m/m)")
    capacity = property(lambda self: self._m.capacity, doc="energy capacity: area under M(theta) up to theta_u (kJ/m)")
    alpha = property(lambda self: self._m.alpha, doc="slenderness (rad)")
    weight = property(lambda self: self._m.weight, doc="weight W per unit length (kN/m)")
    restitution = property(lambda self: self._m.restitution, doc="coefficient of restitution e at each impact (-)")
    frequency_parameter = property(lambda self: self._m.frequency_parameter, doc="p = sqrt(W R / I0) (rad/s)")

    def moment(self, theta):
        """The restoring moment M(theta) of gravity and foundation about the active toe (kN m/m).

        ``theta`` (rad) a number or an array; the result has its shape.
        """
        import numpy as np

        out = self._m.moment(np.asarray(theta, dtype=float))
        return float(out) if np.ndim(theta) == 0 else out

    def free(self, theta0, duration=60.0, *, theta_dot0=0.0, rtol=None, atol=None, history=True):
        """Free rocking from theta0 (rad) and theta_dot0 (rad/s) for ``duration`` (s).

        Returns the result's dict (the keys of :func:`rocking` without ``"record"``)
        and, with ``history``, the numpy arrays ``t`` (s), ``theta`` (rad), ``theta_dot`` (rad/s).
        """
        result, h = self._m.free(theta0, duration, theta_dot0, rtol, atol, history)
        if h is not None:
            result["t"], result["theta"], result["theta_dot"] = h
        return result

    def __repr__(self):
        return "RockingModel(theta_u=%.6g rad, capacity=%.6g kJ/m)" % (self.theta_u, self.capacity)


def _read_rows(path):
    """The rows of a results CSV: a pandas DataFrame when pandas imports, else a numpy structured array."""
    try:
        import pandas as pd
    except ImportError:
        pd = None
    if pd is not None:
        return pd.read_csv(path)
    import csv

    import numpy as np

    with open(path, newline="", encoding="utf-8") as f:
        rows = list(csv.reader(f))
    header, body = rows[0], rows[1:]
    columns = []
    dtypes = []
    for i, name in enumerate(header):
        values = [r[i] for r in body]
        for kind in (int, float):
            try:
                col = [kind(v) if v != "" else (float("nan") if kind is float else None) for v in values]
                if None in col:
                    raise ValueError
                columns.append(col)
                dtypes.append((name, np.int64 if kind is int else np.float64))
                break
            except ValueError:
                continue
        else:
            columns.append(values)
            dtypes.append((name, "U%d" % max([1] + [len(v) for v in values])))
    return np.array(list(zip(*columns)) if body else [], dtype=dtypes)


def campaign(spec, *, threads=None, out=None, resume=False, limit=None, plots=False):
    """A parametric campaign of rocking analyses: what ``assess campaign SPEC --out DIR`` writes.

    Walls x records x scale factors x random realisations x restitution x models
    (docs/user/campaign.md), on ``threads`` threads, results in a deterministic order.

    Parameters
    ----------
    spec : str, os.PathLike or dict
        A campaign file or its content as a dict (relative record paths from the
        working directory, then the data directory).
    threads : int, optional
        Worker threads (default all cores).
    out : str or os.PathLike, optional
        Output directory kept after the call: results.csv, summary.json, campaign.json
        (and index.html, with plots the SVG figures); default a temporary one.
    resume : bool
        Continue the results in ``out`` after their last complete row.
    limit : int, optional
        Run only the analyses with id < limit.
    plots : bool
        Write the plots into ``out``.

    Returns
    -------
    pandas.DataFrame or numpy structured array
        One row per analysis, the columns of results.csv (their names carry the units).
    """
    if limit is not None and limit < 1:
        raise InputError("limit: expected N >= 1 (only ids < N run), got %r" % (limit,))
    if out is None:
        import tempfile

        with tempfile.TemporaryDirectory(prefix="assess-campaign-") as tmp:
            return _read_rows(_assess._campaign(spec, tmp, threads or 0, resume, limit or 0, plots))
    return _read_rows(_assess._campaign(spec, _os.fspath(out), threads or 0, resume, limit or 0, plots))


def fragility(case, *, mechanism="", stripes=None, ida=False, ida_levels=None, records=0, bootstrap=500, seed=1,
              out=None, threads=None, resume=False, plots=False):
    """Fragility curves of a case's mechanism: what ``assess fragility CASE --json`` prints.

    Multiple-stripe analysis (or IDA) with records selected from the library, lognormal
    fits (Baker 2015) with bootstrap bounds, and the annual frequency, return period and
    probability in VN of overturning on the site's hazard curve (docs/user/fragility.md).

    Parameters
    ----------
    case : str, os.PathLike or dict
        A case with a site and a dynamic section, or a building case.
    mechanism : str
        A building case's mechanism (id M1, M2, ... or its name); default the governing one.
    stripes : sequence of float, optional
        Return periods of the stripes (years, in [30, 2475]); default the nine of the hazard grid.
    ida : bool
        Incremental dynamic analysis instead of stripes.
    ida_levels : sequence of float, optional
        PGA levels of the IDA (g).
    records : int
        Records per stripe (0: the case's select/count, 7).
    bootstrap : int
        Bootstrap replicates for the bounds (0: none).
    seed : int
        Seed of the bootstrap.
    out : str or os.PathLike, optional
        Output directory (summary.json, curves.csv, stripes.csv, hazard.csv,
        report.html); default ``CASE.fragility`` in the working directory for a case
        file, a temporary one for a dict.
    threads : int, optional
        Worker threads (default all cores).

    Returns
    -------
    dict
        The summary of ``assess fragility --json`` (SI units, named in each key).
    """
    args = (mechanism, None if stripes is None else list(stripes), ida,
            None if ida_levels is None else list(ida_levels), records, bootstrap, seed)
    if out is None and isinstance(case, dict):
        import tempfile

        with tempfile.TemporaryDirectory(prefix="assess-fragility-") as tmp:
            return _assess._fragility(case, *args, tmp, threads or 0, resume, plots)
    return _assess._fragility(case, *args, out, threads or 0, resume, plots)


from . import records  # noqa: E402  (the submodule uses the names above)
