"""The whole closed loop in one C function: many runs at once, one per SIMD lane.

``<prefix>_closed_loop`` runs ``nruns`` experiments that share a plant, a controller step and the
integration settings, ``HL_W`` at a time (see :mod:`codegen.lanes`): per control sample, the
sensor's reading, one controller step (measurement, loops, law, its guards), then
``steps_per_sample`` classical RK4 steps of the plant with the torque held (zero-order hold). The
metrics of conventions §8 are updated on the fly, row by row (the definitions of
:func:`hybrid.metrics`): a row's with its step's first stage, which gives the signals they read, the
last row's after the last step. A sample among whose rows no edge of a metric's window falls (the
steps of the references, the end's last 0.2 s, the first touch's window) has its windows, counts and
peak torques taken once; its rows update only what their signals change. The joints' sin and cos are
computed at a step's start only when its joints have moved more than 2^-8 rad since they last were;
the stages rotate from there.
Per-step states and torques are written only when asked.

Everything a run may vary is a run-time number in its row of ``runs`` (the initial state, the
plant's parameter arrays, the controller's, the reference steps the metrics read); the manifest
lists the row's blocks by name. A run whose controller step trips a guard or gives a non-finite
output, or whose state stops being finite, gets that status and the sample where it happened; the
others go on.
"""

from __future__ import annotations

from dataclasses import dataclass

import casadi as ca
import sympy as sp

from hybrid.spec.controller_step import CONTROLLER_STEP
from hybrid.spec.metrics import METRIC_NAMES, SETTLING_BAND, STEADY_WINDOW_S, TOUCH_BAND, metric_names

from .emit import Unit, comment_safe, manifest, rk4_step, stamp, status_defines
from .kernel import Arg, Kernel
from .lanes import PRELUDE, lanes_function, libm_maps

#: the record columns the loop reads besides the force: normal force, tangential speed, penetration and
#: the surface's normal force (``hybrid.metrics``' force_normal, velocity_tangential, penetration,
#: contact_force)
SIGNALS = ("Fc_n", "v_t", "penetration", "N")
@dataclass(frozen=True)
class LoopSpec:
    """What one closed loop is made of: the plant's state derivative ``rhs(x, tau, ...)`` and output
    record ``outputs(x, ...)``, the controller ``step`` (:mod:`codegen.controller_step`) and the
    record columns of the sensor's force on the robot (base axes)."""

    rhs: Kernel
    outputs: Kernel
    step: Kernel
    force_columns: tuple[str, ...]


def _rows(expr, index: list[int]):
    if isinstance(expr, ca.SX):
        return expr[index]
    return sp.Matrix([expr[i] for i in index])


def signals_kernel(spec: LoopSpec) -> Kernel:
    """The record columns the loop reads (force, then :data:`SIGNALS`), alone: the rest of the
    output record is not computed at every step."""
    y = spec.outputs.outputs[0]
    wanted = (*spec.force_columns, *SIGNALS)
    missing = [c for c in wanted if c not in y.names]
    if missing:
        raise ValueError(f"the plant records no {', '.join(missing)}; it records {', '.join(y.names)}")
    index = [y.names.index(c) for c in wanted]
    return Kernel("loop_signals", spec.outputs.inputs, (Arg("s", _rows(y.expr, index), names=wanted),),
                  "the record columns the closed loop reads")


def stepping_kernel(spec: LoopSpec) -> Kernel:
    """The state derivative, the record columns the loop reads (:func:`signals_kernel`) and the whole
    output record at one state, together: the first stage of an RK4 step gives the row's signals and
    record with what they share with it (the kinematics, the contact) computed once. (The record is
    computed whether or not it is kept: every build then has the same arithmetic, a run alone and a
    batch of lanes alike.)"""
    rhs, signals = spec.rhs, signals_kernel(spec)
    have = {a.name for a in rhs.inputs}
    extra = tuple(a for a in signals.inputs[1:] if a.name not in have)
    outputs = (rhs.outputs[0], signals.outputs[0], spec.outputs.outputs[0])
    return Kernel("plant_rhs_signals", rhs.inputs + extra, outputs,
                  "the plant's state derivative, the record columns the closed loop reads and the whole record")


def blocks(spec: LoopSpec) -> list[tuple[str, int]]:
    """``(name, size)`` of each block of a run's row: the initial state, the plant's parameter arrays
    (``plant.<input>``), the controller's (``controller.<input>``), then the force and speed steps
    ``(before, after, at)`` the metrics read."""
    x = spec.rhs.inputs[0]
    out, sizes = [("x0", x.size)], {}
    for a in (*spec.rhs.inputs[2:], *spec.outputs.inputs[1:]):
        if sizes.setdefault(a.name, a.size) != a.size:
            raise ValueError(f"plant input {a.name} has two sizes")
    out += [(f"plant.{n}", s) for n, s in sizes.items()]
    out += [(f"controller.{a.name}", a.size) for a in _parameters(spec.step)]
    return out + [("force_step", 3), ("speed_step", 3)]


def _parameters(step: Kernel) -> list[Arg]:
    """The step's parameters (:data:`hybrid.spec.controller_step.CONTROLLER_STEP`'s), in order: a run's row holds
    them; the loop itself drives the inputs that change at every sample."""
    if [a.name for a in step.inputs] != [p.name for p in CONTROLLER_STEP.inputs]:
        raise ValueError(f"the controller step's inputs {[a.name for a in step.inputs]} are not its declaration's")
    return [a for a in step.inputs if a.name in CONTROLLER_STEP.parameters]


#: what the loop gives the step's inputs that change at every sample (the others are zero: the plant's sensor
#: gives the wrench on the robot itself and the surface is told, so no filter and no estimate run, and every
#: reference is a step)
_DRIVEN = {"q": "x", "qd": "x + {nq}", "Fc": "fc", "integrals": "z", "last_torque": "last", "t": "tv"}


def _signature(prefix: str) -> str:
    return (f"int {prefix}_closed_loop(int nruns, const double *runs, int n_samples, int steps_per_sample, "
            "double h, double sample_time, double singular_tol, double *metrics, int *status, "
            "int *failed_sample, double *states, double *taus, double *outputs)")


def _pick(target: str, source: str, index: list[int], indent: str = " " * 8) -> str:
    """C statements copying the elements ``index`` of ``source`` into ``target``, in order."""
    return "".join(f"{indent}{target}[{i}] = {source}[{j}];\n" for i, j in enumerate(index))


def _driver(prefix: str, spec: LoopSpec, stepping: Kernel) -> str:
    rhs, step = spec.rhs, spec.step
    nx, nq = rhs.inputs[0].size, rhs.inputs[1].size
    offset, at = {}, 0
    for name, size in blocks(spec):
        offset[name] = at
        at += size
    nb, nf, m = at, len(spec.force_columns), step.inputs[3].size // 2
    ns, nm = nf + len(SIGNALS), len(metric_names(nq))
    ny = stepping.outputs[2].size  # the output record, computed with each step's first stage
    names = spec.outputs.outputs[0].names
    force, signals = ([names.index(c) for c in cols] for cols in (spec.force_columns, stepping.outputs[1].names))
    iF, iv, ipen, iN = (nf + i for i in range(4))
    plant = {a.name: f"blk + {offset['plant.' + a.name]}" for a in (*rhs.inputs[2:], *spec.outputs.inputs[1:])}
    # the run's arrays each kernel holds fixed, then where its values computed once go
    held = ", ".join([*(plant[a.name] for a in rhs.inputs[2:]), "pre_rhs"])
    shown = ", ".join([*(plant[a.name] for a in spec.outputs.inputs[1:]), "pre_out"])
    both = ", ".join([*(plant[a.name] for a in stepping.inputs[2:]), "pre_both"])
    params = ", ".join([*(f"blk + {offset['controller.' + a.name]}" for a in _parameters(step)), "pre_step"])
    per_sample = [a for a in step.inputs if a.name in CONTROLLER_STEP.per_sample]
    nzero = max(a.size for a in per_sample if a.name not in _DRIVEN)
    driven = ", ".join(_DRIVEN.get(a.name, "zero").format(nq=nq) for a in per_sample)
    M = {name: i for i, name in enumerate(METRIC_NAMES)}
    outs = step.core_outputs()
    out_decl = " ".join(f"hl_v o_{a.name}[{a.size}];" for a in outs)
    out_args = ", ".join(f"o_{a.name}" for a in outs)
    tau, z_next = f"o_{outs[0].name}", f"o_{outs[1].name}"
    guards = "".join(f"        flag(&run, hl_fabs(o_{g.name}[0]) < {g.c_tolerance}, {g.status}, k);\n"
                     for g in step.guards)
    finite = " | ".join(f"hl_not_finite(o_{a.name}, {a.size})" for a in outs)
    def stage(state: str, k: str) -> str:  # the first stage also gives the row's signals
        if k == "k1":
            return f"plant_rhs_signals_lanes({state}, {tau}, pre_both, {k}, s, y, base);"
        return f"plant_rhs_lanes({state}, {tau}, pre_rhs, {k}, base);"

    rk4 = rk4_step(stage, "x", nx, "x", " " * 12, "j")
    fs, vs, x0 = offset["force_step"], offset["speed_step"], offset["x0"]
    return f"""
typedef struct {{
    int status[HL_W], sample[HL_W];
    hl_i alive;
}} lanes_run;

/* a lane still running that meets `bad` stops with `status` at sample k */
static void flag(lanes_run *run, hl_i bad, int status, int k) {{
    int l;
    bad &= run->alive;
    if (!hl_any(bad)) return;
    for (l = 0; l < HL_W; ++l) {{
        if (bad[l]) {{
            run->status[l] = status;
            run->sample[l] = k;
        }}
    }}
    run->alive &= ~bad;
}}

/* the metrics' running sums and extremes (hybrid.metrics' definitions, updated row by row) */
typedef struct {{
    hl_v peak, n_f, first_f, last_out_f, last_f, drop, n_v, dev, v_max, sum_fe, sum_ve, n_last, sum_f2, sum_v2,
        pen, in_prev, losses, t_out, touch, fd0, band, w_end, t_peak, t_last_out, t_last, tau[{nq}];
}} lanes_metrics;

/* the metrics' windows at a row (hybrid.metrics'): after the force step and before the next step or the
   end (in_f), after the speed step (in_v), the last 0.2 s (last), the first touch's (in_t, which the first
   touch itself opens); each window's edges as masks apart, and the references there */
typedef struct {{
    hl_v Fd, vd, sgn, f_band;
    hl_i after_f, before_f_end, in_f, in_v, last, before_w_end, in_t;
    int any_f, any_v, any_last;
}} lanes_window;

static inline void window_at(lanes_window *w, const lanes_metrics *mt, const hl_v *blk, long i, double h,
                             double end) {{
    const hl_v fb = blk[{fs}], fa = blk[{fs + 1}], fat = blk[{fs + 2}];
    const hl_v vb = blk[{vs}], va = blk[{vs + 1}], vat = blk[{vs + 2}];
    const hl_v t = hl_splat((double)i * h), step = fa - fb;
    w->Fd = hl_select(t < fat, fb, fa);
    w->vd = hl_select(t < vat, vb, va);
    w->sgn = hl_select(step >= 0.0, hl_splat(1.0), hl_splat(-1.0));
    w->f_band = {SETTLING_BAND!r} * hl_select(fa != 0.0, hl_fabs(fa), hl_fabs(step));
    w->after_f = t >= fat;
    w->before_f_end = t < hl_select(vat > fat, vat, hl_splat(end));
    w->in_f = w->after_f & w->before_f_end;
    w->in_v = t >= vat;
    w->last = t >= end - {STEADY_WINDOW_S!r};
    w->before_w_end = t < mt->w_end;
    w->in_t = (mt->touch >= 0.0) & w->before_w_end;
    w->any_f = hl_any(w->in_f);
    w->any_v = hl_any(w->in_v);
    w->any_last = hl_any(w->last);
}}

/* the rows from `a`'s to `b`'s lie in the same windows, every lane: no window's edge falls between them (the
   edges are fixed but for the first touch's, which the touch itself opens) */
static inline int same_windows(const lanes_window *a, const lanes_window *b) {{
    return !hl_any((a->after_f ^ b->after_f) | (a->before_f_end ^ b->before_f_end) | (a->in_v ^ b->in_v)
                   | (a->last ^ b->last) | (a->before_w_end ^ b->before_w_end));
}}

/* what row i's signals change: extremes, sums, the rows out of a band, the contact's changes, the first
   touch. A window's updates are skipped on the rows where no lane is in it (they would leave each value as
   it is: a sum there only adds +0 to a sum that is never -0) */
HL_ROW void metrics_signals(lanes_metrics *mt, lanes_window *w, const hl_v *blk, const hl_v *s, long i,
                            double h) {{
    const hl_v fb = blk[{fs}], fa = blk[{fs + 1}], fat = blk[{fs + 2}];
    const double ti = (double)i * h;
    const hl_v t = hl_splat(ti), idx = hl_splat((double)i), Fd = w->Fd, vd = w->vd;
    const hl_v F = s[{iF}], v = s[{iv}], pen = s[{ipen}];
    const hl_i contact = s[{iN}] > 0.0, first = contact & (mt->touch < 0.0);
    if (w->any_f) {{
        mt->peak = hl_select(w->in_f & (w->sgn * F > mt->peak), w->sgn * F, mt->peak);
        mt->last_out_f = hl_select(w->in_f & (hl_fabs(F - fa) > w->f_band), idx, mt->last_out_f);
        mt->drop = hl_select(w->in_f & (vd - v > mt->drop), vd - v, mt->drop);
    }}
    if (w->any_v) {{
        mt->dev = hl_select(w->in_v & (hl_fabs(F - Fd) > mt->dev), hl_fabs(F - Fd), mt->dev);
        mt->v_max = hl_select(w->in_v & (v > mt->v_max), v, mt->v_max);
    }}
    if (w->any_last) {{
        mt->sum_fe += hl_select(w->last, Fd - F, hl_splat(0.0));
        mt->sum_ve += hl_select(w->last, vd - v, hl_splat(0.0));
    }}
    mt->sum_f2 += (Fd - F) * (Fd - F);
    mt->sum_v2 += (vd - v) * (vd - v);
    mt->pen = hl_select(pen > mt->pen, pen, mt->pen);
    if (i > 0) {{
        mt->losses += hl_select((mt->in_prev != 0.0) & ~contact, hl_splat(1.0), hl_splat(0.0));
        mt->t_out += hl_select(contact, hl_splat(0.0), hl_splat(ti - (double)(i - 1) * h));
    }}
    mt->in_prev = hl_bool(contact);
    if (hl_any(first)) {{ /* its window lasts until the force reference next changes: past this row */
        mt->touch = hl_select(first, idx, mt->touch);
        mt->fd0 = hl_select(first, Fd, mt->fd0);
        mt->band = hl_select(first, {TOUCH_BAND!r} * hl_fabs(Fd), mt->band);
        mt->w_end = hl_select(first, hl_select((fa != fb) & (fat > t), fat, hl_splat(INFINITY)), mt->w_end);
        w->in_t |= first;
    }}
    if (hl_any(w->in_t)) {{
        mt->t_peak = hl_select(w->in_t & (F > mt->t_peak), F, mt->t_peak);
        mt->t_last_out = hl_select(w->in_t & (hl_fabs(F - mt->fd0) > mt->band), idx, mt->t_last_out);
    }}
}}

/* what the rows i0 .. i1, all in the windows of `w`, add up to: the counts, a window's first and last row */
static inline void metrics_rows(lanes_metrics *mt, const lanes_window *w, long i0, long i1) {{
    const hl_v n = hl_splat((double)(i1 - i0 + 1)), zero = hl_splat(0.0);
    mt->n_f += hl_select(w->in_f, n, zero);
    mt->first_f = hl_select(w->in_f & (mt->first_f < 0.0), hl_splat((double)i0), mt->first_f);
    mt->last_f = hl_select(w->in_f, hl_splat((double)i1), mt->last_f);
    mt->n_v += hl_select(w->in_v, n, zero);
    mt->n_last += hl_select(w->last, n, zero);
    mt->t_last = hl_select(w->in_t, hl_splat((double)i1), mt->t_last);
}}

/* the joints' peak torques (a torque held for a sample: once per sample) */
static inline void metrics_torque(lanes_metrics *mt, const hl_v *tau) {{
    int j;
    for (j = 0; j < {nq}; ++j) {{
        const hl_v a = hl_fabs(tau[j]);
        mt->tau[j] = hl_select(a > mt->tau[j], a, mt->tau[j]);
    }}
}}

/* one row's metrics, its windows its own */
static void metrics_row(lanes_metrics *mt, const hl_v *blk, const hl_v *s, const hl_v *tau, long i, double h,
                        double end) {{
    lanes_window w;
    window_at(&w, mt, blk, i, h, end);
    metrics_signals(mt, &w, blk, s, i, h);
    metrics_rows(mt, &w, i, i);
    metrics_torque(mt, tau);
}}

static void metrics_of_lane(const lanes_metrics *mt, const hl_v *blk, int l, long rows, double h, double *out) {{
    const double fb = blk[{fs}][l], fa = blk[{fs + 1}][l], vb = blk[{vs}][l], va = blk[{vs + 1}][l];
    int j;
    for (j = 0; j < 6; ++j) out[j] = NAN;
    if (mt->n_f[l] > 0 && fa != fb) {{
        const double step = fa - fb, sgn = step >= 0 ? 1.0 : -1.0;
        const double lo = mt->last_out_f[l], lf = mt->last_f[l], first = mt->first_f[l];
        out[{M['force_overshoot_N']}] = (sgn * mt->peak[l] - fa) * sgn;
        out[{M['force_overshoot_percent']}] = 100 * out[{M['force_overshoot_N']}] / fabs(step);
        out[{M['force_settling_time_2pct_s']}] = lo < 0 ? 0.0 : lo == lf ? NAN : (lo + 1) * h - first * h;
        out[{M['speed_drop_after_force_step_m_per_s']}] = mt->drop[l];
    }}
    if (mt->n_v[l] > 0 && va != vb) {{
        out[{M['force_deviation_after_speed_step_N']}] = mt->dev[l];
        out[{M['speed_overshoot_after_speed_step_m_per_s']}] = mt->v_max[l] - va;
    }}
    out[{M['steady_state_force_error_N']}] = mt->sum_fe[l] / mt->n_last[l];
    out[{M['steady_state_speed_error_m_per_s']}] = mt->sum_ve[l] / mt->n_last[l];
    out[{M['rms_force_error_N']}] = sqrt(mt->sum_f2[l] / (double)rows);
    out[{M['rms_speed_error_m_per_s']}] = sqrt(mt->sum_v2[l] / (double)rows);
    out[{M['max_penetration_m']}] = mt->pen[l];
    out[{M['contact_losses']}] = mt->losses[l];
    out[{M['time_out_of_contact_s']}] = mt->t_out[l];
    out[{M['first_touch_time_s']}] = out[{M['first_touch_overshoot_N']}] = out[{M['first_touch_settling_s']}] = NAN;
    if (mt->touch[l] >= 0) {{
        const double lo = mt->t_last_out[l], lt = mt->t_last[l], first = mt->touch[l];
        out[{M['first_touch_time_s']}] = first * h;
        out[{M['first_touch_overshoot_N']}] = mt->t_peak[l] - mt->fd0[l];
        out[{M['first_touch_settling_s']}] = lo < 0 ? 0.0 : lo == lt ? NAN : (lo + 1) * h - first * h;
    }}
    for (j = 0; j < {nq}; ++j) out[{len(METRIC_NAMES)} + j] = mt->tau[j][l];
}}

/* the row's state of each lane in `state` and torque of each lane in `torque`; NaN for the others (a lane
   that stopped) */
static void record_row(double *states, double *taus, int g, int used, long row, long rows, const hl_v *x,
                       const hl_v *tau, hl_i state, hl_i torque) {{
    int l, j;
    for (l = 0; l < used; ++l) {{
        const long at = (long)(g + l) * rows + row;
        if (states) for (j = 0; j < {nx}; ++j) states[at * {nx} + j] = state[l] ? x[j][l] : NAN;
        if (taus) for (j = 0; j < {nq}; ++j) taus[at * {nq} + j] = torque[l] ? tau[j][l] : NAN;
    }}
}}

/* the output row of each lane still running (NaN for the others) */
static void record_outputs_row(double *outputs, int g, int used, long row, long rows, const hl_v *y, hl_i alive) {{
    int l, j;
    for (l = 0; l < used; ++l) {{
        const long at = (long)(g + l) * rows + row;
        for (j = 0; j < {ny}; ++j) outputs[at * {ny} + j] = alive[l] ? y[j][l] : NAN;
    }}
}}

/* what a run keeps, where it keeps it: the test inline, the copy out of line (a call spills every vector
   register the loop holds, so a run that keeps nothing makes none) */
static inline void record(double *states, double *taus, int g, int used, long row, long rows, const hl_v *x,
                          const hl_v *tau, hl_i state, hl_i torque) {{
    if (states || taus) record_row(states, taus, g, used, row, rows, x, tau, state, torque);
}}
static inline void record_outputs(double *outputs, int g, int used, long row, long rows, const hl_v *y, hl_i alive) {{
    if (outputs) record_outputs_row(outputs, g, used, row, rows, y, alive);
}}

/* the runs g .. g + used - 1 as one group of HL_W lanes (unused lanes repeat run g) */
static void run_lanes(int g, int used, const double *runs, int n_samples, int steps_per_sample, double h,
                      double sample_time, double singular_tol, double *metrics, int *status, int *failed_sample,
                      double *states, double *taus, double *outputs) {{
    hl_v pre_rhs[PLANT_RHS_LANES_NPRE], pre_out[PLANT_OUTPUTS_LANES_NPRE], pre_both[PLANT_RHS_SIGNALS_LANES_NPRE],
        pre_step[{step.name.upper()}_LANES_NPRE];
    hl_v blk[{nb}], x[{nx}], xt[{nx}], k1[{nx}], k2[{nx}], k3[{nx}], k4[{nx}], s[{ns}], fc[6], z[{2 * m}], tv[1],
        zero[{nzero}], base[{3 * nq}], last[{nq + 1}], y[{ny}];
    {out_decl}
    lanes_run run;
    lanes_metrics mt;
    lanes_window win, win_end;
    hl_i at_sample;
    const long rows = (long)n_samples * steps_per_sample + 1;
    const double end = (double)(rows - 1) * h;
    long row = 0;
    int i, j, l, k, steady;
    (void)singular_tol;
    for (l = 0; l < HL_W; ++l) {{
        for (j = 0; j < {nb}; ++j) blk[j][l] = runs[(long)(g + (l < used ? l : 0)) * {nb} + j];
        run.status[l] = HYBRID_OK;
        run.sample[l] = -1;
    }}
    run.alive = hl_splat(0.0) == 0.0;
    mt.peak = mt.drop = mt.dev = mt.v_max = mt.pen = hl_splat(-INFINITY);
    mt.first_f = mt.last_out_f = mt.last_f = hl_splat(-1.0);
    mt.n_f = mt.n_v = mt.sum_fe = mt.sum_ve = mt.n_last = mt.sum_f2 = mt.sum_v2 = mt.in_prev = mt.losses = mt.t_out
        = hl_splat(0.0);
    mt.touch = mt.t_last_out = mt.t_last = hl_splat(-1.0);
    mt.fd0 = mt.band = hl_splat(0.0);
    mt.w_end = hl_splat(INFINITY);
    mt.t_peak = hl_splat(-INFINITY);
    for (j = 0; j < {nq}; ++j) mt.tau[j] = hl_splat(0.0);
    for (j = 0; j < {nzero}; ++j) zero[j] = hl_splat(0.0);
    for (j = 0; j < 6; ++j) fc[j] = hl_splat(0.0);
    for (j = 0; j < {2 * m}; ++j) z[j] = hl_splat(0.0);
    for (j = 0; j <= {nq}; ++j) last[j] = hl_splat(0.0);
    for (j = 0; j < {nx}; ++j) x[j] = blk[{x0} + j];
    for (j = 0; j < {3 * nq}; ++j) base[j] = hl_splat(NAN);  /* none yet: the first step computes it */
    plant_rhs_lanes_pre({held});
    plant_outputs_lanes_pre({shown});
    plant_rhs_signals_lanes_pre({both});
    {step.name}_lanes_pre({params});
    for (k = 0; k < n_samples && hl_any(run.alive); ++k) {{
        /* the sensor's reading at the sample instant (a row's signals come with its step's first stage) */
        plant_outputs_lanes(x, pre_out, y);
{_pick("fc", "y", force)}
        tv[0] = hl_splat(k * sample_time);
        /* the plant's sensor gives the wrench on the robot itself and the surface is told: no filter, no estimate */
        {step.name}_lanes({driven}, pre_step, {out_args});
        at_sample = run.alive;  /* the lanes whose state this sample starts from is recorded */
{guards}        flag(&run, {finite}, HYBRID_NONFINITE, k);
        for (j = 0; j < {2 * m}; ++j) z[j] = {z_next}[j];
        /* the torque the rate limit starts from at the next sample */
        for (j = 0; j < {nq}; ++j) last[j] = {tau}[j];
        last[{nq}] = hl_splat(1.0);
        if (k == 0) record(states, taus, g, used, 0, rows, x, {tau}, hl_splat(0.0) == 0.0, run.alive);
        /* the metrics' windows: where no edge of theirs falls among the sample's rows, each row updates only
           what its signals change, and the counts are the sample's */
        window_at(&win, &mt, blk, row, h, end);
        window_at(&win_end, &mt, blk, row + steps_per_sample - 1, h, end);
        steady = same_windows(&win, &win_end);
        metrics_torque(&mt, {tau});
        for (i = 0; i < steps_per_sample; ++i) {{
            /* the joints' sin and cos the step's stages rotate from: its start's, or an earlier step's */
            hl_rebase(x, base, {nq});
{rk4}
            /* the row the step started from */
            if (!steady) window_at(&win, &mt, blk, row, h, end);
            metrics_signals(&mt, &win, blk, s, row, h);
            if (!steady) metrics_rows(&mt, &win, row, row);
            /* the row's output where its state is recorded (a sample's first row: before its controller's stop) */
            record_outputs(outputs, g, used, row, rows, y, i == 0 ? at_sample : run.alive);
            ++row;
            flag(&run, hl_not_finite(x, {nx}), HYBRID_NONFINITE, k);
            /* a stopped lane restarts from its initial state: its numbers no longer matter, and they stay
               finite */
            if (hl_any(~run.alive)) {{
                for (j = 0; j < {nx}; ++j) x[j] = hl_select(run.alive, x[j], blk[{x0} + j]);
            }}
            record(states, taus, g, used, row, rows, x, {tau}, run.alive, run.alive);
        }}
        if (steady) metrics_rows(&mt, &win, row - steps_per_sample, row - 1);
    }}
    if (k > 0) {{ /* the last row */
        plant_outputs_lanes(x, pre_out, y);
{_pick("s", "y", signals)}        metrics_row(&mt, blk, s, {tau}, row, h, end);
        record_outputs(outputs, g, used, row, rows, y, run.alive);
    }}
    while (++row < rows) {{ /* all stopped */
        record(states, taus, g, used, row, rows, x, {tau}, run.alive, run.alive);
        record_outputs(outputs, g, used, row, rows, y, run.alive);
    }}
    for (l = 0; l < used; ++l) {{
        status[g + l] = run.status[l];
        failed_sample[g + l] = run.sample[l];
        metrics_of_lane(&mt, blk, l, rows, h, metrics + (long)(g + l) * {nm});
    }}
}}

{_signature(prefix)} {{
    int g;
    for (g = 0; g < nruns; g += HL_W) {{
        run_lanes(g, nruns - g < HL_W ? nruns - g : HL_W, runs, n_samples, steps_per_sample, h, sample_time,
                  singular_tol, metrics, status, failed_sample, states, taus, outputs);
    }}
    return HYBRID_OK;
}}

int {prefix}_lanes(void) {{
    return HL_W;
}}
"""


#: a small RK4 stage is inlined into the loop where lanes are many (measured on the paper's plant: 10 %
#: faster with 8 lanes, 8 % slower with one, where the loop is bound by latency, not throughput); a large
#: one is not (the UR5's: the same speed, twice the compile time)
#: and a row's metrics likewise (the paper's: 4 % faster with 8 lanes; with the two of a run alone the
#: same speed, and a tenth of a second longer to compile on a first run)
_STAGE = """#if HL_W > 1 && {small}
#define HL_STAGE static inline __attribute__((always_inline))
#else
#define HL_STAGE static
#endif
#if HL_W > 2
#define HL_ROW static inline __attribute__((always_inline))
#else
#define HL_ROW static
#endif"""
#: the most lines of C the two stage functions may have to be inlined (the paper's plant: about 900; the
#: UR5's: about 11,000)
_INLINE_LINES = 3000


#: a unit compiled in two parts at once, one compiler each (``-DHL_PART=1`` and ``-DHL_PART=2``, linked
#: together, with a binding compiled as ``-DHL_PART=0``, which only declares: :mod:`hybrid.native.build`):
#: the second holds the functions the loop calls out of line (the plant's output record, the controller
#: step, what a run computes once, the exact functions' pass), the first the loop with its stages inlined.
#: A first run waits for the longer part, not for the whole. Without ``HL_PART`` it is one unit as any other.
PARTS = """#ifdef HL_PART
#define HL_APART __attribute__((visibility("hidden")))
#define HL_IN_PART(n) (HL_PART == (n))
#else
#define HL_APART static
#define HL_IN_PART(n) 1
#endif"""
#: the parts the manifest's ``parts`` names
N_PARTS = 2


#: the lanes of the build for one run at a time, each the same run: two (the 128-bit vectors of every
#: x86-64 and ARM processor). One lane alone is slower by about a tenth (the paper's run and the 3-D
#: one): GCC turns a vector of one into scalar and integer code (the masks, selects and absolute values
#: go through integer registers, the selects become branches), where two stay in vector registers.
ONE_RUN_LANES = 2


def build_closed_loop_unit(spec: LoopSpec, prefix: str, what: str, info: dict,
                           lanes: int | None = None) -> Unit:
    """C source, header and manifest of the closed loop ``spec``, deterministic in its inputs; ``lanes``
    fixes the lane count instead of the instruction set's, and 1 is the build for one run at a time (as
    fast as one run goes: :data:`ONE_RUN_LANES` lanes, each the same run)."""
    nq = spec.rhs.inputs[1].size
    rhs = Kernel("plant_rhs", spec.rhs.inputs, spec.rhs.outputs, spec.rhs.doc)
    held = tuple(a.name for a in spec.rhs.inputs[2:])
    shown = tuple(a.name for a in spec.outputs.inputs[1:])
    params = tuple(a.name for a in _parameters(spec.step))
    stepping = stepping_kernel(spec)
    stages = "".join(lanes_function(k, name, fixed, "HL_STAGE", near=nq, apart=True) + "\n" for k, name, fixed in (
        (rhs, "plant_rhs_lanes", held), (stepping, "plant_rhs_signals_lanes", held + shown)))
    width = f"#define HL_W {ONE_RUN_LANES if lanes == 1 else lanes}" if lanes else ""
    body = (f"/* {prefix}: {comment_safe(what)}.\n   Emitted by hybrid's codegen/closed_loop.py. */\n"
            "#if !defined(__GNUC__)\n#error \"the compiled closed loop needs GCC or Clang (vector extensions)\"\n"
            f"#endif\n{width}\n{PRELUDE}\n{status_defines()}\n\n{libm_maps()}\n"
            f"{PARTS}\n{_STAGE.format(small=int(stages.count(chr(10)) <= _INLINE_LINES))}\n{stages}"
            f"{lanes_function(spec.outputs, 'plant_outputs_lanes', shown, 'HL_APART', apart=True)}\n"
            f"{lanes_function(spec.step, spec.step.name + '_lanes', params, 'HL_APART', apart=True)}\n"
            f"#if HL_IN_PART(1)\n{_driver(prefix, spec, stepping)}#else\n{_signature(prefix)};\n"
            f"int {prefix}_lanes(void);\n#endif\n")
    doc = ("run nruns closed loops (rows of runs, blocks as the manifest's closed_loop.blocks), HL_W at a time: "
           "n_samples control samples of sample_time [s], steps_per_sample RK4 steps of h [s] each; writes "
           "metrics (nruns x closed_loop.metrics), status and failed_sample (-1, or the sample where a run "
           "stopped) per run, and states, taus and the output record (closed_loop.outputs) per step when not NULL "
           "(nruns x rows x size)")
    header = f"""#ifndef {prefix.upper()}_H
#define {prefix.upper()}_H
/* cdef-begin */
/* {doc}. */
{_signature(prefix)};
/* the runs per group: HL_W lanes (8 with AVX-512, 4 with AVX, else 2) */
int {prefix}_lanes(void);
/* cdef-end */
#endif
"""
    loop = {"symbol": f"{prefix}_closed_loop", "lanes_symbol": f"{prefix}_lanes",
            "blocks": [{"name": n, "size": s} for n, s in blocks(spec)],
            "state": list(spec.rhs.inputs[0].names or ()), "nx": spec.rhs.inputs[0].size, "nq": nq,
            "metrics": list(metric_names(nq)),
            "signals": [*spec.force_columns, *SIGNALS],
            "outputs": list(stepping.outputs[2].names)}
    text = manifest(prefix, (), f"CasADi {ca.__version__}", {**info, "parts": N_PARTS, "closed_loop": loop})
    return Unit(prefix, stamp(body), stamp(header), text)
