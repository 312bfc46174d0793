# SPDX-License-Identifier: GPL-3.0-or-later
"""Plots of roughroll's results on matplotlib: creep curves, tractions and slip velocities.

Each function draws on the given Axes (a new figure's when ``ax`` is None) and returns it, so
that several results can share one figure::

    import matplotlib.pyplot as plt
    import roughroll, roughroll.plot

    scene = roughroll.read_scene("data/steel-rollers-ground.toml")
    fig, (left, right) = plt.subplots(1, 2, figsize=(12, 4.5))
    roughroll.plot.creep_curve(scene.curve(points=41), ax=left)
    roughroll.plot.traction(scene.traction(), ax=right)

A physical scene (one with materials and a load in newtons) is drawn in its own units when
its SI columns are there: loads in N/mm, lengths in mm, pressures in MPa (``units="auto"``);
``units="dimensionless"`` draws the paper's variables instead.  matplotlib is imported only
when a function is called: ``import roughroll`` does not need it.
"""

import math

import numpy as np

__all__ = ["creep_curve", "traction", "slip_velocity"]

_STICK = "#dbe8f5"  # the stick zones' shade (the command line's traction plot's)
_SLIP = "#fbe3d6"


def _axes(ax):
    if ax is None:
        import matplotlib.pyplot as plt
        _, ax = plt.subplots(figsize=(8, 5))
    return ax


def _si(data, key, units):
    if units not in ("auto", "si", "dimensionless"):
        raise ValueError(f"units must be 'auto', 'si' or 'dimensionless', not {units!r}")
    if units == "si" and key not in data:
        raise ValueError(f"units='si' needs the SI columns ({key!r} and the others of a physical scene)")
    return units == "si" or (units == "auto" and key in data)


def _carter_over_f(q):
    """Carter's creep of smooth rollers over f at Q/f = q: (2/pi)(1 - sqrt(1 - |q|)), odd in q."""
    return np.sign(q) * 2.0 / math.pi * (1.0 - np.sqrt(1.0 - np.abs(q)))


def _has_label(ax, label):
    return any(line.get_label() == label for line in ax.get_lines())


def creep_curve(curve, ax=None, carter=True, *, label=None, units="auto"):
    """Draw a creep curve: xi/f against Q/f, or xi1 against P1 in N/mm for a physical scene.

    Parameters
    ----------
    curve : dict of str to numpy.ndarray
        A curve as :meth:`roughroll.Scene.curve` returns it (or the columns of the program's
        curve CSV): ``Q_over_f``, ``xi_over_f``, ``status``, and for a physical scene
        ``P1_N_per_m``, ``xi1``, ``xi1_carter``.
    ax : matplotlib.axes.Axes, optional
        Where to draw; default: a new figure.
    carter : bool
        Also draw Carter's curve of the same rollers smooth (dimensionless: the one curve
        (2/pi)(1 - sqrt(1 - Q/f)) every scene shares, drawn once per Axes; physical: the
        scene's own, dashed in its colour).
    label : str, optional
        The curve's legend entry (default "roughroll").
    units : {'auto', 'si', 'dimensionless'}
        'auto': N/mm and xi1 when the curve has the SI columns.

    Returns
    -------
    matplotlib.axes.Axes

    Notes
    -----
    Only the rows with status "ok" are drawn, the line broken where a row is refused; the
    refused rows are ticks on the load axis (at their given load), or, on a curve swept in c0
    (a refused row has no load there), a note in the corner.
    """
    ax = _axes(ax)
    si = _si(curve, "xi1", units)
    status = np.asarray(curve["status"]).astype(str)
    ok = status == "ok"
    if si:
        x = np.asarray(curve["P1_N_per_m"], dtype=float) / 1e3
        y = np.asarray(curve["xi1"], dtype=float)
    else:
        x = np.asarray(curve["Q_over_f"], dtype=float)
        y = np.asarray(curve["xi_over_f"], dtype=float)
    # In load order, refused rows as NaN: the line is broken where a row is missing.
    order = np.argsort(np.where(np.isnan(x), np.inf, x), kind="stable")
    x, y, ok = x[order], y[order], ok[order]
    y_drawn = np.where(ok, y, np.nan)
    if carter and not si:
        name = "Carter: smooth rollers"
        if not _has_label(ax, name):
            lo = -1.0 if np.nanmin(x) < 0 else 0.0
            q = np.linspace(lo, 1.0, 801)
            # Wide and light, under the curves: a curve lying on it stays visible.
            ax.plot(q, _carter_over_f(q), color="#c4c4c4", lw=6, zorder=1, label=name, solid_capstyle="butt")
    (line,) = ax.plot(x, y_drawn, marker="o", ms=3, lw=1.8, zorder=3, label=label or "roughroll")
    colour = line.get_color()
    if carter and si:
        xc = np.asarray(curve["xi1_carter"], dtype=float)[order]
        ax.plot(x, xc, ls="--", lw=1.4, color=colour, zorder=2,
                label="Carter: the same rollers smooth")  # in the curve's colour: whose is clear
    refused = ~ok
    n = int(refused.sum())
    if n:
        placed = refused & ~np.isnan(x)
        if placed.any():
            # Ticks on the load axis: data x, axes y (a made-up creep would read as a result).
            ax.plot(x[placed], np.full(placed.sum(), 0.03), ls="none", marker="|", ms=16, mew=2.5, color=colour,
                    transform=ax.get_xaxis_transform(), clip_on=False, zorder=4,
                    label=f"{int(placed.sum())} refused row{'s' if placed.sum() > 1 else ''} (ticks at their load)")
        if (refused & np.isnan(x)).any():
            k = int((refused & np.isnan(x)).sum())
            ax.text(0.99, 0.02, f"{k} refused row{'s' if k > 1 else ''} (swept in c0: no load to place them)",
                    transform=ax.transAxes, ha="right", va="bottom", color=colour)
    if si:
        ax.set_xlabel(r"$P_1$  (N/mm)")
        ax.set_ylabel(r"creep $\xi_1$")
        ax.ticklabel_format(axis="y", style="sci", scilimits=(-3, 3))
    else:
        ax.set_xlabel(r"$Q/f = P_1/(f\,P_2)$")
        ax.set_ylabel(r"$\xi/f$  (creep / friction coefficient)")
        ax.set_xlim(-1.0 if np.nanmin(x) < 0 else 0.0, 1.0)
    ax.grid(True, color="#e0e0e0")
    ax.legend(loc="upper left")
    return ax


def _zones(t):
    """The zones of a traction result as (start, end, state, direction) in r = x1/a: the point's
    own (every zone, however narrow) when it reports them, else the runs of the grid's stick flags."""
    point = t.get("point")
    data = point.to_dict() if hasattr(point, "to_dict") else (point or {})
    zones = data.get("zones") if isinstance(data, dict) else None
    if zones:
        return [(float(z["from"]), float(z["to"]), z["state"], int(z.get("direction", 0))) for z in zones]
    r = np.asarray(t["r"], dtype=float)
    stick = np.asarray(t["stick"], dtype=bool)
    out, start = [], 0
    for i in range(1, len(r) + 1):
        if i == len(r) or stick[i] != stick[start]:
            out.append((r[start], r[i - 1] if i == len(r) else 0.5 * (r[i - 1] + r[i]),
                        "stick" if stick[start] else "slip", 0))
            start = i
    if out:
        out[0] = (-1.0,) + out[0][1:]
    return out


def _shade_zones(ax, t, scale, load_sign):
    """Shades and names every zone above the frame; a zone too narrow to see at this width
    (under 2 % of the contact) is marked by a line and named by an arrow to it."""
    zones = _zones(t)
    narrow_names = []
    ax.narrow_zones_right = any(e - s < 0.04 and s + e > 0 for s, e, _, _ in zones)
    for start, end, state, direction in zones:
        a, b = start * scale, end * scale
        ax.axvspan(a, b, color=_STICK if state == "stick" else _SLIP, zorder=0, lw=0)
        name = state
        if state == "slip" and direction and load_sign and direction != load_sign:
            name = "reversed\nslip"
        if end - start < 0.04:  # 2 % of the contact's width 2
            ax.axvline(0.5 * (a + b), color="#1f4e79" if state == "stick" else "#8c2d04", lw=1.2, zorder=1)
            narrow_names.append((0.5 * (a + b), f"{name.replace(chr(10), ' ')} ({end - start:.2g} a wide)", state))
        else:
            ax.text(0.5 * (a + b), 1.01, name, transform=ax.get_xaxis_transform(), ha="center", va="bottom",
                    color="#1f4e79" if state == "stick" else "#8c2d04")
    # The narrow zones' names near the top (the curves stay below 3/4 of the height), staggered
    # downwards, on the side of the contact's centre, arrows to them.
    for k, (x, text, state) in enumerate(narrow_names):
        right = x > 0.0
        ax.annotate(text, xy=(x, 0.93 - 0.09 * k), xycoords=ax.get_xaxis_transform(),
                    xytext=(-40 if right else 40, 0), textcoords="offset points", ha="right" if right else "left",
                    va="center",
                    color="#1f4e79" if state == "stick" else "#8c2d04",
                    arrowprops=dict(arrowstyle="->", color="#404040", lw=1.0),
                    bbox=dict(boxstyle="round,pad=0.2", fc="white", ec="none", alpha=0.85), zorder=5)
    # Zone boundaries dashed.
    for start, end, _, _ in zones[1:]:
        ax.axvline(start * scale, color="#404040", ls=":", lw=1.0, zorder=1)


def _traction_units(t, units):
    si = _si(t, "x1_m", units)
    r = np.asarray(t["r"], dtype=float)
    if not si:
        return r, 1.0, 1.0, r"$r = x_1/a$", False
    x = np.asarray(t["x1_m"], dtype=float) * 1e3
    # a in mm from the grid (x1 = r a), for the zones' ends given in r.
    k = int(np.argmax(np.abs(r)))
    scale = x[k] / r[k]
    return x, scale, 1e-6, r"$x_1$  (mm)", True


def _load_sign(t):
    point = t.get("point")
    q = getattr(point, "Q", 0.0) if point is not None else 0.0
    return int(np.sign(q)) if q else 0


def traction(t, ax=None, *, units="auto"):
    """Draw the tractions of one point: p, p1, the Coulomb limits +-f p, zones shaded and named.

    Parameters
    ----------
    t : dict
        A result of :meth:`roughroll.Scene.traction` (``r``, ``p``, ``p1``, ``f_p``, ``stick``,
        ``point``; for a physical scene ``x1_m``, ``p2_Pa``, ``p1_Pa``; Hertz's and Carter's
        ``p_hertz``, ``p1_carter`` when present).
    ax : matplotlib.axes.Axes, optional
        Where to draw; default: a new figure.
    units : {'auto', 'si', 'dimensionless'}
        'auto': mm and MPa when the result has the SI columns.

    Returns
    -------
    matplotlib.axes.Axes
        The Axes of p; where p1 is small against p (f < 0.25: p1 would be a flat line on p's
        scale) p1 and +-f p are drawn on a second y axis at the right, ``ax.p1_axis``, whose
        scale is f times p's, so that p1 = f p on a slip zone still reads as p1 touching its limit.
    """
    ax = _axes(ax)
    x, scale, pressure, xlabel, si = _traction_units(t, units)
    if si:
        p = np.asarray(t["p2_Pa"], dtype=float) * pressure
        p1 = np.asarray(t["p1_Pa"], dtype=float) * pressure
        unit = "  (MPa)"
        p_name, p1_name = r"$p_2$", r"$p_1$"
    else:
        p = np.asarray(t["p"], dtype=float)
        p1 = np.asarray(t["p1"], dtype=float)
        unit = ""
        p_name, p1_name = r"$a\,p_2/P_2$", r"$a\,p_1/P_2$"
    point = t.get("point")
    f = float(getattr(point, "f", np.nan)) if point is not None else np.nan
    if not np.isfinite(f):
        f = float(np.nanmax(np.asarray(t["f_p"]) / np.where(t["p"] > 0, t["p"], np.nan)))
    sign = _load_sign(t)
    _shade_zones(ax, t, scale, sign)
    ax.axhline(0.0, color="#808080", lw=0.8, zorder=1)
    ax.plot(x, p, color="black", lw=2.2, zorder=3, label="normal pressure " + p_name)
    if "p_hertz" in t and not si:
        ax.plot(x, t["p_hertz"], color="#505050", lw=1.2, ls=":", zorder=2, label="Hertz (smooth)")
    p_top = float(np.nanmax(p))
    twin = f < 0.25
    q_ax = ax.twinx() if twin else ax
    q_ax.plot(x, f * p, color="#d62728", lw=1.2, zorder=3, label=r"limit $\pm f\,p$")
    q_ax.plot(x, -f * p, color="#d62728", lw=1.2, ls="--", zorder=3)
    q_ax.plot(x, p1, color="#1f77b4", lw=2.6, zorder=4, label="tangential traction " + p1_name)
    if "p1_carter" in t and not si:
        q_ax.plot(x, t["p1_carter"], color="#5fa2dd", lw=1.2, ls="-.", zorder=2, label="Carter (smooth)")
    # Room above the pressure for the legend and the narrow zones' names (the top quarter).
    low, top = -1.3 * f * p_top, 2.0 * p_top
    ax.set_ylim(low / f if twin else low, top)
    if twin:
        # p1's axis is f times p's: f p on the right is p on the left, drawn at the same height.
        # (The twin's background is transparent: ax's shading shows under both axes' curves.)
        q_ax.set_ylim(low, top * f)
        q_ax.set_ylabel(p1_name + r" and $\pm f\,p$" + unit + f"  (f = {f:g})", color="#1f77b4")
        q_ax.tick_params(axis="y", colors="#1f77b4")
        ax.set_ylabel(p_name + unit)
        ax.p1_axis = q_ax
    else:
        ax.set_ylabel(p_name + ",  " + p1_name + unit)
    ax.set_xlabel(xlabel)
    ax.set_xlim(x[0], x[-1])
    handles, labels = ax.get_legend_handles_labels()
    if twin:
        h2, l2 = q_ax.get_legend_handles_labels()
        handles, labels = handles + h2, labels + l2
    # On the side without narrow zones' names; on the twin when there is one (drawn over ax).
    q_ax.legend(handles, labels, loc="upper right" if not ax.narrow_zones_right and _centre_of_stick(t) < 0
                else "upper left", framealpha=0.9)
    return ax


def _centre_of_stick(t):
    c0 = t.get("c0_distribution")
    if c0 is None and t.get("point") is not None:
        c0 = getattr(t["point"], "c0", 0.0)
    return float(c0 if c0 is not None else 0.0)


def slip_velocity(t, ax=None, *, units="auto"):
    """Draw the slip velocity v of (3.6) over the contact, zones shaded and named.

    Parameters
    ----------
    t : dict
        A result of :meth:`roughroll.Scene.traction` (``r``, ``slip_velocity``, ``stick``,
        ``point``; ``x1_m`` for a physical scene).
    ax : matplotlib.axes.Axes, optional
        Where to draw; default: a new figure.
    units : {'auto', 'si', 'dimensionless'}
        'auto': x1 in mm when the result has the SI columns (v stays scaled as xi).

    Returns
    -------
    matplotlib.axes.Axes
    """
    ax = _axes(ax)
    x, scale, _, xlabel, _ = _traction_units(t, units)
    v = np.asarray(t["slip_velocity"], dtype=float)
    _shade_zones(ax, t, scale, _load_sign(t))
    ax.axhline(0.0, color="#808080", lw=0.8, zorder=1)
    ax.plot(x, v, color="#2ca02c", lw=2.2, zorder=3, label="slip velocity v")
    span = float(np.nanmax(v) - np.nanmin(v)) or 1.0
    ax.set_ylim(min(0.0, np.nanmin(v)) - 0.12 * span, max(0.0, np.nanmax(v)) + 0.25 * span)
    ax.set_xlim(x[0], x[-1])
    ax.set_xlabel(xlabel)
    ax.set_ylabel(r"slip velocity $v$  (scaled as $\xi$)")
    return ax
