"""A validated Taylor integrator for a linear 2x2 system ``y' = A(t) y`` in ball arithmetic.

One integrator for every length that varies in time (the ``sine`` modulation, the ramps with
friction, the plateaus between them): the caller gives ``A`` as a function that evaluates on
python-flint ``arb_series`` (its Taylor coefficients about a point) and on ``acb`` (a complex
box, for the bound).  :func:`flow` returns the map from ``t0`` to ``t1`` as four ``arb`` balls
that contain the exact map.

**One step** from ``t_c`` to ``t_c + h``. The Taylor coefficients ``Y_k`` of the fundamental matrix
``Y(t_c + z)`` (``Y(t_c) = I``) solve ``(k+1) Y_{k+1} = sum_j A_j Y_{k-j}`` (computed in ball
arithmetic from the series of ``A``, skipping its zero coefficients). The remainder ``sum_{k >= N}
Y_k h^k`` is bounded by a majorant: if every row sum of ``|A(t_c + z)|`` is at most ``K`` on the
disc ``|z| <= rho`` (an ``acb`` evaluation on the square that holds the disc), Cauchy's estimate
gives ``||A_j|| <= K/rho^j`` (row-sum norm), so ``||Y_k|| <= y_k``, the coefficients of the
solution ``(1 - z/rho)^(-K rho)`` of the majorant equation ``y' = K/(1 - z/rho) y``, ``y(0) = 1``:
``y_k h^k = (K rho)_k/k! x^k`` with ``x = h/rho``. Their ratio is at most ``r = x max(1, (K rho +
N)/(N + 1))`` for ``k >= N``, so the tail is at most ``y_N h^N/(1 - r)`` (``r < 1``), added to
every entry as a ball radius. The step is halved until ``A`` is bounded on the square (no
singularity within ``rho``) and the tail needs at most :data:`MAX_TERMS` terms beyond half the bits
wanted; ``rho = 4 h``.

The result is proven for the ``A`` given: its entries' series and boxes are computed in ball
arithmetic, and nothing else enters.
"""

from __future__ import annotations

from flint import acb, arb, arb_series, ctx

__all__ = ["MAX_TERMS", "flow", "IntegrationError"]

#: the most Taylor terms one step may use beyond half the bits wanted (a step that needs more
#: is halved; with ``rho = 4 h`` each term gains about two bits)
MAX_TERMS = 40

#: the step's radius of convergence used, as a multiple of the step
_RHO = 4


class IntegrationError(ArithmeticError):
    """The integrator could not bound a step (a singularity of ``A`` on the path)."""


def _bound(coef, tc: arb, rho: arb) -> arb | None:
    """An upper bound of the row sums of ``|A|`` on the disc ``|z - tc| <= rho`` (or ``None``
    where ``A`` is not bounded there)."""
    with ctx.workprec(64):
        r = arb((rho + tc.rad()).upper())
        box = acb(arb(tc.mid(), r), arb(0, r))
        a = coef(box)
        rows = []
        for i in (0, 1):
            s = abs(acb(a[2 * i])) + abs(acb(a[2 * i + 1]))
            if not s.is_finite():
                return None
            rows.append(arb(s.upper()))
        return rows[0] if rows[0] >= rows[1] else rows[1]


def _terms(K: arb, rho: arb, h: arb, bits: int) -> tuple[int, arb] | None:
    """The fewest terms ``N <= bits/2 + MAX_TERMS`` whose majorant tail at ``h`` is below
    ``2^-bits``, and that tail; ``None`` if none is."""
    with ctx.workprec(64):
        Kr = K * rho
        x = h / rho
        goal = arb(2) ** (-bits)
        term = arb(1)  # (K rho)_k/k! x^k at k = 0
        for N in range(1, bits // 2 + MAX_TERMS + 1):
            term = term * (Kr + (N - 1)) / N * x
            big = (Kr + N) / (N + 1)
            r = x * (big if big > 1 else arb(1))
            if r < 1:
                tail = arb((term / (1 - r)).upper())
                if tail < goal and N >= 4:
                    return N, tail
        return None


def _step(coef, tc: arb, h: arb, N: int, tail: arb):
    """The map over ``[tc, tc + h]`` (four balls, row-major) with ``N`` Taylor terms."""
    cap = ctx.cap  # python-flint truncates every series to ctx.cap terms: N here, restored
    ctx.cap = N
    try:
        z = arb_series([tc, 1], prec=N)
        a = [_coeffs(s, N) for s in coef(z)]
    finally:
        ctx.cap = cap
    # the nonzero Taylor coefficients of each entry (a linear or constant length has few)
    sparse = [[(j, c) for j, c in enumerate(e) if not (c.is_exact() and c == 0)] for e in a]
    cols = []
    for y0 in ((arb(1), arb(0)), (arb(0), arb(1))):
        u, v = [y0[0]], [y0[1]]
        for k in range(N - 1):
            su = arb(0)
            sv = arb(0)
            for j, c in sparse[0]:
                if j <= k:
                    su += c * u[k - j]
            for j, c in sparse[1]:
                if j <= k:
                    su += c * v[k - j]
            for j, c in sparse[2]:
                if j <= k:
                    sv += c * u[k - j]
            for j, c in sparse[3]:
                if j <= k:
                    sv += c * v[k - j]
            u.append(su / (k + 1))
            v.append(sv / (k + 1))
        cols.append((_horner(u, h), _horner(v, h)))
    err = arb(0, tail)
    return (cols[0][0] + err, cols[1][0] + err, cols[0][1] + err, cols[1][1] + err)


def _coeffs(s, N: int) -> list:
    c = list(s.coeffs()) if isinstance(s, arb_series) else [arb(s)]
    return c[:N] + [arb(0)] * (N - len(c[:N]))


def _horner(c: list, h: arb) -> arb:
    acc = arb(0)
    for x in reversed(c):
        acc = acc * h + x
    return acc


def _mul(P, Q):
    a, b, c, d = P
    e, f, g, k = Q
    return (a * e + b * g, a * f + b * k, c * e + d * g, c * f + d * k)


def flow(coef, t0: arb, t1: arb, *, h0=None, scale=None):
    """The map of ``y' = A(t) y`` from ``t0`` to ``t1 > t0`` (exact ``arb`` points), as four
    ``arb`` balls (row-major) at the working precision ``flint.ctx.prec``; ``coef(t)`` returns
    the four entries of ``A(t)`` for ``t`` an ``arb_series`` or an ``acb``.  ``h0``: the first
    trial step (default ``(t1 - t0)/4``).  ``scale = w`` integrates in the variables ``(y1,
    y2/w)`` (a balanced system takes longer steps) and returns the map of ``(y1, y2)``."""
    if scale is not None:
        w = scale
        inner = coef

        def coef(t):
            a = inner(t)
            return (a[0], a[1] * w, a[2] / w, a[3])

        a, b, c, d = flow(coef, t0, t1, h0=h0)
        return (a, b / w, c * w, d)
    bits = ctx.prec + 10
    M = (arb(1), arb(0), arb(0), arb(1))
    t = t0
    span = t1 - t0
    h = arb(span.mid() / 4) if h0 is None else arb(h0)
    while True:
        rest = t1 - t
        last = not (h < rest)
        step = rest if last else h
        hm = arb(step.upper()) if last else step
        rho = hm * _RHO
        K = _bound(coef, t, rho)
        plan = None if K is None else _terms(K, rho, hm, bits)
        if plan is None:
            h = arb((hm / 2).mid())
            if h < span * arb(2) ** (-60):
                raise IntegrationError("the coefficients are not bounded near the path")
            continue
        N, tail = plan
        M = _mul(_step(coef, t, step, N, tail), M)
        if last:
            return M
        t = t + step
        if N < bits // 2 + MAX_TERMS // 2:  # the step was easy: try a longer one
            h = arb((hm * 2).mid())
