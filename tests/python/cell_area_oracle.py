"""An independent high-precision computation of the area of a Voronoi cell of
disjoint ellipses (the set-Voronoi convention: the site's own area
included), to check ellvor's certified intervals (cells/cell_area.hpp)
without sharing any of its code.

The cell of site p is swept by p's outward normal rays: the point
V = P(theta) + s n(theta) of the ray at p's tangency angle theta, with
P = C + R (a cos, b sin) and n = R (b cos, a sin) (unnormalized, |n| = N),
is at distance s N from p, and the cell's boundary on that ray is at the
smallest s where V is as close to another site q as to p. That s is a root
of the pair (V - Q(phi)) . Q'(phi) = 0 (phi is V's foot point on q),
|V - Q(phi)|^2 = (s N)^2, solved here by Newton's method in mpmath from a
double-precision start (bisection along the ray, with Eberly's foot-point
equation for the distance to an ellipse). The area is
    pi a b + sum over the edges of  integral of (s N^2 + a b s^2 / 2) dtheta
(the Jacobian of (theta, s) -> V), the edges' angle ranges found by
sampling which neighbour is closest along the rays and refining each change
to the angle where two neighbours' roots meet (the Voronoi vertex, by the
secant method in mpmath), and each integral by Gauss-Legendre rules of
mpmath (24 and 48 nodes, halving the range until they agree to the goal:
quad_digits, 30 by default, relative to the area). Every vertex is checked to be a
Voronoi vertex against all sites (its circle has no site closer than its
radius), so a wrong neighbour list shows up as an error, not a wrong area.

Public: read_ell, Ellipse, cell_area(sites, p, neighbours), UnboundedCell.
Working precision: DPS (50) digits.
"""

import bisect
import math
from fractions import Fraction

import mpmath
import numpy as np
from mpmath.calculus.quadrature import GaussLegendre

DPS = 50
QUAD_DIGITS = 30  # the quadrature's goal, relative to the cell's area
mp = mpmath.mp
# Gauss-Legendre nodes cost a second a degree at 50 digits: one rule (with
# its cache of nodes) for every call.
_GAUSS_LEGENDRE = GaussLegendre(mp)


def read_ell(text):
    """The sites of a .ell text as (a, b, w, xc, yc) tuples of Fractions."""
    sites = []
    for line in text.splitlines():
        line = line.split("#", 1)[0].strip()
        if line:
            sites.append(tuple(Fraction(t) for t in line.split()))
    return sites


def _ray(site, ct, st):
    """P and the unnormalized outward normal n at the angle of cosine ct and
    sine st, for `site` = (a, b, cos, sin, xc, yc) in any number type."""
    a, b, c, s, xc, yc = site
    return (xc + c * a * ct - s * b * st, yc + s * a * ct + c * b * st,
            c * b * ct - s * a * st, s * b * ct + c * a * st)


class Ellipse:
    """One site: semi-axes a, b, rotation (cos, sin) from w = tan(omega/2)
    and centre, exactly (Fractions), in mpmath (at the precision in force
    when made) and in doubles."""

    def __init__(self, a, b, w, xc, yc):
        a, b, w, xc, yc = map(Fraction, (a, b, w, xc, yc))
        c = (1 - w * w) / (1 + w * w)
        s = 2 * w / (1 + w * w)
        self.exact = (a, b, c, s, xc, yc)
        self.mp = tuple(mpmath.mpf(v.numerator) / v.denominator for v in self.exact)
        self.f = tuple(float(v) for v in self.exact)

    # -- doubles, vectorized over numpy arrays -------------------------------

    def distance_f(self, x, y):
        """Distance from points (arrays) to the ellipse; -1 for a point
        inside (only its sign is used there)."""
        a, b, c, s, xc, yc = self.f
        dx, dy = x - xc, y - yc
        u, v = c * dx + s * dy, -s * dx + c * dy
        inside = (u / a) ** 2 + (v / b) ** 2 <= 1
        t = self._foot_t_f(u, v)
        d = t * np.sqrt((u / (t + a * a)) ** 2 + (v / (t + b * b)) ** 2)
        return np.where(inside, -1.0, d)

    def _foot_t_f(self, u, v):
        """Eberly's t >= 0 of an outside point in the ellipse's frame: the
        foot point is (a^2 u / (t + a^2), b^2 v / (t + b^2)), at distance
        t |(u / (t + a^2), v / (t + b^2))|. The left side of
        (a u / (t + a^2))^2 + (b v / (t + b^2))^2 = 1 is convex and
        decreasing: Newton from the lower bound sqrt(a^2 u^2 + b^2 v^2) - max(a, b)^2
        climbs monotonically to the root."""
        a, b = self.f[0], self.f[1]
        A, B = a * a, b * b
        t = np.maximum(0.0, np.sqrt(A * u * u + B * v * v) - max(A, B))
        for _ in range(60):
            p, q = a * u / (t + A), b * v / (t + B)
            g = p * p + q * q - 1
            dg = -2 * (p * p / (t + A) + q * q / (t + B))
            step = np.where(g > 0, -g / dg, 0.0)
            t = t + step
            if np.all(step <= 1e-15 * (t + B)):
                break
        return t

    def foot_angle_f(self, x, y):
        a, b, c, s, xc, yc = self.f
        dx, dy = x - xc, y - yc
        u, v = c * dx + s * dy, -s * dx + c * dy
        t = self._foot_t_f(u, v)
        return np.arctan2(b * v / (t + b * b), a * u / (t + a * a))

    def ray_f(self, theta):
        """P(theta), n(theta), N(theta) in doubles."""
        px, py, nx, ny = _ray(self.f, np.cos(theta), np.sin(theta))
        return px, py, nx, ny, np.hypot(nx, ny)

    # -- mpmath --------------------------------------------------------------

    def point(self, phi):
        a, b, c, s, xc, yc = self.mp
        ca, sa = mpmath.cos(phi), mpmath.sin(phi)
        x, y = a * ca, b * sa
        return xc + c * x - s * y, yc + s * x + c * y, ca, sa

    def ray(self, theta):
        """P, n (unnormalized outward normal), N = |n|, at mp precision."""
        px, py, nx, ny = _ray(self.mp, mpmath.cos(theta), mpmath.sin(theta))
        return px, py, nx, ny, mpmath.sqrt(nx * nx + ny * ny)

    def distance(self, x, y):
        """Distance from an outside point to the ellipse at mp precision
        (Newton on Eberly's equation from the double root); None inside."""
        a, b, c, s, xc, yc = self.mp
        dx, dy = x - xc, y - yc
        u, v = c * dx + s * dy, -s * dx + c * dy
        if (u / a) ** 2 + (v / b) ** 2 <= 1:
            return None
        A, B = a * a, b * b
        t = mpmath.mpf(float(self._foot_t_f(np.array([float(u)]), np.array([float(v)]))[0]))
        for _ in range(100):
            p, q = a * u / (t + A), b * v / (t + B)
            g = p * p + q * q - 1
            dg = -2 * (p * p / (t + A) + q * q / (t + B))
            step = -g / dg
            t += step
            if abs(step) <= mpmath.eps * 16 * (abs(t) + B):
                break
        else:
            raise ArithmeticError("foot point: Newton did not converge")
        return t * mpmath.sqrt((u / (t + A)) ** 2 + (v / (t + B)) ** 2)


def ray_bisector_f(p, q, theta):
    """For arrays of p's angles: s of the point of p's normal ray equidistant
    from p and q (inf where the ray never gets as close to q as to p) and
    q's foot angle there, in doubles. f(s) = s N - dist_q(V(s)) increases
    (dist_q is 1-Lipschitz, V moves at speed N) from f(0) < 0; bracketed by
    doubling, then bisected."""
    px, py, nx, ny, N = p.ray_f(theta)
    d0 = q.distance_f(px, py)
    lo = d0 / (2 * N)  # f < 0 below: dist_q(V) >= d0 - s N
    hi = np.maximum(lo, 1e-300)
    f = lambda s: s * N - q.distance_f(px + s * nx, py + s * ny)
    # Beyond a distance of 10^7 times the pair's size f's rounding errors
    # reach its limit (f tends to a constant): roots there count as none.
    size = np.hypot(p.f[4] - q.f[4], p.f[5] - q.f[5]) + max(p.f[:2]) + max(q.f[:2])
    cap = 1e7 * size / N
    active = f(hi) < 0
    while active.any():
        hi = np.where(active, hi * 2, hi)
        active = active & (f(hi) < 0) & (hi < cap)
    active = f(hi) < 0
    finite = ~active
    hi = np.where(finite, hi, 2 * lo + 1)
    lo = np.where(finite, np.minimum(lo, hi), lo)
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        neg = f(mid) < 0
        lo, hi = np.where(neg, mid, lo), np.where(neg, hi, mid)
    s = 0.5 * (lo + hi)
    phi = q.foot_angle_f(px + s * nx, py + s * ny)
    return np.where(finite, s, np.inf), phi


def ray_bisector(p, q, theta, start):
    """(s, phi) at mp precision by Newton's method on
        F1 = (V - Q(phi)) . Q'(phi) = 0,  F2 = |V - Q(phi)|^2 - (s N)^2 = 0,
    V = P(theta) + s n(theta), from start = (s0, phi0). Checked: V lies on
    q's outward normal at Q(phi) (so Q(phi) is V's nearest point of the
    convex q) and s > 0."""
    px, py, nx, ny, N = p.ray(theta)
    a, b, c, sn, xc, yc = q.mp
    s, phi = mpmath.mpf(start[0]), mpmath.mpf(start[1])
    # Newton doubles the digits: after a step below `half` the error is
    # about its square, below `tol`.
    half = mpmath.mpf(10) ** (-(mp.dps // 2))
    for it in range(60):
        qx, qy, ca, sa = q.point(phi)
        dqx, dqy = -c * a * sa - sn * b * ca, -sn * a * sa + c * b * ca  # Q'
        rx, ry = px + s * nx - qx, py + s * ny - qy                      # V - Q
        F1 = rx * dqx + ry * dqy
        F2 = rx * rx + ry * ry - (s * N) ** 2
        J11 = nx * dqx + ny * dqy
        J12 = -(dqx * dqx + dqy * dqy) - (rx * (qx - xc) + ry * (qy - yc))
        J21 = 2 * (rx * nx + ry * ny) - 2 * s * N * N
        J22 = -2 * F1
        det = J11 * J22 - J12 * J21
        ds = (F1 * J22 - J12 * F2) / det
        dphi = (J11 * F2 - J21 * F1) / det
        s -= ds
        phi -= dphi
        if abs(ds) <= half * abs(s) and abs(dphi) <= half:
            break
    else:
        raise ArithmeticError(f"ray bisector: Newton did not converge at theta {float(theta)} from {start}: {float(ds)} {float(dphi)} s {float(s)}")
    qx, qy, ca, sa = q.point(phi)
    mx, my = c * b * ca - sn * a * sa, sn * b * ca + c * a * sa  # q's outward normal
    if not (s > 0 and (px + s * nx - qx) * mx + (py + s * ny - qy) * my > 0):
        raise ArithmeticError("ray bisector: Newton reached a wrong root")
    return s, phi


class _EdgeSolver:
    """s(theta) on one edge (p's ray against neighbour q), each Newton solve
    started from the nearest angle already solved (at first the double
    samples)."""

    def __init__(self, p, q, thetas, s, phi):
        self.p, self.q = p, q
        self.known = sorted((float(t), float(si), float(fi)) for t, si, fi in zip(thetas, s, phi)
                            if math.isfinite(si))
        self.keys = [k[0] for k in self.known]

    def __call__(self, theta):
        key = float(theta) % (2 * math.pi)  # the samples are in [0, 2 pi)
        i = bisect.bisect_left(self.keys, key)
        if 0 < i < len(self.known):  # between two solved angles: interpolate
            (t0, s0, f0), (t1, s1, f1) = self.known[i - 1], self.known[i]
            w = (key - t0) / (t1 - t0) if t1 > t0 else 0.0
            start = (s0 + w * (s1 - s0), f0 + w * _angle_diff(f1, f0))
        else:
            start = self.known[min(i, len(self.known) - 1)][1:]
        try:
            s, phi = ray_bisector(self.p, self.q, theta, start)
        except (ArithmeticError, ZeroDivisionError):
            sf, ff = ray_bisector_f(self.p, self.q, np.array([float(theta)]))
            s, phi = ray_bisector(self.p, self.q, theta, (sf[0], ff[0]))
        self.known.insert(i, (key, float(s), float(phi)))
        self.keys.insert(i, key)
        return s

    def add_start(self, *thetas):
        """Double-precision starts at these angles (where the samples are too
        far apart)."""
        t = np.array(thetas, dtype=float) % (2 * math.pi)
        s, phi = ray_bisector_f(self.p, self.q, t)
        for ti, si, fi in zip(t, s, phi):
            if math.isfinite(si):
                i = bisect.bisect_left(self.keys, ti)
                self.known.insert(i, (float(ti), float(si), float(fi)))
                self.keys.insert(i, float(ti))


def _angle_diff(a, b):
    """a - b reduced to (-pi, pi]."""
    return (a - b + math.pi) % (2 * math.pi) - math.pi


class UnboundedCell(ValueError):
    pass


def _vertex_angle(p, q1, q2, lo, hi, solver1, solver2):
    """The angle in (lo, hi) where q1's and q2's roots on p's rays meet
    (q1 closer at lo, q2 at hi): the secant method in mpmath on
    g = s_q1(theta) - s_q2(theta) from the bracket's ends (the solvers
    start Newton from the samples); when a root is missing at an end or
    the secant leaves the bracket, bisection in doubles narrows the
    bracket first."""
    lo, hi = float(lo), float(hi)

    def g(t):
        return solver1(t) - solver2(t)

    def secant(a, b):
        # The roots s carry ~dps - 5 digits: g cannot get below that, so
        # findroot's own test (|g|^2 < tol) is replaced by ours.
        theta = mpmath.findroot(g, (mpmath.mpf(a), mpmath.mpf(b)), solver="secant", maxsteps=60,
                                verify=False)
        if not (min(a, b) - 1e-12 <= float(theta) <= max(a, b) + 1e-12):
            raise ArithmeticError("vertex angle left its bracket")
        if abs(g(theta)) > mpmath.mpf(10) ** (10 - mp.dps) * abs(solver1(theta)):
            raise ArithmeticError("vertex angle: the secant method did not converge")
        return theta

    try:
        theta = secant(lo, hi)
    except (ArithmeticError, ZeroDivisionError, ValueError):
        def g_f(t):
            s1, _ = ray_bisector_f(p, q1, np.array([t]))
            s2, _ = ray_bisector_f(p, q2, np.array([t]))
            return s1[0] - s2[0] if math.isfinite(s2[0]) else -math.inf
        for _ in range(30):
            mid = 0.5 * (lo + hi)
            if g_f(mid) < 0:
                lo = mid
            else:
                hi = mid
        solver1.add_start(lo, hi)
        solver2.add_start(lo, hi)
        theta = secant(lo, hi)
    return theta, solver1(theta)


def cell_area(sites, p_index, neighbours, samples=256, dps=DPS, quad_digits=QUAD_DIGITS, details=False):
    """The area of site p_index's cell (pi a b included), an mpf at dps
    digits, whose quadrature error is below 10^-quad_digits relative (by
    mpmath's own estimate, which is checked). `sites`: (a, b, w, xc, yc) rationals of
    every site, pairwise disjoint; `neighbours`: ids of p's Voronoi
    neighbours in any order (repeats ignored) — only they are tried along
    the rays, and every vertex found is then checked against all sites.
    Raises UnboundedCell for an unbounded cell, ArithmeticError when a step
    fails. With details=True returns (area, info): info["sequence"] is the
    counter-clockwise list of neighbours across the edges, info["vertices"]
    their angles, info["quad_error"] quad's error estimate of the sum."""
    with mpmath.workdps(dps):
        ells = [Ellipse(*s) for s in sites]
        p = ells[p_index]
        cand = sorted(set(int(n) for n in neighbours) - {p_index})
        if not cand:
            raise UnboundedCell("no neighbour")
        while True:
            thetas = 2 * np.pi * np.arange(samples) / samples
            roots = [ray_bisector_f(p, ells[q], thetas) for q in cand]
            S = np.array([r[0] for r in roots])
            if not np.isfinite(S.min(axis=0)).all():
                raise UnboundedCell(f"site {p_index}: a normal ray meets no bisector")
            owner = S.argmin(axis=0)
            changes = [k for k in range(samples) if owner[k] != owner[k - 1]]
            seen = set(owner.tolist())
            if len(seen) == len(cand) or samples >= 8192:
                break
            samples *= 4  # a short edge fell between two samples
        if not changes:
            raise ArithmeticError(f"site {p_index}: one neighbour all around")
        solvers = {k: _EdgeSolver(p, ells[q], thetas, *roots[k]) for k, q in enumerate(cand)}
        # Vertices: at change k the owner goes from owner[k-1] to owner[k].
        vertices = []
        for k in changes:
            lo = thetas[k - 1] if k > 0 else thetas[-1] - 2 * np.pi
            k1, k2 = owner[k - 1], owner[k]
            theta, s = _vertex_angle(p, ells[cand[k1]], ells[cand[k2]], lo, thetas[k], solvers[k1], solvers[k2])
            vertices.append((theta, s, owner[k - 1], owner[k]))
        _check_vertices(ells, p_index, p, vertices, cand)
        total = mpmath.pi * p.mp[0] * p.mp[1]
        err_total = mpmath.mpf(0)
        # The goal on the area, absolute: quad_digits relative to a scale
        # below the cell's area (the site's, plus its ring out to the
        # smallest root), shared by the edges in proportion to their angle.
        target = mpmath.mpf(10) ** -quad_digits
        s_min = mpmath.mpf(float(S.min()))
        scale = total + s_min * p.mp[0] * p.mp[1] * mpmath.pi
        sequence = []
        a, b = p.mp[0], p.mp[1]
        for i, (theta0, _, _, k) in enumerate(vertices):
            theta1 = vertices[(i + 1) % len(vertices)][0]
            if i + 1 == len(vertices):
                theta1 += 2 * mpmath.pi
            solve = solvers[k]

            def integrand(t):
                s = solve(t)
                _, _, nx, ny, N = p.ray(t)
                return s * (nx * nx + ny * ny) + a * b * s * s / 2
            value, err = _integrate(integrand, theta0, theta1, target * scale / (2 * mpmath.pi))
            total += value
            err_total += err
            sequence.append(cand[k])
        if err_total > abs(total) * target:
            raise ArithmeticError(f"site {p_index}: quadrature error {mpmath.nstr(err_total, 3)}")
        if details:
            return total, {"sequence": sequence, "vertices": [v[0] for v in vertices],
                           "quad_error": err_total}
        return total


def _integrate(f, a, b, goal, depth=0):
    """(integral of f over [a, b], error estimate) by Gauss-Legendre rules
    of 24 and 48 nodes, the 48-node value kept and the difference of the two
    taken as its error (f is analytic on an edge: the larger rule's error is
    far below it); halving the interval until each piece's difference is
    below its share of `goal` (absolute, per unit of angle)."""
    coarse, fine = (mpmath.fdot((w, f(x)) for x, w in _GAUSS_LEGENDRE.get_nodes(a, b, degree, mp.prec))
                    for degree in (4, 5))
    err = abs(fine - coarse)
    if err <= goal * (b - a) or depth >= 14:
        return fine, err
    m = (a + b) / 2
    v1, e1 = _integrate(f, a, m, goal, depth + 1)
    v2, e2 = _integrate(f, m, b, goal, depth + 1)
    return v1 + v2, e1 + e2


def _check_vertices(ells, p_index, p, vertices, cand):
    """Each vertex V (p's ray at its angle, at s) is at distance r = s N from
    p and from its two neighbours and at no less from every other site: a
    Voronoi vertex of the whole set, found without trusting `neighbours`."""
    slack = mpmath.mpf(10) ** (-(mp.dps - 20))
    for theta, s, k1, k2 in vertices:
        px, py, nx, ny, N = p.ray(theta)
        vx, vy, r = px + s * nx, py + s * ny, s * N
        for j, e in enumerate(ells):
            if j == p_index:
                continue
            d = e.distance(vx, vy)
            if d is None or d < r * (1 - slack):
                raise ArithmeticError(f"site {p_index}: vertex at theta {mpmath.nstr(theta, 8)} is closer to "
                                      f"site {j} ({mpmath.nstr(d, 8) if d is not None else 'inside'} < "
                                      f"{mpmath.nstr(r, 8)}): not a Voronoi vertex")
            if j in (cand[k1], cand[k2]) and abs(d - r) > r * slack:
                raise ArithmeticError(f"site {p_index}: vertex not equidistant from site {j}")
