/* hybrid generated file: do not edit; change codegen/ and run `python -m hybrid regenerate`. body-sha256: 5dd9f58801720bed68651efa39e5d6f3f4c61a277ad0669d38816d705e33938f */
#ifndef HYBRID_PART_H
#define HYBRID_PART_H
/* A part's surface: phi, a tricubic B-spline on a uniform grid (the part's fitted signed distance), expanded to
   second order about a point. Standalone C99: no allocation, no globals, no I/O; reentrant.

   status = hybrid_part_expansion(grid, coefficients, p, out);
   grid: HYBRID_PART_GRID_SIZE numbers (the first cell's corner [m], the spacing [m], the cells along x, y, z);
   coefficients: (cells_x + 3) (cells_y + 3) (cells_z + 3) numbers [m], z fastest, NaN beyond the fitted band;
   out: HYBRID_PART_OUT_SIZE numbers, the quadric surface's parameters about p: p, phi(p), grad phi(p) and the
   Hessian's upper triangle (xx, xy, xz, yy, yz, zz) [1/m]. */
#include <math.h>

/* the grid's numbers */
#define HYBRID_PART_GRID_SIZE 7
#define HYBRID_PART_GRID_ORIGIN_X 0
#define HYBRID_PART_GRID_ORIGIN_Y 1
#define HYBRID_PART_GRID_ORIGIN_Z 2
#define HYBRID_PART_GRID_SPACING 3
#define HYBRID_PART_GRID_CELLS_X 4
#define HYBRID_PART_GRID_CELLS_Y 5
#define HYBRID_PART_GRID_CELLS_Z 6
/* the expansion's numbers (the quadric surface's parameters) */
#define HYBRID_PART_OUT_SIZE 13
#define HYBRID_PART_OUT_P_X 0
#define HYBRID_PART_OUT_P_Y 1
#define HYBRID_PART_OUT_P_Z 2
#define HYBRID_PART_OUT_PHI 3
#define HYBRID_PART_OUT_G_X 4
#define HYBRID_PART_OUT_G_Y 5
#define HYBRID_PART_OUT_G_Z 6
#define HYBRID_PART_OUT_H_XX 7
#define HYBRID_PART_OUT_H_XY 8
#define HYBRID_PART_OUT_H_XZ 9
#define HYBRID_PART_OUT_H_YY 10
#define HYBRID_PART_OUT_H_YZ 11
#define HYBRID_PART_OUT_H_ZZ 12
#define HYBRID_PART_OK 0
#define HYBRID_PART_INPUT_NONFINITE 1
#define HYBRID_PART_OFF_BAND 2

/* the arithmetic as written, in every build (no contraction into fused multiply-adds): every caller's
   expansion gives the same numbers */
#if defined(__clang__)
#pragma STDC FP_CONTRACT OFF
#elif defined(__GNUC__)
#pragma GCC push_options
#pragma GCC optimize("fp-contract=off")
#endif

/* the uniform cubic B-spline's four pieces at t in [0, 1) (b), their first (d) and second (dd) derivatives */
static inline void hybrid_part_basis(double t, double *b, double *d, double *dd) {
    const double s = 1.0 - t;
    b[0] = s * s * s / 6.0;
    b[1] = (3.0 * t * t * t - 6.0 * t * t + 4.0) / 6.0;
    b[2] = (-3.0 * t * t * t + 3.0 * t * t + 3.0 * t + 1.0) / 6.0;
    b[3] = t * t * t / 6.0;
    d[0] = -s * s / 2.0;
    d[1] = (3.0 * t * t - 4.0 * t) / 2.0;
    d[2] = (-3.0 * t * t + 2.0 * t + 1.0) / 2.0;
    d[3] = t * t / 2.0;
    dd[0] = s;
    dd[1] = 3.0 * t - 2.0;
    dd[2] = 1.0 - 3.0 * t;
    dd[3] = t;
}

/* the expansion of the part's phi about p into out (HYBRID_PART_OUT_*); HYBRID_PART_OK, or a status with out
   unwritten: HYBRID_PART_INPUT_NONFINITE (p or the grid's numbers not finite, a spacing not positive),
   HYBRID_PART_OFF_BAND (p off the grid, or a coefficient it reads undefined: beyond the fitted band) */
static inline int hybrid_part_expansion(const double *grid, const double *coefficients, const double *p,
                                        double *out) {
    double u[3], t[3], b[3][4], d[3][4], dd[3][4], sum[10] = {0.0};
    long cell[3], n[3];
    int a, k, l, m;
    const double h = grid[HYBRID_PART_GRID_SPACING];
    for (a = 0; a < 3; ++a) {
        const double c = grid[HYBRID_PART_GRID_CELLS_X + a];
        if (!isfinite(p[a]) || !isfinite(grid[a])) return HYBRID_PART_INPUT_NONFINITE;
        /* a count of cells: a whole number from 1 to 2^20 (no index past the caller's array's end it implies) */
        if (!(c >= 1.0 && c <= 1048576.0 && c == floor(c))) return HYBRID_PART_INPUT_NONFINITE;
    }
    if (!(h > 0.0) || !isfinite(h)) return HYBRID_PART_INPUT_NONFINITE;
    for (a = 0; a < 3; ++a) {
        const double c = grid[HYBRID_PART_GRID_CELLS_X + a];
        u[a] = (p[a] - grid[a]) / h;
        if (!(u[a] >= 0.0 && u[a] < c)) return HYBRID_PART_OFF_BAND;
        cell[a] = (long)floor(u[a]);
        n[a] = (long)c + 3;
        t[a] = u[a] - (double)cell[a];
        hybrid_part_basis(t[a], b[a], d[a], dd[a]);
    }
    /* phi, its gradient and its Hessian (xx, xy, xz, yy, yz, zz) in grid units, the sums over the 64 coefficients */
    for (k = 0; k < 4; ++k) {
        for (l = 0; l < 4; ++l) {
            const double *row = coefficients + ((cell[0] + k) * n[1] + (cell[1] + l)) * n[2] + cell[2];
            for (m = 0; m < 4; ++m) {
                const double c = row[m];
                sum[0] += c * b[0][k] * b[1][l] * b[2][m];
                sum[1] += c * d[0][k] * b[1][l] * b[2][m];
                sum[2] += c * b[0][k] * d[1][l] * b[2][m];
                sum[3] += c * b[0][k] * b[1][l] * d[2][m];
                sum[4] += c * dd[0][k] * b[1][l] * b[2][m];
                sum[5] += c * d[0][k] * d[1][l] * b[2][m];
                sum[6] += c * d[0][k] * b[1][l] * d[2][m];
                sum[7] += c * b[0][k] * dd[1][l] * b[2][m];
                sum[8] += c * b[0][k] * d[1][l] * d[2][m];
                sum[9] += c * b[0][k] * b[1][l] * dd[2][m];
            }
        }
    }
    for (k = 0; k < 10; ++k) {
        if (!isfinite(sum[k])) return HYBRID_PART_OFF_BAND;
    }
    for (a = 0; a < 3; ++a) out[HYBRID_PART_OUT_P_X + a] = p[a];
    out[HYBRID_PART_OUT_PHI] = sum[0];
    for (a = 0; a < 3; ++a) out[HYBRID_PART_OUT_G_X + a] = sum[1 + a] / h;
    for (a = 0; a < 6; ++a) out[HYBRID_PART_OUT_H_XX + a] = sum[4 + a] / (h * h);
    return HYBRID_PART_OK;
}

#if defined(__clang__)
#pragma STDC FP_CONTRACT DEFAULT
#elif defined(__GNUC__)
#pragma GCC pop_options
#endif

/* Entry points with external linkage, for a caller that binds the evaluator from another language (the
   runtime's, with HYBRID_PART_ENTRY_POINTS defined) */
/* cdef-begin */
int hybrid_part_expansion_entry(const double *grid, const double *coefficients, const double *p, double *out);
/* cdef-end */
#ifdef HYBRID_PART_ENTRY_POINTS
int hybrid_part_expansion_entry(const double *grid, const double *coefficients, const double *p, double *out) {
    return hybrid_part_expansion(grid, coefficients, p, out);
}
#endif
#endif
