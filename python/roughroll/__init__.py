# SPDX-License-Identifier: GPL-3.0-or-later
"""roughroll: rolling contact of long elastic cylinders with two-parameter surface roughness.

The C++ library of the project (the consistent formulation of Pauk & Wozniak's model,
docs/formulation.md) from Python.  A scene comes from a TOML file or from a dict / keyword
arguments with the same keys and the same checks; a point, a creep curve or the tractions of a
scene are computed by the same calls as the command line, so the numbers agree bit for bit::

    import roughroll
    s = roughroll.read_scene("data/fig2a-T1.toml")
    p = s.point()                 # Q from the scene; s.point(0.2, method="product", n=96)
    p.c0, p.xi, p.hertz_load_ratio
    p.to_dict()                   # == the object of `roughroll point data/fig2a-T1.toml --json`
    c = s.curve(points=41, sweep=True)   # dict of NumPy arrays: Q, c0, xi, xi_carter, ...

Errors raise InputError (a ValueError), ResolutionError or NumericalError (an
ArithmeticError), all subclasses of roughroll.Error, with the command line's one-line message.
Solves release the GIL; solve(..., threads=k) runs many points on k threads.
"""

from __future__ import annotations

import math
import numbers
import os
import warnings
from collections import namedtuple
from collections.abc import Mapping
from typing import Any, Dict, Iterable, List, Optional, Sequence, Union

import numpy as np

from ._errors import Error, InputError, NumericalError, RefusedPointWarning, ResolutionError
from . import _roughroll as _core
from . import _toml
from ._results import Point

__all__ = [
    "Error", "InputError", "ResolutionError", "NumericalError", "RefusedPointWarning", "Point", "Scene", "read_scene", "scene",
    "point", "solve", "roughness", "carter", "Carter", "kernel", "normal_problem", "REFERENCE",
]

#: The paper roughroll implements (also the field "reference" of every JSON output).
REFERENCE = ("V. Pauk, M. Wo\u017aniak, Rolling contact of long elastic cylinders with surface roughness "
             "described by a two parameter model (roughroll solves its corrected formulation, "
             "docs/formulation.md)")

# Arguments are checked here for their types (TypeError, as Python does); every check of a
# value is the library's own (InputError with the command line's message).


def _real(x, name):
    if x is None:
        return None
    if isinstance(x, bool) or not isinstance(x, numbers.Real):
        raise TypeError(f"{name} must be a number, not {type(x).__name__}")
    return float(x)


def _integer(x, name):
    if isinstance(x, bool) or not isinstance(x, numbers.Integral):
        raise TypeError(f"{name} must be an integer, not {type(x).__name__}")
    return int(x)


def _nodes(n):
    if n is None:
        return None
    n = _integer(n, "n")
    if not -2**31 <= n < 2**31:  # beyond C++'s int: the library's message, with the number as given
        raise InputError(f"n = {n} is outside the supported range [{_core.min_nodes}, {_core.max_nodes}]")
    return n


def _method(m):
    if m is None or isinstance(m, str):
        return m
    raise TypeError(f"method must be a string ('paper', 'product', 'extrapolated' or 'one-parameter'), "
                    f"not {type(m).__name__}")


def _zones(z):
    if z is None or isinstance(z, str):
        return z
    raise TypeError(f"zones must be a string ('auto', 'single' or 'general'), not {type(z).__name__}")


def _path(path, what):
    if not isinstance(path, (str, os.PathLike)):
        raise TypeError(f"{what} must be a path (str or os.PathLike), not {type(path).__name__}")
    path = os.fspath(path)
    if isinstance(path, bytes):
        path = os.fsdecode(path)
    if "\0" in path:
        raise InputError(f"{what} {path!r} holds a NUL character")
    return path


def _numbers(values, name):
    try:
        a = np.asarray(values, dtype=float)
    except (TypeError, ValueError) as e:
        raise TypeError(f"{name} must be numbers ({e})") from None
    if a.ndim != 1:
        raise TypeError(f"{name} must be a one-dimensional sequence of numbers (got {a.ndim} dimensions)")
    return a


class Scene:
    """The inputs of one rolling contact, checked as a scene file is (README, "Scene files").

    ``Scene(mapping, **keys)``: from a dict and/or keyword arguments with the keys of the TOML
    format (``label``, ``friction``, ``Q`` or ``Q_over_f``, ``cylinder1``/``cylinder2`` with ``tangential``/
    ``normal`` tables of ``T``, ``A`` of (3.26), ``beta_d``, ``coupling``, ``solver`` with ``n``,
    ``method``; a physical scene's ``E``, ``nu`` (or ``shear_modulus``, ``poisson`` in
    ``cylinder1``/``cylinder2``), ``R1``, ``R2``, ``P2``, ``P1``, ``contact_width``, ``k``, ``t``
    of (2.10) and ``micro_geometry`` tables (2.6)-(2.14)); nested dicts are tables, ``None``
    leaves a key out; a relative ``profile_csv`` is relative to ``base_dir``.  Every key not in
    the format, every wrong type or value raises InputError naming it, as for a file.
    ``read_scene(path)`` reads a file.

    A scene is immutable and keeps the text it was read from (``to_dict()``), so it pickles,
    copies and deep-copies: unpickling parses that text again with the same checks, a relative
    ``profile_csv`` being read from the same absolute folder (``base_dir``), which must exist
    where the scene is unpickled (a Dask worker on the same machine or a shared file system).
    ``replace(**keys)`` varies a scene; two scenes are equal when their keys
    (``to_dict()``) and ``base_dir`` are.
    """

    __slots__ = ("_core", "_source", "_text", "_base_dir", "_hash")

    def __init__(self, mapping=None, /, *, base_dir=".", **keys):
        data = {}
        if mapping is not None:
            if not isinstance(mapping, Mapping):
                raise TypeError(f"a scene is a dict (or keyword arguments), not {type(mapping).__name__}")
            data.update(mapping)
        data.update(keys)
        base_dir = _path(base_dir, "base_dir")
        text = _toml.dumps(data)
        self._set(_core._Scene.parse(text, "scene", base_dir), "scene", text, base_dir)

    def _set(self, core, source, text, base_dir):
        self._core = core
        self._source = source
        self._text = text
        # Absolute, so that a scene unpickled in another working folder reads the same files.
        self._base_dir = os.path.abspath(base_dir or ".")
        self._hash = None

    @classmethod
    def _wrap(cls, core, source, text, base_dir):
        s = cls.__new__(cls)
        s._set(core, source, text, base_dir)
        return s

    @classmethod
    def from_toml(cls, text, source="scene", base_dir="."):
        """A scene from TOML text (the scene file format).

        Parameters
        ----------
        text : str
            The scene, as a scene file holds it.
        source : str
            Names the scene in error messages.
        base_dir : str or os.PathLike
            The folder a relative ``profile_csv`` is relative to.

        Returns
        -------
        Scene
        """
        if not isinstance(text, str):
            raise TypeError(f"text must be a str, not {type(text).__name__}")
        if not isinstance(source, str):
            raise TypeError(f"source must be a str, not {type(source).__name__}")
        base_dir = _path(base_dir, "base_dir")
        return cls._wrap(_core._Scene.parse(text, source, base_dir), source, text, base_dir)

    # What the scene says (after its checks).
    label = property(lambda self: self._core.label, doc="The scene's label ('' when none).")
    friction = property(lambda self: self._core.friction, doc="The friction coefficient f.")
    Q = property(lambda self: self._core.Q,
                 doc="The scene's load Q = P1/P2 (P1/P2 of a physical scene, (Q/f) f of Q_over_f), or None.")
    Q_over_f = property(lambda self: self._core.Q_over_f,
                        doc="The scene's load as Q/f (as given by the key Q_over_f, else Q/f), or None.")
    n = property(lambda self: self._core.n, doc="The Gauss-Chebyshev nodes (4.6) the scene's method uses "
                                                "(without solver.n: the method's default, the ladder's first rung).")
    tolerance = property(lambda self: self._core.tolerance,
                         doc="The relative tolerance with which n is chosen (solver.tolerance, default 1e-4); "
                             "None when the scene gives n.")
    method = property(lambda self: self._core.method, doc="The scene's method.")
    roughness = property(lambda self: self._core.roughness,
                         doc="T, A of (3.26) per cylinder and direction (None: smooth); for a physical "
                             "scene at Hertz's half-width a_H(P2), before the width for the load is found.")
    physical = property(lambda self: self._core.physical,
                        doc="A physical scene's E, nu, R1, R2, P2, P1, width rule, a_H and k, t of (2.10); "
                            "None for a dimensionless scene.")
    beta_d = property(lambda self: self._core.beta_d,
                      doc="Dundurs' beta_D (docs/formulation.md 8(a)): 0 for similar rollers.")
    coupling = property(lambda self: self._core.coupling,
                        doc="The coupling of dissimilar rollers: 'johnson' or 'full' (docs/formulation.md 8(e)).")
    source = property(lambda self: self._source, doc="The name of the scene in messages (a file's path, or 'scene').")
    base_dir = property(lambda self: self._base_dir,
                        doc="The absolute folder a relative profile_csv is relative to (a file's own folder).")

    def to_dict(self) -> Dict[str, Any]:
        """The scene's keys as a (nested) dict, as its file or dict gave them.

        Returns
        -------
        dict
            The keys of the scene file (tables as dicts), without the defaults the checks fill
            in; ``Scene(s.to_dict(), base_dir=s.base_dir)`` is a scene equal to ``s``.  A
            relative ``profile_csv`` stays relative (to ``base_dir``).
        """
        return _toml.loads(self._text)

    def replace(self, **keys) -> "Scene":
        """A new scene: this one with ``keys`` replaced (the scene as a template).

        Parameters
        ----------
        **keys
            Keys of the scene format.  A dict replaces inside a table, key by key
            (``solver={"n": 96}`` keeps the method), ``None`` removes a key or a table
            (``cylinder1=None``: a smooth roller 1).  For example
            ``read_scene("data/steel-rollers.toml").replace(P2=2e5, P1=None, Q=0.1)``.

        Returns
        -------
        Scene
            Checked as a file is (InputError naming a wrong key or value).  Its ``base_dir``
            is this scene's: a relative ``profile_csv`` still names a file beside the original
            scene file.
        """
        data = _merged(self.to_dict(), keys)
        source = self._source if not keys else f"{self._source} (with {', '.join(keys)} replaced)"
        return Scene.from_toml(_toml.dumps(data), source, self._base_dir)

    def __reduce__(self):
        # The text and its folder, parsed again on unpickling: the same checks, the same scene.
        return (_scene_from_source, (self._text, self._source, self._base_dir))

    # Immutable: a copy is the scene itself (as for a tuple of numbers).
    def __copy__(self):
        return self

    def __deepcopy__(self, memo):
        return self

    def __eq__(self, other):
        if not isinstance(other, Scene):
            return NotImplemented
        if self._base_dir != other._base_dir:
            return False
        return self._text == other._text or self.to_dict() == other.to_dict()

    def __hash__(self):
        if self._hash is None:
            self._hash = hash((_frozen(self.to_dict()), self._base_dir))
        return self._hash

    def point(self, Q: Optional[float] = None, *, Q_over_f: Optional[float] = None, P1: Optional[float] = None,
              method: Optional[str] = None, n: Optional[int] = None, zones: Optional[str] = None,
              friction: Optional[float] = None, tolerance: Optional[float] = None) -> Point:
        """One creep point for the load ``Q``, as ``roughroll point``.

        The normal problem (3.19)-(3.20) gives P_H/P2 and the pressure; the tangential problem
        (3.21)-(3.22) is solved for c0 with Q(c0) of (4.5) = Q by Brent's method, giving the
        creep xi; the checks (3.3)-(3.4) are made on the solution.  A physical scene is first
        solved for the half-width a that carries P2 (docs/formulation.md 2(j)).

        Parameters
        ----------
        Q : float, optional
            The load P1/P2, |Q| <= f, as ``--Q``; default: the scene's load.
        Q_over_f : float, optional
            The load as Q/f in [-1, 1], as ``--Q-over-f`` (Q = (Q/f) f, at ``friction`` if given).
        P1 : float, optional
            The tangential load in N/m of a physical scene, |P1| <= f P2, as ``--P1``.  At most one
            of ``Q``, ``Q_over_f`` and ``P1``.
        method : {'extrapolated', 'product', 'paper', 'one-parameter'}, optional
            Overrides the scene's ``[solver] method``, as ``--method``.
        n : int, optional
            Gauss-Chebyshev nodes (4.6), over the scene's ``[solver] n``, as ``--n``.
        zones : {'auto', 'single', 'general'}, optional
            How the stick and slip zones are found (docs/formulation.md section 7), as ``--zones``.
        friction : float, optional
            Over the scene's friction coefficient, as ``--friction`` (checked as the scene's key;
            the load is then checked against it).
        tolerance : float, optional
            The relative accuracy every error estimate must meet, in (0, 1), as ``--tolerance``:
            n is chosen from the method's default up to 1000 (over the scene's ``[solver] n``
            and ``tolerance``; without n the default 1e-4); not with ``n``.

        Returns
        -------
        Point
            Its ``to_dict()`` is the program's JSON for the same scene and options.

        Raises
        ------
        InputError
            No load, |Q| > f, |Q/f| > 1, |P1| > f P2, P1 for a dimensionless scene, two loads,
            a bad method, n or zones (the program's message).
        ResolutionError, NumericalError
            A point the discretisation cannot resolve; a numerical fault.
        """
        return Point._from_json(self._core.point_json(_real(Q, "Q"), _real(Q_over_f, "Q_over_f"), _real(P1, "P1"),
                                                      _nodes(n), _method(method), _zones(zones), _real(friction, "friction"),
                                                      _real(tolerance, "tolerance")))

    def points(self, loads: Optional[Sequence[float]] = None, *, Q_over_f: Optional[Sequence[float]] = None,
               P1: Optional[Sequence[float]] = None, method: Optional[str] = None, n: Optional[int] = None,
               zones: Optional[str] = None, friction: Optional[float] = None, threads: int = 1,
               tolerance: Optional[float] = None) -> List[Point]:
        """Points for many loads, on ``threads`` threads (see ``roughroll.solve``).

        Parameters
        ----------
        loads : sequence of float
            The loads Q = P1/P2.
        Q_over_f : sequence of float
            Or the loads as Q/f (``--Q-over-f``).
        P1 : sequence of float
            Or, for a physical scene, as P1 in N/m (``--P1``).  One of ``loads``, ``Q_over_f``
            and ``P1``.
        threads : int
            Threads to solve on; -1: every core (as scipy's ``workers=-1``).
        method : {'extrapolated', 'product', 'paper', 'one-parameter'}, optional
            Overrides the scene's ``[solver] method``, as ``--method``.
        n : int, optional
            Gauss-Chebyshev nodes (4.6), over the scene's ``[solver] n``, as ``--n``.
        zones : {'auto', 'single', 'general'}, optional
            How the stick and slip zones are found (docs/formulation.md section 7), as ``--zones``.
        friction : float, optional
            Over the scene's friction coefficient, as ``--friction`` (checked as the scene's key;
            the load is then checked against it).
        tolerance : float, optional
            The relative accuracy every error estimate must meet, in (0, 1), as ``--tolerance``:
            n is chosen from the method's default up to 1000 (over the scene's ``[solver] n``
            and ``tolerance``; without n the default 1e-4); not with ``n``.

        Returns
        -------
        list of Point
            The same numbers as ``[self.point(Q) for Q in loads]``.
        """
        given = [(k, v) for k, v in (("Q", loads), ("Q_over_f", Q_over_f), ("P1", P1)) if v is not None]
        if len(given) != 1:
            raise InputError("give the loads once, as loads (Q), Q_over_f or P1")
        key, values = given[0]
        name = "loads" if key == "Q" else key
        return solve([(self, {key: x}) for x in _numbers(values, name)], threads=threads, method=method, n=n,
                     zones=zones, friction=friction, tolerance=tolerance)

    def curve(self, loads: Optional[Sequence[float]] = None, *, Q_over_f: Optional[Sequence[float]] = None,
              points: int = 51, sweep: bool = False,
              method: Optional[str] = None, n: Optional[int] = None, zones: Optional[str] = None,
              friction: Optional[float] = None, tolerance: Optional[float] = None) -> Dict[str, np.ndarray]:
        """A creep curve xi(Q) as NumPy arrays, as ``roughroll curve`` writes it.

        Parameters
        ----------
        loads : sequence of float, optional
            The loads Q of the rows; default: ``points`` loads chosen as below.
        Q_over_f : sequence of float, optional
            Or the loads as Q/f, each in [-1, 1] (Q = (Q/f) f at ``friction`` if given).
        points : int
            The rows of a curve without ``loads``.
        sweep : bool
            Sweep the curve in c0 instead of solving each load (dissimilar rollers at Johnson's
            level: the same loads, each row started from the previous row's zones).
        method : {'extrapolated', 'product', 'paper', 'one-parameter'}, optional
            Overrides the scene's ``[solver] method``, as ``--method``.
        n : int, optional
            Gauss-Chebyshev nodes (4.6), over the scene's ``[solver] n``, as ``--n``.
        zones : {'auto', 'single', 'general'}, optional
            How the stick and slip zones are found (docs/formulation.md section 7), as ``--zones``.
        friction : float, optional
            Over the scene's friction coefficient, as ``--friction`` (checked as the scene's key;
            the load is then checked against it).
        tolerance : float, optional
            The relative accuracy every error estimate must meet, in (0, 1), as ``--tolerance``:
            n is chosen from the method's default up to 1000 (over the scene's ``[solver] n``
            and ``tolerance``; without n the default 1e-4); not with ``n``.

        Returns
        -------
        dict of str to numpy.ndarray
            The columns described in the notes, one entry per row.

        Notes
        -----
        Without ``loads``: ``points`` loads Q/f = 1 - (1 - u)^2, u uniform on [0, 1], each solved
        for c0 by Brent on (4.5) (for dissimilar rollers, ``beta_d != 0``: Q uniform from -f to f,
        the curve not being odd in Q, each row the point at its load, formulation 8(j)); with ``sweep=True`` the curve is swept in c0 instead
        ((1 + c0)/2 uniform, one linear solve of (4.4)-(4.5) per point, the loads being Q(c0)); for
        dissimilar rollers at ``coupling = "johnson"`` the loads stay those of the curve and each row's
        zone search starts from the previous row's zones (the same points, 2 to 3.5 times faster;
        refused at ``coupling = "full"``).
        Keys: the CSV's columns Q, Q_over_f, c0, xi, xi_over_f, xi_carter, c0_carter (Carter's
        closed form), checks_hold, c0/xi/Q_error_estimate (NaN where the CSV is empty), zones (how many stick and
        slip zones), stick_start (formulation section 7) with stick_start_error_estimate, and zone_path ("single", "general", or
        "no-slip" where the edge layers were neglected, formulation 8(n); "" for a refused row,
        an array of str), n (the row's nodes: the ladder's
        choice without an explicit n; 0 for a refused row), for a
        physical scene P1_N_per_m, xi1, xi1_carter with P1_N_per_m_error_estimate and
        xi1_error_estimate (the row's estimates scaled, docs/formulation.md 2(j); NaN where the
        CSV is empty), and status ("ok" or "refused", an array of str).  The normal problem is solved once.

        A point the method cannot answer honestly at this n (the program's ``roughroll:
        refused:`` line and exit status 3) does not stop the curve: its row has status
        "refused", keeps only its given load (Q, Q_over_f and Carter's columns) or its given c0
        on a swept curve, has NaN for every computed number (zones 0), and a
        RefusedPointWarning with the program's line is issued.  ``c["status"] == "ok"`` selects
        the answered rows.  Bad input and numerical faults still raise, as the program exits 2.
        """
        if not isinstance(sweep, (bool, np.bool_)):
            raise TypeError(f"sweep must be True or False, not {type(sweep).__name__}")
        if loads is not None and Q_over_f is not None:
            raise InputError("give the loads once, as loads (Q) or Q_over_f")
        if loads is not None or Q_over_f is not None:
            if sweep:
                raise InputError("a curve swept in c0 chooses its own loads: give loads or sweep=True, not both")
        if loads is not None:
            loads = _numbers(loads, "loads").tolist()
        if Q_over_f is not None:
            Q_over_f = _numbers(Q_over_f, "Q_over_f").tolist()
        # Beyond C++'s int the library's own check answers (its message names no number).
        points = min(max(_integer(points, "points"), -2**31), 2**31 - 1)
        c = self._core.curve(loads, Q_over_f, points, bool(sweep), _nodes(n), _method(method), _zones(zones), _real(friction, "friction"),
                             _real(tolerance, "tolerance"))
        for line in c.pop("_refused"):
            warnings.warn(line, RefusedPointWarning, stacklevel=2)
        c["status"] = np.array(c["status"], dtype=str)
        c["zone_path"] = np.array(c["zone_path"], dtype=str)
        return c

    def traction(self, Q: Optional[float] = None, *, Q_over_f: Optional[float] = None, P1: Optional[float] = None,
                 r: Optional[Sequence[float]] = None, points: int = 401, method: Optional[str] = None,
                 n: Optional[int] = None, zones: Optional[str] = None,
                 friction: Optional[float] = None, tolerance: Optional[float] = None) -> Dict[str, Any]:
        """The tractions of one point on a grid of r = x1/a in [-1, 1], as ``roughroll traction``.

        Parameters
        ----------
        Q : float, optional
            The load P1/P2; default: the scene's load.
        Q_over_f : float, optional
            The load as Q/f in [-1, 1], as ``--Q-over-f``.
        P1 : float, optional
            The tangential load in N/m of a physical scene, as ``--P1``.  At most one of ``Q``,
            ``Q_over_f`` and ``P1``.
        r : sequence of float, optional
            The grid, each in [-1, 1]; default: ``points`` points evenly from -1 to 1.
        points : int
            The default grid's points, in [3, 100000].
        method : {'extrapolated', 'product', 'paper', 'one-parameter'}, optional
            Overrides the scene's ``[solver] method``, as ``--method``.
        n : int, optional
            Gauss-Chebyshev nodes (4.6), over the scene's ``[solver] n``, as ``--n``.
        zones : {'auto', 'single', 'general'}, optional
            How the stick and slip zones are found (docs/formulation.md section 7), as ``--zones``.
        friction : float, optional
            Over the scene's friction coefficient, as ``--friction`` (checked as the scene's key;
            the load is then checked against it).
        tolerance : float, optional
            The relative accuracy every error estimate must meet, in (0, 1), as ``--tolerance``:
            n is chosen from the method's default up to 1000 (over the scene's ``[solver] n``
            and ``tolerance``; without n the default 1e-4); not with ``n``.

        Returns
        -------
        dict
            The keys in the notes: the Point and NumPy arrays on the grid.

        Notes
        -----
        Keys: ``point`` (the Point), ``r``, ``p`` (the pressure a p2/P2 of (4.1)), ``p1`` (the
        traction a p1/P2 of (3.15)), ``slip_velocity`` (v of (3.6), 0 on the stick zone;
        NaN where not resolved: the trailing edge layer of free rolling with its layers neglected, formulation 8(n)),
        ``stick`` (start <= r < c0: the stick zone, which starts at -1 in the paper's structure), ``f_p`` (the Coulomb limit f p of (3.3)),
        ``p_hertz`` and ``p1_carter`` (smooth cylinders at the same Q and f, each on its own
        half-width: Hertz's pressure and Carter's traction, dimensionless as ``p`` and ``p1``) and
        ``c0_distribution`` (the stick zone of the distributions: level n's when extrapolating);
        for a physical scene also ``x1_m`` (r a, m), ``p2_Pa`` and ``p1_Pa`` (p P2/a, p1 P2/a,
        Pa).  The columns of ``roughroll traction``'s CSV, computed by the same code.  Default
        grid: the program's, ``points`` points from -1 to 1.
        """
        if r is None:
            points = _integer(points, "points")
            if not 3 <= points <= 100000:
                raise InputError("points must lie in [3, 100000]")
            r = [(2 * i - (points - 1)) / (points - 1) for i in range(points)]
        else:
            r = _numbers(r, "r").tolist()
        t = self._core.traction(_real(Q, "Q"), _real(Q_over_f, "Q_over_f"), _real(P1, "P1"), r, _nodes(n),
                                _method(method), _zones(zones), _real(friction, "friction"),
                                _real(tolerance, "tolerance"))
        t["point"] = Point._from_json(t["point"])
        t["f_p"] = t["point"].f * t["p"]
        return t

    def __repr__(self):
        # Everything that tells two scenes apart at a glance: a rough and a smooth scene, steel
        # and aluminium, Johnson's and full coupling print differently.
        kind = "physical " if self.physical else ""
        parts = [repr(self.label)] if self.label else []
        parts.append(f"f={self.friction!r}")
        p = self.physical
        if p is None:
            parts.append(f"Q={self.Q!r}")
            parts.append(_describe_surfaces(self.roughness, ("T", "A")))
        else:
            if p["E"] is not None:
                parts.append(f"E={p['E']!r}, nu={p['nu']!r}")
            else:
                parts.append(", ".join(f"{c}(shear_modulus={p[m]['shear_modulus']!r}, poisson={p[m]['poisson']!r})"
                                       for c, m in (("cylinder1", "material1"), ("cylinder2", "material2"))))
            parts.append(f"R1={p['R1']!r}, R2={p['R2']!r}, P2={p['P2']!r}, P1={p['P1']!r} (Q={self.Q!r})")
            parts.append(_describe_surfaces(p, ("k", "t")))
            parts.append(f"contact_width={p['contact_width']!r}")
        if self.beta_d != 0 or self.coupling != "johnson":
            parts.append(f"beta_d={self.beta_d!r}, coupling={self.coupling!r}")
        parts.append(f"method={self.method!r}, n={self.n}")
        return f"<roughroll {kind}Scene " + ", ".join(parts) + ">"


def _describe_surfaces(surfaces, names):
    """'cylinder1 tangential T=0.5 A=0.5 normal T=1 A=0.5, cylinder2 smooth' (or 'smooth')."""
    out = []
    for c in ("cylinder1", "cylinder2"):
        terms = [(d, surfaces[c][d]) for d in ("tangential", "normal") if surfaces[c][d] is not None]
        if terms:
            out.append(c + " " + " ".join(f"{d} {names[0]}={t[names[0]]!r} {names[1]}={t[names[1]]!r}" for d, t in terms))
        else:
            out.append(c + " smooth")
    return "smooth" if all(o.endswith(" smooth") for o in out) else ", ".join(out)


def _merged(data, keys):
    out = dict(data)
    for k, v in keys.items():
        if v is None:
            out.pop(k, None)
        elif isinstance(v, Mapping) and isinstance(out.get(k), Mapping):
            out[k] = _merged(out[k], v)
        else:
            out[k] = v
    return out


def _frozen(x):
    if isinstance(x, Mapping):
        return frozenset((k, _frozen(v)) for k, v in x.items())
    if isinstance(x, list):
        return tuple(_frozen(v) for v in x)
    return x


def _scene_from_source(text, source, base_dir):
    """A scene parsed from its text (how a pickled Scene is rebuilt)."""
    return Scene._wrap(_core._Scene.parse(text, source, base_dir), source, text, base_dir)


def read_scene(path: Union[str, "os.PathLike[str]"]) -> Scene:
    """The scene file at ``path`` (TOML, README "Scene files"), checked strictly.

    Parameters
    ----------
    path : str or os.PathLike
        The scene file; a relative ``profile_csv`` in it is relative to its folder.

    Returns
    -------
    Scene
        Keeping the file's text (``to_dict()``, pickling) and folder (``base_dir``).

    Raises
    ------
    InputError
        With the file's name and the problem, as the command line prints it.
    """
    path = _path(path, "scene file")
    core = _core._Scene.read(path)
    # The bytes the library has just read and checked, kept for to_dict() and pickling.
    with open(path, "rb") as f:
        text = f.read()
    return Scene._wrap(core, path, text, os.path.dirname(path))


def scene(mapping: Optional[Mapping] = None, /, *, base_dir: Union[str, "os.PathLike[str]"] = ".", **keys) -> Scene:
    """A Scene from a dict and/or keyword arguments (the keys of a scene file): ``Scene(...)``."""
    return Scene(mapping, base_dir=base_dir, **keys)


def _as_scene(s):
    if isinstance(s, Scene):
        return s
    if isinstance(s, Mapping):
        return Scene(s)
    if isinstance(s, (str, os.PathLike)):
        return read_scene(s)
    raise TypeError(f"a scene is a Scene, a dict or a path, not {type(s).__name__}")


def point(scene: Union[Scene, Mapping, str, "os.PathLike[str]"], Q: Optional[float] = None, *,
          Q_over_f: Optional[float] = None, P1: Optional[float] = None,
          method: Optional[str] = None, n: Optional[int] = None, zones: Optional[str] = None,
          friction: Optional[float] = None) -> Point:
    """One creep point of ``scene`` (a Scene, a dict of scene keys or a scene file's path):
    ``Scene.point``, the program's ``roughroll point``."""
    return _as_scene(scene).point(Q, Q_over_f=Q_over_f, P1=P1, method=method, n=n, zones=zones, friction=friction)


def solve(items: Iterable[Any], *, threads: int = 1, method: Optional[str] = None, n: Optional[int] = None,
          zones: Optional[str] = None, friction: Optional[float] = None,
          tolerance: Optional[float] = None) -> List[Point]:
    """Many creep points, on ``threads`` threads (C++ std::thread, the GIL released).

    Parameters
    ----------
    items : iterable
        Scenes (Scene, dict or path; the scene's load) or pairs (scene, Q), the load also as
        (scene, {"Q_over_f": q}) or, for a physical scene, (scene, {"P1": P1}) (N/m).
    threads : int
        Threads to solve on, at most 1024; -1 means one per core this process may run on,
        -2 one fewer, and so on (scipy's ``workers=-1``).
    method, n, zones, friction, tolerance
        As for ``Scene.point``, for every item.

    Ctrl-C stops the batch between points (the points being solved finish first) and raises
    KeyboardInterrupt; one point alone cannot be interrupted.

    Returns
    -------
    list of Point
        In the items' order, with exactly the numbers of the serial loop
        ``[point(s, Q, method=method, n=n) for s, Q in items]`` (each point is independent:
        its own contact and workspaces).

    Raises
    ------
    Error
        The first failing item's (in the items' order, after all ran), of the class the item
        alone would raise, its message starting with the item: ``items[3] (Q = 0.5, scene
        'Fig. 2a'): |Q| = 0.5 exceeds f = 0.3``.
    """
    if isinstance(threads, bool) or not isinstance(threads, numbers.Integral):
        raise TypeError(f"threads must be an integer, not {type(threads).__name__}")
    threads = int(threads)
    if threads < 0:
        cores = _cores()
        if threads + 1 + cores < 1:
            raise InputError(f"threads = {threads} leaves no thread of the {cores} cores")
        threads = min(threads + 1 + cores, 1024)
    if not 1 <= threads <= 1024:
        raise InputError(f"threads must lie in [1, 1024], or be negative (-1: every core) (got {threads})")
    jobs = []
    for item in items:
        if isinstance(item, tuple):
            if len(item) != 2:
                raise TypeError("an item is a scene or a pair (scene, Q) or (scene, {'Q_over_f': q}) or (scene, {'P1': P1})")
            s, load = item
        else:
            s, load = item, None
        jobs.append((_as_scene(s)._core, *_load(load)))
    return [Point._from_json(text) for text in _core.solve_all(jobs, int(threads), _nodes(n), _method(method), _zones(zones),
                                                               _real(friction, "friction"), _real(tolerance, "tolerance"))]


def _load(load):
    """(Q, Q_over_f, P1) of an item's load: a number Q, or a dict of one of the three keys."""
    if isinstance(load, Mapping):
        unknown = set(load) - {"Q", "Q_over_f", "P1"}
        if unknown:
            raise TypeError(f"a load is given by the key Q, Q_over_f or P1, not {sorted(map(str, unknown))}")
        return tuple(_real(load.get(k), k) for k in ("Q", "Q_over_f", "P1"))
    return (_real(load, "Q"), None, None)


def _cores():
    """The cores this process may run on (its affinity, as a container or taskset limits it)."""
    try:
        return len(os.sched_getaffinity(0))
    except (AttributeError, OSError):
        return os.cpu_count() or 1


def roughness(spec, *, base_dir="."):
    """The roughness parameters k, t, alpha of (2.11)-(2.15) of a rough layer, with the averages
    (2.9) and the quadrature's error estimates: the object ``roughroll roughness SPEC --json``
    prints.  ``spec``: a spec file's path, or a dict of its keys (lambda0, mu0, H, l, profile,
    delta, profile_csv, micro_shape, decay; docs/roughness-parameters.md), checked the same way.
    """
    import json
    if isinstance(spec, Mapping):
        return json.loads(_core.roughness_spec(_toml.dumps(spec), "spec", _path(base_dir, "base_dir")))
    return json.loads(_core.read_roughness_spec(_path(spec, "spec file")))


Carter = namedtuple("Carter", "c0 xi")


def carter(Q, f):
    """Carter's closed form for smooth cylinders (the T = 0 limit of (3.19)-(3.22)):
    (1 + c0)/2 = sqrt(1 - |Q|/f), xi = sign(Q) (2f/pi)(1 - sqrt(1 - |Q|/f)), lambda = 1.
    Scalars give Carter(c0, xi); arrays (broadcast) give arrays."""
    if np.ndim(Q) == 0 and np.ndim(f) == 0:
        return Carter(*_core.carter(_real(Q, "Q"), _real(f, "f")))
    Qa, fa = np.broadcast_arrays(_numbers(np.ravel(Q), "Q").reshape(np.shape(Q)),
                                 _numbers(np.ravel(f), "f").reshape(np.shape(f)))
    c0 = np.empty(Qa.shape)
    xi = np.empty(Qa.shape)
    for i in np.ndindex(Qa.shape):
        c0[i], xi[i] = _core.carter(float(Qa[i]), float(fa[i]))
    return Carter(c0, xi)


def _terms(terms):
    out = []
    for t in terms:
        if isinstance(t, Mapping):
            T, A = t.get("T"), t.get("A")
        else:
            T, A = t
        out.append((_real(T, "T"), _real(A, "A")))
    return out


def kernel(terms, z):
    """The kernel K*(z) = sum T exp(-A |z|) sgn z of (3.23)-(3.24) (E1, E2 corrected) at the
    points z, for terms (T, A) (or dicts with keys T, A).  T may be negative here (a difference
    K2* - K1*, or the printed sign of E2, to look at); K*(0) is returned as 0 (the kernel jumps
    there and the value is never used)."""
    return np.asarray(_core.kernel(_terms(terms), _numbers(np.atleast_1d(z), "z").tolist()))


def normal_problem(terms=(), *, n=96, method="product", r=None):
    """The normal problem (3.19)-(3.20) alone, discretised by (4.2)-(4.3) on the nodes and
    collocation points (4.6)-(4.7), for the normal kernel K2* of ``terms`` (T, A) (T may be
    negative: see kernel).  ``method``: 'product' (product integration) or 'paper' (the node sum
    of (4.2)).  Returns hertz_load_ratio (P_H/P2), gamma (gamma_0n, -> 0 by (4.8)), rcond, n,
    nodes, weights, collocation, phi (phi(eta_k) of (4.1)) and, at the points ``r``, p(r) =
    phi(r) sqrt(1 - r^2) (4.1).  No terms: Hertz's solution, P_H/P2 = 1."""
    r = [] if r is None else _numbers(np.atleast_1d(r), "r").tolist()
    if not isinstance(method, str):
        raise TypeError(f"method must be a string, not {type(method).__name__}")
    n = _nodes(n)
    d = _core.normal_problem(_terms(terms), n, method, r)
    for key in ("nodes", "weights", "collocation", "phi", "p"):
        d[key] = np.asarray(d[key])
    return d


__version__ = _core.__version__
