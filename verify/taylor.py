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
fewer than ``bits/``:data:`_GROW` terms; ``rho = 4 h``.  The coefficients of ``A`` are computed
to ``bits/2 + 8`` terms first, and the majorant's count ``N`` only where the recurrence needs
more (the defect bound usually stops it sooner): with ``n >= N`` terms computed, the remainder
``sum_{k >= n} Y_k h^k`` is at most the majorant's tail after ``N`` (its terms are nonnegative).

The result is proven for the ``A`` given: its entries' series and boxes are computed in ball
arithmetic, and nothing else enters.
"""

from __future__ import annotations

from bisect import bisect_right
from operator import mul

from flint import acb, arb, arb_series, ctx

from .certify import CertificationError

__all__ = ["MAX_TERMS", "MAX_STEPS", "flow", "IntegrationError"]

#: the most Taylor terms one step may use beyond half the bits wanted (a step that needs more
#: is halved; with ``rho = 4 h`` each term gains about two bits)
MAX_TERMS = 40

#: a step that needed fewer than ``bits/_GROW`` terms is followed by a trial step twice as long
_GROW = 4

#: the step's radius of convergence used, as a multiple of the step
_RHO = 4


class IntegrationError(CertificationError):
    """The integrator could not bound a step (a singularity of ``A`` on the path), or the path
    needs more than :data:`MAX_STEPS` steps."""


#: the most Taylor steps one :func:`flow` tries (taken or shortened).  Where the coefficients
#: vary fast (a length that comes close to zero: the sine modulation at a depth near 1 over a
#: long period) the steps are short and many, each of them dear; a path that needs more is
#: refused, and so is one whose steps so far, extrapolated over the whole span, would number more
#: (checked from the :data:`_FORESEE`-th step on).
MAX_STEPS = 3000
_FORESEE = 64


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


def _series(coef, tc: arb, L: int) -> list:
    """The first ``L`` Taylor coefficients of each entry of ``A`` at ``tc`` (balls)."""
    cap = ctx.cap  # python-flint truncates every series to ctx.cap terms: L here, restored
    ctx.cap = L
    try:
        z = arb_series([tc, 1], prec=L)
        return [_coeffs(s, L) for s in coef(z)]
    finally:
        ctx.cap = cap


def _sparse(a: list) -> list:
    """Per entry: the powers ``js`` (ascending) of its nonzero coefficients, their values, and
    whether they are dense (every power below the last); a constant length has few."""
    out = []
    for e in a:
        pairs = [(j, c) for j, c in enumerate(e) if not (c.is_exact() and c == 0)]
        js = [j for j, _ in pairs]
        out.append((js, [c for _, c in pairs], js == list(range(len(js)))))
    return out


def _above(a: list, sparse: list, M: int, hpow: list, K: arb, x: arb) -> list:
    """``above[m] >= sum_{j >= m} ||A_j|| h^j`` for ``m <= M`` (64 bits): the row sums of the
    coefficients' absolute values (upper bounds) for ``j < M``, Cauchy's ``||A_j|| <= K/rho^j``
    beyond (``x = h/rho``: ``sum_{j >= M} K x^j = K x^M/(1 - x)``).  ``hpow[j] >= h^j``;
    ``sparse``: :func:`_sparse` of ``a`` (an entry without nonzero coefficients is left out)."""
    rows = [[a[e] for e in (2 * i, 2 * i + 1) if sparse[e][0]] for i in (0, 1)]
    sums = []
    for row in rows:
        if len(row) == 1:
            sums.append([abs(c).upper() for c in row[0][:M]])
        elif row:
            sums.append(
                [(abs(p) + abs(q)).upper() for p, q in zip(row[0][:M], row[1][:M], strict=True)]
            )
    if not sums:
        r = [arb(0)] * M
    elif len(sums) == 1:
        r = sums[0]
    else:  # exact numbers: the comparison is exact
        r = [p if p >= q else q for p, q in zip(*sums, strict=True)]
    above = [arb(0)] * (M + 1)
    acc = above[M] = _upper(K * x**M / (1 - x))
    for j in range(M - 1, -1, -1):
        acc = above[j] = _upper(acc + r[j] * hpow[j])
    return above


def _step(coef, tc: arb, h: arb, K: arb, rho: arb, bits: int):
    """The map over ``[tc, tc + h]`` (four balls, row-major) and the number of Taylor terms
    used: as many as the defect bound (:func:`_defect_tail`) needs to prove the remainder below
    ``2^-bits``, or the majorant's count (:func:`_terms`) with its tail where that is fewer;
    ``None`` where neither is below ``2^-bits`` within ``bits/2 +`` :data:`MAX_TERMS` terms.

    The coefficients of ``A`` are computed to ``M = bits/2 + 8`` terms first (the defect bound
    sums them explicitly); the majorant is asked only where the recurrence needs more."""
    M = bits // 2 + 8  # the coefficients of A summed explicitly (balls); Cauchy beyond
    a = _series(coef, tc, M)
    sparse = _sparse(a)
    with ctx.workprec(64):
        hh = arb(h.upper())
        x = hh / rho
        hpow = [arb(1)]  # upper bounds of h^j
        for _ in range(M):
            hpow.append(_upper(hpow[-1] * hh))
        above = _above(a, sparse, M, hpow, K, x)
        Kr = _bound(coef, tc + hh / 2, hh / 2, real=True)
        grow = hh * ((K if Kr is None else Kr) * hh).exp()
    goal = arb(2) ** (-bits)
    cols = ([arb(1)], [arb(0)], [arb(0)], [arb(1)])  # u, v of column 0; u, v of column 1
    yn = [arb(1)]  # ||Y_k|| h^k (upper bounds, 64 bits)
    zero = arb(0)
    known = M  # the coefficients of A known: Y_0 .. Y_known computable
    N = None  # the majorant's count of terms (asked for when the recurrence passes M)
    tail = None
    k = 0
    while True:
        n = k + 1  # the terms known: Y_0 .. Y_k
        if N is not None and n >= N:
            break  # the majorant's count: its tail bounds the rest
        if k + 1 > known:
            # the defect bound has not sufficed within M terms: the majorant's count
            plan = _terms(K, rho, hh, bits)
            N, tail = plan if plan is not None else (bits // 2 + MAX_TERMS, None)
            if n >= N:
                break  # with n >= N terms the majorant's tail after N bounds the rest
            a = _series(coef, tc, N)
            sparse = _sparse(a)
            known = N
        for u, v in (cols[0:2], cols[2:4]):
            # (k + 1) Y_{k+1} = sum_j A_j Y_{k-j}: the products c_j y_{k-j} of each entry
            # summed in the order of j (sum() adds left to right)
            u.append(
                sum(_terms_of(sparse[1], v, k), sum(_terms_of(sparse[0], u, k), zero)) / (k + 1)
            )
            v.append(
                sum(_terms_of(sparse[3], v, k), sum(_terms_of(sparse[2], u, k), zero)) / (k + 1)
            )
        k += 1
        with ctx.workprec(64):
            while len(hpow) <= k:
                hpow.append(_upper(hpow[-1] * hh))
            yn.append(_rows(cols[0][k], cols[2][k], cols[1][k], cols[3][k]) * hpow[k])
            if k + 1 >= 4 and yn[-1] < goal:
                bound = _defect_tail(yn, above, grow)
                if bound < goal:
                    tail = bound
                    break
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


def _rows(a: arb, b: arb, c: arb, d: arb) -> arb:
    """The row-sum norm of the 2x2 matrix ``[[a, b], [c, d]]`` (an upper bound, 64 bits)."""
    r0, r1 = (abs(a) + abs(b)).upper(), (abs(c) + abs(d)).upper()
    return r0 if r0 >= r1 else r1  # exact numbers: the comparison is exact


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
    whole = float(span.mid())
    tries = 0
    h = arb(span.mid() / 4) if h0 is None else arb(h0)
    while True:
        rest = t1 - t
        last = not (h < rest)
        step = rest if last else h
        hm = arb(step.upper()) if last else step
        rho = hm * _RHO
        tries += 1
        if tries >= _FORESEE and tries * whole > MAX_STEPS * float((t - t0).mid()):
            raise IntegrationError(
                f"the coefficients vary too fast to integrate over this period: {tries} Taylor "
                f"steps cover {float(((t - t0) / span).mid()):.2g} of it (at most {MAX_STEPS} "
                "in all); ask for a smaller depth m or a shorter period T"
            )
        K = _bound(coef, t, rho)
        done = None if K is None else _step(coef, t, step, K, rho, bits)
        if done is None:
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
