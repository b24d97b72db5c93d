/* hybrid generated file: do not edit; change codegen/ and run `python -m hybrid regenerate`. body-sha256: 14ea142a19aa8575649035557c80856a125077d63809b0eacca05761c94bb97a */
#ifndef HYBRID_PATH_H
#define HYBRID_PATH_H
/* The path follower: a path on a surface as a table, followed from the tip's measured position.
   Standalone C99: no allocation, no globals, no I/O; reentrant (the state is the caller's).

   Each sample: status = hybrid_path_follow(table, settings, state, p, R, force, out);  (R: 9, force: 3 numbers)
   then state = out[0 .. HYBRID_PATH_STATE_SIZE - 1] (the first outputs are the state after the sample), and
   out gives the task frame's direction e (HYBRID_PATH_OUT_E_X..Z) and the loops' references.

   The table: HYBRID_PATH_COLUMNS numbers per node, nodes in increasing arc length from 0 to the length.
   Between nodes the path is the cubic Hermite curve through the nodes' points with their unit tangents;
   the normal, the geodesic curvature, the speed and the force are interpolated linearly. */
#include <math.h>

/* a node's numbers: one row of the table */
#define HYBRID_PATH_TABLE_SIZE 15
#define HYBRID_PATH_TABLE_S 0
#define HYBRID_PATH_TABLE_P_X 1
#define HYBRID_PATH_TABLE_P_Y 2
#define HYBRID_PATH_TABLE_P_Z 3
#define HYBRID_PATH_TABLE_T_X 4
#define HYBRID_PATH_TABLE_T_Y 5
#define HYBRID_PATH_TABLE_T_Z 6
#define HYBRID_PATH_TABLE_N_X 7
#define HYBRID_PATH_TABLE_N_Y 8
#define HYBRID_PATH_TABLE_N_Z 9
#define HYBRID_PATH_TABLE_KAPPA_G 10
#define HYBRID_PATH_TABLE_SPEED 11
#define HYBRID_PATH_TABLE_FORCE 12
#define HYBRID_PATH_TABLE_TILT 13
#define HYBRID_PATH_TABLE_LEAD 14

/* the follower's settings */
#define HYBRID_PATH_SETTINGS_SIZE 15
#define HYBRID_PATH_SETTINGS_ROWS 0
#define HYBRID_PATH_SETTINGS_CLOSED 1
#define HYBRID_PATH_SETTINGS_LENGTH 2
#define HYBRID_PATH_SETTINGS_START 3
#define HYBRID_PATH_SETTINGS_DISTANCE 4
#define HYBRID_PATH_SETTINGS_SPEED_START 5
#define HYBRID_PATH_SETTINGS_ACCELERATION 6
#define HYBRID_PATH_SETTINGS_CROSS_TRACK_GAIN 7
#define HYBRID_PATH_SETTINGS_CROSS_TRACK_LIMIT 8
#define HYBRID_PATH_SETTINGS_TOUCH_FORCE 9
#define HYBRID_PATH_SETTINGS_SAMPLE_TIME 10
#define HYBRID_PATH_SETTINGS_UNLOAD_TIME 11
#define HYBRID_PATH_SETTINGS_RETREAT_DISTANCE 12
#define HYBRID_PATH_SETTINGS_RETREAT_SPEED 13
#define HYBRID_PATH_SETTINGS_ORIENTATION_GAIN 14

/* the follower's state (the first outputs are the state after a sample) */
#define HYBRID_PATH_STATE_SIZE 6
#define HYBRID_PATH_STATE_S 0
#define HYBRID_PATH_STATE_TRAVELLED 1
#define HYBRID_PATH_STATE_ROW 2
#define HYBRID_PATH_STATE_STARTED 3
#define HYBRID_PATH_STATE_PHASE 4
#define HYBRID_PATH_STATE_PHASE_TIME 5

/* what a sample gives */
#define HYBRID_PATH_OUT_SIZE 31
#define HYBRID_PATH_OUT_S 0
#define HYBRID_PATH_OUT_TRAVELLED 1
#define HYBRID_PATH_OUT_ROW 2
#define HYBRID_PATH_OUT_STARTED 3
#define HYBRID_PATH_OUT_PHASE 4
#define HYBRID_PATH_OUT_PHASE_TIME 5
#define HYBRID_PATH_OUT_C_X 6
#define HYBRID_PATH_OUT_C_Y 7
#define HYBRID_PATH_OUT_C_Z 8
#define HYBRID_PATH_OUT_T_X 9
#define HYBRID_PATH_OUT_T_Y 10
#define HYBRID_PATH_OUT_T_Z 11
#define HYBRID_PATH_OUT_N_X 12
#define HYBRID_PATH_OUT_N_Y 13
#define HYBRID_PATH_OUT_N_Z 14
#define HYBRID_PATH_OUT_E_X 15
#define HYBRID_PATH_OUT_E_Y 16
#define HYBRID_PATH_OUT_E_Z 17
#define HYBRID_PATH_OUT_SPEED 18
#define HYBRID_PATH_OUT_SPEED_RATE 19
#define HYBRID_PATH_OUT_LATERAL_SPEED 20
#define HYBRID_PATH_OUT_LATERAL_RATE 21
#define HYBRID_PATH_OUT_NORMAL_REFERENCE 22
#define HYBRID_PATH_OUT_CROSS_TRACK 23
#define HYBRID_PATH_OUT_PATH_ERROR 24
#define HYBRID_PATH_OUT_HEIGHT 25
#define HYBRID_PATH_OUT_DONE 26
#define HYBRID_PATH_OUT_RETREAT 27
#define HYBRID_PATH_OUT_SPIN_T1 28
#define HYBRID_PATH_OUT_SPIN_T2 29
#define HYBRID_PATH_OUT_TOOL_ANGLE_ERROR 30

#define HYBRID_PATH_COLUMNS HYBRID_PATH_TABLE_SIZE
/* the phases (HYBRID_PATH_OUT_PHASE) */
#define HYBRID_PATH_APPROACH 0
#define HYBRID_PATH_FOLLOW 1
#define HYBRID_PATH_UNLOAD 2
#define HYBRID_PATH_RETREAT 3
#define HYBRID_PATH_CLEAR 4
#define HYBRID_PATH_OK 0
#define HYBRID_PATH_INPUT_NONFINITE 1
#define HYBRID_PATH_TABLE_INVALID 2
/* how close to the end of the distance to travel counts as done [m] */
#define HYBRID_PATH_DONE_TOL 0.0001
/* Newton steps of the progress per sample */
#define HYBRID_PATH_NEWTON_STEPS 3

#define HYBRID_PATH_AT(table, i, k) ((table)[(long)(i) * HYBRID_PATH_COLUMNS + (k)])

/* the follower's arithmetic as written, in every build: no contraction into fused multiply-adds (a build
   for this processor would contract, a strict one not), so every caller's follower gives the same numbers */
#if defined(__clang__)
#pragma STDC FP_CONTRACT OFF
#elif defined(__GNUC__)
#pragma GCC push_options
#pragma GCC optimize("fp-contract=off")
#endif

static inline double hybrid_path_dot3(const double *a, const double *b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

static inline void hybrid_path_cross3(const double *a, const double *b, double *c) {
    c[0] = a[1] * b[2] - a[2] * b[1];
    c[1] = a[2] * b[0] - a[0] * b[2];
    c[2] = a[0] * b[1] - a[1] * b[0];
}

/* v turned by the angle (cos c, sin s) about the unit axis k (Rodrigues), into out */
static inline void hybrid_path_turn(const double *v, const double *k, double c, double s, double *out) {
    double kxv[3], kv = hybrid_path_dot3(k, v);
    int i;
    hybrid_path_cross3(k, v, kxv);
    for (i = 0; i < 3; ++i) out[i] = c * v[i] + s * kxv[i] + (1.0 - c) * kv * k[i];
}

/* 1: the settings are values the follower can use: a whole number of rows >= 2, closed 0 or 1, a positive
   length, a start within it, a distance, a start speed and a cross-track gain >= 0, a positive acceleration */
static inline int hybrid_path_settings_valid(const double *settings) {
    int i;
    for (i = 0; i < HYBRID_PATH_SETTINGS_SIZE; ++i)
        if (!(settings[i] == settings[i])) return 0;
    return settings[HYBRID_PATH_SETTINGS_ROWS] >= 2.0 && settings[HYBRID_PATH_SETTINGS_ROWS] <= 1e9
        && settings[HYBRID_PATH_SETTINGS_ROWS] == floor(settings[HYBRID_PATH_SETTINGS_ROWS])
        && (settings[HYBRID_PATH_SETTINGS_CLOSED] == 0.0 || settings[HYBRID_PATH_SETTINGS_CLOSED] == 1.0)
        && isfinite(settings[HYBRID_PATH_SETTINGS_LENGTH]) && settings[HYBRID_PATH_SETTINGS_LENGTH] > 0.0
        && settings[HYBRID_PATH_SETTINGS_START] >= 0.0
        && settings[HYBRID_PATH_SETTINGS_START] <= settings[HYBRID_PATH_SETTINGS_LENGTH]
        && settings[HYBRID_PATH_SETTINGS_DISTANCE] >= 0.0
        && isfinite(settings[HYBRID_PATH_SETTINGS_SPEED_START]) && settings[HYBRID_PATH_SETTINGS_SPEED_START] >= 0.0
        && isfinite(settings[HYBRID_PATH_SETTINGS_ACCELERATION]) && settings[HYBRID_PATH_SETTINGS_ACCELERATION] > 0.0
        && isfinite(settings[HYBRID_PATH_SETTINGS_CROSS_TRACK_GAIN])
        && settings[HYBRID_PATH_SETTINGS_CROSS_TRACK_GAIN] >= 0.0
        && isfinite(settings[HYBRID_PATH_SETTINGS_CROSS_TRACK_LIMIT])
        && settings[HYBRID_PATH_SETTINGS_CROSS_TRACK_LIMIT] >= 0.0
        && settings[HYBRID_PATH_SETTINGS_TOUCH_FORCE] < 1e300
        && isfinite(settings[HYBRID_PATH_SETTINGS_SAMPLE_TIME]) && settings[HYBRID_PATH_SETTINGS_SAMPLE_TIME] > 0.0
        && isfinite(settings[HYBRID_PATH_SETTINGS_UNLOAD_TIME]) && settings[HYBRID_PATH_SETTINGS_UNLOAD_TIME] >= 0.0
        && isfinite(settings[HYBRID_PATH_SETTINGS_RETREAT_DISTANCE])
        && settings[HYBRID_PATH_SETTINGS_RETREAT_DISTANCE] >= 0.0
        && isfinite(settings[HYBRID_PATH_SETTINGS_RETREAT_SPEED]) && settings[HYBRID_PATH_SETTINGS_RETREAT_SPEED] >= 0.0
        && isfinite(settings[HYBRID_PATH_SETTINGS_ORIENTATION_GAIN])
        && settings[HYBRID_PATH_SETTINGS_ORIENTATION_GAIN] >= 0.0;
}

/* 1: the whole table is finite, starts at arc length 0, grows strictly and ends at the length (a check for
   the caller's set-up; each sample checks the two nodes it reads) */
static inline int hybrid_path_table_valid(const double *table, const double *settings) {
    long i, k, rows;
    if (!hybrid_path_settings_valid(settings)) return 0;
    rows = (long)settings[HYBRID_PATH_SETTINGS_ROWS];
    for (i = 0; i < rows; ++i)
        for (k = 0; k < HYBRID_PATH_COLUMNS; ++k)
            if (!isfinite(HYBRID_PATH_AT(table, i, k))) return 0;
    for (i = 1; i < rows; ++i)
        if (!(HYBRID_PATH_AT(table, i, HYBRID_PATH_TABLE_S) > HYBRID_PATH_AT(table, i - 1, HYBRID_PATH_TABLE_S)))
            return 0;
    return HYBRID_PATH_AT(table, 0, HYBRID_PATH_TABLE_S) == 0.0
        && HYBRID_PATH_AT(table, rows - 1, HYBRID_PATH_TABLE_S) == settings[HYBRID_PATH_SETTINGS_LENGTH];
}

/* the row i (0 .. rows - 2) whose interval [s_i, s_i+1) holds s: from the hint where s is a row or two away
   from it (a sample's motion), else by bisection (a jump: a closed path's wrap, a start) */
static inline long hybrid_path_row(const double *table, long rows, long hint, double s) {
    long i = hint < 0 ? 0 : hint > rows - 2 ? rows - 2 : hint, lo = 0, hi = rows - 2, steps;
    for (steps = 0; steps < 2 && i < rows - 2 && s >= HYBRID_PATH_AT(table, i + 1, HYBRID_PATH_TABLE_S); ++steps)
        ++i;
    for (steps = 0; steps < 2 && i > 0 && s < HYBRID_PATH_AT(table, i, HYBRID_PATH_TABLE_S); ++steps) --i;
    if ((i == rows - 2 || s < HYBRID_PATH_AT(table, i + 1, HYBRID_PATH_TABLE_S))
        && (i == 0 || s >= HYBRID_PATH_AT(table, i, HYBRID_PATH_TABLE_S)))
        return i;
    while (lo < hi) { /* the last row whose s_i <= s */
        long mid = lo + (hi - lo + 1) / 2;
        if (HYBRID_PATH_AT(table, mid, HYBRID_PATH_TABLE_S) <= s) lo = mid; else hi = mid - 1;
    }
    return lo;
}

/* the row whose node is nearest p (a search of every node: where the follower starts, wherever the tip is) */
static inline long hybrid_path_nearest(const double *table, long rows, const double *p) {
    long i, best = 0;
    double d, least = HUGE_VAL, r[3];
    int k;
    for (i = 0; i < rows; ++i) {
        for (k = 0; k < 3; ++k) r[k] = p[k] - HYBRID_PATH_AT(table, i, HYBRID_PATH_TABLE_P_X + k);
        d = hybrid_path_dot3(r, r);
        if (d < least) {
            least = d;
            best = i;
        }
    }
    return best;
}

/* the path at s within row i: its point c, unit tangent t and, with n given, the surface's unit normal
   (orthogonal to t) and the interpolation weight u of the next node; 0 where the two nodes are unusable */
static inline int hybrid_path_at(const double *table, long i, double s, double *c, double *t, double *n, double *u_out) {
    const double *a = &HYBRID_PATH_AT(table, i, 0), *b = &HYBRID_PATH_AT(table, i + 1, 0);
    double h = b[HYBRID_PATH_TABLE_S] - a[HYBRID_PATH_TABLE_S], u, h00, h10, h01, h11, d00, d10, d01, d11, len, nt;
    int k;
    for (k = 0; k < HYBRID_PATH_COLUMNS; ++k)
        if (!isfinite(a[k]) || !isfinite(b[k])) return 0;
    if (!(h > 0.0)) return 0;
    u = (s - a[HYBRID_PATH_TABLE_S]) / h;
    h00 = (2.0 * u - 3.0) * u * u + 1.0;
    h10 = ((u - 2.0) * u + 1.0) * u;
    h01 = (3.0 - 2.0 * u) * u * u;
    h11 = (u - 1.0) * u * u;
    d00 = 6.0 * u * (u - 1.0);
    d10 = (3.0 * u - 4.0) * u + 1.0;
    d01 = -d00;
    d11 = (3.0 * u - 2.0) * u;
    for (k = 0; k < 3; ++k) {
        double pa = a[HYBRID_PATH_TABLE_P_X + k], pb = b[HYBRID_PATH_TABLE_P_X + k];
        double ta = a[HYBRID_PATH_TABLE_T_X + k], tb = b[HYBRID_PATH_TABLE_T_X + k];
        c[k] = h00 * pa + h10 * h * ta + h01 * pb + h11 * h * tb;
        t[k] = (d00 * pa + d01 * pb) / h + d10 * ta + d11 * tb;
    }
    len = sqrt(hybrid_path_dot3(t, t));
    if (!(len > 0.0)) return 0;
    for (k = 0; k < 3; ++k) t[k] /= len;
    if (n == 0) return 1;
    for (k = 0; k < 3; ++k) n[k] = (1.0 - u) * a[HYBRID_PATH_TABLE_N_X + k] + u * b[HYBRID_PATH_TABLE_N_X + k];
    nt = hybrid_path_dot3(n, t);
    for (k = 0; k < 3; ++k) n[k] -= nt * t[k];
    len = sqrt(hybrid_path_dot3(n, n));
    if (!(len > 0.0)) return 0;
    for (k = 0; k < 3; ++k) n[k] /= len;
    *u_out = u;
    return 1;
}

/* One sample: from the follower's state, the tip's position p [m, base axes], the tip frame's rotation R (9
   numbers, row by row: its third column is the tool's axis) and the contact force on the robot there (force, 3
   numbers [N, base axes]: along n, positive pressing), the outputs out (HYBRID_PATH_OUT_*: the state
   after the sample first). Returns HYBRID_PATH_OK, or a status with out unwritten: HYBRID_PATH_INPUT_NONFINITE
   (p, the force or the state is not finite), HYBRID_PATH_TABLE_INVALID (the settings, or the nodes the sample
   reads) */
static inline int hybrid_path_follow(const double *table, const double *settings, const double *state,
                                     const double *p, const double *R, const double *force, double *out) {
    long rows, i;
    int k, step, closed, phase;
    double length, distance, s, travelled, c[3], t[3], n[3], e[3], r[3], u = 0.0, v, rate, a, d, rn, lateral;
    double v_table, kappa_g, normal, advance, phase_time, dt, touch, lateral_rate, retreat = 0.0, done;
    double tilt, lead, tool[3], z0[3], z1[3], zd[3], w[3], gain;
    const double *na, *nb;
    if (!hybrid_path_settings_valid(settings)) return HYBRID_PATH_TABLE_INVALID;
    for (k = 0; k < 3; ++k)
        if (!isfinite(p[k])) return HYBRID_PATH_INPUT_NONFINITE;
    for (k = 0; k < HYBRID_PATH_STATE_SIZE; ++k)
        if (!isfinite(state[k])) return HYBRID_PATH_INPUT_NONFINITE;
    for (k = 0; k < 3; ++k)
        if (!isfinite(force[k])) return HYBRID_PATH_INPUT_NONFINITE;
    for (k = 0; k < 9; ++k)
        if (!isfinite(R[k])) return HYBRID_PATH_INPUT_NONFINITE;
    rows = (long)settings[HYBRID_PATH_SETTINGS_ROWS];
    closed = settings[HYBRID_PATH_SETTINGS_CLOSED] == 1.0;
    length = settings[HYBRID_PATH_SETTINGS_LENGTH];
    distance = settings[HYBRID_PATH_SETTINGS_DISTANCE];
    a = settings[HYBRID_PATH_SETTINGS_ACCELERATION];
    dt = settings[HYBRID_PATH_SETTINGS_SAMPLE_TIME];
    touch = settings[HYBRID_PATH_SETTINGS_TOUCH_FORCE];
    if (state[HYBRID_PATH_STATE_STARTED] == 1.0) {
        s = state[HYBRID_PATH_STATE_S];
        travelled = state[HYBRID_PATH_STATE_TRAVELLED];
        phase = (int)fmax(fmin(state[HYBRID_PATH_STATE_PHASE], HYBRID_PATH_CLEAR), HYBRID_PATH_APPROACH);
        phase_time = state[HYBRID_PATH_STATE_PHASE_TIME] + dt;
    } else {
        /* the first sample: from the path's start, unless the tip is clearly nearer another node (by more than the
           nodes' spacing there: a start off the path's start, a reset mid-run); on an open path what lies before
           that node counts as travelled from the start */
        long start = hybrid_path_row(table, rows, 0, settings[HYBRID_PATH_SETTINGS_START]);
        long near = hybrid_path_nearest(table, rows, p);
        double gap = HYBRID_PATH_AT(table, start + 1, HYBRID_PATH_TABLE_S)
                     - HYBRID_PATH_AT(table, start, HYBRID_PATH_TABLE_S);
        double to_start = 0.0, to_near = 0.0;
        for (k = 0; k < 3; ++k) {
            double from_start = p[k] - HYBRID_PATH_AT(table, start, HYBRID_PATH_TABLE_P_X + k);
            double from_near = p[k] - HYBRID_PATH_AT(table, near, HYBRID_PATH_TABLE_P_X + k);
            to_start += from_start * from_start;
            to_near += from_near * from_near;
        }
        s = sqrt(to_start) <= sqrt(to_near) + gap ? settings[HYBRID_PATH_SETTINGS_START]
                                                  : HYBRID_PATH_AT(table, near, HYBRID_PATH_TABLE_S);
        travelled = closed ? 0.0 : s - settings[HYBRID_PATH_SETTINGS_START];
        phase = HYBRID_PATH_APPROACH;
        phase_time = 0.0;
    }
    if (s < 0.0) s = 0.0;
    if (s > length) s = length;
    i = hybrid_path_row(table, rows, (long)fmax(fmin(state[HYBRID_PATH_STATE_ROW], 1e9), 0.0), s);
    /* the progress: Newton steps towards the path's point nearest the tip, the advance counted as travelled */
    for (step = 0; step < HYBRID_PATH_NEWTON_STEPS; ++step) {
        double s_next;
        if (!hybrid_path_at(table, i, s, c, t, 0, &u)) return HYBRID_PATH_TABLE_INVALID;
        for (k = 0; k < 3; ++k) r[k] = p[k] - c[k];
        advance = hybrid_path_dot3(r, t);
        s_next = s + advance;
        if (closed) {
            if (s_next >= length) s_next -= length;
            if (s_next < 0.0) s_next += length;
            if (!(s_next >= 0.0 && s_next < length)) s_next = fmod(fmod(s_next, length) + length, length);
        } else {
            if (s_next < 0.0) s_next = 0.0;
            if (s_next > length) s_next = length;
            advance = s_next - s;
        }
        travelled += advance;
        s = s_next;
        i = hybrid_path_row(table, rows, i, s);
    }
    if (!hybrid_path_at(table, i, s, c, t, n, &u)) return HYBRID_PATH_TABLE_INVALID;
    na = &HYBRID_PATH_AT(table, i, 0);
    nb = &HYBRID_PATH_AT(table, i + 1, 0);
    kappa_g = (1.0 - u) * na[HYBRID_PATH_TABLE_KAPPA_G] + u * nb[HYBRID_PATH_TABLE_KAPPA_G];
    normal = (1.0 - u) * na[HYBRID_PATH_TABLE_FORCE] + u * nb[HYBRID_PATH_TABLE_FORCE];
    v_table = (1.0 - u) * na[HYBRID_PATH_TABLE_SPEED] + u * nb[HYBRID_PATH_TABLE_SPEED];
    tilt = (1.0 - u) * na[HYBRID_PATH_TABLE_TILT] + u * nb[HYBRID_PATH_TABLE_TILT];
    lead = (1.0 - u) * na[HYBRID_PATH_TABLE_LEAD] + u * nb[HYBRID_PATH_TABLE_LEAD];
    /* e = n x t: the task frame's direction, so that t1 = e x n = t and t2 = n x t1 = e */
    e[0] = n[1] * t[2] - n[2] * t[1];
    e[1] = n[2] * t[0] - n[0] * t[2];
    e[2] = n[0] * t[1] - n[1] * t[0];
    /* the speed: the table's, within the trapezoid of the acceleration limit, and its rate v dv/ds */
    v = v_table;
    rate = v_table * (nb[HYBRID_PATH_TABLE_SPEED] - na[HYBRID_PATH_TABLE_SPEED])
           / (nb[HYBRID_PATH_TABLE_S] - na[HYBRID_PATH_TABLE_S]);
    {
        double vs = settings[HYBRID_PATH_SETTINGS_SPEED_START];
        double up = sqrt(vs * vs + 2.0 * a * fmax(travelled, 0.0));
        double down = sqrt(2.0 * a * fmax(distance - travelled, 0.0));
        if (up < v) { v = up; rate = a; }
        if (down < v) { v = down; rate = -a; }
    }
    for (k = 0; k < 3; ++k) r[k] = p[k] - c[k];
    d = hybrid_path_dot3(r, e);
    rn = hybrid_path_dot3(r, n);
    lateral = 0.0;
    for (k = 0; k < 3; ++k) lateral += (r[k] - rn * n[k]) * (r[k] - rn * n[k]);
    lateral_rate = kappa_g * v * v;
    done = distance - travelled <= HYBRID_PATH_DONE_TOL;
    /* the phase: the touch starts the path, its end the release of the force, the release the retreat */
    if (phase == HYBRID_PATH_APPROACH && hybrid_path_dot3(force, n) >= touch) {
        phase = HYBRID_PATH_FOLLOW;
        phase_time = 0.0;
    }
    if (phase == HYBRID_PATH_FOLLOW && done == 1.0 && settings[HYBRID_PATH_SETTINGS_RETREAT_DISTANCE] > 0.0) {
        phase = HYBRID_PATH_UNLOAD;
        phase_time = 0.0;
    }
    if (phase == HYBRID_PATH_UNLOAD && phase_time >= settings[HYBRID_PATH_SETTINGS_UNLOAD_TIME]) {
        phase = HYBRID_PATH_RETREAT;
        phase_time = 0.0;
    }
    if (phase == HYBRID_PATH_RETREAT && rn >= settings[HYBRID_PATH_SETTINGS_RETREAT_DISTANCE]) {
        phase = HYBRID_PATH_CLEAR;
        phase_time = 0.0;
    }
    if (phase != HYBRID_PATH_FOLLOW || done == 1.0) {
        v = 0.0;
        rate = 0.0;
        lateral_rate = 0.0;
    }
    if (done == 1.0 && phase == HYBRID_PATH_FOLLOW) {
        /* at the end (an open path's, a closed one's last lap) the tip is held there: its overshoot along the
           tangent corrected as the cross-track error is */
        double limit = settings[HYBRID_PATH_SETTINGS_CROSS_TRACK_LIMIT];
        v = fmax(fmin(-settings[HYBRID_PATH_SETTINGS_CROSS_TRACK_GAIN] * hybrid_path_dot3(r, t), limit), -limit);
    }
    if (phase == HYBRID_PATH_UNLOAD) {
        /* linearly from the path's force down to the touch force (at least 0) */
        double floor_force = fmax(touch, 0.0), left = settings[HYBRID_PATH_SETTINGS_UNLOAD_TIME] > 0.0
            ? fmax(1.0 - phase_time / settings[HYBRID_PATH_SETTINGS_UNLOAD_TIME], 0.0) : 0.0;
        normal = floor_force + left * (normal - floor_force);
    }
    if (phase >= HYBRID_PATH_RETREAT) {
        retreat = 1.0;
        normal = phase == HYBRID_PATH_RETREAT ? settings[HYBRID_PATH_SETTINGS_RETREAT_SPEED] : 0.0;
    }
    out[HYBRID_PATH_OUT_S] = s;
    out[HYBRID_PATH_OUT_TRAVELLED] = travelled;
    out[HYBRID_PATH_OUT_ROW] = (double)i;
    out[HYBRID_PATH_OUT_STARTED] = 1.0;
    out[HYBRID_PATH_OUT_PHASE] = (double)phase;
    out[HYBRID_PATH_OUT_PHASE_TIME] = phase_time;
    for (k = 0; k < 3; ++k) {
        out[HYBRID_PATH_OUT_C_X + k] = c[k];
        out[HYBRID_PATH_OUT_T_X + k] = t[k];
        out[HYBRID_PATH_OUT_N_X + k] = n[k];
        out[HYBRID_PATH_OUT_E_X + k] = e[k];
    }
    out[HYBRID_PATH_OUT_SPEED] = v;
    out[HYBRID_PATH_OUT_SPEED_RATE] = rate;
    out[HYBRID_PATH_OUT_LATERAL_SPEED] = fmax(fmin(-settings[HYBRID_PATH_SETTINGS_CROSS_TRACK_GAIN] * d,
                                                   settings[HYBRID_PATH_SETTINGS_CROSS_TRACK_LIMIT]),
                                              -settings[HYBRID_PATH_SETTINGS_CROSS_TRACK_LIMIT]);
    out[HYBRID_PATH_OUT_LATERAL_RATE] = lateral_rate;
    out[HYBRID_PATH_OUT_NORMAL_REFERENCE] = normal;
    out[HYBRID_PATH_OUT_CROSS_TRACK] = d;
    out[HYBRID_PATH_OUT_PATH_ERROR] = sqrt(lateral);
    out[HYBRID_PATH_OUT_HEIGHT] = rn;
    out[HYBRID_PATH_OUT_DONE] = done;
    out[HYBRID_PATH_OUT_RETREAT] = retreat;
    /* the tool's axis towards -n turned by the lead about t2 (= e), then by the tilt about t1 (= t) */
    for (k = 0; k < 3; ++k) {
        tool[k] = R[3 * k + 2];
        z0[k] = -n[k];
    }
    hybrid_path_turn(z0, e, cos(lead), sin(lead), z1);
    hybrid_path_turn(z1, t, cos(tilt), sin(tilt), zd);
    hybrid_path_cross3(tool, zd, w);
    gain = settings[HYBRID_PATH_SETTINGS_ORIENTATION_GAIN];
    out[HYBRID_PATH_OUT_SPIN_T1] = gain * hybrid_path_dot3(w, t);
    out[HYBRID_PATH_OUT_SPIN_T2] = gain * hybrid_path_dot3(w, e);
    out[HYBRID_PATH_OUT_TOOL_ANGLE_ERROR] = atan2(sqrt(hybrid_path_dot3(w, w)), hybrid_path_dot3(tool, zd));
    return HYBRID_PATH_OK;
}

#if defined(__clang__)
#pragma STDC FP_CONTRACT DEFAULT
#elif defined(__GNUC__)
#pragma GCC pop_options
#endif

/* Entry points with external linkage, for a caller that binds the follower from another language (the
   runtime's cffi module defines HYBRID_PATH_ENTRY_POINTS before it includes this header). */
/* cdef-begin */
int hybrid_path_follow_entry(const double *table, const double *settings, const double *state, const double *p,
                             const double *R, const double *force, double *out);
int hybrid_path_table_entry(const double *table, const double *settings);
/* cdef-end */
#ifdef HYBRID_PATH_ENTRY_POINTS
int hybrid_path_follow_entry(const double *table, const double *settings, const double *state, const double *p,
                             const double *R, const double *force, double *out) {
    return hybrid_path_follow(table, settings, state, p, R, force, out);
}
int hybrid_path_table_entry(const double *table, const double *settings) {
    return hybrid_path_table_valid(table, settings);
}
#endif

#endif
