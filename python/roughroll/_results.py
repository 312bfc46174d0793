# SPDX-License-Identifier: GPL-3.0-or-later
"""Result objects: a creep point with every field of ``roughroll point SCENE --json``."""

import copy
import json


class Point:
    """One creep point: the solution of the normal problem (3.19)-(3.20) and of the tangential
    problem (3.21)-(3.22) for one load Q = P1/P2, with the checks (3.3)-(3.4), Carter's values
    for smooth cylinders and an error estimate.

    Every field of the program's JSON is an attribute of the same name (``Q``, ``f``, ``c0``,
    ``xi``, ``hertz_load_ratio`` (P_H/P2), ``gamma`` (gamma_0n of (4.2)), ``n``, ``method``,
    ``seconds``, ``checks_hold``, ``checks``, ``c0_carter``, ``xi_carter``,
    ``brent_iterations``, ``rcond_normal``, ``rcond_tangential``, ``error_estimate``, ``si``
    (a physical scene's SI units, else None), ``label``, ``reference``);  ``to_dict()`` is the
    object ``roughroll point SCENE --json`` prints for the same scene and options, bit for bit
    (``seconds`` apart, a wall time).
    """

    __slots__ = ("_data",)

    def __init__(self, data):
        object.__setattr__(self, "_data", data)

    @classmethod
    def _from_json(cls, text):
        return cls(json.loads(text))

    def to_dict(self):
        """The point as the program's JSON object (a deep copy)."""
        return copy.deepcopy(self._data)

    def __getattr__(self, name):
        # Reached only when the slot and the class have no such name.  While _data is unset
        # (an object pickle or copy has allocated but not yet filled) looking it up here would
        # call __getattr__ again without end: it is simply missing then.
        if name == "_data" or (name.startswith("__") and name.endswith("__")):
            raise AttributeError(name)
        try:
            return self._data[name]
        except KeyError:
            raise AttributeError(f"a point has no field {name!r}") from None

    # A point is its JSON object: pickled, copied and deep-copied as that object (so a point
    # returned by a Dask task, a multiprocessing or joblib worker arrives equal).
    def __reduce__(self):
        return (Point, (self._data,))

    def __copy__(self):
        return Point(self._data)

    def __deepcopy__(self, memo):
        return Point(copy.deepcopy(self._data, memo))

    def __setattr__(self, name, value):
        raise AttributeError("a point is read-only")

    def __dir__(self):
        return sorted(set(super().__dir__()) | set(self._data))

    def __eq__(self, other):
        return isinstance(other, Point) and self._data == other._data

    __hash__ = None

    def __repr__(self):
        d = self._data
        label = f"{d['label']!r}, " if d.get("label") else ""
        return (f"Point({label}Q={d['Q']!r}, f={d['f']!r}, c0={d['c0']!r}, xi={d['xi']!r}, "
                f"hertz_load_ratio={d['hertz_load_ratio']!r}, method={d['method']!r}, n={d['n']!r}, "
                f"checks_hold={d['checks_hold']!r})")
