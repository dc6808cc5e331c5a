"""The record library (spectra/records/): list it, select records for a site, read a record.

``assess.records.list(...)`` is ``assess records list --json``, ``assess.records.select(site, ...)``
is ``assess records select --json`` (the REXEL-style selection with the rules of every selection:
site class first, scale <= 3, near-fault and pulse-like records left out, misfit flagged;
docs/theory/record-selection.md), ``assess.records.read(path)`` a record file as a numpy array.
"""

import os as _os

from . import _assess

__all__ = ["list", "select", "read"]


def _strings(value):
    if value is None:
        return []
    if isinstance(value, str):
        return [value]
    return [str(v) for v in value]


def _path(value):
    return None if value is None else _os.fspath(value)


def list(*, mw_min=None, mw_max=None, r_min=None, r_max=None, site_class=None, country=None, all=False,
         catalogue=None):
    """The components of the record library: what ``assess records list --json`` prints.

    Parameters
    ----------
    mw_min, mw_max : float, optional
        Moment magnitude window (-).
    r_min, r_max : float, optional
        Distance window (km).
    site_class : str or sequence of str, optional
        Accepted site classes (A..E).
    country : str or sequence of str, optional
        Accepted countries.
    all : bool
        Every file, also those not usable for design (without filters).
    catalogue : str or os.PathLike, optional
        A catalogue.json (default the shipped spectra/records/catalogue.json).

    Returns
    -------
    list of dict
        One dict per component: id, file, event, date, Mw, station, component, distance_km,
        distance_kind, vs30_m_s, site_class and its basis, country, lowest_usable_hz, pulse,
        pulse_period_s, near_fault, pga_g (g), significant_duration_s (s), usable_for_design, note.
    """
    return _assess._records_list(_path(catalogue), mw_min, mw_max, r_min, r_max, _strings(site_class),
                                 _strings(country), bool(all))


def select(site, limit_state="SLV", *, count=7, t_min=0.15, t_max=2.0, max_scale=3.0, max_mean_scale=2.0,
           max_pga_ratio=2.5, max_misfit=0.5, per_event=3, per_station=1, near_fault="exclude", near_fault_km=10.0,
           mw_min=None, mw_max=None, r_min=None, r_max=None, site_class=None, country=None, relax=True,
           catalogue=None):
    """Records compatible with a site's elastic spectrum: what ``assess records select --json`` prints.

    Parameters
    ----------
    site : dict
        The case file's ``"site"`` block (see :func:`assess.spectrum`); its soil class is
        the default site-class filter.
    limit_state : str
        SLO, SLD, SLV (default) or SLC.
    count : int
        Number of records N (1 to 50).
    t_min, t_max : float
        Period range of the compatibility check (s).
    max_scale, max_mean_scale : float
        Largest scale factor of a record and of the set's mean (-).
    max_pga_ratio : float
        Guard: scaled PGA <= ratio * ag S (-).
    max_misfit : float
        A record's misfit flagged above it (-).
    per_event, per_station : int
        Components per event and per station.
    near_fault : str
        ``"exclude"`` (default) or ``"include"`` near-fault and pulse-like records.
    near_fault_km : float
        Distance below which a record is near-fault (km).
    mw_min, mw_max, r_min, r_max, site_class, country :
        Filters as in :func:`list`.
    relax : bool
        Widen the site classes when they give no compatible set.
    catalogue : str or os.PathLike, optional
        A catalogue.json (default the shipped one).

    Returns
    -------
    dict
        status, message, warnings, the records chosen (each with its scale, scaled_pga_g,
        deviation, rank and flags), the records rejected and why, ``periods_s`` (s),
        ``target_m_s2`` and ``mean_psa_m_s2`` (m/s^2).
    """
    for name, value in (("count", count), ("per_event", per_event), ("per_station", per_station)):
        if isinstance(value, bool) or not isinstance(value, int) or not 1 <= value <= 50:
            raise _assess.InputError("%s: expected an integer from 1 to 50, got %r" % (name, value))
    return _assess._records_select(site, limit_state, _path(catalogue), count, t_min, t_max, max_scale,
                                   max_mean_scale, max_pga_ratio, max_misfit, per_event, per_station, near_fault,
                                   near_fault_km, mw_min, mw_max, r_min, r_max, _strings(site_class),
                                   _strings(country), bool(relax))


def read(path, dt=None, unit=None):
    """One record file as a numpy array, with the readers of the command line.

    Parameters
    ----------
    path : str or os.PathLike
        PEER AT2, ESM/ITACA ASCII, .cor.acc, or a plain file with ``dt`` (one column)
        or ``unit`` (two columns: time, acceleration).
    dt : float, optional
        Time step of a plain file (s).
    unit : str, optional
        Unit of a plain file: g (default), m/s^2, cm/s^2.

    Returns
    -------
    dict
        name, format, source, event, station, component, dt (s), npts, pga_g (g) and
        ``acc``, the accelerations in m/s^2 (numpy array): ``assess.rocking(..., acc,
        dt=r["dt"], unit="m/s^2")`` analyses the same record.
    """
    return _assess._records_read(path, dt, unit or "")

