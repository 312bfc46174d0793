# SPDX-License-Identifier: GPL-3.0-or-later
"""roughroll's errors as Python exceptions.

Each carries the one-line message the command line prints after ``roughroll: error:``
(docs/robustness.md lists them, with the exception each one raises here).
"""


class Error(Exception):
    """Base of every error roughroll reports (a roughroll::error of the C++ library)."""


class InputError(Error, ValueError):
    """Bad input: a scene, a key, a value, a load, a method, a number of nodes, a spec."""


class ResolutionError(Error):
    """A case the chosen discretisation cannot resolve (it would return noise): use a finer
    n or another method, as the message says."""


class NumericalError(Error, ArithmeticError):
    """A numerical fault: a GSL status, a singular system, a non-finite result, a root search
    without a bracket."""


class RefusedPointWarning(UserWarning):
    """A point of a creep curve the method cannot answer honestly at this n (the program's
    ``roughroll: refused:`` line, exit status 3): its row has status "refused" and NaN for every
    computed number; the rest of the curve is computed."""
