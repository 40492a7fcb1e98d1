"""Reference force-motion models of planar pushing: the field's baselines for measured diagrams.

Conventions (all arrays N x 3, SI):
  twist   t = (vx, vy, omega * R)          [m/s]  the body's motion
  wrench  w = (Fx, Fy, Mz / R)             [N]    the FRICTION on the body, as in the data files
R is the characteristic length (the disk's radius) the caller divided the spin and torque by.

Sign: friction opposes motion, so the load that keeps the body sliding quasi-statically, the
applied (pusher) wrench of the limit-surface literature, is W = -w. Every model here works with
W internally: the limit surface is {W : H(W) = 1}, H convex and homogeneous, and by the maximum
power inequality the twist is the outward normal there, t ∝ ∇H(W), so that W . t > 0. The public
methods take and return the friction wrench w of the data; `applied(w)` is the one place the sign
is flipped.

Models (each with fit(twists, wrenches), motion_from_force(wrenches) -> unit twists and
force_from_motion(twists) -> friction wrenches):
  EllipsoidLimitSurface  H = W^T A W, A SPD (Howe & Cutkosky, "Practical force-motion models
                         for sliding manipulation", IJRR 1996).
  QuarticLimitSurface    H = sum_k (W^T B_k W)^2, K = 3 terms, B_1 SPD, B_2, B_3 PSD: convex by
                         construction, a homogeneous quartic as in Zhou, Paolini, Bagnell, Mason,
                         "A convex polynomial force-motion model for planar sliding:
                         identification and application", ICRA 2016.
  NearestNeighbour       no physics: k nearest neighbours in unit-direction space.

Fit (both limit surfaces, after Zhou et al.): scipy.optimize.least_squares (trust region,
analytic Jacobian) on the Cholesky factors of the matrices, minimising
  sum_i (H(W_i)^(1/d) - 1)^2 + ALIGN_WEIGHT * sum_i |∇H(W_i)/|∇H(W_i)| - t_i/|t_i||^2,
d = 2 or 4 the degree of H. The surface residual is the gauge form of H(W_i) - 1: equal to
(H(W_i) - 1)/d to first order, it is the relative radial distance of W_i from the surface for
every degree. With H - 1 itself, the quartic's residuals grow like |W|^4 - 1 over the data's
spread of wrench magnitudes (0.5-2x their mean) and the few largest wrenches push the surface
outwards: on the disk data the quartic then put the measured wrenches a median 27 % inside its
surface, and its force predictions were 0.1-0.2 worse in relative error. The alignment residual
is Zhou et al.'s |∇H(W_i) - γ_i t_i|^2 (free γ_i >= 0, in a semidefinite program) with the
scale eliminated: no extra unknowns, and every row's direction weighs alike. The Cholesky
factors keep the surface convex and closed with no semidefinite constraint.
"""

from __future__ import annotations

import numpy as np
from scipy.optimize import least_squares, minimize

# Weight of the alignment residuals (unit-vector differences) against the gauge residuals
# (relative radial misses); both dimensionless: a normal off by 0.1 rad costs as much as a
# wrench 10 % off the surface. On 80/20 splits of the disk data, 0.25 and 4 change the median
# angles by a few tenths of a degree.
ALIGN_WEIGHT = 1.0
# least_squares' ftol, xtol and gtol, and its evaluation budget (a quartic fit on 400 real rows
# takes 10-700 evaluations; the cost then changes in its 8th digit).
FIT_TOL = 1e-10
FIT_MAX_NFEV = 1000


def as_rows(x, name: str) -> np.ndarray:
    """Checks an N x 3 array of finite numbers; a ValueError names the first bad row."""
    a = np.asarray(x, dtype=float)
    if a.ndim == 1 and a.shape == (3,):
        a = a[None, :]
    if a.ndim != 2 or a.shape[1] != 3:
        raise ValueError(f"{name}: expected an N x 3 array, got shape {a.shape}")
    bad = ~np.all(np.isfinite(a), axis=1)
    if bad.any():
        raise ValueError(f"{name}: row {int(np.argmax(bad))} is not finite (NaN or inf)")
    return a


def unit_rows(x, name: str) -> np.ndarray:
    """Rows divided by their Euclidean norm; a zero row has no direction: ValueError."""
    a = as_rows(x, name)
    n = np.linalg.norm(a, axis=1)
    if np.any(n <= 0.0):
        raise ValueError(f"{name}: row {int(np.argmax(n <= 0.0))} is zero and has no direction")
    return a / n[:, None]


def applied(wrenches) -> np.ndarray:
    """The applied (pusher) wrench W = -w of friction wrenches w: the limit-surface argument."""
    return -as_rows(wrenches, "wrenches")


def _check_pairs(twists, wrenches, n_params: int) -> tuple[np.ndarray, np.ndarray]:
    """Unit twists and applied wrenches W = -w of a training set, checked for a fit."""
    t = unit_rows(twists, "twists")
    w = as_rows(wrenches, "wrenches")
    if t.shape[0] != w.shape[0]:
        raise ValueError(f"{t.shape[0]} twists but {w.shape[0]} wrenches")
    if t.shape[0] < n_params:
        raise ValueError(f"{t.shape[0]} rows cannot fit {n_params} parameters")
    W = -w
    zero = np.linalg.norm(W, axis=1) <= 0.0
    if zero.any():
        raise ValueError(f"wrenches: row {int(np.argmax(zero))} is zero and cannot lie on a "
                         "limit surface")
    return t, W


def _lower(p: np.ndarray, strict: bool) -> np.ndarray:
    """Lower-triangular 3 x 3 factor L from 6 numbers (row-major lower triangle); strict: the
    diagonal is exp(p) > 0, so L L^T is SPD; otherwise L L^T is only PSD."""
    L = np.zeros((3, 3))
    L[_TRIL] = p
    if strict:
        L[np.diag_indices(3)] = np.exp(np.diag(L))
    return L


def _factor_params(M: np.ndarray, strict: bool) -> np.ndarray:
    """The 6 numbers whose `_lower` factor L has L L^T = M (M SPD)."""
    L = np.linalg.cholesky(M)
    if strict:
        L[np.diag_indices(3)] = np.log(np.diag(L))
    return L[_TRIL]


_TRIL = np.tril_indices(3)


def _term_derivatives(L: np.ndarray, strict: bool, V: np.ndarray):
    """q = V^T B V and B V of B = L L^T, with their derivatives by the 6 parameters of L:
    for the entry (a, b) of L, d(B V) = s (e_a (L^T V)_b + L[:, b] V_a) and dq = 2 s V_a
    (L^T V)_b, s = L_aa for a strict (exp) diagonal entry, else 1. Shapes N, Nx3, Nx6, Nx3x6."""
    LtV = V @ L
    BV = LtV @ L.T
    q = np.sum(LtV * LtV, axis=1)
    n = V.shape[0]
    dq = np.empty((n, 6))
    dBV = np.zeros((n, 3, 6))
    for j, (a, b) in enumerate(zip(*_TRIL)):
        s = L[a, a] if (strict and a == b) else 1.0
        dq[:, j] = 2.0 * s * V[:, a] * LtV[:, b]
        dBV[:, a, j] += s * LtV[:, b]
        dBV[:, :, j] += s * V[:, a, None] * L[:, b]
    return q, BV, dq, dBV


class _FittedSurface:
    """H(W) = sum_k (W^T B_k W)^m, B_k = L_k L_k^T (B_1 SPD, the others PSD), homogeneous of
    degree 2m: m = 1 with one term is the ellipsoid, m = 2 the quartic. The matrices are held in
    scaled coordinates V = W / scale, scale the RMS of the training |W| (so |V| ~ 1 and the fit
    is well conditioned); `A`, `B`, `value`, `gradient`, `hessian` are in SI units."""

    power = 1
    # The first factor's diagonal: exp(p) (B_1 SPD through the parameters) or free (B_1 PSD)
    # with ridge * I added in scaled coordinates, which keeps B_1 SPD and lets an eigenvalue go
    # to ~0 at finite parameters instead of exp(p) creeping towards p = -inf.
    strict_first = True
    ridge = 0.0

    def __init__(self, terms: int = 1) -> None:
        if terms < 1:
            raise ValueError("a limit surface needs at least one term")
        self.terms = terms
        self.n_params = 6 * terms
        self.scale = 1.0
        self.matrices: list[np.ndarray] = []  # in scaled coordinates
        self.fit_result = None

    @property
    def degree(self) -> int:
        """The degree of homogeneity of H: H(s W) = s^degree H(W)."""
        return 2 * self.power

    def _factors(self, p: np.ndarray) -> list[np.ndarray]:
        return [_lower(p[6 * k:6 * k + 6], strict=(k == 0 and self.strict_first))
                for k in range(self.terms)]

    def _matrices(self, p: np.ndarray) -> list[np.ndarray]:
        """B_k = L_k L_k^T, plus ridge * I for B_1 (scaled coordinates)."""
        mats = [L @ L.T for L in self._factors(p)]
        mats[0] = mats[0] + self.ridge * np.eye(3)
        return mats

    def _value_gradient(self, mats, V):
        """H = sum_k q_k^m and ∇H = sum_k 2 m q_k^(m-1) B_k V of q_k = V^T B_k V."""
        H = np.zeros(V.shape[0])
        g = np.zeros_like(V)
        for B in mats:
            BV = V @ B
            q = np.sum(V * BV, axis=1)
            H += q**self.power
            g += (2.0 * self.power * q ** (self.power - 1))[:, None] * BV
        return H, g

    def _residuals_jacobian(self, p, t, V, want_jacobian: bool):
        """Residuals (H(V_i)^(1/d) - 1, sqrt(ALIGN_WEIGHT) (n_i - t̂_i)), n = ∇H/|∇H|, d the
        degree, and their Jacobian by p: d(H^(1/d)) = H^(1/d) dH / (d H), dH = m q^(m-1) dq, d∇H = 2 m ((m-1) q^(m-2) dq B V + q^(m-1) d(B V)),
        dn = (I - n n^T) d∇H / |∇H|."""
        m, n_rows = self.power, V.shape[0]
        H, g = np.zeros(n_rows), np.zeros_like(V)
        dH, dg = np.zeros((n_rows, self.n_params)), np.zeros((n_rows, 3, self.n_params))
        for k, L in enumerate(self._factors(p)):
            q, BV, dq, dBV = _term_derivatives(L, k == 0 and self.strict_first, V)
            if k == 0 and self.ridge:
                q, BV = q + self.ridge * np.sum(V * V, axis=1), BV + self.ridge * V
            H += q**m
            g += (2.0 * m * q ** (m - 1))[:, None] * BV
            cols = slice(6 * k, 6 * k + 6)
            dH[:, cols] = (m * q ** (m - 1))[:, None] * dq
            dg[:, :, cols] = 2.0 * m * ((m - 1) * q[:, None, None] ** max(m - 2, 0)
                                        * BV[:, :, None] * dq[:, None, :]
                                        + q[:, None, None] ** (m - 1) * dBV)
        gn = np.maximum(np.linalg.norm(g, axis=1), 1e-300)
        n = g / gn[:, None]
        gauge = np.maximum(H, 1e-300) ** (1.0 / self.degree)
        r = np.concatenate([gauge - 1.0, np.sqrt(ALIGN_WEIGHT) * (n - t).ravel()])
        if not want_jacobian:
            return r
        dn = (dg - n[:, :, None] * np.einsum("ni,nip->np", n, dg)[:, None, :]) / gn[:, None, None]
        return np.concatenate([(gauge / (self.degree * np.maximum(H, 1e-300)))[:, None] * dH,
                               np.sqrt(ALIGN_WEIGHT) * dn.reshape(3 * n_rows, -1)])

    def _initial(self, t: np.ndarray, V: np.ndarray) -> np.ndarray:  # pragma: no cover
        raise NotImplementedError

    def fit(self, twists, wrenches):
        """Least-squares fit on measured pairs (friction wrenches w; the surface is fitted to
        the applied W = -w): sum_i (H(W_i)^(1/d) - 1)^2 + ALIGN_WEIGHT sum_i |n_i - t̂_i|^2
        (module docstring), trust-region least squares with the analytic Jacobian. Returns self; scipy's result is kept in `fit_result`."""
        t, W = _check_pairs(twists, wrenches, self.n_params)
        self.scale = float(np.sqrt(np.mean(np.sum(W * W, axis=1))))
        V = W / self.scale
        res = least_squares(lambda p: self._residuals_jacobian(p, t, V, False),
                            self._initial(t, V), method="trf",
                            jac=lambda p: self._residuals_jacobian(p, t, V, True),
                            ftol=FIT_TOL, xtol=FIT_TOL, gtol=FIT_TOL, max_nfev=FIT_MAX_NFEV)
        self.matrices = self._matrices(res.x)
        self.fit_result = res
        return self

    def _set_matrices(self, mats) -> None:
        """Stores matrices given in SI units, choosing a scale with mean eigenvalue 1 of their
        sum; B_1 must be SPD, the others PSD."""
        mats = [np.asarray(M, dtype=float) for M in mats]
        if len(mats) != self.terms:
            raise ValueError(f"expected {self.terms} matrices, got {len(mats)}")
        for M in mats:
            if M.shape != (3, 3) or not np.all(np.isfinite(M)) or not np.allclose(M, M.T):
                raise ValueError("expected finite symmetric 3 x 3 matrices")
        if np.linalg.eigvalsh(mats[0])[0] <= 0.0:
            raise ValueError("the first matrix must be positive definite")
        if any(np.linalg.eigvalsh(M)[0] < -1e-12 * np.trace(M) for M in mats[1:]):
            raise ValueError("the other matrices must be positive semidefinite")
        self.scale = float(np.sqrt(3.0 / np.trace(sum(mats))))
        self.matrices = [M * self.scale**2 for M in mats]

    def value(self, W) -> np.ndarray:
        """H(W) of applied wrenches W [N] (the surface is H = 1)."""
        V = as_rows(W, "W") / self.scale
        return self._value_gradient(self.matrices, V)[0]

    def gradient(self, W) -> np.ndarray:
        """∇H(W) of applied wrenches W [1/N]."""
        V = as_rows(W, "W") / self.scale
        return self._value_gradient(self.matrices, V)[1] / self.scale

    def hessian(self, W) -> np.ndarray:
        """∇²H(W) of applied wrenches W (N x 3 x 3): sum_k 2m q^(m-1) B_k + 4m(m-1) q^(m-2)
        (B_k W)(B_k W)^T, PSD everywhere by construction."""
        V = as_rows(W, "W") / self.scale
        return self._hessian_scaled(V) / self.scale**2

    def _hessian_scaled(self, V):
        m = self.power
        out = np.zeros((V.shape[0], 3, 3))
        for B in self.matrices:
            BV = V @ B
            q = np.sum(V * BV, axis=1)
            out += (2.0 * m * q ** (m - 1))[:, None, None] * B
            if m > 1:
                out += (4.0 * m * (m - 1) * q ** (m - 2))[:, None, None] * (
                    BV[:, :, None] * BV[:, None, :])
        return out

    def motion_from_force(self, wrenches) -> np.ndarray:
        """Unit twists of friction wrenches w: t̂ = ∇H(W)/|∇H(W)| at W = -w. H is homogeneous,
        so the normal at the radial projection W / H(W)^(1/degree) has the same direction."""
        g = self.gradient(applied(wrenches))
        n = np.linalg.norm(g, axis=1)
        if np.any(n <= 0.0):
            raise ValueError(f"wrenches: row {int(np.argmax(n <= 0.0))} is zero: no motion")
        return g / n[:, None]

    def project(self, W) -> np.ndarray:
        """The radial projection W / H(W)^(1/degree) of applied wrenches onto the surface."""
        W = as_rows(W, "W")
        return W / self.value(W)[:, None] ** (1.0 / self.degree)


class EllipsoidLimitSurface(_FittedSurface):
    """Ellipsoidal limit surface H(W) = W^T A W = 1, A = L L^T SPD (L lower triangular with a
    positive diagonal: 6 parameters). Motion: t ∝ ∇H = 2 A W. Force of a twist t: the support
    point W = A^{-1} t / sqrt(t^T A^{-1} t) (H(W) = 1 and A W ∝ t); W = -w throughout."""

    power = 1

    def __init__(self) -> None:
        super().__init__(terms=1)

    @classmethod
    def from_matrix(cls, A) -> "EllipsoidLimitSurface":
        """The ellipsoid of a given SPD matrix A [1/N^2] (no fit)."""
        m = cls()
        m._set_matrices([A])
        return m

    @property
    def A(self) -> np.ndarray:
        """The matrix A of H(W) = W^T A W in SI units [1/N^2]."""
        return self.matrices[0] / self.scale**2

    def _initial(self, t, V):
        """The unit sphere of V: H = |V|^2, 1 on average over the data by the choice of scale."""
        return np.zeros(6)

    def force_from_motion(self, twists) -> np.ndarray:
        """Friction wrenches w = -W of twists t, W = A^{-1} t / sqrt(t^T A^{-1} t)."""
        t = unit_rows(twists, "twists")
        x = np.linalg.solve(self.matrices[0], t.T).T
        V = x / np.sqrt(np.sum(x * t, axis=1))[:, None]
        return -V * self.scale


class QuarticLimitSurface(_FittedSurface):
    """Convex homogeneous quartic limit surface H(W) = sum_{k=1..K} (W^T B_k W)^2 = 1.

    B_k = L_k L_k^T (L_k lower triangular, free: PSD of any rank) and B_1 gets ridge * I on top
    (1e-6 in the coordinates W / RMS|W| of the fit, where the B_k are of order 1), so B_1 is SPD.
    K = 3 (the default) gives 18 parameters for the 15 coefficients of a ternary quartic. On
    80/20 splits of the disk data K = 2 predicted abs_v10's motion 1 degree worse (the other files
    alike); K = 4 gained under 0.1 degree and fitted several times slower.
    Convex by construction: q_k = W^T B_k W is convex and >= 0, and s -> s^2 is convex and
    increasing on s >= 0, so each q_k^2 is convex (∇²(q_k^2) = 4 q_k B_k + 8 B_k W W^T B_k is
    PSD); B_1 SPD makes H > 0 off the origin, so {H <= 1} is a compact convex set with the origin
    inside. The family holds Zhou et al.'s (c . W)^4 terms (B_k = c c^T) and the ellipsoids
    (K = 1). Motion: t ∝ ∇H = 4 sum_k q_k B_k W. Force of a twist t: the support point, argmax
    W . t on H(W) <= 1, from the stationarity ∇H(u) = t (Newton, below) then W = u / H(u)^(1/4).
    """

    power = 2
    strict_first = False
    ridge = 1e-6

    def __init__(self, terms: int = 3) -> None:
        super().__init__(terms=terms)

    @classmethod
    def from_matrices(cls, mats) -> "QuarticLimitSurface":
        """The quartic of given matrices B_1 (SPD), B_2, ... (PSD) [1/N^2] (no fit)."""
        m = cls(terms=len(mats))
        m._set_matrices(mats)
        return m

    @property
    def B(self) -> list[np.ndarray]:
        """The matrices B_k of H(W) = sum_k (W^T B_k W)^2 in SI units [1/N^2]."""
        return [M / self.scale**2 for M in self.matrices]

    def _initial(self, t, V):
        """From the ellipsoid fitted to the same rows: B_1 = sqrt(0.7) A and B_k = c C D_k C^T
        (A = C C^T, D_k a diagonal emphasising axis k), so H starts near 0.7 q^2 + 0.3 q^2."""
        A = EllipsoidLimitSurface().fit(t, -V).A
        C = np.linalg.cholesky(A)
        params = [_factor_params(np.sqrt(0.7) * A - self.ridge * np.eye(3), strict=False)]
        c = np.sqrt(0.3 / max(self.terms - 1, 1))
        for k in range(1, self.terms):
            d = np.full(3, 0.3)
            d[(k - 1) % 3] = 1.0
            params.append(_factor_params(c * (C * d) @ C.T, strict=False))
        return np.concatenate(params)

    def force_from_motion(self, twists) -> np.ndarray:
        """Friction wrenches w = -W of twists t, W the support point of the surface in t's
        direction: u solves ∇H(u) = t̂ (the minimiser of the strictly convex H(u) - t̂ . u, by
        damped Newton from the answer of the ellipsoid W^T (sum_k B_k) W = 1; rows it leaves
        unconverged go to scipy's trust-exact, and to the ellipsoid's answer if that fails
        too), then W = u / H(u)^(1/4). Never NaN for a nonzero twist."""
        t = unit_rows(twists, "twists")
        u0 = self._start(t)
        u, ok = self._newton(t, u0.copy())
        for i in np.flatnonzero(~ok):
            u[i] = self._fallback(t[i], u0[i])
        H = self._value_gradient(self.matrices, u)[0]
        return -(u / H[:, None] ** 0.25) * self.scale

    def _start(self, t):
        """u0 = c V0: V0 the support point of the ellipsoid W^T (sum B_k) W = 1, c the best
        scale along it, argmin_c c^4 H(V0) - c t . V0 = (t . V0 / (4 H(V0)))^(1/3)."""
        x = np.linalg.solve(sum(self.matrices), t.T).T
        V0 = x / np.sqrt(np.sum(x * t, axis=1))[:, None]
        H0 = self._value_gradient(self.matrices, V0)[0]
        c = np.cbrt(np.sum(t * V0, axis=1) / (4.0 * H0))
        return c[:, None] * V0

    def _newton(self, t, u, iterations: int = 60, tol: float = 1e-12):
        """Damped Newton on φ(u) = H(u) - t . u for all rows at once (Armijo backtracking far
        from the solution, full steps once |∇φ| < 1e-6; ∇²φ = ∇²H is positive definite off the
        origin since B_1 is SPD). Returns u and the converged rows."""
        for _ in range(iterations):
            H, g = self._value_gradient(self.matrices, u)
            r = g - t
            rn = np.linalg.norm(r, axis=1)
            active = rn > tol
            if not active.any():
                break
            try:
                step = -np.linalg.solve(self._hessian_scaled(u[active]),
                                        r[active][:, :, None])[..., 0]
            except np.linalg.LinAlgError:  # a singular Hessian: every row to the fallback
                return u, np.zeros(len(u), dtype=bool)
            alpha = self._armijo(t[active], u[active], step, H[active], r[active], rn[active])
            u[active] = u[active] + alpha[:, None] * step
        H, g = self._value_gradient(self.matrices, u)
        ok = np.all(np.isfinite(u), axis=1) & (np.linalg.norm(g - t, axis=1) <= 1e3 * tol)
        return u, ok

    def _armijo(self, t, u, step, H, r, rn):
        """Backtracking step lengths: halve until φ(u + a step) <= φ(u) + 1e-4 a ∇φ . step."""
        phi0 = H - np.sum(t * u, axis=1)
        slope = np.sum(r * step, axis=1)
        alpha = np.ones(u.shape[0])
        pending = rn >= 1e-6
        for _ in range(50):
            if not pending.any():
                break
            trial = u[pending] + alpha[pending, None] * step[pending]
            phi = self._value_gradient(self.matrices, trial)[0] - np.sum(t[pending] * trial, 1)
            good = phi <= phi0[pending] + 1e-4 * alpha[pending] * slope[pending]
            idx = np.flatnonzero(pending)
            alpha[idx[~good]] *= 0.5
            pending[idx[good]] = False
        return alpha

    def _fallback(self, t, u0):
        """One row: scipy trust-exact on φ(u) = H(u) - t . u; u0 itself if that is not finite."""
        def phi(u):
            H, g = self._value_gradient(self.matrices, u[None, :])
            return H[0] - t @ u, g[0] - t

        res = minimize(phi, u0, jac=True, method="trust-exact", options={"gtol": 1e-11},
                       hess=lambda u: self._hessian_scaled(u[None, :])[0])
        ok = np.all(np.isfinite(res.x)) and np.linalg.norm(res.x) > 0
        return res.x if ok else u0


# Nearest neighbour: the number of neighbours and their weighting (see NearestNeighbour).
NN_K = 5


class NearestNeighbour:
    """k-nearest-neighbour predictor with no physics, in unit-direction space.

    Motion from force: the k training rows whose unit applied wrench W/|W| (W = -w) is nearest
    (Euclidean distance of unit vectors, monotone in the angle) to the query's; the answer is
    their weighted mean unit twist, normalised. Force from motion: the k rows whose unit twist is
    nearest to the query's; the answer is their weighted mean friction wrench (magnitude
    included). weights="distance" (default): weights 1/distance, and a query that coincides with
    training rows gets their answer alone, so a training point returns its own answer;
    weights="uniform": the plain mean of the k.

    k = 5 (NN_K), a compromise: each push gives 5-20 nearly identical rows, so on random splits a
    test row's nearest training rows are mostly from its own push and k = 1 scores best (abs_v10,
    distance weights: median motion angle 5.5 degrees at k = 1, 7.3 at k = 5, 8.5 at k = 10;
    force error 0.10 for k = 1..5); across speeds, where no push is shared, a few neighbours
    smooth the scatter instead (abs_v10 -> abs_v50: 15.9 degrees and 0.27 at k = 1, 13.6 and
    0.26 at k = 5; the reverse: 14.6 and 0.32 at k = 1, 14.7 and 0.29 at k = 5).
    """

    def __init__(self, k: int = NN_K, weights: str = "distance") -> None:
        if k < 1:
            raise ValueError("k must be at least 1")
        if weights not in ("distance", "uniform"):
            raise ValueError("weights must be 'distance' or 'uniform'")
        self.k = k
        self.weights = weights
        self.n_params = k

    def fit(self, twists, wrenches) -> "NearestNeighbour":
        """Stores the unit twists, unit applied wrenches W = -w and friction wrenches w."""
        t, W = _check_pairs(twists, wrenches, self.k)
        self.twist_dirs = t
        self.wrench_dirs = W / np.linalg.norm(W, axis=1)[:, None]
        self.wrenches = -W
        return self

    def _neighbours(self, keys: np.ndarray, queries: np.ndarray):
        """Indices (n x k) of the k nearest keys of each query and their normalised weights."""
        d2 = np.maximum(2.0 - 2.0 * queries @ keys.T, 0.0)  # |a - b|^2 of unit vectors
        k = min(self.k, keys.shape[0])
        idx = np.argpartition(d2, k - 1, axis=1)[:, :k]
        d = np.linalg.norm(queries[:, None, :] - keys[idx], axis=2)  # exact 0 for a coincidence
        if self.weights == "uniform":
            return idx, np.full(d.shape, 1.0 / k)
        exact = d <= 1e-12
        w = np.where(exact.any(axis=1)[:, None], exact.astype(float), 1.0 / np.maximum(d, 1e-300))
        return idx, w / w.sum(axis=1)[:, None]

    def motion_from_force(self, wrenches) -> np.ndarray:
        """Unit twists: the weighted mean unit twist of the nearest unit applied wrenches."""
        q = unit_rows(applied(wrenches), "wrenches")
        idx, w = self._neighbours(self.wrench_dirs, q)
        m = np.einsum("nk,nkj->nj", w, self.twist_dirs[idx])
        n = np.linalg.norm(m, axis=1)
        nearest = self.twist_dirs[idx[np.arange(len(idx)), np.argmax(w, axis=1)]]
        m = np.where((n > 1e-12)[:, None], m / np.maximum(n, 1e-300)[:, None], nearest)
        return m

    def force_from_motion(self, twists) -> np.ndarray:
        """Friction wrenches: the weighted mean wrench of the nearest unit twists."""
        q = unit_rows(twists, "twists")
        idx, w = self._neighbours(self.twist_dirs, q)
        return np.einsum("nk,nkj->nj", w, self.wrenches[idx])
