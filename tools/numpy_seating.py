"""Independent numpy reference model of one quasi-static seating of a Maxwell
coupling of V-grooves made of planes (scene 01,
scenes/01_maxwell_vgroove_steel.toml), written from docs/model.md, as the
speed reference of `tools/speed-vs-numpy`.

`seat(mu_s)` seats the coupling once with the six static coefficients
`mu_s` and returns the pose of the centre evaluation point relative to the
nominal seating (every coefficient at the scene's mu_static), which is what
a study's per-sample output is (docs/output.md, "DOF order everywhere":
translation of the point and the rotation vector of R R_ref^-1, relative to
the nominal seating; docs/model.md, "The coupling": the two poses differ by
a constant). `seat_from_touching(mu_s)` gives the displacement from the
touching pose (the other pose `kinrepro run` prints).

Equations and their sources (section names of docs/model.md):

* "The coupling", "Axes and contact numbering": balls on the circle of
  diameter D at azimuths 90, 210, 330 deg, ball k owns contacts 2k-1, 2k
  with n = +-sin(alpha) s + cos(alpha) e_z, s = e_z x e_r,
  alpha = 90 deg - opening/2; origin at the centre in the touching pose;
  preload along -z at the centre, ramped from 0. A flank is the plane
  through the touching point with normal n: gap = (c - q).n - r.
* "Materials": 1/E* = sum (1 - nu^2)/E, 1/G* = sum (2 - nu)/G.
* "Normal contact: Hertz", circular contact: F = K delta^(3/2),
  K = 4/3 E* sqrt(R), a = (3 F R / (4 E*))^(1/3), k_n = 3/2 K delta^(1/2);
  ball on a plane: R = r.
* "Mindlin's tangential stiffness": k_t = 8 G* a (circle); "K_t of an
  increment": k_t at a_eff = (2/3)(a0^2 + a0 a1 + a1^2)/(a0 + a1).
* "Coulomb stick and slip", "Which coefficient acts while sliding" (switch
  reading): F_trial = R F_old + K_t du_t, stick if |F_trial| <= mu F_n with
  mu = mu_s while sticking and mu_d = dynamic_ratio mu_s while sliding,
  else radial return to mu_d F_n. The flank normals are fixed, so R = I.
  The force on the moving half is F_n n - F_t (F_t the law's force along
  the ball's tangential displacement du).
* "Load path and equilibrium", "Quasi-static path following": pose with
  finite rotations (unit quaternion), six contacts recomputed at every
  iterate; Newton with the consistent tangent, converged when
  |R_F| < 1e-10 F_p and |R_M| < 1e-10 F_p L; frictionless linearised
  predictor for the first increment; halving where a loaded contact
  changes between stick and slip.
* "Load-path error control": levels of N = 3, 6, 12, ... increments
  uniform in t (s = t^2, lambda = s^(3/2) = t^3), each from the touching
  pose; after each level N >= 6: d = x_N - x_(N/2) (a twist),
  x* = x_N + d, err = |d|_L / |x_N - x_0|_L + M 1e-10, stop at
  err <= 1e-5 and report x*.

Points the docs leave open, taken from the Rust source (and said so in the
report of the tool): the contact point is midway between the two surface
points, p = c - n (r + gap/2) (src/assembly/geometry/mod.rs); the
tangential increment du is the displacement of the ball's material point
now at p since the committed pose, du = p - T_c T^-1 p
(src/solve/contact_layer.rs); twists are about the world origin and a pose
moves as q' = exp(w) q, t' = exp(w) t + v (src/assembly/mod.rs); after the
first increment the predictor is the secant of the last accepted increment
scaled in s (src/solve/quasistatic/path.rs: it affects only the Newton
iteration count, not the result).
"""

import math
import tomllib
from pathlib import Path

import numpy as np

#: Built-in materials used by the bundled scenes (E [Pa], nu), as
#: `kinrepro materials` lists them (docs/model.md, "Materials").
MATERIALS = {
    "steel": (210e9, 0.30),
    "silicon-carbide": (410e9, 0.14),
}

SCENE_01 = Path(__file__).resolve().parent.parent / "scenes" / "01_maxwell_vgroove_steel.toml"

NEWTON_TOL = 1e-10
MAX_NEWTON = 40
MAX_SPLITS = 8
PATH_TOL = 1e-5
FIRST_LEVEL = 3
FINEST_LEVEL = 6144
EPS = np.finfo(float).eps


class SeatingError(RuntimeError):
    pass


# --- unit quaternions (w, x, y, z) as Python tuples: four numbers are
# cheaper in plain floats than in numpy calls.

def q_mul(a, b):
    aw, ax, ay, az = a
    bw, bx, by, bz = b
    return (aw * bw - ax * bx - ay * by - az * bz,
            aw * bx + ax * bw + ay * bz - az * by,
            aw * by - ax * bz + ay * bw + az * bx,
            aw * bz + ax * by - ay * bx + az * bw)


def q_conj(a):
    return (a[0], -a[1], -a[2], -a[3])


def q_exp(w):
    """Unit quaternion of the rotation vector w."""
    th = math.sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2])
    if th < 1e-4:  # Taylor series, exact to rounding at these angles
        c = 1.0 - th * th / 8.0
        s = 0.5 - th * th / 48.0
    else:
        c = math.cos(0.5 * th)
        s = math.sin(0.5 * th) / th
    return (c, s * w[0], s * w[1], s * w[2])


def q_log(q):
    """Rotation vector of the unit quaternion q (angle in [0, pi])."""
    c, x, y, z = q
    if c < 0.0:
        c, x, y, z = -c, -x, -y, -z
    vn = math.sqrt(x * x + y * y + z * z)
    if vn == 0.0:
        return np.zeros(3)
    f = 2.0 * math.atan2(vn, c) / vn
    return np.array([f * x, f * y, f * z])


def q_minus_identity(q):
    """R(q) - I = 2 w [v]x + 2 [v]x^2, without the cancellation of R - I."""
    w, x, y, z = q
    xx, yy, zz = x * x, y * y, z * z
    return np.array([
        [-2.0 * (yy + zz), 2.0 * (x * y - w * z), 2.0 * (x * z + w * y)],
        [2.0 * (x * y + w * z), -2.0 * (xx + zz), 2.0 * (y * z - w * x)],
        [2.0 * (x * z - w * y), 2.0 * (y * z + w * x), -2.0 * (xx + yy)],
    ])


def q_matrix(q):
    return np.eye(3) + q_minus_identity(q)


# --- poses (q, t): a body point P is at R(q) P + t.

def moved(pose, dx):
    """The pose moved by the twist dx = (v, w) about the world origin."""
    q, t = pose
    dq = q_exp(dx[3:])
    return q_mul(dq, q), q_matrix(dq) @ t + dx[:3]


def twist_between(a, b):
    """The twist dx with moved(a, dx) == b."""
    dq = q_mul(b[0], q_conj(a[0]))
    return np.concatenate([b[1] - q_matrix(dq) @ a[1], q_log(dq)])


def size_L(dx, length):
    return math.hypot(np.linalg.norm(dx[:3]), length * np.linalg.norm(dx[3:]))


_I1, _I2 = [1, 2, 0], [2, 0, 1]


def cross(a, b):
    """Row-wise a x b of (n, 3) arrays (np.cross costs several times more
    on arrays this small)."""
    return a[:, _I1] * b[:, _I2] - a[:, _I2] * b[:, _I1]


def skew(v):
    """[v]x of each row of v (n, 3) -> (n, 3, 3)."""
    out = np.zeros((v.shape[0], 3, 3))
    out[:, 0, 1], out[:, 0, 2] = -v[:, 2], v[:, 1]
    out[:, 1, 0], out[:, 1, 2] = v[:, 2], -v[:, 0]
    out[:, 2, 0], out[:, 2, 1] = -v[:, 1], v[:, 0]
    return out


def skew1(v):
    return np.array([[0.0, -v[2], v[1]], [v[2], 0.0, -v[0]], [-v[1], v[0], 0.0]])


class MaxwellPlanes:
    """A Maxwell coupling of three V-grooves of planes, balls on the moving
    half, a constant preload along -z at the centre (scene file subset)."""

    def __init__(self, scene=SCENE_01):
        sc = tomllib.loads(Path(scene).read_text())
        cp, fr, pl = sc["coupling"], sc["friction"], sc["preload"]
        if cp.get("arrangement") != "maxwell" or cp.get("groove") != "planes":
            raise ValueError("only a Maxwell coupling of planes is modelled")
        if fr.get("law", "switch") != "switch" or fr.get("tangential_law", "coulomb") != "coulomb":
            raise ValueError("only the Coulomb law with the sudden switch is modelled")
        for key in ("support_compliance", "point", "direction", "forces", "gravity"):
            if key in cp or key in pl:
                raise ValueError(f"{key}: not modelled")
        self.L = 0.5 * cp["diameter"]
        self.r = 0.5 * cp["ball_diameter"]
        self.Fp = float(pl["force"])
        self.mu0 = float(fr["mu_static"])
        self.spread = float(fr.get("spread", 0.0))
        self.ratio = float(fr.get("dynamic_ratio", 1.0))
        # Materials: effective moduli of the pair.
        e1, nu1 = MATERIALS[cp["ball_material"]]
        e2, nu2 = MATERIALS[cp["groove_material"]]
        g1, g2 = e1 / (2 * (1 + nu1)), e2 / (2 * (1 + nu2))
        e_star = 1.0 / ((1 - nu1 ** 2) / e1 + (1 - nu2 ** 2) / e2)
        g_star = 1.0 / ((2 - nu1) / g1 + (2 - nu2) / g2)
        R = self.r  # ball on a plane
        self.K = 4.0 / 3.0 * e_star * math.sqrt(R)
        self.a_coef = (3.0 * R / (4.0 * e_star)) ** (1.0 / 3.0)
        self.kt_coef = 8.0 * g_star
        # Geometry in the touching pose (= body frame).
        alpha = math.radians(90.0 - 0.5 * cp.get("opening_angle_deg", 90.0))
        centres, normals = [], []
        for az in np.radians([90.0, 210.0, 330.0]):
            e_r = np.array([math.cos(az), math.sin(az), 0.0])
            s = np.cross([0.0, 0.0, 1.0], e_r)
            c = self.L * e_r
            for sign in (1.0, -1.0):
                normals.append(sign * math.sin(alpha) * s + math.cos(alpha) * np.array([0, 0, 1.0]))
                centres.append(c)
        self.C = np.array(centres)           # ball centre of each contact (body)
        self.N = np.array(normals)           # fixed flank normals (world)
        self.Q = self.C - self.r * self.N    # a point of each flank
        self.Pn = np.eye(3) - self.N[:, :, None] * self.N[:, None, :]  # tangent projectors
        self.P = np.array([0.0, 0.0, -self.Fp])   # preload at full load
        self.p_P = np.zeros(3)                     # its point (body)
        self.touching = ((1.0, 0.0, 0.0, 0.0), np.zeros(3))
        self.x1 = self._predictor()
        self._nominal = None

    # -- frictionless linearised predictor (docs: "Quasi-static path following")
    def _predictor(self):
        W = np.hstack([self.N, cross(self.C, self.N)])   # d gap / d(v, w)
        wrench = np.concatenate([self.P, np.cross(self.p_P, self.P)])
        f = np.linalg.solve(W.T, -wrench)
        delta = (np.maximum(f, 0.0) / self.K) ** (2.0 / 3.0)
        return np.linalg.solve(W, -delta)

    # -- the six contacts at a trial pose
    def evaluate(self, pose, committed, state, mu_s, mu_d):
        """Forces at `pose` from the committed pose and contact `state`
        (F_old (6,3), sliding (6,), F_n committed (6,)). Returns the
        residual's parts and what the tangent needs."""
        q, t = pose
        Rm = q_matrix(q)
        c = self.C @ Rm.T + t
        gap = np.einsum("ij,ij->i", c - self.Q, self.N) - self.r
        delta = -gap
        closed = delta > 0.0
        all_closed = closed.all()
        if not all_closed:  # an open contact carries nothing (a Newton iterate may open one)
            delta = np.where(closed, delta, 0.0)
        p = c - self.N * (self.r + 0.5 * gap)[:, None]
        # du = p - p_c, p_c = R_c R^T (p - t) + t_c  (material point at p)
        D = q_minus_identity(q_mul(committed[0], q_conj(q)))
        pt = p - t
        du = -(pt @ D.T) - (committed[1] - t)
        # Hertz
        sd = np.sqrt(delta)
        fn = self.K * delta * sd
        kn = 1.5 * self.K * sd
        # Mindlin at a_eff (K_t of an increment)
        F_old, sliding, fn_old = state
        a0 = self.a_coef * np.cbrt(fn_old)
        a1 = self.a_coef * np.cbrt(fn)
        ssum = a0 + a1 if all_closed else np.where(a0 + a1 > 0.0, a0 + a1, 1.0)
        qa = a0 * a0 + a0 * a1 + a1 * a1
        kt = self.kt_coef * (2.0 / 3.0) * qa / ssum
        # Coulomb return map (circle: K_t = k_t (I - n n^T))
        du_t = du - self.N * np.einsum("ij,ij->i", du, self.N)[:, None]
        trial = F_old + kt[:, None] * du_t
        T = np.sqrt(np.einsum("ij,ij->i", trial, trial))
        limit = np.where(sliding, mu_d, mu_s) * fn
        slip = T > limit
        ratio = np.where(slip, mu_d * fn / np.where(slip, T, 1.0), 1.0)
        if not all_closed:  # no friction without normal force; the history is lost
            slip &= closed
            ratio = np.where(closed, ratio, 0.0)
        Ft = trial * ratio[:, None]
        f = self.N * fn[:, None] - Ft
        ev = dict(c=c, p=p, fn=fn, kn=kn, kt=kt, a0=a0, a1=a1, ssum=ssum, qa=qa,
                  du_t=du_t, trial=trial, T=T, slip=slip, ratio=ratio, Ft=Ft, f=f)
        return ev

    def residual(self, pose, ev, lam):
        f, p = ev["f"], ev["p"]
        P = lam * self.P
        pP = q_matrix(pose[0]) @ self.p_P + pose[1]
        return np.concatenate([f.sum(0) + P, cross(p, f).sum(0) + skew1(pP) @ P])

    def jacobian(self, pose, ev, lam, mu_d):
        """dR/d(v, w) with the consistent tangent of the return map."""
        N, fn, kn, kt, du_t = self.N, ev["fn"], ev["kn"], ev["kt"], ev["du_t"]
        slip, ratio = ev["slip"], ev["ratio"]
        # d ln a_eff / dF_n, and dk_t/dF_n = k_t dlog
        a0, a1, ssum, qa = ev["a0"], ev["a1"], ev["ssum"], ev["qa"]
        dlog = (2.0 * a0 + a1) * a1 * a1 / np.where(fn > 0.0, ssum * qa * 3.0 * fn, np.inf)
        ck = kt * dlog
        Pn = self.Pn
        tt = ev["trial"] / np.where(ev["T"] > 0, ev["T"], 1.0)[:, None]
        tdu = np.einsum("ij,ij->i", tt, du_t)
        s = slip[:, None]
        dFt_du = (ratio * kt)[:, None, None] * np.where(
            slip[:, None, None], Pn - tt[:, :, None] * tt[:, None, :], Pn)
        dFt_dfn = np.where(s, mu_d[:, None] * tt + (ratio * ck)[:, None] * (du_t - tt * tdu[:, None]),
                           ck[:, None] * du_t)
        # d f / d(displacement of the contact point)
        K = (dFt_dfn - N)[:, :, None] * (kn[:, None] * N)[:, None, :] - dFt_du
        p, c, f = ev["p"], ev["c"], ev["f"]
        Sp, Sc, Sf = skew(p), skew(c), skew(f)
        KSp = K @ Sp
        J = np.empty((6, 6))
        J[:3, :3] = K.sum(0)
        J[:3, 3:] = -KSp.sum(0)
        J[3:, :3] = (Sp @ K - Sf).sum(0)
        J[3:, 3:] = (-Sp @ KSp + Sf @ Sc).sum(0)
        # the preload: fixed direction at a point of the body
        P = lam * self.P
        pP = q_matrix(pose[0]) @ self.p_P + pose[1]
        SP = skew1(P)
        J[3:, :3] -= SP
        J[3:, 3:] += SP @ skew1(pP)
        return J

    def newton(self, committed, state, start, lam, mu_s, mu_d):
        pose, last = start, math.inf
        for it in range(MAX_NEWTON):
            ev = self.evaluate(pose, committed, state, mu_s, mu_d)
            r = self.residual(pose, ev, lam)
            rf, rm = r[:3] @ r[:3], r[3:] @ r[3:]
            rel = max(math.sqrt(rf) / self.Fp, math.sqrt(rm) / (self.Fp * self.L))
            if not math.isfinite(rel):
                return None, it + 1
            if rel < NEWTON_TOL:
                return (pose, ev), it + 1
            stalled = rel > 0.1 * last
            last = rel
            dx = np.linalg.solve(self.jacobian(pose, ev, lam, mu_d), -r)
            if stalled and np.linalg.norm(dx[:3]) + self.L * np.linalg.norm(dx[3:]) <= 64 * EPS * self.L:
                return (pose, ev), it + 1
            pose = moved(pose, dx)
        return None, MAX_NEWTON

    def level(self, n, mu_s, mu_d):
        """One seating on n increments uniform in t = sqrt(s), from the
        touching pose and virgin contacts; halving at a stick/slip change
        of a loaded contact or a Newton failure."""
        nominal = 1.0 / n
        h_min = nominal / 2.0 ** MAX_SPLITS
        pose = self.touching
        state = (np.zeros((6, 3)), np.zeros(6, bool), np.zeros(6))
        h, t, s = nominal, 0.0, 0.0
        last = None
        count = iters = 0
        while s < 1.0:
            t_next = 1.0 if t + h > 1.0 - 1e-12 else t + h
            s_next = t_next * t_next
            lam = s_next * math.sqrt(s_next)
            dx = self.x1 * (s_next - s) if last is None else last[0] * ((s_next - s) / last[1])
            can_halve = h > 1.5 * h_min
            res, its = self.newton(pose, state, moved(pose, dx), lam, mu_s, mu_d)
            iters += its
            if res is None:
                if not can_halve:
                    raise SeatingError(f"Newton failed at lambda = {lam}")
                h *= 0.5
                continue
            new_pose, ev = res
            changed = bool(np.any((ev["slip"] != state[1]) & (state[2] > 0.0)))
            if changed and can_halve:
                h *= 0.5
                continue
            if np.any(ev["fn"] <= 0.0):
                raise SeatingError(f"contact {int(np.argmin(ev['fn'])) + 1} opened at lambda = {lam}")
            last = (twist_between(pose, new_pose), s_next - s)
            pose = new_pose
            state = (ev["Ft"], ev["slip"], ev["fn"])
            s, t = s_next, t_next
            count += 1
            if not changed:
                h = min(2.0 * h, nominal)
        return pose, count, iters

    def seat_pose(self, mu_s):
        """The reported seated pose (q, t) under load-path error control,
        with the path error estimate and the increments and Newton
        iterations taken."""
        mu_s = np.asarray(mu_s, float)
        mu_d = self.ratio * mu_s
        n = FIRST_LEVEL
        coarse, count, iters = self.level(n, mu_s, mu_d)
        while True:
            n *= 2
            fine, c2, i2 = self.level(n, mu_s, mu_d)
            count += c2
            iters += i2
            d = twist_between(coarse, fine)
            motion = size_L(twist_between(self.touching, fine), self.L)
            err = (size_L(d, self.L) / motion if motion > 0 else 0.0) + c2 * NEWTON_TOL
            if err <= PATH_TOL or n >= FINEST_LEVEL:
                return moved(fine, d), err, count, iters
            coarse = fine

    def seat_from_touching(self, mu_s):
        """Pose of the centre point from the touching pose:
        (x, y, z, phi_x, phi_y, phi_z)."""
        q, t = self.seat_pose(mu_s)[0]
        return np.concatenate([t, q_log(q)])

    def nominal(self):
        if self._nominal is None:
            self._nominal = self.seat_pose(np.full(6, self.mu0))[0]
        return self._nominal

    def seat(self, mu_s):
        """Pose of the centre point relative to the nominal seating, as a
        study reports it: (x, y, z [m], phi_x, phi_y, phi_z [rad]) of
        R R_ref^-1."""
        q, t = self.seat_pose(mu_s)[0]
        q0, t0 = self.nominal()
        return np.concatenate([t - t0, q_log(q_mul(q, q_conj(q0)))])

    def draw(self, rng, k):
        """k friction vectors as the study draws them: mu0 + spread (2u - 1)."""
        return self.mu0 + self.spread * (2.0 * rng.random((k, 6)) - 1.0)


_DEFAULT = None


def seat(mu_s):
    """Scene 01 seated with the six static coefficients `mu_s`: the 6-vector
    pose of the centre point relative to the nominal seating."""
    global _DEFAULT
    if _DEFAULT is None:
        _DEFAULT = MaxwellPlanes(SCENE_01)
    return _DEFAULT.seat(mu_s)


if __name__ == "__main__":
    m = MaxwellPlanes()
    pose, err, count, iters = m.seat_pose(np.full(6, m.mu0))
    print("nominal from touching:", m.seat_from_touching(np.full(6, m.mu0)),
          f"path error {err:.1e}, {count} increments, {iters} Newton iterations")
    print("frictionless z:", m.seat_from_touching(np.zeros(6))[2])
