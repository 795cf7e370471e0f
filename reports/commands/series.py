"""``paramres series``: the edges of an interval as power series in the depth m.

    paramres series --order N [--terms K] [--Q Q] [--damping exact|paper] [--json]

Without ``--Q``: both edges ``T-/T0`` and ``T+/T0`` (and in units of ``T_av``) through ``m**K`` for
any order ``N`` (``odd``/``even`` give the closed forms in the symbol ``n``).  With ``--Q``: the
threshold depth ``m_min(Q)`` (tangency of the normal form) and the edges above it in the
distinguished scaling (``1/Q ~ m`` for odd orders, ``m**2`` for even), in the chosen damping model.
``--system``/``--duty`` take another member of the family (integer orders): there the scaling is
``1/Q ~ m^p`` with ``p = 2`` where ``n D`` is an integer and ``1`` otherwise.
"""

from __future__ import annotations

import argparse

from reports.output import dump_json
from verify.inputs import InputError, as_damping, as_quality

from ._arguments import add_friction, add_json, add_system, system_of

__all__ = ["register", "run", "render_text", "parse_terms"]


def register(subparsers) -> None:
    p = subparsers.add_parser(
        "series",
        help="edges of the n-th interval as power series in m (any order, any number of terms)",
        description=(
            "Both edges of the interval of instability of order N as power series in the depth m, "
            "derived from the per-edge equations of the normal form (exact rational arithmetic in "
            "m, coefficients in pi). Units: T/T0 (lower/upper) and T/T_av (in_Tav). N may be 'odd' "
            "or 'even' for the closed forms in the symbol n. With --Q the threshold depth m_min(Q) "
            "and the edges above it are given in the distinguished scaling 1/Q ~ m (odd N) or "
            "1/Q ~ m^2 (even N), in the chosen damping model."
        ),
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    p.add_argument(
        "--order",
        required=True,
        metavar="N",
        help="order of the resonance, 1 to 10000, or odd/even",
    )
    p.add_argument(
        "--terms",
        default="4",
        metavar="K",
        help="highest power of m kept, 1 to 40 (24 for odd/even, 12 with friction or another "
        "system; default 4)",
    )
    add_friction(p)
    add_system(p)
    add_json(p)
    p.set_defaults(func=run)


def parse_terms(text) -> int:
    from analytic.expansions import MAX_TERMS

    t = str(text).strip()
    if not t.isdigit():
        raise InputError(f"terms {text!r} is not an integer; allowed range 1 to {MAX_TERMS}")
    k = int(t)
    if not 1 <= k <= MAX_TERMS:
        raise InputError(f"terms {k} is outside the allowed range 1 to {MAX_TERMS}")
    return k


def _order(text):
    from verify.inputs import as_order

    t = str(text).strip().lower()
    return t if t in ("odd", "even") else as_order(text)


def run(args) -> int:
    from analytic.expansions import edge_series

    order = _order(args.order)
    terms = parse_terms(args.terms)
    damping = as_damping(args.damping)
    Q = as_quality(args.Q)
    sysv = system_of(args)
    es = edge_series(order, terms, Q=Q, damping=damping, system=sysv)
    payload = es.as_json(edge_printer=_s)
    payload["lower"] = payload["in_T0"]["lower"]  # in T0 whatever the units
    payload["upper"] = payload["in_T0"]["upper"]
    if Q is not None:
        payload["threshold"] = {
            **payload.get("threshold", {}),
            **_threshold_payload(order, terms, Q, damping, sysv),
        }
    if args.json:
        dump_json(payload)
    else:
        print(render_text(es, payload))
    return 0


def _s(expr) -> str:
    import sympy as sp

    return sp.sstr(expr, order="rev-lex")


def _threshold_payload(order, terms: int, Q, damping: str, sysv=None) -> dict:
    import sympy as sp

    from analytic.thresholds import threshold_series

    th = threshold_series(
        order, terms, damping=damping, **({} if sysv is None else {"system": sysv})
    )
    # the series in the symbol Q (parse with sympify(text, locals={"Q": Symbol("Q")}): sympy's own
    # name Q is its assumptions object)
    out = {
        "m_min_series": _s(th.m_min),
        "m_min_squared_series": _s(th.m_min2),
        "Q_min_series": _s(th.Q_min),
        "theta_at_threshold": _s(th.theta),
        "scaling_power": th.p,
    }
    if isinstance(order, int):
        from analytic.model import S

        qv = (
            sp.Rational(Q.numerator, Q.denominator)
            if hasattr(Q, "numerator")
            else sp.Float(str(Q), 30)
        )
        out["m_min_value"] = str(sp.N(th.m_min.subs(S.Q, qv), 20))
    return out


def render_text(es, payload: dict) -> str:
    import sympy as sp

    lines = []
    what = f"order {es.order}" if isinstance(es.order, int) else f"every {es.order} order n"
    where = (
        ""
        if getattr(es, "system", None) is None or es.system.is_paper
        else (f" of the {es.system.label}")
    )
    if es.Q is None:
        lines.append(f"Edges of the interval of {what}{where}, no friction, through m^{es.terms}:")
    else:
        lines.append(
            f"Edges of the interval of {what}{where} with friction Q = {es.Q} ({es.damping} "
            f"model), through m^{es.terms} in the distinguished scaling:"
        )
    O = f" + O(m^{es.terms + 1})"
    src = payload
    if es.scaled is not None:
        src = {u: {k: _s(v) for k, v in es.scaled[u].items()} for u in ("T0", "Tav")}
        src = {"in_T0": src["T0"], "in_Tav": src["Tav"]}
        mm = es.scaled["m_min0"]
        p = (payload.get("threshold") or {}).get("scaling_power")
        if p is None:
            p = 1 if (es.order % 2 if isinstance(es.order, int) else es.order == "odd") else 2
        lines.append(
            f"  with s = sqrt(1 - (m_min0/m)^{2 * p}), m_min0 = {_s(mm)} = {sp.N(mm, 12)} "
            "(the leading threshold); the --json output has s written out"
        )
    lines.append("  in units of T0:")
    lines.append(f"    T-/T0   = {src['in_T0']['lower']}{O}")
    lines.append(f"    T+/T0   = {src['in_T0']['upper']}{O}")
    unit = "T_av" if not where else "2 pi/omega_mean (exact tuning n/2)"
    lines.append(f"  in units of {unit}:")
    lines.append(f"    T-/T_av = {src['in_Tav']['lower']}{O}")
    lines.append(f"    T+/T_av = {src['in_Tav']['upper']}{O}")
    if es.lower_factor is not None:
        f = "cos" if es.order % 2 else "sin"
        sign = "-" if es.lower_factor > 0 else "+"
        other = "+" if sign == "-" else "-"
        lines.append(
            f"  lower edge: root of {f}(x) {sign} r {f}(beta x) (eps = {es.lower_factor:+d}); "
            f"upper edge: root of {f}(x) {other} r {f}(beta x)  (x = omega_av T/2, small m)"
        )
    th = payload.get("threshold")
    if th:
        lines.append("  threshold (double root of the normal form):")
        lines.append(
            f"    m_min(Q) = {th['m_min_series']}"
            + (f" ~ {th['m_min_value']} (series value)" if "m_min_value" in th else "")
        )
        lines.append(f"    Q_min(m) = {th['Q_min_series']}")
        lines.append("  the edges hold above the threshold, as series in m at fixed m_min/m")
    return "\n".join(lines)
