#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Compare two folders written by validation/golden/run (issue 24: pin the outputs before moving code).

    validation/golden/compare.py REFERENCE NEW

Every number must be identical, or have moved by no more than its error estimate: a JSON point's
c0, xi, hertz_load_ratio, stick_start, gamma and pressure_peak's p and r against their error_estimate entries, full
coupling's offset_e, hertz_load_ratio_johnson and peak_pressure_change against coupling.error_estimate's (where bounded),
its SI values against si.error_estimate's (T and A at a by its roughness_at_a_relative; where neither
folder has them, the peak's SI values against the dimensionless ones scaled), a curve's or figure's
column X against its column X_error_estimate; another derived number (xi_over_f, p_centre_Pa) against
the largest relative estimate of its point or row. Estimates and iteration counts may change (listed). Timings and the
version are ignored; a JSON key or CSV column only in NEW is listed as added, and changed
header lines of a CSV as header. Exit 0 when nothing moved outside its estimate, 1 otherwise; one line per change.
"""
import csv
import json
import math
import sys
from pathlib import Path

IGNORED = {"seconds", "version"}
# A JSON key and the error_estimate entry that bounds it (the peak pressure's value and position by their own
# estimates, not by the point's largest relative estimate).
ESTIMATED = {"c0": "c0", "xi": "xi", "hertz_load_ratio": "hertz_load_ratio", "stick_start": "stick_start",
             "pressure_peak.p": "pressure_peak_p", "pressure_peak.r": "pressure_peak_r", "gamma": "gamma"}
# Full coupling's measured values and their estimates (coupling.error_estimate, session 28; null where none is bounded).
COUPLING_ESTIMATED = {"coupling.offset_e": "offset_e", "coupling.hertz_load_ratio_johnson": "hertz_load_ratio_johnson",
                      "coupling.peak_pressure_change": "peak_pressure_change"}
# An SI value and the dimensionless one it scales: judged by that one's estimate times the scale (x_peak_m is
# pressure_peak.r times the half-width, near zero where the peak sits at the centre).
SCALED = {"si.x_peak_m": "pressure_peak.r", "si.p_peak_Pa": "pressure_peak.p"}
# How the solver got there (iteration counts, the alternation's contraction): listed when they change, never a
# moved result; pressure_peak.r_resolution, the band of a flat maximum within which the pressures agree to
# rounding (docs/cli.md), is such a measure with no estimate of its own (session 26 review R16).
DIAGNOSTIC = {"brent_iterations", "coupling.iterations", "coupling.newton_residuals", "coupling.contraction",
              "si.width_iterations", "pressure_peak.r_resolution"}


def flatten(value, prefix=""):
    if isinstance(value, dict):
        for k, v in value.items():
            yield from flatten(v, f"{prefix}.{k}" if prefix else k)
    elif isinstance(value, list):
        for i, v in enumerate(value):
            yield from flatten(v, f"{prefix}[{i}]")
    else:
        yield prefix, value


def si_allowance(key, old, old_flat, new_flat):
    """The SI value's own estimate (si.error_estimate, the larger of the two folders'), or None where neither has one."""
    if key.startswith("si.roughness_at_a."):
        est_key, factor = "si.error_estimate.roughness_at_a_relative", abs(old)
    else:
        est_key, factor = "si.error_estimate." + key[len("si."):], 1.0
    ests = [f.get(est_key) for f in (old_flat, new_flat)]
    ests = [e for e in ests if isinstance(e, (int, float)) and not isinstance(e, bool)]
    return max(ests) * factor if ests else None


def relative_scale(values, estimates):
    """The largest relative estimate of a record: the allowance of its derived numbers."""
    worst = 0.0
    for key, est in estimates.items():
        v = values.get(key)
        if isinstance(v, (int, float)) and isinstance(est, (int, float)) and v != 0:
            worst = max(worst, abs(est) / abs(v))
    return worst


class Report:
    def __init__(self):
        self.outside = 0
        self.lines = []

    def note(self, kind, where, text):
        if kind == "OUTSIDE":
            self.outside += 1
        self.lines.append(f"{kind:10s} {where}: {text}")


def compare_numbers(report, where, key, old, new, allowance):
    if old == new or (isinstance(old, float) and isinstance(new, float) and math.isnan(old) and math.isnan(new)):
        return
    if not (isinstance(old, (int, float)) and isinstance(new, (int, float))) or isinstance(old, bool):
        report.note("OUTSIDE", where, f"{key}: {old!r} -> {new!r}")
        return
    diff = abs(new - old)
    kind = "within" if allowance is not None and diff <= allowance else "OUTSIDE"
    report.note(kind, where, f"{key}: {old!r} -> {new!r} (moved {diff:.3g}, estimate {allowance if allowance is None else f'{allowance:.3g}'})")


def compare_json(report, name, old, new):
    old_flat, new_flat = dict(flatten(old)), dict(flatten(new))
    old_est = old.get("error_estimate") or {}
    new_est = new.get("error_estimate") or {}
    scale = max(relative_scale(old, old_est), relative_scale(new, new_est))
    for key in sorted(set(old_flat) | set(new_flat)):
        if key.split(".")[-1] in IGNORED:
            continue
        if key not in old_flat:  # a new output: nothing pinned moved
            report.note("added", name, f"{key} = {new_flat[key]!r}")
            continue
        if key not in new_flat:
            # A null that became an object (an estimate that appears, e.g. coupling.error_estimate on the edge layers'
            # closed form since session 29): its keys are reported as added; no number of the reference moved.
            if old_flat[key] is None and any(k.startswith((key + ".", key + "[")) for k in new_flat):
                report.note("added", name, f"{key}: null in the reference, an object here (its keys: added)")
                continue
            report.note("OUTSIDE", name, f"{key} only in the reference")
            continue
        o, n = old_flat[key], new_flat[key]
        if o == n:
            continue
        if key.startswith(("error_estimate", "si.error_estimate", "coupling.error_estimate")):
            report.note("estimate", name, f"{key}: {o!r} -> {n!r}")
            continue
        if key in DIAGNOSTIC:
            report.note("diagnostic", name, f"{key}: {o!r} -> {n!r}")
            continue
        allowance = si_allowance(key, o, old_flat, new_flat) if key.startswith("si.") else None
        if allowance is not None:
            compare_numbers(report, name, key, o, n, allowance)
            continue
        if key in COUPLING_ESTIMATED:
            est = COUPLING_ESTIMATED[key]
            bounds = [e.get(est) for e in ((old.get("coupling") or {}).get("error_estimate") or {},
                                           (new.get("coupling") or {}).get("error_estimate") or {})]
            if isinstance(bounds[0], (int, float)):
                compare_numbers(report, name, key, o, n, max(b for b in bounds if isinstance(b, (int, float))))
                continue
        base = SCALED.get(key)
        est_key = ESTIMATED.get(base or key)
        if est_key is not None and isinstance(old_est.get(est_key), (int, float)):
            allowance = max(old_est[est_key], new_est.get(est_key) or 0.0)
            if base is not None:
                v = old_flat.get(base)
                allowance = allowance * abs(o / v) if isinstance(v, (int, float)) and v != 0 else None
        elif isinstance(o, (int, float)) and not isinstance(o, bool) and scale > 0:
            allowance = scale * abs(o)
        compare_numbers(report, name, key, o, n, allowance)


def read_csv(path):
    lines = path.read_text().splitlines()
    header = [l for l in lines if l.startswith("#") and not l.startswith("# roughroll ")]
    rows = list(csv.DictReader([l for l in lines if not l.startswith("#")]))
    return header, rows


def number(text):
    try:
        return float(text)
    except ValueError:
        return text


def compare_csv(report, name, old_path, new_path):
    old_header, old_rows = read_csv(old_path)
    new_header, new_rows = read_csv(new_path)
    if old_header != new_header:  # words, not numbers: listed
        for line in sorted(set(new_header) - set(old_header)):
            report.note("header", name, line)
    if len(old_rows) != len(new_rows):
        report.note("OUTSIDE", name, f"{len(old_rows)} rows -> {len(new_rows)}")
        return
    if old_rows and new_rows:
        missing = [c for c in old_rows[0] if c not in new_rows[0]]
        if missing:
            report.note("OUTSIDE", name, f"columns only in the reference: {', '.join(missing)}")
            return
        for column in (c for c in new_rows[0] if c not in old_rows[0]):
            report.note("added", name, f"column {column}")
    for i, (o, n) in enumerate(zip(old_rows, new_rows)):
        n = {k: n[k] for k in o}  # the reference's columns; an added one is listed above
        estimates = {k[: -len("_error_estimate")]: number(v) for k, v in o.items()
                     if k.endswith("_error_estimate") and v != ""}
        new_estimates = {k[: -len("_error_estimate")]: number(v) for k, v in n.items()
                         if k.endswith("_error_estimate") and v != ""}
        values = {k: number(v) for k, v in o.items()}
        scale = max(relative_scale(values, estimates), relative_scale(values, new_estimates))
        for key in o:
            if o[key] == n[key]:
                continue
            if key.endswith("_error_estimate"):
                report.note("estimate", f"{name} row {i}", f"{key}: {o[key]} -> {n[key]}")
                continue
            ov, nv = number(o[key]), number(n[key])
            allowance = None
            if key in estimates and isinstance(estimates[key], float):
                allowance = max(estimates[key], new_estimates.get(key, 0.0) or 0.0)
            elif isinstance(ov, float) and scale > 0:
                allowance = scale * abs(ov)
            compare_numbers(report, f"{name} row {i}", key, ov, nv, allowance)


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: compare.py REFERENCE NEW")
    old_dir, new_dir = Path(sys.argv[1]), Path(sys.argv[2])
    report = Report()
    old_files = {p.relative_to(old_dir) for p in old_dir.rglob("*") if p.is_file()}
    new_files = {p.relative_to(new_dir) for p in new_dir.rglob("*") if p.is_file()}
    for missing in sorted(old_files ^ new_files):
        report.note("OUTSIDE", str(missing), "only in " + ("new" if missing in new_files else "reference"))
    for rel in sorted(old_files & new_files):
        old_path, new_path = old_dir / rel, new_dir / rel
        if old_path.read_bytes() == new_path.read_bytes():
            continue
        if rel.suffix == ".json":
            try:
                compare_json(report, str(rel), json.loads(old_path.read_text()), json.loads(new_path.read_text()))
            except json.JSONDecodeError:  # a refusal's one line
                report.note("OUTSIDE", str(rel), f"{old_path.read_text().strip()!r} -> {new_path.read_text().strip()!r}")
        elif rel.suffix == ".csv":
            compare_csv(report, str(rel), old_path, new_path)
        else:
            report.note("OUTSIDE", str(rel), f"{old_path.read_text().strip()!r} -> {new_path.read_text().strip()!r}")
    print("\n".join(report.lines) if report.lines else "identical")
    print(f"{len(old_files & new_files)} files compared; {report.outside} changes outside their estimates")
    sys.exit(1 if report.outside else 0)


if __name__ == "__main__":
    main()
