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
every entry as a ball radius.  That majorant is pessimistic (its terms shrink by about ``x``
each, where the solution's shrink like ``(|A| h)^k/k!``), so the recurrence stops sooner where
a **defect bound** proves the remainder small: with ``P`` the Taylor polynomial of ``n`` terms,
``P' = [A P]_{< n-1}`` (the recurrence), so ``R = Y - P`` solves ``R' = A R + [A P]_{>= n-1}``,
``R(0) = 0``; on ``[t_c, t_c + h]`` the forcing is at most ``sum_i ||Y_i|| h^i sum_{j >= n-1-i}
||A_j|| h^j`` (the ``A_j`` computed, for ``j < bits/2 + 8``; Cauchy's ``K/rho^j`` beyond), and
Gronwall's lemma with ``||A|| <= K_r`` on the segment bounds ``||R(h)||`` by ``h e^(K_r h)``
times that.  The step is halved until ``A`` is bounded on the square (no singularity within
``rho``) and one of the two bounds is below ``2^-bits`` within the majorant's count of terms
(at most :data:`MAX_TERMS` beyond half the bits wanted), and doubled after a step that needed
fewer than ``bits/``:data:`_GROW` terms; ``rho = 4 h``.

The result is proven for the ``A`` given: its entries' series and boxes are computed in ball
arithmetic, and nothing else enters.
"""

from __future__ import annotations

from bisect import bisect_right
from operator import mul

from flint import acb, arb, arb_series, ctx

__all__ = ["MAX_TERMS", "flow", "IntegrationError"]

#: the most Taylor terms one step may use beyond half the bits wanted (a step that needs more
#: is halved; with ``rho = 4 h`` each term gains about two bits)
MAX_TERMS = 40

#: a step that needed fewer than ``bits/_GROW`` terms is followed by a trial step twice as long
_GROW = 4

#: the step's radius of convergence used, as a multiple of the step
_RHO = 4


class IntegrationError(ArithmeticError):
    """The integrator could not bound a step (a singularity of ``A`` on the path)."""


def _bound(coef, tc: arb, rho: arb, real: bool = False) -> arb | None:
    """An upper bound of the row sums of ``|A|`` on the disc ``|z - tc| <= rho`` (``real``: on
    the segment ``|t - tc| <= rho``), or ``None`` where ``A`` is not bounded there."""
    with ctx.workprec(64):
        r = arb((rho + tc.rad()).upper())
        box = acb(arb(tc.mid(), r), 0 if real else arb(0, r))
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


def _step(coef, tc: arb, h: arb, N: int, tail: arb | None, K: arb, rho: arb, bits: int):
    """The map over ``[tc, tc + h]`` (four balls, row-major): at most ``N`` Taylor terms with
    the majorant's tail ``tail``, fewer where the defect bound (:func:`_defect_tail`) proves
    the remainder below ``2^-bits`` sooner."""
    M = bits // 2 + 8  # the coefficients of A summed explicitly (balls); Cauchy beyond
    L = max(N, M)
    cap = ctx.cap  # python-flint truncates every series to ctx.cap terms: L here, restored
    ctx.cap = L
    try:
        z = arb_series([tc, 1], prec=L)
        a = [_coeffs(s, L) for s in coef(z)]
    finally:
        ctx.cap = cap
    # the nonzero Taylor coefficients of each entry (a linear or constant length has few), as
    # their powers ``js`` (ascending) and values ``cs``; ``dense``: every power below the last
    sparse = []
    for e in a:
        pairs = [(j, c) for j, c in enumerate(e[:N]) if not (c.is_exact() and c == 0)]
        js = [j for j, _ in pairs]
        sparse.append((js, [c for _, c in pairs], js == list(range(len(js)))))
    with ctx.workprec(64):
        hh = arb(h.upper())
        x = hh / rho
        # above[m]: sum over m <= j < M of ||A_j|| h^j, plus Cauchy's bound of the j >= M
        rows = [
            [e for e in a[2 * i : 2 * i + 2] if not all(c.is_exact() and c == 0 for c in e)]
            for i in (0, 1)
        ]
        above = [arb(0)] * (M + 1)
        above[M] = _upper(K * x**M / (1 - x))
        for j in range(M - 1, -1, -1):
            r = max((sum(abs(e[j]) for e in row) if row else arb(0)).upper() for row in rows)
            above[j] = _upper(above[j + 1] + arb(r) * hh**j)
        Kr = _bound(coef, tc + hh / 2, hh / 2, real=True)
        grow = hh * ((K if Kr is None else Kr) * hh).exp()
        hpow = [hh**i for i in range(N)]
    goal = arb(2) ** (-bits)
    cols = ([arb(1)], [arb(0)], [arb(0)], [arb(1)])  # u, v of column 0; u, v of column 1
    yn = [arb(1)]  # ||Y_k|| h^k (upper bounds, 64 bits)
    zero = arb(0)
    for k in range(N - 1):
        for u, v in (cols[0:2], cols[2:4]):
            # (k + 1) Y_{k+1} = sum_j A_j Y_{k-j}: the products c_j y_{k-j} of each entry summed
            # from arb(0) in the order of j, entry (0, 0) then (0, 1) for u, (1, 0) then (1, 1)
            # for v (sum() adds left to right: the same ball arithmetic as a loop)
            u.append(
                sum(_terms_of(sparse[1], v, k), sum(_terms_of(sparse[0], u, k), zero)) / (k + 1)
            )
            v.append(
                sum(_terms_of(sparse[3], v, k), sum(_terms_of(sparse[2], u, k), zero)) / (k + 1)
            )
        with ctx.workprec(64):
            yn.append(_upper(_rows(cols[i][k + 1] for i in (0, 2, 1, 3))) * hpow[k + 1])
            n = k + 2  # the terms known
            if n >= 4 and n <= N and yn[-1] < goal:
                bound = _defect_tail(yn, above, grow)
                if bound < goal:
                    tail = bound
                    break
    else:
        if tail is None:
            return None
    c = [_horner(col, h) for col in cols]
    err = arb(0, tail)
    return (c[0] + err, c[2] + err, c[1] + err, c[3] + err), len(cols[0])


def _terms_of(entry, y: list, k: int):
    """The products ``c_j y[k - j]`` of one entry's nonzero coefficients ``c_j`` (``j <= k``),
    in the order of ``j`` (``entry``: the powers, the values, and whether they are dense)."""
    js, cs, dense = entry
    if dense:  # c_0 y_k, c_1 y_{k-1}, ...: zip stops at the shorter
        return map(mul, cs, y[k::-1])
    n = bisect_right(js, k)
    return map(mul, cs[:n], [y[k - j] for j in js[:n]])


def _rows(entries) -> arb:
    """The row-sum norm of a 2x2 matrix given row-major (an upper bound, 64 bits)."""
    a, b, c, d = entries
    return arb(max((abs(a) + abs(b)).upper(), (abs(c) + abs(d)).upper()))


def _upper(x: arb) -> arb:
    return arb(x.upper())


def _defect_tail(yn: list, above: list, grow: arb) -> arb:
    """A proven bound of the remainder ``R(h) = Y(h) - sum_{k < n} Y_k h^k`` (``n = len(yn)``,
    ``yn[k] >= ||Y_k|| h^k``).  ``R' = A R + r`` with ``R(0) = 0`` and ``r = [A P]_{>= n-1}``
    the part of degree ``n - 1`` and up of ``A`` times the Taylor polynomial ``P``, since ``P'
    = [A P]_{< n-1}`` (the recurrence).  On ``[0, h]``: ``||r|| <= sum_i yn[i] sum_{j >= n-1-i}
    ||A_j|| h^j`` (``above[m]``, the coefficients known to ``M`` and Cauchy's ``K/rho^j``
    beyond), and Gronwall's lemma with ``||A|| <= K`` gives ``||R(h)|| <= h e^(K h) max ||r||``
    (``grow = h e^(K h)``)."""
    with ctx.workprec(64):
        n = len(yn)
        r = arb(0)
        for i in range(n):
            r += yn[i] * above[min(n - 1 - i, len(above) - 1)]
        return _upper(grow * r)


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


def flow(coef, t0: arb, t1: arb, *, h0=None, scale=None, goal_bits=None):
    """The map of ``y' = A(t) y`` from ``t0`` to ``t1 > t0`` (exact ``arb`` points), as four
    ``arb`` balls (row-major) at the working precision ``flint.ctx.prec``; ``coef(t)`` returns
    the four entries of ``A(t)`` for ``t`` an ``arb_series`` or an ``acb``.  ``h0``: the first
    trial step (default ``(t1 - t0)/4``).  ``scale = w`` integrates in the variables ``(y1,
    y2/w)`` (a balanced system takes longer steps) and returns the map of ``(y1, y2)``.
    ``goal_bits``: each step's remainder is bounded below ``2^-goal_bits`` (default the working
    precision plus 10 bits); a smaller goal gives wider balls, still proven, in fewer terms."""
    if scale is not None:
        w = scale
        inner = coef

        def coef(t):
            a = inner(t)
            return (a[0], a[1] * w, a[2] / w, a[3])

        a, b, c, d = flow(coef, t0, t1, h0=h0, goal_bits=goal_bits)
        return (a, b / w, c * w, d)
    bits = ctx.prec + 10 if goal_bits is None else goal_bits
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
        if K is not None:
            N, tail = plan if plan is not None else (bits // 2 + MAX_TERMS, None)
            done = _step(coef, t, step, N, tail, K, rho, bits)
        if K is None or done is None:
            h = arb((hm / 2).mid())
            if h < span * arb(2) ** (-60):
                raise IntegrationError("the coefficients are not bounded near the path")
            continue
        P, used = done
        M = _mul(P, M)
        if last:
            return M
        t = t + step
        if used < bits // _GROW:  # the step was easy: try a longer one
            h = arb((hm * 2).mid())
