# SPDX-License-Identifier: GPL-3.0-or-later
"""Scene and spec text from Python dicts, so that a dict is checked by the same code as a file.

The dict is written as TOML (every value as it is: an int stays an integer, a float a float,
a bool a boolean, a list an array) and parsed by the library's strict reader; a wrong key, type
or value is then reported as it would be in a file.  ``None`` leaves a key out.
"""

import math
import numbers
import os
from collections.abc import Mapping

from ._errors import InputError


def _key(k, path):
    if not isinstance(k, str):
        raise TypeError(f"key {k!r} in {_where(path)}: keys are strings, not {type(k).__name__}")
    return _string(k)


def _where(path):
    return "'" + ".".join(path) + "'" if path else "the top level"


def _string(s):
    out = ['"']
    for ch in s:
        code = ord(ch)
        if ch == '"':
            out.append('\\"')
        elif ch == "\\":
            out.append("\\\\")
        elif code < 0x20 or code == 0x7F:
            out.append(f"\\u{code:04x}")
        elif 0xD800 <= code <= 0xDFFF:
            raise InputError(f"a string holds a lone surrogate U+{code:04X}: not text")
        else:
            out.append(ch)
    out.append('"')
    return "".join(out)


def _value(v, path):
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, numbers.Integral):
        return str(int(v))
    if isinstance(v, numbers.Real):
        x = float(v)
        if math.isnan(x):
            return "nan"
        if math.isinf(x):
            return "inf" if x > 0 else "-inf"
        return repr(x)
    if isinstance(v, (str, os.PathLike)):
        return _string(os.fspath(v) if not isinstance(v, str) else v)
    if hasattr(v, "ndim") and hasattr(v, "tolist"):  # a NumPy array (a measured profile's x1, h0)
        if v.ndim != 1:
            raise TypeError(f"{_where(path)}: an array of {v.ndim} dimensions is not a scene value "
                            "(give a one-dimensional array)")
        if getattr(v.dtype, "kind", "") == "f":
            # A float array at once (a profile of 1e6 samples): repr is _value's text for every
            # float, nan, inf and -inf included.
            return "[" + ", ".join(map(repr, v.tolist())) + "]"
        v = v.tolist()
    if isinstance(v, (list, tuple)):
        return "[" + ", ".join(_value(x, path) for x in v) + "]"
    if isinstance(v, Mapping):  # inside an array: an inline table
        return "{" + ", ".join(f"{_key(k, path)} = {_value(x, path + [k])}" for k, x in v.items() if x is not None) + "}"
    raise TypeError(f"{_where(path)}: a {type(v).__name__} is not a scene value (number, string, bool, list or dict)")


def dumps(mapping):
    """TOML text of a (nested) mapping: scalars first, then one [table] per nested mapping."""
    if not isinstance(mapping, Mapping):
        raise TypeError(f"a scene is a dict (or keyword arguments), not {type(mapping).__name__}")
    lines = []
    _table(mapping, [], lines)
    return "\n".join(lines) + "\n"


def _table(mapping, path, lines):
    scalars = []
    tables = []
    for k, v in mapping.items():
        name = _key(k, path)
        if v is None:
            continue
        (tables if isinstance(v, Mapping) else scalars).append((k, name, v))
    if path and (scalars or not tables):
        lines.append("[" + ".".join(_string(p) for p in path) + "]")
    for k, name, v in scalars:
        lines.append(f"{name} = {_value(v, path + [k])}")
    for k, _, v in tables:
        _table(v, path + [k], lines)


def loads(text):
    """The (nested) dict of scene text (str, or the bytes of a file), by Python's own TOML reader
    (the library has already checked the text: this only gives its keys back)."""
    try:
        import tomllib
    except ImportError:  # Python < 3.11
        try:
            import tomli as tomllib
        except ImportError:
            raise ImportError("a scene's keys need Python 3.11's tomllib or the package tomli") from None
    if isinstance(text, bytes):
        text = text.decode("utf-8-sig")  # a BOM, as the library allows
    return tomllib.loads(text)
