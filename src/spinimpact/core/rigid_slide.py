"""The sliding phase of one rigid-body contact in 3D whose slip direction turns, on floats.

:func:`spinimpact.core.scalar_rigid.rigid_impact` (whose notes give the model) calls
:func:`_slide` while the slip turns. The equations are integrated in ``tau = int dpn /
|v_t|`` by Dormand and Prince's 8(5,3) pair (:func:`_step`, generated from the tableau),
with events placed by Newton's method on re-taken steps; a slip that settles on a
direction ``W`` keeps goes on as the straight slide along it (:func:`_settle`), and one
about to stop is finished there to first order in its remaining turn (:func:`_finish_stop`).
Registered with Numba alongside :mod:`spinimpact.core.scalar_rigid`; nothing is validated.
"""

from __future__ import annotations

import math

import numpy as np
from scipy.integrate._ivp import dop853_coefficients as _dop853

_SAFETY = 0.9
_GROW = 5.0
_STABLE = 3.0  # the most |rate| * step in tau (the pair is stable to about 6)
_MAX_STEPS = 200_000
_STOP = 1e-14  # the slip counts as stopped below this fraction of the speed scale
_N = 4  # the sliding phase's state: the impulse (p1, p2, pn) and the normal work since its start

# Dormand and Prince's 8(5,3) pair (Hairer, Norsett & Wanner, "Solving Ordinary
# Differential Equations I", 2nd ed., sec. II.10), its coefficients as SciPy's DOP853
# solver holds them: the 12 stages' matrix, the 8th-order weights, and the two error
# estimates' weights (the 13th stage is the derivative at the step's end).
_A = np.ascontiguousarray(_dop853.A[:12, :12])
_B = np.ascontiguousarray(_dop853.B)
_E5 = np.ascontiguousarray(_dop853.E5)
_E3 = np.ascontiguousarray(_dop853.E3)
_STAGES = 12


def _rate_lines(src, dst, indent):
    """Source lines computing the sliding phase's derivatives in ``tau`` (``dtau = dpn /
    |v_t|``) of state ``src(i)`` into ``dst(i)``.

    The state is the impulse ``(p1, p2, pn)`` and the normal work since the phase began,
    with ``c0, c1, c2`` the contact velocity then: the velocity is ``c + W p`` (``w0 ..
    w5`` hold ``W``), so it needs no equations of its own and stays exactly the impulse's
    (a Runge-Kutta method keeps such linear relations to rounding anyway). Each
    derivative is ``|v_t|`` times the one in ``pn``: ``-mu v_t``, ``|v_t|`` and
    ``vn |v_t|``; no division."""
    lines = [f"v1 = c0 + w0 * {src(0)} + w1 * {src(1)} + w2 * {src(2)}",
             f"v2 = c1 + w1 * {src(0)} + w3 * {src(1)} + w4 * {src(2)}",
             f"vn = c2 + w2 * {src(0)} + w4 * {src(1)} + w5 * {src(2)}",
             "rho = math.sqrt(v1 * v1 + v2 * v2)",
             f"{dst(0)} = -mu * v1",
             f"{dst(1)} = -mu * v2",
             f"{dst(2)} = rho",
             f"{dst(3)} = vn * rho"]  # fmt: skip
    return [" " * indent + line for line in lines]


def _source():
    """The source of :func:`_slide_rate` and :func:`_step`. The step is written out stage
    by stage in local variables, the tableau's nonzero coefficients as literals, so that
    the compiler keeps everything in registers."""
    unpack = ["    w0, w1, w2, w3, w4, w5 = w[0], w[1], w[2], w[3], w[4], w[5]",
              "    c0, c1, c2 = c[0], c[1], c[2]"]  # fmt: skip
    lines = ["def _slide_rate(w, mu, c, z, k, row):", *unpack]
    lines += _rate_lines(lambda i: f"z[{i}]", lambda i: f"k[row, {i}]", 4)
    lines += ["", "", "def _step(w, mu, c, z, h, k, out):", *unpack]
    lines += [f"    z{i} = z[{i}]" for i in range(_N)]
    lines += [f"    k0_{i} = k[0, {i}]" for i in range(_N)]

    def combination(weights, stages, i):
        pairs = zip(weights[: len(stages)], stages, strict=True)
        return " + ".join(f"{float(x)!r} * k{j}_{i}" for x, j in pairs if x != 0.0)

    for stage in range(1, _STAGES):
        lines += [f"    t{i} = z{i} + h * ({combination(_A[stage], range(stage), i)})"
                  for i in range(_N)]  # fmt: skip
        lines += _rate_lines(lambda i: f"t{i}", lambda i, s=stage: f"k{s}_{i}", 4)
    lines += [f"    o{i} = z{i} + h * ({combination(_B, range(_STAGES), i)})"
              for i in range(_N)]  # fmt: skip
    lines += _rate_lines(lambda i: f"o{i}", lambda i: f"k{_STAGES}_{i}", 4)
    for i in range(_N):
        lines += [f"    out[{i}] = o{i}",
                  f"    k[{_STAGES}, {i}] = k{_STAGES}_{i}",
                  f"    k[13, {i}] = h * ({combination(_E5, range(_STAGES + 1), i)})",
                  f"    k[14, {i}] = h * ({combination(_E3, range(_STAGES + 1), i)})"]  # fmt: skip
    return "\n".join(lines) + "\n"


_generated: dict = {"math": math}
exec(compile(_source(), "<scalar_rigid._source>", "exec"), _generated)
_slide_rate = _generated["_slide_rate"]
_step = _generated["_step"]
_slide_rate.__doc__ = """The sliding phase's derivatives in ``tau`` at state ``z`` into ``k[row]``
(:func:`_rate_lines`; ``c`` the contact velocity where the phase began)."""
_step.__doc__ = """One step of the 8(5,3) pair of length ``h`` from ``z``, whose derivative is
already in ``k[0]``: the 8th-order state into ``out``, its derivative into ``k[12]``, and
the 5th- and 3rd-order error estimates of each component into ``k[13]`` and ``k[14]``."""


def _event(kind, law, kappa, vn0, wn_c, target, w, c, z):
    """An event's function at state ``z`` (it reaches 0 at the event): ``kind`` 0 the end
    of compression (``vn = 0``), 1 the end by ``law`` after compression, 2 the normal
    impulse ``target``. ``c`` holds the contact velocity, the normal work and the normal
    impulse where the phase began (``c[0:3]``, ``c[3]``, ``c[4]``)."""
    if kind == 2 or (kind == 1 and law == 1):
        return c[4] + z[2] - target
    if kind == 0 or law == 0:
        vn = c[2] + w[2] * z[0] + w[4] * z[1] + w[5] * z[2]
        return vn if kind == 0 else vn + kappa * vn0
    return (c[3] + z[3] - wn_c) + kappa * kappa * wn_c


def _rate(kind, law, w, k, row):
    """The derivative in ``tau`` of event ``kind``'s function, from the state's in
    ``k[row]``."""
    if kind == 2 or (kind == 1 and law == 1):
        return k[row, 2]
    if kind == 0 or law == 0:
        return w[2] * k[row, 0] + w[4] * k[row, 1] + w[5] * k[row, 2]
    return k[row, 3]


def _root(w, mu, c, z, h, k, out, kind, law, kappa, vn0, wn_c, target):
    """The step length in ``(0, h]`` at which event ``kind`` (:func:`_event`) crosses zero,
    by Newton's method on re-taken steps (the event's derivative is the state's at the
    step's end), kept inside the bracket by bisection, its last small correction applied
    to the state by Taylor's expansion; ``out`` holds the state there and ``k[12]`` its
    derivative. ``out`` holds the full step's state on entry."""
    a, b = 0.0, h
    fa = _event(kind, law, kappa, vn0, wn_c, target, w, c, z)
    fb = _event(kind, law, kappa, vn0, wn_c, target, w, c, out)
    # the first guess: the root of the cubic through both ends' values and derivatives
    # (the event's function is linear in the state, so these are exact)
    ra = h * _rate(kind, law, w, k, 0)
    rb = h * _rate(kind, law, w, k, _STAGES)
    u = fa / (fa - fb) if fb != fa else 0.5
    for _ in range(8):
        u2 = u * u
        u3 = u2 * u
        e = ((2.0 * u3 - 3.0 * u2 + 1.0) * fa + (u3 - 2.0 * u2 + u) * ra
             + (3.0 * u2 - 2.0 * u3) * fb + (u3 - u2) * rb)  # fmt: skip
        de = ((6.0 * u2 - 6.0 * u) * (fa - fb) + (3.0 * u2 - 4.0 * u + 1.0) * ra
              + (3.0 * u2 - 2.0 * u) * rb)  # fmt: skip
        if de == 0.0:
            break
        u -= e / de
        if not 0.0 < u < 1.0:
            u = fa / (fa - fb) if fb != fa else 0.5
            break
    t = u * h
    _step(w, mu, c, z, t, k, out)
    ft = _event(kind, law, kappa, vn0, wn_c, target, w, c, out)
    if (ft < 0.0) == (fa < 0.0):
        a, fa = t, ft
    else:
        b, fb = t, ft
    for _ in range(100):
        if ft == 0.0:
            break
        slope = _rate(kind, law, w, k, _STAGES)
        change = ft / slope if slope != 0.0 else math.inf
        if abs(change) <= 1e-7 * h and a < t - change < b:
            # the last correction by Taylor's expansion of the state: its error is
            # change^2 |z''| / 2, below 1e-14 of a step's change of the state
            t -= change
            for i in range(_N):
                out[i] -= change * k[_STAGES, i]
            _slide_rate(w, mu, c, out, k, _STAGES)
            break
        nxt = t - change
        if not a < nxt < b:
            nxt = a - fa * (b - a) / (fb - fa) if fb != fa else 0.5 * (a + b)
            if not a < nxt < b:
                nxt = 0.5 * (a + b)
        t = nxt
        _step(w, mu, c, z, t, k, out)
        ft = _event(kind, law, kappa, vn0, wn_c, target, w, c, out)
        if ft == 0.0 or b - a <= 4e-16 * h:
            break
        if (ft < 0.0) == (fa < 0.0):
            a, fa = t, ft
        else:
            b, fb = t, ft
    return t


def _slide(w, mu, kappa, law, rtol, p_max, scale, y, state, k, z, out, c, steps, vn0):
    """Integrate the sliding phase whose direction turns, from ``y`` at ``state[0]``, to the
    law's end, ``p_max``, the slip's stop (finished along its last direction) or until it
    has settled on a direction ``W`` keeps (:func:`_settle`); returns ``(steps, ended,
    settled)`` with ``y`` and ``state`` advanced (``k``, ``z``, ``out``, ``c`` scratch).

    The independent variable is ``tau`` with ``dtau = dpn / |v_t|``, not ``pn``. In ``pn``
    the slip's angle turns at ``s_perp . g(s) / |v_t|``: as the slip vanishes at a stop its
    angle and speed behave like powers of the impulse left, ``(p_stop - pn)^beta`` with
    ``beta`` in general not an integer, so a pair of fixed order takes steps that shrink
    with the slip (several hundred to reach a stop at ``rtol = 1e-13``). In ``tau`` the
    angle obeys ``dphi/dtau = s_perp . g(s)`` and ``d ln|v_t| / dtau = s . g(s)``: smooth,
    with the stop approached exponentially (``tau`` grows without bound there). The state
    is the impulse and the normal work since the phase began (:func:`_rate_lines`); every
    event (compression's end, the law's end, ``p_max``) is a root of a function of it, and
    the tangential work follows at the end from the work of the impulse,
    ``p . (v_before + v_after) / 2`` over the phase.

    The pair is Dormand and Prince's 8(5,3) with its combined error estimate, kept to
    ``rtol`` times the speed scale for the velocity ``W p`` per step; each step is also
    kept within ``|rate| h <= 3`` for both rates of the linearized equations (well inside
    the pair's region of stability, about 6 on the real axis), where that estimate holds:
    beyond it, on directions already settled, it fell 100-fold short of the error.
    """
    p0 = state[0]
    for i in range(3):
        c[i] = y[i]
    c[3] = y[3]
    c[4] = p0
    for i in range(_N):
        z[i] = 0.0
    compressed = state[1] > 0.0
    p_c, wn_c, wt_c = state[2], state[3], state[5]
    trace = w[0] + w[3] + w[5]
    p_unit = scale / trace  # W p then errs by at most rtol * scale
    tol_v = rtol * scale
    h = 0.01 * abs(y[2]) / w[5] / math.hypot(y[0], y[1])
    ended = False
    settled = False
    _slide_rate(w, mu, c, z, k, 0)
    while steps < _MAX_STEPS:
        v1 = c[0] + w[0] * z[0] + w[1] * z[1] + w[2] * z[2]
        v2 = c[1] + w[1] * z[0] + w[3] * z[1] + w[4] * z[2]
        rho = math.sqrt(v1 * v1 + v2 * v2)
        if rho <= _STOP * scale or p0 + z[2] >= p_max:
            break
        a, gp, dgp, da = _turn(w, mu, v1 / rho, v2 / rho)
        if _settle(w, mu, rho, trace, tol_v, a, gp, dgp):
            settled = True
            break
        if a < 0.0 and rho < 1e-3 * scale:
            dp = _stop_close(w, mu, v1, v2, trace, tol_v, scale)
            if dp > 0.0:  # close to the stop: finish there unless an event comes first
                vn = c[2] + w[2] * z[0] + w[4] * z[1] + w[5] * z[2]
                vn_end = vn + dp * (w[5] - mu * (w[2] * v1 + w[4] * v2) / rho)
                p_end = p0 + z[2] + dp
                if not compressed:
                    first = vn_end >= 0.0
                elif law == 0:
                    first = vn_end + kappa * vn0 >= 0.0
                elif law == 1:
                    first = p_end >= (1.0 + kappa) * p_c
                else:
                    wn = c[3] + z[3] + 0.5 * dp * (vn + vn_end)
                    first = (wn - wn_c) + kappa * kappa * wn_c >= 0.0
                if not first and p_end < p_max:
                    break
        h = min(h, _STABLE / max(abs(a), abs(dgp)))
        _step(w, mu, c, z, h, k, out)
        steps += 1
        e5 = max(abs(k[13, 0]), abs(k[13, 1]), abs(k[13, 2])) / (rtol * p_unit)
        e3 = max(abs(k[14, 0]), abs(k[14, 1]), abs(k[14, 2])) / (rtol * p_unit)
        e5 = max(e5, abs(k[13, 3]) / (tol_v * p_unit))
        e3 = max(e3, abs(k[14, 3]) / (tol_v * p_unit))
        err = e5 * e5 / math.sqrt(e5 * e5 + 0.01 * e3 * e3) if e5 > 0.0 else 0.0
        err = max(err, 1e-4 * e5)  # and trusted 10,000-fold at most
        if err > 1.0:
            h *= max(0.2, _SAFETY * err**-0.125)
            continue
        # the first event within the step, if any
        kind = -1
        t = h
        target = math.inf
        if not compressed and _event(0, law, kappa, vn0, wn_c, target, w, c, out) >= 0.0:
            kind = 0
        elif compressed:
            target = (1.0 + kappa) * p_c if law == 1 else math.inf
            if _event(1, law, kappa, vn0, wn_c, target, w, c, out) >= 0.0:
                kind = 1
        if kind >= 0:
            t = _root(w, mu, c, z, h, k, out, kind, law, kappa, vn0, wn_c, target)
        if p0 + out[2] > p_max:  # p_max comes first
            if kind >= 0:
                _step(w, mu, c, z, h, k, out)
            kind = 2
            target = p_max
            t = _root(w, mu, c, z, h, k, out, kind, law, kappa, vn0, wn_c, target)
        for i in range(_N):
            z[i] = out[i]
            k[0, i] = k[_STAGES, i]
        if kind == 0:
            compressed = True
            p_c = p0 + z[2]
            wn_c = c[3] + z[3]
            wt_c = y[4] + _impulse_work(w, c, z) - z[3]
            if law != 1 and _event(1, law, kappa, vn0, wn_c, math.inf, w, c, z) >= 0.0:
                ended = True  # kappa = 0 (or kappa^2 below the smallest float)
                break
            if law == 1 and kappa == 0.0:
                ended = True
                break
            h = t
            continue
        if kind == 1:
            ended = True
            break
        if kind == 2:
            z[2] = p_max - p0
            break
        h *= min(_GROW, _SAFETY * max(err, 1e-10) ** -0.125)
    # the state from the impulse: the velocity c + W p, and the tangential work from the
    # impulse's work p . (v_before + v_after) / 2 less the normal work
    v1 = c[0] + w[0] * z[0] + w[1] * z[1] + w[2] * z[2]
    v2 = c[1] + w[1] * z[0] + w[3] * z[1] + w[4] * z[2]
    vn = c[2] + w[2] * z[0] + w[4] * z[1] + w[5] * z[2]
    y[4] += _impulse_work(w, c, z) - z[3]
    y[0], y[1], y[2] = v1, v2, vn
    y[3] = c[3] + z[3]
    y[5] += z[0]
    y[6] += z[1]
    p = p0 + z[2]
    if settled:
        _settled_slip(w, mu, y)
    elif not ended and p < p_max and steps < _MAX_STEPS:
        p += _finish_stop(w, mu, y)
        state[4] = p
    state[0] = p
    if compressed:
        state[1], state[2], state[3], state[5] = 1.0, p_c, wn_c, wt_c
    return steps, ended, settled


def _impulse_work(w, c, z):
    """The work of the impulse ``z[0:3]`` on a body whose contact velocity was ``c[0:3]``
    before it, ``p . (v_before + v_after) / 2`` with ``v_after = c + W p`` (exact for rigid
    bodies: ``W`` is symmetric)."""
    v1 = c[0] + w[0] * z[0] + w[1] * z[1] + w[2] * z[2]
    v2 = c[1] + w[1] * z[0] + w[3] * z[1] + w[4] * z[2]
    vn = c[2] + w[2] * z[0] + w[4] * z[1] + w[5] * z[2]
    return 0.5 * (z[0] * (c[0] + v1) + z[1] * (c[1] + v2) + z[2] * (c[2] + vn))


def _stop_direction(w, mu, c, s):
    """The direction ``(c, s)`` that ``W`` keeps (``g_perp = 0``) nearest the slip's, by
    Newton's method in its angle, with its slip rate ``a``, or ``nan`` where the iteration
    fails or the direction is not one along which a slip shrinks (``a < 0``) and which
    draws the slip's direction to it (``dg_perp/dphi < 0``; a slip near a direction that
    repels it swings past zero instead of stopping)."""
    a, gp, dgp, da = _turn(w, mu, c, s)
    phi = math.atan2(s, c)
    start = phi
    for _ in range(8):
        if dgp == 0.0:
            return math.nan, math.nan, math.nan
        phi -= gp / dgp
        c, s = math.cos(phi), math.sin(phi)
        a, gp, dgp, da = _turn(w, mu, c, s)
    if (abs(gp) > 1e-12 * (abs(a) + mu * (w[0] + w[3])) or abs(phi - start) > 0.3
            or a >= 0.0 or dgp >= 0.0):  # fmt: skip
        return math.nan, math.nan, math.nan
    return c, s, a


def _stop_close(w, mu, v1, v2, trace, tol_v, scale):
    """Whether a shrinking slip ``(v1, v2)`` is close enough to its stop for
    :func:`_finish_stop`: the normal impulse to the stop (about ``|v_t| / |a*|``) if so,
    else 0. With ``d`` its angle from the direction ``s*`` it stops along and ``a*`` the
    rate there, the neglected terms move the velocity by at most ``tr W mu d^2 |v_t| /
    |a*|`` and the normal work by ``tr W mu |d| |v_t|^2 / a*^2`` times ``tr W``: each
    must be below its tolerance."""
    rho = math.hypot(v1, v2)
    c, s, a = _stop_direction(w, mu, v1 / rho, v2 / rho)
    if math.isnan(a):
        return 0.0
    d = math.atan2(v2 * c - v1 * s, v1 * c + v2 * s)
    first = trace * mu * d * d * rho / -a
    second = trace * trace * mu * abs(d) * rho * rho / (a * a) / (scale / trace)
    return rho / -a if first + second <= tol_v else 0.0


def _finish_stop(w, mu, y):
    """Finish a slip ``y[0:2]`` that is about to stop; returns the normal impulse it takes,
    with ``y`` advanced to the stop.

    It stops along a direction ``s*`` that ``W`` keeps, ``g(s*) = a* s*`` with ``a* < 0``
    (:func:`_stop_direction`). To first order in the slip's angle ``d`` from ``s*`` the
    tangential impulse left is ``-mu s* dp + q s*_perp`` (``q`` what the turn adds
    across), and the slip after it is zero: ``v_t + a* s* dp + q W_tt s*_perp = 0``, two
    equations for ``dp`` and ``q``. What is left out is of order ``mu d^2 dp``. Where no
    such direction is found (a slip of rounding size), the slip is finished along its own
    direction. The normal work is the trapezoid's (``vn`` is linear in the impulse but for
    the ``q`` part), the tangential work the rest of the impulse's work
    ``p . (v_before + v_after) / 2``."""
    rho = math.hypot(y[0], y[1])
    c, s, a = _stop_direction(w, mu, y[0] / rho, y[1] / rho)
    if math.isnan(a):  # along the slip's own direction
        c, s = y[0] / rho, y[1] / rho
        g1 = w[2] - mu * (w[0] * c + w[1] * s)
        g2 = w[4] - mu * (w[1] * c + w[3] * s)
        a = c * g1 + s * g2
        dp = rho / -a if a < 0.0 else 0.0
        q1, q2 = -mu * c * dp, -mu * s * dp
    else:
        # columns a* s* and W_tt s*_perp; solve for (dp, q) by Cramer's rule
        m11, m21 = a * c, a * s
        m12 = -w[0] * s + w[1] * c
        m22 = -w[1] * s + w[3] * c
        det = m11 * m22 - m12 * m21
        dp = (-y[0] * m22 + y[1] * m12) / det
        q = (-m11 * y[1] + m21 * y[0]) / det
        q1 = -mu * c * dp - q * s
        q2 = -mu * s * dp + q * c
    vn = y[2] + w[2] * q1 + w[4] * q2 + w[5] * dp
    normal = 0.5 * dp * (y[2] + vn)
    work = 0.5 * (q1 * y[0] + q2 * y[1] + dp * (y[2] + vn))  # the slip ends at zero
    y[3] += normal
    y[4] += work - normal
    y[2] = vn
    y[5] += q1
    y[6] += q2
    y[0] = y[1] = 0.0
    return dp


def _turn(w, mu, c, s):
    """At the slip direction ``(c, s)`` (cosine and sine of its angle ``phi``): the slip's
    growth ``a = s . g(s)``, its turning ``g_perp = s_perp . g(s)``, and their derivatives
    in ``phi``: ``dg_perp/dphi = -a - mu s_perp . W_tt s_perp`` and
    ``da/dphi = g_perp - mu s . W_tt s_perp``."""
    g1 = w[2] - mu * (w[0] * c + w[1] * s)
    g2 = w[4] - mu * (w[1] * c + w[3] * s)
    a = c * g1 + s * g2
    gp = c * g2 - s * g1
    dgp = -a - mu * (w[0] * s * s - 2.0 * w[1] * c * s + w[3] * c * c)
    da = gp - mu * (-w[0] * c * s + w[1] * (c * c - s * s) + w[3] * c * s)
    return a, gp, dgp, da


def _settle(w, mu, rho, trace, tol_v, a, gp, dgp):
    """Whether the slip has settled on a direction ``s*`` that ``W`` keeps
    (``g_perp(s*) = 0``, drawn to it: ``dg_perp/dphi < 0``), closely enough that the rest
    of the slide is the straight one along ``s*`` (:func:`_settled_slip` sets it).

    In ``tau`` (``dtau = dpn / |v_t|``), with ``d = phi - phi*``, ``d' = g_perp'(phi*) d``
    and ``(ln |v_t|)' = a* + a'(phi*) d`` to first order in ``d``: ``d`` decays as
    ``exp(g_perp' tau)``, and the slip goes on as the straight slide along ``s*`` from the
    speed ``|v_t| exp(-a' d / g_perp')``. Where ``|g_perp'|`` far exceeds ``|a|`` (near
    the stick boundary ``|W_tt^-1 W_tn| = mu``, for one) the equations are stiff and an
    explicit pair would crawl at its stability limit with the direction fixed to
    rounding. What this neglects: the transient's impulse, ``|v_t| |d| mu / |g_perp'|``
    in each direction, the slip's jump ``|v_t| |d|`` onto the straight slide, and the
    second order of ``d`` in the speed, ``|v_t| d^2 mu tr W / |g_perp'|``, which moves a
    stop by that over ``|a|`` (a slip that grows: by that over ``|g_perp'|``). Their
    effect on the velocity, bounded with ``tr W``, must be below the step's tolerance
    ``tol_v``, and ``|d| < 1e-3``."""
    if a == 0.0 or dgp >= 0.0 or abs(gp) >= 1e-3 * -dgp:
        return False
    d = gp / dgp
    first = rho * abs(d) * (1.0 + trace * (mu + mu * trace / -dgp) / -dgp)
    second = rho * d * d * mu * trace * trace / (-dgp * (-a if a < 0.0 else -dgp))
    if first + second > tol_v:
        return False
    return True


def _settled_slip(w, mu, y):
    """The slip ``y[0:2]`` moved onto the straight slide it settles on (:func:`_settle`):
    the direction ``s*`` by Newton's method from the slip's, the speed
    ``|v_t| exp(-a' d / g_perp')`` with ``d = phi - phi*``."""
    rho = math.hypot(y[0], y[1])
    c, s = y[0] / rho, y[1] / rho
    a, gp, dgp, da = _turn(w, mu, c, s)
    phi = math.atan2(s, c)
    for _ in range(4):  # Newton's method for phi*
        phi -= gp / dgp
        c, s = math.cos(phi), math.sin(phi)
        a, gp, dgp, da = _turn(w, mu, c, s)
    d = math.atan2(y[1] * c - y[0] * s, y[0] * c + y[1] * s)  # phi - phi*, from the state
    speed = rho * math.exp(-da * d / dgp)
    y[0] = speed * c
    y[1] = speed * s
