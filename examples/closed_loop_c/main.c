/* The UR5 tracing a circle on a sphere (the tracing experiment), closed in C alone: the generated
   controller (ur5_controller.c) against the generated plant (ur5_plant.c), then the run's metrics.

   Per control sample k (t = k * sample_time): the sensor's reading from the state, one controller step,
   then steps_per_sample RK4 steps of the plant with the torque held. The metrics are those of
   hybrid.metrics, over every RK4 step's row (t = i * h, the state at the step's start and the last one),
   taken against the references the plant declares (the experiment's force and speed steps).

   Build (after `python -m hybrid generate --experiment tracing --out . --name ur5`):
       cc -std=c99 -O2 main.c ur5_controller.c ur5_plant.c -lm -o closed_loop
   Run:
       ./closed_loop [--duration SECONDS] [--record FILE] [--per-sample] [--part FILE]
   --record writes a row per RK4 step (per control sample with --per-sample): t, the state x
   (UR5_PLANT_NX, the order of ur5_plant.json's "state") and the torque acting from t on
   (UR5_PLANT_NQ); as text when FILE ends in .csv, else as raw doubles (this machine's byte order).

   An experiment on a part (hybrid.MeshSurface, written by Experiment.generate with its data file
   ur5_part.bin) builds the same way: the controller and the plant then include hybrid_part.h, and the
   loop reads the part's data file (ur5_part.bin, or --part FILE: another part, the same build) and
   gives its numbers to both.

   An experiment with a path task (hybrid.PathTask: a raster or any path across the surface or a part) builds
   the same way: the controller then includes hybrid_path.h, the plant declares the path's metrics, and the
   loop prints them too, from the controller's follower replayed at each control sample on the arm tip and
   the contact force (hybrid.metrics' path_*). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "ur5_controller.h"
#include "ur5_plant.h"

/* the metrics' running sums and extremes, updated row by row */
typedef struct {
    double fb, fa, fat, vb, va, vat; /* the force and speed references' steps (before, after, at) */
    double end;                      /* the last row's time */
    long rows, n_f, n_v, n_last, first_f, last_out_f, last_f, losses, touch, t_last_out, t_last;
    double peak, drop, dev, v_max, sum_fe, sum_ve, sum_f2, sum_v2, pen, t_out;
    double fd0, t_band, w_end, t_peak; /* the first touch: F_d then, its band, its window's end, the peak */
    int in_prev;
    double tau[UR5_PLANT_NQ];
} metrics;

static double step_value(double before, double after, double at, double t) {
    return t < at ? before : after;
}

static void metrics_start(metrics *m, const ur5_plant *p, long rows, double h) {
    int j;
    memset(m, 0, sizeof *m);
    /* the references the metrics are taken against (the experiment's force step on the normal and speed step
       along t1, which a path task's controller does not hold: its follower gives its references) */
    m->fb = p->references[UR5_PLANT_REFERENCES_FORCE_BEFORE];
    m->fa = p->references[UR5_PLANT_REFERENCES_FORCE_AFTER];
    m->fat = p->references[UR5_PLANT_REFERENCES_FORCE_AT];
    m->vb = p->references[UR5_PLANT_REFERENCES_SPEED_BEFORE];
    m->va = p->references[UR5_PLANT_REFERENCES_SPEED_AFTER];
    m->vat = p->references[UR5_PLANT_REFERENCES_SPEED_AT];
    m->rows = rows;
    m->end = (double)(rows - 1) * h;
    m->first_f = m->last_out_f = m->last_f = -1;
    m->touch = m->t_last_out = m->t_last = -1;
    m->w_end = INFINITY;
    m->peak = m->drop = m->dev = m->v_max = m->pen = m->t_peak = -INFINITY;
    for (j = 0; j < UR5_PLANT_NQ; ++j) m->tau[j] = 0.0;
}

/* row i (time i * h) of the run: the plant's signals there */
static void metrics_row(metrics *m, const double *s, long i, double h) {
    const double t = (double)i * h;
    const double F = s[UR5_PLANT_SIGNALS_FC_N], v = s[UR5_PLANT_SIGNALS_V_T], pen = s[UR5_PLANT_SIGNALS_PENETRATION];
    const double Fd = step_value(m->fb, m->fa, m->fat, t), vd = step_value(m->vb, m->va, m->vat, t);
    const double step = m->fa - m->fb, sgn = step >= 0 ? 1.0 : -1.0;
    /* the window after the force step ends at the speed step (the next disturbance), if later */
    const double f_end = m->vat > m->fat ? m->vat : m->end;
    const double band = UR5_PLANT_SETTLING_BAND_PERCENT / 100.0 * (m->fa != 0.0 ? fabs(m->fa) : fabs(step));
    const int contact = s[UR5_PLANT_SIGNALS_N] > 0.0;
    if (t >= m->fat && t < f_end) {
        if (sgn * F > m->peak) m->peak = sgn * F;
        ++m->n_f;
        if (m->first_f < 0) m->first_f = i;
        if (fabs(F - m->fa) > band) m->last_out_f = i;
        m->last_f = i;
        if (vd - v > m->drop) m->drop = vd - v;
    }
    if (t >= m->vat) {
        ++m->n_v;
        if (fabs(F - Fd) > m->dev) m->dev = fabs(F - Fd);
        if (v > m->v_max) m->v_max = v;
    }
    if (t >= m->end - UR5_PLANT_STEADY_WINDOW_MS / 1000.0) {
        m->sum_fe += Fd - F;
        m->sum_ve += vd - v;
        ++m->n_last;
    }
    m->sum_f2 += (Fd - F) * (Fd - F);
    m->sum_v2 += (vd - v) * (vd - v);
    if (pen > m->pen) m->pen = pen;
    if (i > 0) {
        if (m->in_prev && !contact) ++m->losses;
        if (!contact) m->t_out += t - (double)(i - 1) * h;
    }
    m->in_prev = contact;
    /* the first touch: the first row in contact, then its window until the force reference next changes */
    if (contact && m->touch < 0) {
        m->touch = i;
        m->fd0 = Fd;
        m->t_band = UR5_PLANT_TOUCH_BAND_PERCENT / 100.0 * fabs(Fd);
        m->w_end = m->fa != m->fb && m->fat > t ? m->fat : INFINITY;
    }
    if (m->touch >= 0 && t < m->w_end) {
        if (F > m->t_peak) m->t_peak = F;
        if (fabs(F - m->fd0) > m->t_band) m->t_last_out = i;
        m->t_last = i;
    }
}

static void metrics_torque(metrics *m, const double *tau) {
    int j;
    for (j = 0; j < UR5_PLANT_NQ; ++j) {
        if (fabs(tau[j]) > m->tau[j]) m->tau[j] = fabs(tau[j]);
    }
}

/* the run's metrics into out, at the indices the plant's header declares (hybrid.metrics' order; NaN where
   they are not taken) */
static void metrics_values(const metrics *m, double h, double *out) {
    const double step = m->fa - m->fb, sgn = step >= 0 ? 1.0 : -1.0;
    int j;
    for (j = 0; j < UR5_PLANT_NMETRICS; ++j) out[j] = NAN;
    if (m->n_f > 0 && m->fa != m->fb) {
        out[UR5_PLANT_METRIC_FORCE_OVERSHOOT_N] = (sgn * m->peak - m->fa) * sgn;
        out[UR5_PLANT_METRIC_FORCE_OVERSHOOT_PERCENT] = 100 * out[UR5_PLANT_METRIC_FORCE_OVERSHOOT_N] / fabs(step);
        out[UR5_PLANT_METRIC_FORCE_SETTLING_TIME_2PCT_S] = m->last_out_f < 0 ? 0.0
            : m->last_out_f == m->last_f ? NAN : (double)(m->last_out_f + 1) * h - (double)m->first_f * h;
        out[UR5_PLANT_METRIC_SPEED_DROP_AFTER_FORCE_STEP_M_PER_S] = m->drop;
    }
    if (m->n_v > 0 && m->va != m->vb) {
        out[UR5_PLANT_METRIC_FORCE_DEVIATION_AFTER_SPEED_STEP_N] = m->dev;
        out[UR5_PLANT_METRIC_SPEED_OVERSHOOT_AFTER_SPEED_STEP_M_PER_S] = m->v_max - m->va;
    }
    out[UR5_PLANT_METRIC_STEADY_STATE_FORCE_ERROR_N] = m->sum_fe / (double)m->n_last;
    out[UR5_PLANT_METRIC_STEADY_STATE_SPEED_ERROR_M_PER_S] = m->sum_ve / (double)m->n_last;
    out[UR5_PLANT_METRIC_RMS_FORCE_ERROR_N] = sqrt(m->sum_f2 / (double)m->rows);
    out[UR5_PLANT_METRIC_RMS_SPEED_ERROR_M_PER_S] = sqrt(m->sum_v2 / (double)m->rows);
    out[UR5_PLANT_METRIC_MAX_PENETRATION_M] = m->pen;
    out[UR5_PLANT_METRIC_CONTACT_LOSSES] = (double)m->losses;
    out[UR5_PLANT_METRIC_TIME_OUT_OF_CONTACT_S] = m->t_out;
    if (m->touch >= 0) {
        out[UR5_PLANT_METRIC_FIRST_TOUCH_TIME_S] = (double)m->touch * h;
        out[UR5_PLANT_METRIC_FIRST_TOUCH_OVERSHOOT_N] = m->t_peak - m->fd0;
        out[UR5_PLANT_METRIC_FIRST_TOUCH_SETTLING_S] = m->t_last_out < 0 ? 0.0
            : m->t_last_out == m->t_last ? NAN : (double)(m->t_last_out + 1) * h - (double)m->touch * h;
    }
    for (j = 0; j < UR5_PLANT_NQ; ++j) out[UR5_PLANT_METRIC_PEAK_TORQUE + j] = m->tau[j];
}

#ifdef HYBRID_PATH_H
/* A path task's metrics (hybrid.metrics' path_*), sample by sample: the controller's follower (its table and
   settings) replayed at each control sample on the arm tip and the contact force of the plant's record, as
   hybrid.metrics replays it, and the sensor tip's distance from the path. */
typedef struct {
    const double *table, *settings;
    double state[HYBRID_PATH_STATE_SIZE];
    long k, n_on, n_press, n_follow, losses;
    int settled, touching;
    double err2, err_max, t_done, travelled, f2, v2, end_peak;
} path_metrics;

static void path_start(path_metrics *m, const ur5_controller *c) {
    memset(m, 0, sizeof *m);
    m->table = c->path_table;
    m->settings = c->path_settings;
    m->t_done = NAN;
    m->err_max = m->travelled = m->end_peak = -INFINITY;
}

/* the first node at or past arc length s (numpy's searchsorted) */
static long path_node(const double *table, long rows, double s) {
    long lo = 0, hi = rows;
    while (lo < hi) {
        const long mid = lo + (hi - lo) / 2;
        if (HYBRID_PATH_AT(table, mid, HYBRID_PATH_TABLE_S) < s) lo = mid + 1;
        else hi = mid;
    }
    return lo;
}

static const double path_identity[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};

/* the sensor tip's distance from the path: the follower from the node nearest it within the metrics' window
   about the arm tip's progress s (NaN where the follower refuses it) */
static double path_error_at(const path_metrics *m, const double *tip, double s) {
    const long rows = (long)m->settings[HYBRID_PATH_SETTINGS_ROWS];
    long lo = path_node(m->table, rows, s - UR5_PLANT_PATH_BEHIND_MM / 1000.0);
    long hi = path_node(m->table, rows, s + UR5_PLANT_PATH_AHEAD_MM / 1000.0), i, near;
    double best = INFINITY, state[HYBRID_PATH_STATE_SIZE] = {0}, out[HYBRID_PATH_OUT_SIZE];
    const double none[3] = {0, 0, 0};
    if (lo > rows - 1) lo = rows - 1;
    if (hi < lo + 1) hi = lo + 1;
    for (near = i = lo; i < hi; ++i) {
        const double dx = HYBRID_PATH_AT(m->table, i, HYBRID_PATH_TABLE_P_X) - tip[0];
        const double dy = HYBRID_PATH_AT(m->table, i, HYBRID_PATH_TABLE_P_Y) - tip[1];
        const double dz = HYBRID_PATH_AT(m->table, i, HYBRID_PATH_TABLE_P_Z) - tip[2];
        const double d = sqrt(dx * dx + dy * dy + dz * dz);
        if (d < best) {
            best = d;
            near = i;
        }
    }
    state[HYBRID_PATH_STATE_S] = HYBRID_PATH_AT(m->table, near, HYBRID_PATH_TABLE_S);
    state[HYBRID_PATH_STATE_ROW] = (double)(near < rows - 2 ? near : rows - 2);
    state[HYBRID_PATH_STATE_STARTED] = 1.0;
    state[HYBRID_PATH_STATE_PHASE] = HYBRID_PATH_FOLLOW;
    if (hybrid_path_follow(m->table, m->settings, state, tip, path_identity, none, out) != HYBRID_PATH_OK) return NAN;
    return out[HYBRID_PATH_OUT_PATH_ERROR];
}

/* a control sample at time t: y the plant's record there, x its state; HYBRID_PATH_OK or the follower's refusal */
static int path_sample(path_metrics *m, double t, const double *y, const double *x) {
    const double *r = y + UR5_PLANT_Y_R_X, *force = y + UR5_PLANT_Y_FC_X, *sd = x + UR5_PLANT_X_SD_X;
    double out[HYBRID_PATH_OUT_SIZE], normal, tip_speed, error;
    int j, phase, follow, touching;
    const int status = hybrid_path_follow(m->table, m->settings, m->state, r, path_identity, force, out);
    if (status != HYBRID_PATH_OK) return status;
    for (j = 0; j < HYBRID_PATH_STATE_SIZE; ++j) m->state[j] = out[j];
    phase = (int)out[HYBRID_PATH_OUT_PHASE];
    follow = phase == HYBRID_PATH_FOLLOW;
    normal = force[0] * out[HYBRID_PATH_OUT_N_X] + force[1] * out[HYBRID_PATH_OUT_N_Y]
             + force[2] * out[HYBRID_PATH_OUT_N_Z];
    tip_speed = sd[0] * out[HYBRID_PATH_OUT_T_X] + sd[1] * out[HYBRID_PATH_OUT_T_Y] + sd[2] * out[HYBRID_PATH_OUT_T_Z];
    touching = normal > 0.0;
    /* on the path (following it, or releasing the force at its end): the sensor tip's distance from it */
    if (follow || phase == HYBRID_PATH_UNLOAD) {
        error = path_error_at(m, y + UR5_PLANT_Y_S_X, out[HYBRID_PATH_OUT_S]);
        m->err2 += error * error;
        if (error > m->err_max || isnan(error)) m->err_max = error;
        ++m->n_on;
    }
    if (out[HYBRID_PATH_OUT_TRAVELLED] > m->travelled) m->travelled = out[HYBRID_PATH_OUT_TRAVELLED];
    if (isnan(m->t_done) && out[HYBRID_PATH_OUT_TRAVELLED] >= m->settings[HYBRID_PATH_SETTINGS_DISTANCE]
        - UR5_PLANT_PATH_END_TOL_UM / 1e6) m->t_done = t;
    if (follow) {
        /* the force's error once it came within the band of its reference (the touch's transient is the first
           touch's metrics'), the speed's along the path's tangent, a contact lost while following */
        const double fe = normal - out[HYBRID_PATH_OUT_NORMAL_REFERENCE], ve = tip_speed - out[HYBRID_PATH_OUT_SPEED];
        if (fabs(fe) <= UR5_PLANT_PATH_SETTLED_PERCENT / 100.0 * fabs(out[HYBRID_PATH_OUT_NORMAL_REFERENCE]))
            m->settled = 1;
        if (m->settled) {
            m->f2 += fe * fe;
            ++m->n_press;
        }
        m->v2 += ve * ve;
        ++m->n_follow;
        if (m->k > 0 && m->touching && !touching) ++m->losses;
    }
    if (phase >= HYBRID_PATH_UNLOAD && normal > m->end_peak) m->end_peak = normal;
    m->touching = touching;
    ++m->k;
    return HYBRID_PATH_OK;
}

static void path_values(const path_metrics *m, double *out) {
    out[UR5_PLANT_METRIC_PATH_ERROR_RMS_M] = m->n_on ? sqrt(m->err2 / (double)m->n_on) : NAN;
    out[UR5_PLANT_METRIC_PATH_ERROR_MAX_M] = m->n_on ? m->err_max : NAN;
    out[UR5_PLANT_METRIC_PATH_TIME_S] = m->t_done;
    out[UR5_PLANT_METRIC_PATH_TRAVELLED_M] = m->travelled;
    out[UR5_PLANT_METRIC_PATH_FORCE_RMS_ERROR_N] = m->n_press ? sqrt(m->f2 / (double)m->n_press) : NAN;
    out[UR5_PLANT_METRIC_PATH_SPEED_RMS_ERROR_M_PER_S] = m->n_follow ? sqrt(m->v2 / (double)m->n_follow) : NAN;
    out[UR5_PLANT_METRIC_PATH_CONTACT_LOSSES] = (double)m->losses;
    out[UR5_PLANT_METRIC_PATH_END_PEAK_FORCE_N] = m->end_peak > -INFINITY ? m->end_peak : NAN;
}
#endif

/* one row of the record: t, x, the torque acting from t on */
static int write_row(FILE *out, int csv, double t, const double *x, const double *tau) {
    double row[1 + UR5_PLANT_NX + UR5_PLANT_NQ];
    int j, n = 1 + UR5_PLANT_NX + UR5_PLANT_NQ;
    row[0] = t;
    for (j = 0; j < UR5_PLANT_NX; ++j) row[1 + j] = x[j];
    for (j = 0; j < UR5_PLANT_NQ; ++j) row[1 + UR5_PLANT_NX + j] = tau[j];
    if (!csv) return fwrite(row, sizeof row[0], (size_t)n, out) == (size_t)n;
    for (j = 0; j < n; ++j) {
        if (fprintf(out, j ? ",%.17g" : "%.17g", row[j]) < 0) return 0;
    }
    return fputc('\n', out) != EOF;
}

static int usage(const char *self) {
    fprintf(stderr, "usage: %s [--duration SECONDS] [--record FILE] [--per-sample] [--part FILE]\n", self);
    return 2;
}

#ifdef HYBRID_PART_H
/* the part's data file read whole, as doubles (*count of them; the generated C checks them): NULL where it
   cannot be read */
static double *read_part(const char *path, size_t *count) {
    FILE *f = fopen(path, "rb");
    double *data = NULL;
    long bytes;
    if (!f) return NULL;
    if (fseek(f, 0, SEEK_END) == 0 && (bytes = ftell(f)) >= 0 && fseek(f, 0, SEEK_SET) == 0) {
        *count = (size_t)bytes / sizeof(double);
        data = malloc(*count > 0 ? *count * sizeof(double) : 1);
        if (data && fread(data, sizeof(double), *count, f) != *count) {
            free(data);
            data = NULL;
        }
    }
    fclose(f);
    return data;
}
#endif

int main(int argc, char **argv) {
    ur5_controller c;
    ur5_plant p;
    metrics m;
    double wrench[6], s[UR5_PLANT_NSIGNALS], tau[UR5_PLANT_NQ], prev[UR5_PLANT_NQ], duration;
    double values[UR5_PLANT_NMETRICS];
#ifdef HYBRID_PATH_H
    path_metrics path_m;
    double y[UR5_PLANT_NY];
#endif
    const char *path = NULL;
#ifdef HYBRID_PART_H
    const char *part_path = "ur5_part.bin";
    double *part;
    size_t part_count = 0;
#endif
    FILE *out = NULL;
    int per_sample = 0, csv = 0, status, a, i, j;
    long k, n_samples, row = 0;

    ur5_controller_init(&c);
    ur5_plant_init(&p);
    duration = p.duration;
    for (a = 1; a < argc; ++a) {
        if (!strcmp(argv[a], "--duration") && a + 1 < argc) {
            char *end;
            duration = strtod(argv[++a], &end);
            if (*end || !(duration > 0)) return usage(argv[0]);
        } else if (!strcmp(argv[a], "--record") && a + 1 < argc) {
            path = argv[++a];
        } else if (!strcmp(argv[a], "--per-sample")) {
            per_sample = 1;
#ifdef HYBRID_PART_H
        } else if (!strcmp(argv[a], "--part") && a + 1 < argc) {
            part_path = argv[++a];
#endif
        } else {
            return usage(argv[0]);
        }
    }
#ifdef HYBRID_PART_H
    /* the part: its data file's numbers, kept while the controller and the plant point at them */
    part = read_part(part_path, &part_count);
    if (!part) {
        perror(part_path);
        return 1;
    }
    status = ur5_controller_set_part(&c, part, part_count);
    if (status == UR5_OK) status = ur5_plant_set_part(&p, part, part_count);
    if (status != UR5_OK) {
        fprintf(stderr, "%s is not a part's data file (refused: %s)\n", part_path, ur5_status_name(status));
        free(part);
        return 1;
    }
#endif
    /* as the experiment counts its samples: duration / sample_time, rounded up */
    n_samples = (long)ceil(duration / p.sample_time - 1e-9);
    if (path) {
        const size_t n = strlen(path);
        csv = n >= 4 && !strcmp(path + n - 4, ".csv");
        out = fopen(path, csv ? "w" : "wb");
        if (!out) {
            perror(path);
            return 1;
        }
    }
    metrics_start(&m, &p, n_samples * p.steps_per_sample + 1, p.h);
#ifdef HYBRID_PATH_H
    path_start(&path_m, &c);
#endif
    for (j = 0; j < UR5_PLANT_NQ; ++j) prev[j] = 0.0;
    for (k = 0; k < n_samples; ++k) {
        /* the sensor's reading at the sample instant, one control sample */
        ur5_plant_wrench(&p, wrench);
        status = ur5_controller_step(&c, (double)k * p.sample_time, p.x, p.x + UR5_PLANT_NQ, wrench, tau);
        if (status != UR5_OK) {
            fprintf(stderr, "the controller stopped at t = %.4f s: %s\n", (double)k * p.sample_time,
                    ur5_status_name(status));
            return 1;
        }
        metrics_torque(&m, tau);
#ifdef HYBRID_PATH_H
        /* the path's metrics at the sample instant, from the plant's record there */
        ur5_plant_outputs(&p, y);
        status = path_sample(&path_m, (double)k * p.sample_time, y, p.x);
        if (status != HYBRID_PATH_OK) {
            fprintf(stderr, "the path's metrics stopped at t = %.4f s: the follower refused the sample (%d)\n",
                    (double)k * p.sample_time, status);
            return 1;
        }
#endif
        /* the torque held over the sample: the plant's RK4 steps, each row's signals at the step's start */
        for (i = 0; i < p.steps_per_sample; ++i, ++row) {
            ur5_plant_signals(&p, s);
            metrics_row(&m, s, row, p.h);
            if (out && (!per_sample || i == 0) && !write_row(out, csv, (double)row * p.h, p.x, tau)) {
                perror(path);
                return 1;
            }
            status = ur5_plant_advance(&p, tau, 1);
            if (status != UR5_PLANT_OK) {
                fprintf(stderr, "the plant stopped at t = %.5f s: %s\n", (double)row * p.h,
                        ur5_plant_status_name(status));
                return 1;
            }
        }
        for (j = 0; j < UR5_PLANT_NQ; ++j) prev[j] = tau[j];
    }
    /* the last row: the state after the last step, the last torque */
    ur5_plant_signals(&p, s);
    metrics_row(&m, s, row, p.h);
    if (out && !write_row(out, csv, (double)row * p.h, p.x, prev)) {
        perror(path);
        return 1;
    }
    if (out && fclose(out) != 0) {
        perror(path);
        return 1;
    }
    printf("# the UR5");
#ifdef HYBRID_PART_H
    free(part);
    printf(" on the part of %s", part_path);
#endif
#ifdef HYBRID_PATH_H
    printf(" along its path task");
#endif
    printf(": %ld samples of %g s,\n# each %d RK4 steps of %g s\n", n_samples, p.sample_time, p.steps_per_sample, p.h);
    /* the run's metrics, in the order and under the names the plant's header declares (hybrid.metrics') */
    metrics_values(&m, p.h, values);
#ifdef HYBRID_PATH_H
    path_values(&path_m, values);
#endif
    for (j = 0; j < UR5_PLANT_NMETRICS; ++j) printf("%s %.17g\n", ur5_plant_metric_name(j), values[j]);
    return 0;
}
