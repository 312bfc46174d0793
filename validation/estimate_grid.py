#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Random-scene study of roughroll's printed error estimates (issue 23, section 1).

For each case (scene, Q, method, n) runs

    roughroll point SCENE --Q Q --method M --n N --json

and compares c0, xi and hertz_load_ratio with a reference made by two finer
routes that do not share a level:

    paper, product, extrapolated:  --method product --n 1000  and  --method extrapolated --n 512
    one-parameter:                 --method one-parameter --n 1000  and  --n 768

A reference counts for a quantity only where both routes answer and agree within
the sum of their own estimates; else that quantity has "no reference".  The
error's lower bound is

    err_lo = max(0, min(|v - r1|, |v - r2|) - |r1 - r2|)

and the case under-reports a quantity when err_lo > estimate (ratio > 1).  For c0
also the relative error of the slip zone's length 1 - c0 (and of the stick zone's
length 1 + c0, which is what is small near gross sliding).

References are cached per (scene, Q, family) and reused across methods and n.

Usage:
    nice -n 10 /usr/bin/python3 validation/estimate_grid.py --bin /tmp/roughroll-grid-base \
        --seed 1 --scenes 40 --jobs 2 --out /tmp/grid.csv
    ... --known                     # also run issue 23's listed cases (a)-(d)
    ... --known --scenes 0          # only those
    ... --cases FILE                # re-run a saved case list (JSON lines, as written to OUT.cases.jsonl,
                                    # or validation/estimate_grid_cases.txt)
    ... --levels                    # for each under-report, also run n/4, n/2, n, 2n and print them

Exit status: 0 when no answered point under-reports, 1 when one does (2 on a usage error).
"""

import argparse
import concurrent.futures
import csv
import hashlib
import json
import math
import os
import random
import resource
import shlex
import subprocess
import sys
import tempfile
import threading
import time

QUANTITIES = ("c0", "xi", "hertz_load_ratio")
LAYERS = (("cylinder1", "tangential"), ("cylinder1", "normal"),
          ("cylinder2", "tangential"), ("cylinder2", "normal"))
TWO_PARAMETER_METHODS = ("paper", "product", "extrapolated")
METHODS = TWO_PARAMETER_METHODS + ("one-parameter",)
N_CHOICES = (16, 16, 32, 32, 48, 64, 64, 96, 128, 128, 256, 512)
REFS = {
    "two-parameter": (("product", 1000), ("extrapolated", 512)),
    "one-parameter": (("one-parameter", 1000), ("one-parameter", 768)),
}


def family(method):
    return "one-parameter" if method == "one-parameter" else "two-parameter"


# ----------------------------------------------------------------------------- scenes

def scene_toml(scene):
    lines = ["friction = %r" % scene["friction"], "Q = 0", ""]
    for cyl, direction in LAYERS:
        layer = scene.get("%s.%s" % (cyl, direction))
        if layer:
            lines += ["[%s.%s]" % (cyl, direction), "T = %r" % layer[0], "A = %r" % layer[1], ""]
    lines += ["[solver]", "n = 96", 'method = "product"', ""]
    return "\n".join(lines)


def scene_id(scene):
    return hashlib.sha1(scene_toml(scene).encode()).hexdigest()[:12]


def scene_short(scene):
    parts = ["f=%.4g" % scene["friction"]]
    for cyl, direction in LAYERS:
        layer = scene.get("%s.%s" % (cyl, direction))
        if layer:
            parts.append("%s%s(T=%.4g,A=%.4g)" % (cyl[-1], direction[0], layer[0], layer[1]))
    return " ".join(parts)


def log_uniform(rng, lo, hi):
    return math.exp(rng.uniform(math.log(lo), math.log(hi)))


def round_sig(x, digits=4):
    return float("%.*g" % (digits, x))


def random_scene(rng):
    while True:
        scene = {"friction": round_sig(log_uniform(rng, 0.01, 1.0))}
        for cyl, direction in LAYERS:
            u = rng.random()
            if u < 0.35:
                continue  # no layer (T = 0)
            T = round_sig(log_uniform(rng, 1e-3, 100.0))
            A = round_sig(log_uniform(rng, 1e-3, 50.0))
            scene["%s.%s" % (cyl, direction)] = (T, A)
        if len(scene) > 1:
            return scene


def random_load_ratio(rng):
    u = rng.random()
    if u < 0.35:  # near full stick
        return round_sig(log_uniform(rng, 1e-11, 1e-3))
    if u < 0.70:  # near gross sliding: 1 - Q/f in [1e-15, 1e-6]
        return 1.0 - round_sig(log_uniform(rng, 1e-15, 1e-6), 2)
    if u < 0.85:
        return round_sig(log_uniform(rng, 1e-3, 0.5))
    return 1.0 - round_sig(log_uniform(rng, 1e-6, 0.5))


def random_cases(seed, scenes, loads_per_scene, combos_per_load, p_one_parameter):
    rng = random.Random(seed)
    cases = []
    for _ in range(scenes):
        scene = random_scene(rng)
        for _ in range(loads_per_scene):
            x = random_load_ratio(rng)
            Q = x * scene["friction"]
            seen = set()
            for k in range(combos_per_load):
                method = ("one-parameter" if k == 0 and rng.random() < p_one_parameter
                          else rng.choice(TWO_PARAMETER_METHODS))
                n = rng.choice(N_CHOICES)
                if (method, n) in seen:
                    continue
                seen.add((method, n))
                cases.append({"scene": scene, "Q": Q, "method": method, "n": n, "tag": "random"})
    return cases


def known_cases():
    a = {"friction": 0.05, "cylinder1.normal": (0.411, 0.00071), "cylinder2.normal": (10.0, 0.3),
         "cylinder2.tangential": (0.001, 0.001)}
    b = {"friction": 1.0, "cylinder1.normal": (5.0, 0.3), "cylinder1.tangential": (0.0137, 0.355),
         "cylinder2.normal": (5.0, 0.5)}
    c = {"friction": 0.3, "cylinder1.tangential": (0.001, 1.0), "cylinder1.normal": (0.001, 1.0)}
    # one-parameter: eps_i = sum 2T/A^2 (docs/formulation.md section 6): eps1 = 0.1, eps2 = 0.3
    d = {"friction": 0.3, "cylinder1.tangential": (0.05, 1.0), "cylinder1.normal": (0.15, 1.0)}
    cases = [{"scene": a, "Q": 5e-11, "method": "extrapolated", "n": 16, "tag": "known-a"}]
    cases += [{"scene": a, "Q": 5e-11, "method": "product", "n": n, "tag": "known-a"} for n in (16, 32, 64)]
    cases += [{"scene": b, "Q": 0.001, "method": "product", "n": n, "tag": "known-b"} for n in (48, 96)]
    cases += [{"scene": c, "Q": 0.15, "method": "one-parameter", "n": 128, "tag": "known-c"}]
    cases += [{"scene": d, "Q": 0.9999 * 0.3, "method": "one-parameter", "n": 128, "tag": "known-d"}]
    return cases


def read_cases(path):
    cases = []
    with open(path) as fh:
        for line in fh:
            line = line.strip()
            if not line or line.startswith("#"):
                continue
            c = json.loads(line)
            c["scene"] = {k: (tuple(v) if isinstance(v, list) else v) for k, v in c["scene"].items()}
            c.setdefault("tag", "file")
            cases.append(c)
    return cases


# ----------------------------------------------------------------------------- running

class Runner:
    def __init__(self, binary, workdir, timeout, ref_timeout):
        self.binary = binary
        self.workdir = workdir
        self.timeout = timeout
        self.ref_timeout = ref_timeout
        self.lock = threading.Lock()
        self.refs = {}        # (scene_id, Q, family) -> (r1, r2)
        self.ref_events = {}  # same key -> threading.Event while being computed
        self.runs = 0

    def scene_path(self, scene):
        path = os.path.join(self.workdir, "scene-%s.toml" % scene_id(scene))
        if not os.path.exists(path):
            tmp = path + ".tmp%d" % threading.get_ident()
            with open(tmp, "w") as fh:
                fh.write(scene_toml(scene))
            os.replace(tmp, path)
        return path

    def command(self, scene, Q, method, n):
        return [self.binary, "point", self.scene_path(scene), "--Q", repr(Q),
                "--method", method, "--n", str(n), "--json"]

    def run(self, scene, Q, method, n, timeout):
        cmd = self.command(scene, Q, method, n)
        t0 = time.time()
        try:
            p = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                               timeout=timeout, universal_newlines=True)
        except subprocess.TimeoutExpired:
            return {"status": "timeout", "reason": "no answer within %g s" % timeout,
                    "seconds": time.time() - t0}
        with self.lock:
            self.runs += 1
        out = {"seconds": time.time() - t0}
        if p.returncode == 0:
            try:
                d = json.loads(p.stdout)
            except ValueError:
                out.update(status="bad-output", reason=p.stdout[-300:])
                return out
            est = d.get("error_estimate") or {}
            out.update(status="answered", reason="", checks_hold=d.get("checks_hold"),
                       zone_path=d.get("zone_path"), against=est.get("against", ""))
            for q in QUANTITIES:
                out[q] = d.get(q)
                out["est_" + q] = est.get(q)
            return out
        reason = " ".join(p.stderr.strip().split())
        if reason.startswith("roughroll: error: "):
            reason = reason[len("roughroll: error: "):]
        out.update(status="refused" if p.returncode == 2 else "exit%d" % p.returncode,
                   reason=reason[:400])
        return out

    def references(self, scene, Q, fam):
        key = (scene_id(scene), repr(Q), fam)
        with self.lock:
            if key in self.refs:
                return self.refs[key]
            ev = self.ref_events.get(key)
            mine = ev is None
            if mine:
                ev = self.ref_events[key] = threading.Event()
        if not mine:
            ev.wait()
            return self.refs[key]
        r = tuple(self.run(scene, Q, m, n, self.ref_timeout) for m, n in REFS[fam])
        with self.lock:
            self.refs[key] = r
        ev.set()
        return r


def fnum(x):
    return "" if x is None else repr(x)


def evaluate(runner, case):
    scene, Q, method, n = case["scene"], case["Q"], case["method"], case["n"]
    fam = family(method)
    r1, r2 = runner.references(scene, Q, fam)
    t = runner.run(scene, Q, method, n, runner.timeout)
    f = scene["friction"]
    row = {"tag": case.get("tag", ""), "scene_id": scene_id(scene), "friction": f}
    for cyl, direction in LAYERS:
        layer = scene.get("%s.%s" % (cyl, direction))
        row["%s_%s_T" % (cyl, direction)] = layer[0] if layer else 0.0
        row["%s_%s_A" % (cyl, direction)] = layer[1] if layer else ""
    eps1 = sum(2 * scene[k][0] / scene[k][1] ** 2 for k in scene if k.endswith("tangential"))
    eps2 = sum(2 * scene[k][0] / scene[k][1] ** 2 for k in scene if k.endswith("normal"))
    row.update(eps1=eps1, eps2=eps2, Q=Q, Q_over_f=Q / f, one_minus_Q_over_f=1 - Q / f,
               method=method, n=n, status=t["status"], reason=t.get("reason", ""),
               checks_hold=t.get("checks_hold", ""), zone_path=t.get("zone_path", ""),
               against=t.get("against", ""), seconds=round(t["seconds"], 3),
               ref1_status=r1["status"], ref2_status=r2["status"],
               ref1_zone_path=r1.get("zone_path", ""), ref2_zone_path=r2.get("zone_path", ""),
               ref_reason=(r1.get("reason") or r2.get("reason") or "")[:200])
    worst = None
    for q in QUANTITIES:
        v, e = t.get(q), t.get("est_" + q)
        a, b = r1.get(q), r2.get(q)
        ea, eb = r1.get("est_" + q), r2.get("est_" + q)
        row[q] = fnum(v)
        row["est_" + q] = fnum(e)
        row["ref1_" + q] = fnum(a)
        row["ref2_" + q] = fnum(b)
        ref_ok = (a is not None and b is not None and ea is not None and eb is not None
                  and abs(a - b) <= ea + eb)
        row["refok_" + q] = int(ref_ok)
        row["err_" + q] = row["errlo_" + q] = row["ratio_" + q] = ""
        if v is None or not ref_ok:
            continue
        err = abs(v - a)
        lo = max(0.0, min(abs(v - a), abs(v - b)) - abs(a - b))
        row["err_" + q] = repr(err)
        row["errlo_" + q] = repr(lo)
        if e is None:
            ratio = math.inf if lo > 0 else 0.0
        elif e > 0:
            ratio = lo / e
        else:
            ratio = math.inf if lo > 0 else 0.0
        row["ratio_" + q] = repr(ratio)
        if worst is None or ratio > worst[0]:
            worst = (ratio, q)
    # the zones' lengths: slip 1 - c0, stick 1 + c0 (small near gross sliding)
    row["slip_rel_err"] = row["slip_rel_est"] = row["stick_rel_err"] = row["stick_rel_est"] = ""
    if row["errlo_c0"] != "":
        c0r = r1["c0"]
        lo, e = float(row["errlo_c0"]), t.get("est_c0")
        if 1 - c0r > 0:
            row["slip_rel_err"] = repr(lo / (1 - c0r))
            row["slip_rel_est"] = fnum(None if e is None else e / (1 - c0r))
        if 1 + c0r > 0:
            row["stick_rel_err"] = repr(lo / (1 + c0r))
            row["stick_rel_est"] = fnum(None if e is None else e / (1 + c0r))
    row["worst_ratio"] = "" if worst is None else repr(worst[0])
    row["worst_quantity"] = "" if worst is None else worst[1]
    row["under_reports"] = int(worst is not None and worst[0] > 1)
    row["command"] = " ".join(shlex.quote(x) for x in runner.command(scene, Q, method, n))
    row["_case"] = case
    return row


FIELDS = None


def write_csv(path, rows):
    fields = [k for k in rows[0] if not k.startswith("_")]
    with open(path, "w", newline="") as fh:
        w = csv.DictWriter(fh, fieldnames=fields, extrasaction="ignore")
        w.writeheader()
        for r in rows:
            w.writerow(r)


def level_table(runner, row):
    case = row["_case"]
    lines = []
    for m in (1, 2, 4, 8):
        n = case["n"] * m // 4
        if n < 2 or n > 1000:
            continue
        t = runner.run(case["scene"], case["Q"], case["method"], n, runner.timeout)
        if t["status"] != "answered":
            lines.append("      n=%4d  %s: %s" % (n, t["status"], t.get("reason", "")[:120]))
            continue
        lines.append("      n=%4d  c0=%.16g (+-%.2g)  xi=%.16g (+-%.2g)  P_H/P2=%.16g (+-%.2g)  checks=%s %s"
                     % (n, t["c0"], t["est_c0"] or 0, t["xi"], t["est_xi"] or 0,
                        t["hertz_load_ratio"], t["est_hertz_load_ratio"] or 0,
                        t["checks_hold"], t["zone_path"]))
    return lines


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter, epilog=__doc__)
    ap.add_argument("--bin", required=True, help="roughroll executable")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--scenes", type=int, default=25, help="random scenes (default 25: about 10 min CPU)")
    ap.add_argument("--loads", type=int, default=4, help="loads Q per scene (default 4)")
    ap.add_argument("--combos", type=int, default=3, help="(method, n) per load (default 3)")
    ap.add_argument("--p-one-parameter", type=float, default=0.3,
                    help="chance that a load also gets a one-parameter case (default 0.3)")
    ap.add_argument("--jobs", type=int, default=1)
    ap.add_argument("--out", default="estimate_grid.csv")
    ap.add_argument("--cases", help="re-run the cases of this file (JSON lines) instead of random ones")
    ap.add_argument("--known", action="store_true", help="add issue 23's listed cases (a)-(d)")
    ap.add_argument("--timeout", type=float, default=120.0, help="per tested point, s")
    ap.add_argument("--ref-timeout", type=float, default=120.0, help="per reference point, s")
    ap.add_argument("--levels", action="store_true",
                    help="for each under-report also print the same point at n/4, n/2, n, 2n")
    ap.add_argument("--worst", type=int, default=20)
    args = ap.parse_args()

    binary = os.path.abspath(args.bin)
    if not os.access(binary, os.X_OK):
        ap.error("--bin %s is not executable" % args.bin)
    cases = read_cases(args.cases) if args.cases else random_cases(
        args.seed, args.scenes, args.loads, args.combos, args.p_one_parameter)
    if args.known:
        cases = known_cases() + cases
    if not cases:
        ap.error("no cases")

    workdir = tempfile.mkdtemp(prefix="estimate-grid-")
    runner = Runner(binary, workdir, args.timeout, args.ref_timeout)
    t0 = time.time()
    rows = [None] * len(cases)
    done = [0]

    # Group by (scene, Q, family) so that one worker computes a group's references while
    # the others work on other groups.
    groups = {}
    for i, c in enumerate(cases):
        groups.setdefault((scene_id(c["scene"]), repr(c["Q"]), family(c["method"])), []).append(i)

    def work(indices):
        for i in indices:
            rows[i] = evaluate(runner, cases[i])
            with runner.lock:
                done[0] += 1
                if done[0] % 25 == 0:
                    print("  %d/%d cases, %.0f s" % (done[0], len(cases), time.time() - t0),
                          file=sys.stderr, flush=True)

    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, args.jobs)) as ex:
        for fut in [ex.submit(work, idx) for idx in groups.values()]:
            fut.result()

    wall = time.time() - t0
    ru = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = ru.ru_utime + ru.ru_stime

    write_csv(args.out, rows)
    with open(args.out + ".cases.jsonl", "w") as fh:
        for c in cases:
            fh.write(json.dumps({k: c[k] for k in ("scene", "Q", "method", "n", "tag")}) + "\n")

    # --------------------------------------------------------------------- summary
    def count(pred):
        return sum(1 for r in rows if pred(r))

    print("roughroll %s: %d cases (%d (scene, Q) groups, %d program runs), %.0f s wall, %.0f s CPU (children)"
          % (binary, len(rows), len(groups), runner.runs, wall, cpu))
    print("%-14s %6s %8s %8s %7s %9s %10s %12s" % ("method", "cases", "answered", "refused", "other",
                                                    "with ref", "under-rep", "checks fail"))
    for m in METHODS + ("all",):
        sel = [r for r in rows if m == "all" or r["method"] == m]
        if not sel:
            continue
        ans = [r for r in sel if r["status"] == "answered"]
        print("%-14s %6d %8d %8d %7d %9d %10d %12d" % (
            m, len(sel), len(ans), sum(r["status"] == "refused" for r in sel),
            sum(r["status"] not in ("answered", "refused") for r in sel),
            sum(r["worst_ratio"] != "" for r in ans), sum(r["under_reports"] for r in ans),
            sum(r["checks_hold"] is False for r in ans)))
    for q in QUANTITIES:
        print("  under-reports of %-16s: %d" % (q, count(lambda r: r["ratio_" + q] != "" and float(r["ratio_" + q]) > 1)))
    noref = count(lambda r: r["status"] == "answered" and r["worst_ratio"] == "")
    print("  answered without any reference (routes refused or disagree): %d" % noref)
    reasons = {}
    for r in rows:
        if r["status"] != "answered":
            key = r["reason"].split(":")[0][:70] if r["reason"] else r["status"]
            reasons[key] = reasons.get(key, 0) + 1
    if reasons:
        print("refusal reasons (first words):")
        for k, v in sorted(reasons.items(), key=lambda kv: -kv[1])[:10]:
            print("  %4d  %s" % (v, k))

    under = sorted((r for r in rows if r["under_reports"]), key=lambda r: -float(r["worst_ratio"]))
    if under:
        print("\nworst %d under-reports (ratio = error lower bound / estimate):" % min(args.worst, len(under)))
    for r in under[:args.worst]:
        q = r["worst_quantity"]
        print("  %-8s ratio %-8.3g %-16s %-13s n=%-4d Q/f=%-.10g (1-Q/f=%.2g) checks=%s path=%s [%s]" % (
            r["tag"], float(r["worst_ratio"]), q, r["method"], r["n"], r["Q_over_f"], r["one_minus_Q_over_f"],
            r["checks_hold"], r["zone_path"], scene_short(r["_case"]["scene"])))
        print("      value %s +- %s, refs %s / %s; slip rel err %s, stick rel err %s" % (
            r[q], r["est_" + q], r["ref1_" + q], r["ref2_" + q],
            r["slip_rel_err"] and "%.2g" % float(r["slip_rel_err"]),
            r["stick_rel_err"] and "%.2g" % float(r["stick_rel_err"])))
        print("      " + r["command"])
        if args.levels:
            for line in level_table(runner, r):
                print(line)
    print("\nCSV: %s   cases: %s.cases.jsonl   scenes in %s" % (args.out, args.out, workdir))
    return 1 if under else 0


if __name__ == "__main__":
    sys.exit(main())
