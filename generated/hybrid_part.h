/* hybrid generated file: do not edit; change codegen/ and run `python -m hybrid regenerate`. body-sha256: 9e29cd2e885c425f0cb1ec64b481ff37263e78d35876afcbc3729e3a7a610c21 */
#ifndef HYBRID_PART_H
#define HYBRID_PART_H
/* A part's surface: phi, a tricubic B-spline on a uniform grid (the part's fitted signed distance), expanded to
   second order about a point. Standalone C99: no allocation, no globals, no I/O; reentrant.

   status = hybrid_part_expansion(grid, coefficients, p, out);
   grid: HYBRID_PART_GRID_SIZE numbers (the first cell's corner [m], the spacing [m], the cells along x, y, z);
   coefficients: (cells_x + 3) (cells_y + 3) (cells_z + 3) numbers [m], z fastest, NaN beyond the fitted band;
   out: HYBRID_PART_OUT_SIZE numbers, the quadric surface's parameters about p: p, phi(p), grad phi(p) and the
   Hessian's upper triangle (xx, xy, xz, yy, yz, zz) [1/m].

   status = hybrid_part_data(data, count, &grid, &coefficients);
   data: the count numbers of a part's data file (<name>_part.bin, read whole as doubles); HYBRID_PART_OK
   points grid and coefficients into it, after checking its header, its grid, its size and its CRC-32. */
#include <math.h>
#include <stddef.h>

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
#define HYBRID_PART_DATA_INVALID 3
/* the data file: IEEE-754 binary64 numbers, little-endian; HYBRID_PART_DATA_HEADER_SIZE numbers (the tag, the
   layout's version, HYBRID_PART_GRID_SIZE, the coefficients' count, the CRC-32 (zlib's) of the bytes after the
   header), the grid's numbers, the coefficients */
#define HYBRID_PART_DATA_HEADER_SIZE 5
#define HYBRID_PART_DATA_TAG 0
#define HYBRID_PART_DATA_VERSION 1
#define HYBRID_PART_DATA_GRID_SIZE 2
#define HYBRID_PART_DATA_COEFFICIENTS 3
#define HYBRID_PART_DATA_CRC32 4
#define HYBRID_PART_DATA_TAG_VALUE 1213812820.0 /* "HYPT" as a number: another file, or the other byte order, differs */
#define HYBRID_PART_DATA_VERSION_VALUE 1.0
/* the most cells along an axis: no index the grid implies runs past the caller's array's end */
#define HYBRID_PART_MOST_CELLS 1048576.0

/* the arithmetic as written, in every build (no contraction into fused multiply-adds): every caller's
   expansion gives the same numbers */
#if defined(__clang__)
#pragma STDC FP_CONTRACT OFF
#elif defined(__GNUC__)
#pragma GCC push_options
#pragma GCC optimize("fp-contract=off")
#endif

/* the uniform cubic B-spline's four pieces at t in [0, 1), w[m] = (b, d, dd, 0): the piece times 6 (the sums
   divide by 6 once per b they hold, not each piece), its first and second derivatives (four numbers a piece,
   so that the sums below run on vectors of four where the compiler has them) */
static inline void hybrid_part_basis(double t, double w[4][4]) {
    const double s = 1.0 - t;
    w[0][0] = s * s * s;
    w[1][0] = 3.0 * t * t * t - 6.0 * t * t + 4.0;
    w[2][0] = -3.0 * t * t * t + 3.0 * t * t + 3.0 * t + 1.0;
    w[3][0] = t * t * t;
    w[0][1] = -s * s / 2.0;
    w[1][1] = (3.0 * t * t - 4.0 * t) / 2.0;
    w[2][1] = (-3.0 * t * t + 2.0 * t + 1.0) / 2.0;
    w[3][1] = t * t / 2.0;
    w[0][2] = s;
    w[1][2] = 3.0 * t - 2.0;
    w[2][2] = 1.0 - 3.0 * t;
    w[3][2] = t;
    w[0][3] = w[1][3] = w[2][3] = w[3][3] = 0.0;
}

/* the expansion of the part's phi about p into out (HYBRID_PART_OUT_*); HYBRID_PART_OK, or a status with out
   unwritten: HYBRID_PART_INPUT_NONFINITE (p or the grid's numbers not finite, a spacing not positive),
   HYBRID_PART_OFF_BAND (p off the grid, or a coefficient it reads undefined: beyond the fitted band) */
/* 1 when the grid's numbers are a grid's: its corner finite, its spacing positive and finite, its counts of cells
   whole numbers from 1 to HYBRID_PART_MOST_CELLS; 0 otherwise */
static inline int hybrid_part_grid_valid(const double *grid) {
    int a;
    const double h = grid[HYBRID_PART_GRID_SPACING];
    for (a = 0; a < 3; ++a) {
        const double c = grid[HYBRID_PART_GRID_CELLS_X + a];
        if (!isfinite(grid[a])) return 0;
        if (!(c >= 1.0 && c <= HYBRID_PART_MOST_CELLS && c == floor(c))) return 0;
    }
    return h > 0.0 && isfinite(h);
}

static inline int hybrid_part_expansion(const double *grid, const double *coefficients, const double *p,
                                        double *out) {
    /* the sums over x (S: of b, d, dd; T: of b, d; U: of b), each of four along z's (b, d, dd, -) */
    double u[3], t[3], w[3][4][4], S[3][4] = { {0.0} }, T[2][4] = { {0.0} }, U[4] = {0.0}, sum[10];
    long cell[3], n[3];
    int a, j, k, l, m;
    const double h = grid[HYBRID_PART_GRID_SPACING];
    for (a = 0; a < 3; ++a) {
        if (!isfinite(p[a])) return HYBRID_PART_INPUT_NONFINITE;
    }
    if (!hybrid_part_grid_valid(grid)) return HYBRID_PART_INPUT_NONFINITE;
    for (a = 0; a < 3; ++a) {
        const double c = grid[HYBRID_PART_GRID_CELLS_X + a];
        u[a] = (p[a] - grid[a]) / h;
        if (!(u[a] >= 0.0 && u[a] < c)) return HYBRID_PART_OFF_BAND;
        cell[a] = (long)floor(u[a]);
        n[a] = (long)c + 3;
        t[a] = u[a] - (double)cell[a];
        hybrid_part_basis(t[a], w[a]);
    }
    /* phi, its gradient and its Hessian (xx, xy, xz, yy, yz, zz) in grid units: the sums over the 64
       coefficients, one axis at a time (the tensor product's basis factors): along z each row of four gives
       its (b, d, dd) sums (z[l]), along y each plane its sums of b, d and dd of those (Y), along x the sums of
       the planes'; a ninth of the products of the sums written term by term, each element's sum in one
       order whatever the vectors */
    for (k = 0; k < 4; ++k) {
        double z[4][4] = { {0.0} }, Y[3][4] = { {0.0} };
        for (l = 0; l < 4; ++l) {
            const double *row = coefficients + ((cell[0] + k) * n[1] + (cell[1] + l)) * n[2] + cell[2];
            for (m = 0; m < 4; ++m) {
                for (j = 0; j < 4; ++j) z[l][j] += row[m] * w[2][m][j];
            }
        }
        for (l = 0; l < 4; ++l) {
            for (a = 0; a < 3; ++a) {
                for (j = 0; j < 4; ++j) Y[a][j] += w[1][l][a] * z[l][j];
            }
        }
        for (j = 0; j < 4; ++j) {
            for (a = 0; a < 3; ++a) S[a][j] += w[0][k][a] * Y[0][j];
            for (a = 0; a < 2; ++a) T[a][j] += w[0][k][a] * Y[1][j];
            U[j] += w[0][k][0] * Y[2][j];
        }
    }
    /* (x, y, z) pieces: bbb, dbb, bdb, bbd; ddbb, ddb, dbd, bddb, bdd, bbdd */
    sum[0] = S[0][0];
    sum[1] = S[1][0];
    sum[2] = T[0][0];
    sum[3] = S[0][1];
    sum[4] = S[2][0];
    sum[5] = T[1][0];
    sum[6] = S[1][1];
    sum[7] = U[0];
    sum[8] = T[0][1];
    sum[9] = S[0][2];
    for (k = 0; k < 10; ++k) {
        if (!isfinite(sum[k])) return HYBRID_PART_OFF_BAND;
    }
    for (a = 0; a < 3; ++a) out[HYBRID_PART_OUT_P_X + a] = p[a];
    /* the pieces' 6 once for each b in a sum (three in phi's, two in the gradient's and the Hessian's diagonal,
       one in its other entries), and the grid's spacing once for each derivative */
    out[HYBRID_PART_OUT_PHI] = sum[0] / 216.0;
    for (a = 0; a < 3; ++a) out[HYBRID_PART_OUT_G_X + a] = sum[1 + a] / (36.0 * h);
    for (a = 0; a < 6; ++a) {
        const double pieces = a == 0 || a == 3 || a == 5 ? 36.0 : 6.0; /* xx, yy, zz: two b; xy, xz, yz: one */
        out[HYBRID_PART_OUT_H_XX + a] = sum[4 + a] / (pieces * h * h);
    }
    return HYBRID_PART_OK;
}

#if defined(__clang__)
#pragma STDC FP_CONTRACT DEFAULT
#elif defined(__GNUC__)
#pragma GCC pop_options
#endif

/* the CRC-32 of zlib (reflected, polynomial 0xEDB88320) of the n bytes at b, four bits at a time */
static inline unsigned long hybrid_part_crc32(const unsigned char *b, size_t n) {
    static const unsigned long nibble[16] = {
        0x00000000UL, 0x1DB71064UL, 0x3B6E20C8UL, 0x26D930ACUL,
        0x76DC4190UL, 0x6B6B51F4UL, 0x4DB26158UL, 0x5005713CUL,
        0xEDB88320UL, 0xF00F9344UL, 0xD6D6A3E8UL, 0xCB61B38CUL,
        0x9B64C2B0UL, 0x86D3D2D4UL, 0xA00AE278UL, 0xBDBDF21CUL
    };
    unsigned long crc = 0xFFFFFFFFUL;
    size_t i;
    for (i = 0; i < n; ++i) {
        crc ^= b[i];
        crc = (crc >> 4) ^ nibble[crc & 15UL];
        crc = (crc >> 4) ^ nibble[crc & 15UL];
    }
    return crc ^ 0xFFFFFFFFUL;
}

/* the part's grid and coefficients in the count numbers of its data file at data (read whole, as doubles):
   HYBRID_PART_OK with grid and coefficients pointing into data, or HYBRID_PART_DATA_INVALID with them unchanged
   (no data; a count other than the header's; a tag, a version or a grid's size not this layout's (another file,
   or the other byte order); a grid that is not one; a CRC-32 other than the bytes': a damaged file) */
static inline int hybrid_part_data(const double *data, size_t count, const double **grid,
                                   const double **coefficients) {
    const size_t head = HYBRID_PART_DATA_HEADER_SIZE, body = HYBRID_PART_DATA_HEADER_SIZE + HYBRID_PART_GRID_SIZE;
    const double *g;
    double n;
    int a;
    if (data == 0 || grid == 0 || coefficients == 0 || count < body) return HYBRID_PART_DATA_INVALID;
    g = data + head;
    if (data[HYBRID_PART_DATA_TAG] != HYBRID_PART_DATA_TAG_VALUE
        || data[HYBRID_PART_DATA_VERSION] != HYBRID_PART_DATA_VERSION_VALUE
        || data[HYBRID_PART_DATA_GRID_SIZE] != (double)HYBRID_PART_GRID_SIZE
        || !hybrid_part_grid_valid(g)) return HYBRID_PART_DATA_INVALID;
    /* the coefficients' count, (cells + 3) along each axis, as the header and the count both give it (each factor
       at most 2^20 + 3: the product is exact where it is a count of numbers in memory) */
    n = 1.0;
    for (a = 0; a < 3; ++a) n *= g[HYBRID_PART_GRID_CELLS_X + a] + 3.0;
    if (data[HYBRID_PART_DATA_COEFFICIENTS] != n || (double)(count - body) != n) return HYBRID_PART_DATA_INVALID;
    if (data[HYBRID_PART_DATA_CRC32] != (double)hybrid_part_crc32((const unsigned char *)(data + head),
                                                                 (count - head) * sizeof(double))) {
        return HYBRID_PART_DATA_INVALID;
    }
    *grid = g;
    *coefficients = data + body;
    return HYBRID_PART_OK;
}

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
