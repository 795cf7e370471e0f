"""Certified edges against a plain arb interval Newton with precision doubling.

The floor is the least a certified edge can cost: the per-edge equation of order 3 (eq. 13 with
its sign, in ``theta = x - 3 pi/2``: ``F = sin(theta) - eps r cos(beta (3 pi/2 + theta))``; for
``eps = +-1`` the two edges) written out here with python-flint ``arb``; the parameters ``beta =
m/(1 + s)``, ``s = sqrt(1 - m^2)``, ``r = beta (3 + beta^2)/(1 + 3 beta^2)``, ``w = sqrt((1 +
s)/2)/s``; a float Newton start, Newton on midpoints doubling the precision each step, one interval
Newton test ``x - F(x)/F'(X)`` inside ``X`` at the target precision, and ``T/T0 = (3/2 +
theta/pi)/w`` as a ball.  No safeguards, no offsets, no formatting.  Ours is
``paramres.boundary(3, "3/10", digits=D)`` (both edges, every digit proven, offsets and radii
included), through the whole public path.  The other members of the family (the torsion
pendulum, the Meissner equation, a duty of 1/3, a custom system) are timed against the same
floor: their edges take the same steps, with their own parameters.
"""

from __future__ import annotations

import math
from fractions import Fraction

from flint import arb, ctx

from analytic.system import custom

M = Fraction(3, 10)
ORDER = 3
DIGITS = (15, 50, 100, 1000, 5000, 10000, 20000, 100000)
QUICK_DIGITS = (15, 50, 1000, 10000)
#: the growth of the time with the digits is measured from here on, against ``D^GROWTH_TARGET``
GROWTH_FROM = 1000
GROWTH_TARGET = 1.7


def _params(m: Fraction):
    mb = arb(m.numerator) / m.denominator
    s = (1 - mb * mb).sqrt()
    beta = mb / (1 + s)
    b2 = beta * beta
    r = beta * (3 + b2) / (1 + 3 * b2)
    w = ((1 + s) / 2).sqrt() / s
    return r, beta, w


def _float_root(eps: int, r: float, beta: float) -> float:
    c = 1.5 * math.pi
    th = 0.0
    for _ in range(30):
        f = math.sin(th) - eps * r * math.cos(beta * (c + th))
        d = math.cos(th) + eps * r * beta * math.sin(beta * (c + th))
        step = f / d
        th -= step
        if abs(step) < 1e-15:
            break
    return th


def floor_edges(m: Fraction, digits: int):
    """Both edges ``T/T0`` of order 3 at depth ``m`` as proven balls (the floor)."""
    bits = int(math.ceil(digits * math.log2(10))) + 10
    rf, bf, _ = (float(x) for x in _params(m))
    out = []
    for eps in (1, -1):
        x = arb(_float_root(eps, rf, bf))
        prec = 53
        while prec < bits:
            prec = min(2 * prec, bits)
            with ctx.workprec(prec + 10):
                r, beta, _ = _params(m)
                c = 3 * arb.pi() / 2
                s, co = x.sin_cos()
                sb, cb = (beta * (c + x)).sin_cos()
                x = (x - (s - eps * r * cb) / (co + eps * r * beta * sb)).mid()
        with ctx.workprec(bits + 10):
            r, beta, w = _params(m)
            pi = arb.pi()
            c = 3 * pi / 2
            X = arb(x, arb(2) ** (-bits + 4) * abs(x))
            s, co = x.sin_cos()
            fx = s - eps * r * (beta * (c + x)).cos()
            Xs, Xc = X.sin_cos()
            dX = Xc + eps * r * beta * (beta * (c + X)).sin()
            N = x - fx / dX
            if not X.contains_interior(N):  # pragma: no cover - the start is always good here
                raise ArithmeticError("interval Newton failed")
            out.append((arb(ORDER) / 2 + N / pi) / w)
    return out


def previous() -> dict:
    """Seconds per call (both edges) of the certified solver in the previous release, by digits
    (``benchmarks/results.json``: per edge, median over its scenes)."""
    import json
    from pathlib import Path

    path = Path(__file__).with_name("results.json")
    try:
        doc = json.loads(path.read_text())
    except (OSError, ValueError):
        return {}
    out = {}
    for row in doc.get("methods", []):
        name = row.get("method", "")
        if name.startswith("certified ") and name.split()[1].isdigit():
            out[int(name.split()[1])] = 2 * row["seconds"]
    for row in doc.get("targets", []):  # the same job as here: order 3 at m = 0.3, both edges
        if row.get("name", "").startswith("certified 50 digits, n = 3, m = 0.3"):
            out[50] = row["seconds"]
    return out


def scenes(quick: bool) -> list[dict]:
    import paramres

    prev = previous()
    out = []
    for d in QUICK_DIGITS if quick else DIGITS:
        out.append(
            {
                "name": f"certified {d} digits",
                "target": 1.5,
                "ours": lambda d=d: paramres.boundary(ORDER, "3/10", digits=d),
                "floor": lambda d=d: floor_edges(M, d),
                "note": "plain arb interval Newton with precision doubling, both edges",
                "baseline": prev.get(d),
            }
        )
    # the growth with the digits: ours at the next precision against ours at this one, timed
    # alternately like every scene (a shared machine's load falls on both), so that the exponent
    # does not depend on how busy the machine was when each precision's scene ran
    ds = [d for d in (QUICK_DIGITS if quick else DIGITS) if d >= GROWTH_FROM]
    for d1, d2 in zip(ds, ds[1:], strict=False):
        out.append(
            {
                "name": f"certified growth {d1} -> {d2} digits",
                "target": (d2 / d1) ** GROWTH_TARGET,
                "ours": lambda d=d2: paramres.boundary(ORDER, "3/10", digits=d),
                "floor": lambda d=d1: paramres.boundary(ORDER, "3/10", digits=d),
                "note": f"ours at {d2} digits against ours at {d1} (target: time ~ D^1.7)",
            }
        )
    # friction: the Q = 7 boundary against the frictionless one (the floor here is ours at Q=None),
    # at m = 0.3 and at a deep modulation (the bracket wide, the shape in several pieces); and
    # with no interval (closed by friction: the proof that D < 0 on the bracket) -- the paper's
    # pendulum at Q = 3, and the custom system at Q = 30
    for label, kw, m, Q, d in (
        ("", {}, "3/10", 7, 15),
        ("", {}, "3/10", 7, 50),
        (", m = 0.9", {}, "9/10", 7, 15),
        (", no interval", {}, "3/10", 3, 15),
        (" custom, no interval", OTHERS[-1][1], None, 30, 15),
    ):
        out.append(
            {
                "name": f"friction Q={Q} / none{label}, {d} digits",
                "target": 2.0,
                "ours": lambda kw=kw, m=m, Q=Q, d=d: paramres.boundary(
                    ORDER, m, Q=Q, digits=d, **kw
                ),
                "floor": lambda kw=kw, m=m, d=d: paramres.boundary(ORDER, m, digits=d, **kw),
                "note": "the friction boundary against the frictionless one",
            }
        )
    # the other members of the family: the same work with their own parameters, against the
    # same floor; and their friction boundary against their frictionless one (Q = 30: at Q = 7
    # the torsion pendulum and the Meissner equation have no third interval at m = 0.3; the
    # custom system, whose parameters do not depend on m, has none up to Q = 120)
    for label, kw, m, Q in OTHERS:
        for d in (15, 1000) if quick else (15, 100, 1000):
            out.append(
                {
                    "name": f"certified {label}, {d} digits",
                    "target": 1.5,
                    "ours": lambda d=d, kw=kw, m=m: paramres.boundary(ORDER, m, digits=d, **kw),
                    "floor": lambda d=d: floor_edges(M, d),
                    "note": "the paper's floor: the same work, other parameters",
                }
            )
        out.append(
            {
                "name": f"friction Q={Q} / none {label}, 15 digits",
                "target": 2.0,
                "ours": lambda kw=kw, m=m, Q=Q: paramres.boundary(ORDER, m, Q=Q, digits=15, **kw),
                "floor": lambda kw=kw, m=m: paramres.boundary(ORDER, m, digits=15, **kw),
                "note": "the friction boundary against the frictionless one",
            }
        )
    return out


#: the other members of the family timed here (as the grid's scenes: torsion, Meissner, D = 1/3;
#: and a custom system), with the depth and the quality factor of their friction scene
OTHERS = (
    ("torsion", {"system": "torsion"}, "3/10", 30),
    ("meissner", {"system": "meissner"}, "3/10", 30),
    ("duty 1/3", {"duty": "1/3"}, "3/10", 30),
    ("custom", {"system": custom(("4/5", "6/5"), jump="3/2", duty="2/5")}, None, 1000),
)


def summary(rows: list[dict]) -> list[str]:
    """How the certified time grows with the digits: the exponent ``a`` of ``time ~ D^a``
    between successive measured precisions from 1000 digits on (target: ``a <= 1.7``), from the
    growth scenes (the two precisions timed alternately); from the medians of the separate
    scenes where a growth scene is missing."""
    out = []
    growth = {}
    for r in rows:
        words = r["name"].split()
        if r["name"].startswith("certified growth "):
            d1, d2 = int(words[2]), int(words[4])
            growth[d1, d2] = math.log(r["ratio"]) / math.log(d2 / d1)
    pts = sorted(
        (int(r["name"].split()[1]), r["ours_seconds"])
        for r in rows
        if r["name"].startswith("certified ") and r["name"].split()[1].isdigit()
    )
    pts = [(d, t) for d, t in pts if d >= GROWTH_FROM]
    for (d1, t1), (d2, t2) in zip(pts, pts[1:], strict=False):
        a = growth.get((d1, d2))
        how = "timed alternately"
        if a is None:
            a, how = math.log(t2 / t1) / math.log(d2 / d1), "medians of separate scenes"
        out.append(
            f"certified time ~ D^{a:.2f} from {d1} to {d2} digits, {how} "
            f"(target <= {GROWTH_TARGET})"
        )
    return out
