"""The small-signal model of the sampled task-space loops: what the simulation runs, linear (conventions §15).

About a contact at rest the closed loop is linear. Per task axis ``i`` (task frame) its parts are:

* the arm tip's displacement ``x_i``, moved between samples by the law's held command: ``x'' = M a +
  G (F_c(t) - F_m) - V x' + V_hat x'_k + K xi``, with ``a`` the loops' command, ``F_m`` the measured
  force the law compensates and ``x'_k`` the velocity at the sample, all held over the sample period
  ``T`` (the zero-order hold on the torque); ``G`` the arm's mobility in task axes (``J_t B^-1 J_t^T``
  [1/kg]), ``M = G Lambda_hat`` the controller's model against the arm's (the identity on the exact
  model), ``V`` and ``V_hat`` the joints' viscosity and the share the model compensates, in task axes
  [1/s], ``K`` the change of the held ``J^T F_0`` and gravity with the configuration [1/s^2], ``xi`` the
  displacement since the sample;
* along the linear axes, the sensor's tip mass ``m_s`` on its spring-damper ``K_s, D_s``, measured as
  ``F_c = K_s (s - x) + D_s (s' - x')``, and on a force axis the environment's ``k_e, d_e``:
  ``m_s s'' = -F_c - k_e s - d_e s'``;
* the reading's chain at each sample: the sensor's first-order lag ``y_k = alpha y_k-1 + (1 - alpha) F_k``,
  its delay of ``d`` samples, the controller's Butterworth filter ``(b0, b1, b2, a1, a2)``;
* the loops of conventions §4: PI² on velocity (``e_v = v_d - x'``), impedance and integral on force
  (``e_F = F_d - F_m``), integrals advanced once per sample, the current error included.

The sampled model is exact for this linear plant: the plant's part is discretised by the matrix
exponential over ``T`` with ``a`` and ``F_m`` held, the rest is already discrete. Its state is
``X = (x_F, x', s - x, s', lag, delay line, filter, integrals)``, its inputs the references ``(v_d or F_d)``
per axis. Left out (first order in small quantities the docs state): friction, the surface's curvature,
gravity's and the Jacobian's change with the configuration, the moving operating point.

Every array may carry leading batch axes: a map of many settings is one call.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

#: the rows of the Butterworth filter's coefficients that mean "no filter"
NO_FILTER = (1.0, 0.0, 0.0, 0.0, 0.0)


@dataclass(frozen=True)
class Structure:
    """What shapes the model's matrices (the settings that change their size).

    Parameters
    ----------
    force : tuple of bool
        Per task axis: a force axis (True) or a velocity axis.
    linear : tuple of bool
        Per task axis: a linear axis, along which the sensor's spring acts (the sensor measures force
        only: rotational axes have none).
    delay : int
        The reading's delay [samples].
    lag, filtered : bool
        Whether the reading has the sensor's lag, the controller's filter.
    integrals : tuple of int
        Per task axis, the integrators its gains use (velocity: 0-2, force: 0-1): an integrator whose
        gain is 0 feeds nothing back, and its eigenvalue 1 is left out.
    feeds_desired_force : bool
        The law's contact term is the desired force ``F_d`` on the force axes (Khatib's scheme, nothing on
        the others) rather than the measured force ``F_m`` it cancels (the task law).
    """

    force: tuple[bool, ...]
    linear: tuple[bool, ...]
    delay: int = 0
    lag: bool = False
    filtered: bool = False
    integrals: tuple[int, ...] = ()
    feeds_desired_force: bool = False

    @property
    def n(self) -> int:
        """The number of task axes."""
        return len(self.force)

    @property
    def sensed(self) -> np.ndarray:
        """The indices of the linear axes (those the sensor measures)."""
        return np.flatnonzero(self.linear)

    @property
    def sizes(self) -> dict[str, int]:
        """The state's blocks and their sizes, in order."""
        n, nl = self.n, len(self.sensed)
        return {"x": int(sum(self.force)), "xdot": n, "stretch": nl, "sdot": nl, "lag": nl * self.lag,
                "delay": nl * self.delay,
                "filter": 4 * nl * self.filtered, "integrals": sum(self.integrals)}


def plant_matrices(st: Structure, p: dict) -> tuple[np.ndarray, np.ndarray]:
    """The plant's continuous dynamics between samples, ``X_p' = A X_p + B (a, F_m)``.

    The plant's state is ``(x_F, x', delta, s')``: the arm tip's displacement along the force axes (along a
    velocity axis nothing depends on it: a neutral mode, left out), its velocity along every axis, the
    sensor's stretch ``delta = s - x`` and its tip's velocity along the linear axes.

    Parameters
    ----------
    st : Structure
        The model's structure.
    p : dict
        The numbers, each with leading batch axes ``...``: ``mobility``, ``gain``, ``viscosity``,
        ``compensated_viscosity`` (``... x n x n``), ``sensor_mass``, ``sensor_stiffness``, ``sensor_damping``,
        ``contact_stiffness``, ``contact_damping`` (``...``; the contact acts on force axes), and
        optionally ``held_stiffness`` (``... x n x n`` [1/s^2], below).

    Returns
    -------
    A : numpy.ndarray
        ``... x (np + n) x (np + n)``, ``np = n_F + n + 2 n_l``: the plant's state, then ``xi``, the
        displacement since the sample (0 at each sample).
    B : numpy.ndarray
        ``... x (np + n) x (2 n + n_l)``: the held command ``a``, the measured force ``F_m``, the
        velocity ``x'_k``.
    """
    n, L, F = st.n, st.sensed, np.flatnonzero(st.force)
    nl, nf = len(L), len(F)
    batch = np.shape(p["sensor_mass"])
    size = nf + n + 2 * nl + n
    A = np.zeros(batch + (size, size))
    B = np.zeros(batch + (size, 2 * n + nl))
    G, M, V, Vh = (np.broadcast_to(p[k], batch + (n, n)) for k in ("mobility", "gain", "viscosity",
                                                                    "compensated_viscosity"))
    Ks, Ds, ms = (np.asarray(p[k], float)[..., None] for k in ("sensor_stiffness", "sensor_damping", "sensor_mass"))
    x, xd = np.arange(nf), nf + np.arange(n)
    d, sd = nf + n + np.arange(nl), nf + n + nl + np.arange(nl)
    A[..., x, xd[F]] = 1.0
    A[..., d, sd] = 1.0                     # delta' = s' - x'
    A[..., d, xd[L]] = -1.0
    # x'' = M a + G_L (F_c - F_m) - V x' + V_hat x'_k, F_c = K_s delta + D_s (s' - x'_L)
    GL = G[..., :, L]
    A[..., xd[:, None], xd[None, :]] -= V
    A[..., xd[:, None], d[None, :]] += GL * Ks[..., None, :]
    A[..., xd[:, None], sd[None, :]] += GL * Ds[..., None, :]
    A[..., xd[:, None], xd[L][None, :]] -= GL * Ds[..., None, :]
    B[..., xd, :n] = M
    B[..., xd[:, None], n + np.arange(nl)[None, :]] = -GL
    B[..., xd[:, None], n + nl + np.arange(n)[None, :]] = Vh
    # the torque holds J^T F_0 and gravity at the sample's configuration while the arm moves: a stiffness
    # on the displacement since the sample, xi (xi' = x', 0 at each sample)
    xi = nf + n + 2 * nl + np.arange(n)
    A[..., xi, xd] = 1.0
    A[..., xd[:, None], xi[None, :]] += np.broadcast_to(p.get("held_stiffness", 0.0), batch + (n, n))
    # m_s s'' = -F_c - k_e s - d_e s' (s = delta + x; the contact on the force axes, where x is kept)
    A[..., sd, d] = -Ks / ms
    A[..., sd, sd] = -Ds / ms
    A[..., sd, xd[L]] = Ds / ms
    on = np.flatnonzero(np.asarray(st.force, bool)[L])       # the sensed axes in contact
    ke, de = (np.asarray(p[k], float)[..., None] for k in ("contact_stiffness", "contact_damping"))
    where = {int(axis): j for j, axis in enumerate(F)}
    rows, cols = sd[on], np.array([where[int(L[j])] for j in on], int)
    A[..., rows, d[on]] -= ke / ms
    A[..., rows, x[cols]] -= ke / ms
    A[..., rows, sd[on]] -= de / ms
    return A, B


def held(A: np.ndarray, B: np.ndarray, T) -> tuple[np.ndarray, np.ndarray]:
    """``(Phi, Gamma)``: the exact discretisation of ``X' = A X + B u`` with ``u`` held over ``T`` [s]."""
    n, m = A.shape[-1], B.shape[-1]
    aug = np.zeros(A.shape[:-2] + (n + m, n + m))
    aug[..., :n, :n] = A
    aug[..., :n, n:] = B
    E = expm(aug * np.asarray(T, float)[..., None, None])
    return E[..., :n, :n], E[..., :n, n:]


#: the Taylor series' order and the norm it is summed at in :func:`expm` (its remainder below 1e-20)
TAYLOR_ORDER, TAYLOR_NORM = 18, 0.5


def expm(M: np.ndarray) -> np.ndarray:
    """``exp(M)`` of each matrix of a stack (``... x n x n``): scaling and squaring of a Taylor series.

    Each matrix is scaled by ``2^-s`` to a norm below :data:`TAYLOR_NORM`, summed to
    :data:`TAYLOR_ORDER` terms and squared ``s`` times: a few batched products for the whole stack
    (SciPy's ``expm`` takes the matrices one by one). Non-finite entries give a non-finite result.
    """
    with np.errstate(over="ignore", invalid="ignore"):  # a matrix beyond the floats' range gives inf or NaN
        return _expm(np.asarray(M, float))


def _expm(M: np.ndarray) -> np.ndarray:
    norm = np.abs(M).sum(axis=-2).max(axis=-1)                     # the 1-norm of each
    with np.errstate(divide="ignore", invalid="ignore"):
        s = np.where(norm > TAYLOR_NORM, np.ceil(np.log2(norm / TAYLOR_NORM)), 0.0)
    s = np.where(np.isfinite(s), s, 0.0).astype(int)
    X = M * np.exp2(-s)[..., None, None]
    eye = np.broadcast_to(np.eye(M.shape[-1]), M.shape)
    E = eye + X / TAYLOR_ORDER
    for k in range(TAYLOR_ORDER - 1, 0, -1):                       # Horner: I + X/1 (I + X/2 (I + ...))
        E = eye + (X @ E) / k
    for i in range(int(s.max(initial=0))):
        squared = E @ E
        E = np.where((s > i)[..., None, None], squared, E)
    return E


class _Rows:
    """Linear expressions over ``(X_k, r)``: each signal is rows of coefficients (batched)."""

    def __init__(self, batch: tuple, width: int):
        self.batch, self.width = batch, width

    def unit(self, index) -> np.ndarray:
        index = np.atleast_1d(index)
        rows = np.zeros(self.batch + (len(index), self.width))
        rows[..., np.arange(len(index)), index] = 1.0
        return rows

    def zeros(self, k: int) -> np.ndarray:
        return np.zeros(self.batch + (k, self.width))


def _scale(c, rows: np.ndarray) -> np.ndarray:
    """``c`` (batched scalars, or batched per-row values) times ``rows``."""
    c = np.asarray(c, float)
    return c[..., None, None] * rows if c.ndim == rows.ndim - 2 else c[..., None] * rows


def closed_loop(st: Structure, p: dict) -> dict[str, np.ndarray]:
    """The sampled closed loop ``X_k+1 = A X_k + B r_k`` and its signals at the samples.

    Parameters
    ----------
    st : Structure
        The model's structure.
    p : dict
        As :func:`plant_matrices`, and ``sample_time`` [s], ``KPv, KIv, KI2v, KPf, KDf, KIf`` (the
        gains, :class:`~hybrid.Gains`), ``lag`` (``alpha``), ``filter`` (``... x 5``), all batched alike.

    Returns
    -------
    dict of str to numpy.ndarray
        ``A`` (``... x N x N``), ``B`` (``... x N x n``), the outputs' rows over ``(X_k, r_k)``:
        ``force`` (the true force along each linear axis [N]), ``velocity`` (``x'`` per axis),
        ``command`` (``a`` per axis); and the open loop cut at the command: ``A_open`` (the plant fed an
        outside ``a``), ``B_open`` (``... x N x n``, the command's way in).
    """
    n, L = st.n, st.sensed
    nl = len(L)
    sizes = st.sizes
    offsets = np.cumsum([0] + list(sizes.values()))
    block = {k: np.arange(offsets[i], offsets[i + 1]) for i, k in enumerate(sizes)}
    N = int(offsets[-1])
    batch = np.shape(p["sensor_mass"])
    rows = _Rows(batch, N + n)
    T = np.asarray(p["sample_time"], float)
    Ac, Bc = plant_matrices(st, p)
    Phi, Gam = held(Ac, Bc, T)
    size = Ac.shape[-1] - n  # xi is 0 at each sample, and not kept
    Phi, Gam = Phi[..., :size, :size], Gam[..., :size, :]

    plant = np.concatenate([block["x"], block["xdot"], block["stretch"], block["sdot"]])
    xdot = rows.unit(block["xdot"])
    Ks, Ds = (np.asarray(p[k], float) for k in ("sensor_stiffness", "sensor_damping"))
    force = _scale(Ks, rows.unit(block["stretch"])) + _scale(Ds, rows.unit(block["sdot"]) - rows.unit(block["xdot"][L]))
    nxt = rows.zeros(N)

    # the reading: lag, delay, filter (each block's new value written into nxt)
    y = force
    if st.lag:
        alpha = np.asarray(p["lag"], float)
        y = _scale(alpha, rows.unit(block["lag"])) + _scale(1 - alpha, force)
        nxt[..., block["lag"], :] = y
    m = y
    if st.delay:
        line = block["delay"].reshape(st.delay, nl)
        m = rows.unit(line[-1])
        nxt[..., line[0], :] = y
        for i in range(1, st.delay):
            nxt[..., line[i], :] = rows.unit(line[i - 1])
    z = m
    if st.filtered:
        m1, m2, z1, z2 = block["filter"].reshape(4, nl)
        b = np.asarray(p["filter"], float)
        z = (_scale(b[..., 0], m) + _scale(b[..., 1], rows.unit(m1)) + _scale(b[..., 2], rows.unit(m2))
             - _scale(b[..., 3], rows.unit(z1)) - _scale(b[..., 4], rows.unit(z2)))
        nxt[..., m1, :], nxt[..., m2, :] = m, rows.unit(m1)
        nxt[..., z1, :], nxt[..., z2, :] = z, rows.unit(z1)

    # the loops (conventions §4), integrals advanced with the current error
    command = rows.zeros(n)
    slot = iter(block["integrals"])
    sensed_index = {int(axis): j for j, axis in enumerate(L)}
    reference = rows.unit(N + np.arange(n))
    for i in range(n):
        used = st.integrals[i] if st.integrals else 0
        if st.force[i]:
            e = reference[..., i, :] - z[..., sensed_index[i], :]
            a = -_gain(p["KPf"], e) - _gain(p["KDf"], xdot[..., i, :])
            if used:
                k = next(slot)
                integral = rows.unit(k)[..., 0, :] + _gain(T, e)
                nxt[..., k, :] = integral
                a = a - _gain(p["KIf"], integral)
        else:
            e = reference[..., i, :] - xdot[..., i, :]
            a = _gain(p["KPv"], e)
            previous = None
            for name in ("KIv", "KI2v")[:used]:
                k = next(slot)
                integral = rows.unit(k)[..., 0, :] + _gain(T, e if previous is None else previous)
                nxt[..., k, :] = integral
                a = a + _gain(p[name], integral)
                previous = integral
        command[..., i, :] = a

    open_next = nxt.copy()
    # the plant over the sample, fed the command and the force the law compensates: the measured one, or
    # (Khatib's scheme) the desired one on the force axes, fed forward
    fed = z
    if st.feeds_desired_force:
        fed = rows.zeros(nl)
        for j, axis in enumerate(L):
            if st.force[axis]:
                fed[..., j, :] = reference[..., axis, :]
    plant_rows = rows.unit(plant)
    open_next[..., plant, :] = Phi @ plant_rows + Gam[..., :, n:n + nl] @ fed + Gam[..., :, n + nl:] @ xdot
    nxt[..., plant, :] = open_next[..., plant, :] + Gam[..., :, :n] @ command
    B_open = np.zeros(batch + (N, n))
    B_open[..., plant, :] = Gam[..., :, :n]
    return {"A": nxt[..., :N], "B": nxt[..., N:], "force": force, "velocity": xdot, "command": command,
            "A_open": open_next[..., :N], "B_open": B_open, "blocks": block}


def _gain(k, row: np.ndarray) -> np.ndarray:
    """A batched scalar gain times one row."""
    return np.asarray(k, float)[..., None] * row
