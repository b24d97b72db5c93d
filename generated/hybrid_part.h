/* hybrid generated file: do not edit; change codegen/ and run `python -m hybrid regenerate`. body-sha256: a43d95703e46330b916bbf826ad6369d0ae1a584ed694037bd3fc93eb25d3699 */
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
#include <string.h>

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

/* vectors of four doubles: GCC's and Clang's vector extensions (the processor's SIMD instructions, or pairs of
   narrower ones, where it has them), else a struct of four (with HYBRID_PART_PLAIN_C defined too); the same
   operation on each element either way, so the same numbers. Macros, not functions, on the vectors: a function
   taking or returning one changes the calling convention where AVX is off (GCC's -Wpsabi) */
#if (defined(__GNUC__) || defined(__clang__)) && !defined(HYBRID_PART_PLAIN_C)
typedef double hybrid_part_v4 __attribute__((vector_size(32)));
#define HYBRID_PART_V4(a, b, c, d) {a, b, c, d}
#define HYBRID_PART_E(v, i) ((v)[i])
#define HYBRID_PART_ADD(x, y) ((x) + (y))
#define HYBRID_PART_MUL(x, y) ((x) * (y))
#define HYBRID_PART_LOAD(v, q) memcpy(&(v), (q), sizeof(v))
#else
typedef struct { double e[4]; } hybrid_part_v4;
#define HYBRID_PART_V4(a, b, c, d) { {a, b, c, d} }
#define HYBRID_PART_E(v, i) ((v).e[i])
#define HYBRID_PART_ADD(x, y) hybrid_part_add(x, y)
#define HYBRID_PART_MUL(x, y) hybrid_part_mul(x, y)
#define HYBRID_PART_LOAD(v, q) memcpy((v).e, (q), sizeof((v).e))
static inline hybrid_part_v4 hybrid_part_add(hybrid_part_v4 x, hybrid_part_v4 y) {
    int i;
    for (i = 0; i < 4; ++i) x.e[i] = x.e[i] + y.e[i];
    return x;
}
static inline hybrid_part_v4 hybrid_part_mul(hybrid_part_v4 x, hybrid_part_v4 y) {
    int i;
    for (i = 0; i < 4; ++i) x.e[i] = x.e[i] * y.e[i];
    return x;
}
#endif

/* the uniform cubic B-spline's four pieces at t in [0, 1) as polynomials in t, c[0] + t (c[1] + t (c[2] + t c[3]))
   (Horner's form; the powers beyond the order's degree add exact zeros), each c a vector over the pieces: the
   pieces times 6 (the sums divide by 6 once per b they hold, not each piece), their first and second derivatives */
static const double hybrid_part_pieces[3][4][4] = {
    { {1.0, 4.0, 1.0, 0.0}, {-3.0, 0.0, 3.0, 0.0}, {3.0, -6.0, 3.0, 0.0}, {-1.0, 3.0, -3.0, 1.0} },
    { {-0.5, 0.0, 0.5, 0.0}, {1.0, -2.0, 1.0, 0.0}, {-0.5, 1.5, -1.5, 0.5}, {0.0, 0.0, 0.0, 0.0} },
    { {1.0, -2.0, 1.0, 0.0}, {-1.0, 3.0, -3.0, 1.0}, {0.0, 0.0, 0.0, 0.0}, {0.0, 0.0, 0.0, 0.0} }
};

/* w = the four pieces of the order (0: b, 1: d, 2: dd) at t (T: four times t) */
#define HYBRID_PART_PIECES(w, order, T) do { \
        hybrid_part_v4 c0_, c1_, c2_, c3_; \
        HYBRID_PART_LOAD(c0_, hybrid_part_pieces[order][0]); \
        HYBRID_PART_LOAD(c1_, hybrid_part_pieces[order][1]); \
        HYBRID_PART_LOAD(c2_, hybrid_part_pieces[order][2]); \
        HYBRID_PART_LOAD(c3_, hybrid_part_pieces[order][3]); \
        (w) = HYBRID_PART_ADD(c0_, HYBRID_PART_MUL(T, HYBRID_PART_ADD(c1_, HYBRID_PART_MUL(T, \
            HYBRID_PART_ADD(c2_, HYBRID_PART_MUL(T, c3_)))))); \
    } while (0)

/* s = sum_k x[k] v[k] (x a vector's four numbers, each times a whole vector), in the order k = 0, 1, 2, 3 */
#define HYBRID_PART_COMBINE(s, x, v0, v1, v2, v3) do { \
        const hybrid_part_v4 x0_ = HYBRID_PART_V4(HYBRID_PART_E(x, 0), HYBRID_PART_E(x, 0), HYBRID_PART_E(x, 0), \
                                                  HYBRID_PART_E(x, 0)); \
        const hybrid_part_v4 x1_ = HYBRID_PART_V4(HYBRID_PART_E(x, 1), HYBRID_PART_E(x, 1), HYBRID_PART_E(x, 1), \
                                                  HYBRID_PART_E(x, 1)); \
        const hybrid_part_v4 x2_ = HYBRID_PART_V4(HYBRID_PART_E(x, 2), HYBRID_PART_E(x, 2), HYBRID_PART_E(x, 2), \
                                                  HYBRID_PART_E(x, 2)); \
        const hybrid_part_v4 x3_ = HYBRID_PART_V4(HYBRID_PART_E(x, 3), HYBRID_PART_E(x, 3), HYBRID_PART_E(x, 3), \
                                                  HYBRID_PART_E(x, 3)); \
        (s) = HYBRID_PART_ADD(HYBRID_PART_ADD(HYBRID_PART_ADD(HYBRID_PART_MUL(x0_, v0), HYBRID_PART_MUL(x1_, v1)), \
                                              HYBRID_PART_MUL(x2_, v2)), HYBRID_PART_MUL(x3_, v3)); \
    } while (0)

/* s[i] = (a[i][0] b[i][0] + a[i][1] b[i][1]) + (a[i][2] b[i][2] + a[i][3] b[i][3]) for the four i: four dot
   products of four at once, their products' vectors transposed */
#define HYBRID_PART_DOTS(s, a, b) do { \
        const hybrid_part_v4 p0_ = HYBRID_PART_MUL((a)[0], (b)[0]), p1_ = HYBRID_PART_MUL((a)[1], (b)[1]); \
        const hybrid_part_v4 p2_ = HYBRID_PART_MUL((a)[2], (b)[2]), p3_ = HYBRID_PART_MUL((a)[3], (b)[3]); \
        const hybrid_part_v4 e0_ = HYBRID_PART_V4(HYBRID_PART_E(p0_, 0), HYBRID_PART_E(p1_, 0), \
                                                  HYBRID_PART_E(p2_, 0), HYBRID_PART_E(p3_, 0)); \
        const hybrid_part_v4 e1_ = HYBRID_PART_V4(HYBRID_PART_E(p0_, 1), HYBRID_PART_E(p1_, 1), \
                                                  HYBRID_PART_E(p2_, 1), HYBRID_PART_E(p3_, 1)); \
        const hybrid_part_v4 e2_ = HYBRID_PART_V4(HYBRID_PART_E(p0_, 2), HYBRID_PART_E(p1_, 2), \
                                                  HYBRID_PART_E(p2_, 2), HYBRID_PART_E(p3_, 2)); \
        const hybrid_part_v4 e3_ = HYBRID_PART_V4(HYBRID_PART_E(p0_, 3), HYBRID_PART_E(p1_, 3), \
                                                  HYBRID_PART_E(p2_, 3), HYBRID_PART_E(p3_, 3)); \
        (s) = HYBRID_PART_ADD(HYBRID_PART_ADD(e0_, e1_), HYBRID_PART_ADD(e2_, e3_)); \
    } while (0)

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
    /* w[a][o]: the pieces of order o along the axis a; Y[k][o]: the plane x = k's sums along y (of order o), a
       vector along z; V: the sums along y and x of the orders (x, y) 00, 10, 01, 20, 11, 02; S: the ten sums */
    double u[3], t[3];
    hybrid_part_v4 w[3][3], Y[4][3], V[6], A[12], B[12], S[3], check;
    long cell[3], n[3];
    int a, k, o;
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
    }
    for (a = 0; a < 3; ++a) {
        const hybrid_part_v4 T = HYBRID_PART_V4(t[a], t[a], t[a], t[a]);
        for (o = 0; o < 3; ++o) HYBRID_PART_PIECES(w[a][o], o, T);
    }
    /* phi, its gradient and its Hessian (xx, xy, xz, yy, yz, zz) in grid units: the sums over the 64
       coefficients, one axis at a time (the tensor product's basis factors), on vectors along z (a row of four
       coefficients): along y each plane's rows (Y), along x the planes' (V), then along z each of V's four
       numbers times the pieces' */
    for (k = 0; k < 4; ++k) {
        const double *row = coefficients + ((cell[0] + k) * n[1] + cell[1]) * n[2] + cell[2];
        hybrid_part_v4 r0, r1, r2, r3;
        HYBRID_PART_LOAD(r0, row);
        HYBRID_PART_LOAD(r1, row + n[2]);
        HYBRID_PART_LOAD(r2, row + 2 * n[2]);
        HYBRID_PART_LOAD(r3, row + 3 * n[2]);
        for (o = 0; o < 3; ++o) HYBRID_PART_COMBINE(Y[k][o], w[1][o], r0, r1, r2, r3);
    }
    HYBRID_PART_COMBINE(V[0], w[0][0], Y[0][0], Y[1][0], Y[2][0], Y[3][0]);
    HYBRID_PART_COMBINE(V[1], w[0][1], Y[0][0], Y[1][0], Y[2][0], Y[3][0]);
    HYBRID_PART_COMBINE(V[2], w[0][0], Y[0][1], Y[1][1], Y[2][1], Y[3][1]);
    HYBRID_PART_COMBINE(V[3], w[0][2], Y[0][0], Y[1][0], Y[2][0], Y[3][0]);
    HYBRID_PART_COMBINE(V[4], w[0][1], Y[0][1], Y[1][1], Y[2][1], Y[3][1]);
    HYBRID_PART_COMBINE(V[5], w[0][0], Y[0][2], Y[1][2], Y[2][2], Y[3][2]);
    /* (x, y, z) pieces: bbb, dbb, bdb, bbd; ddbb, ddb, dbd, bddb; bdd, bbdd (and bbdd twice more, unused) */
    A[0] = V[0], B[0] = w[2][0], A[1] = V[1], B[1] = w[2][0], A[2] = V[2], B[2] = w[2][0], A[3] = V[0], B[3] = w[2][1];
    A[4] = V[3], B[4] = w[2][0], A[5] = V[4], B[5] = w[2][0], A[6] = V[1], B[6] = w[2][1], A[7] = V[5], B[7] = w[2][0];
    A[8] = V[2], B[8] = w[2][1];
    for (k = 9; k < 12; ++k) A[k] = V[0], B[k] = w[2][2];
    for (k = 0; k < 3; ++k) HYBRID_PART_DOTS(S[k], A + 4 * k, B + 4 * k);
    /* a sum times zero: zero where it is a number, NaN where it is not (NaN or infinite); their sum, NaN where
       one is */
    {
        const hybrid_part_v4 zero = HYBRID_PART_V4(0.0, 0.0, 0.0, 0.0);
        check = HYBRID_PART_ADD(HYBRID_PART_ADD(HYBRID_PART_MUL(S[0], zero), HYBRID_PART_MUL(S[1], zero)),
                                HYBRID_PART_MUL(S[2], zero));
        if ((HYBRID_PART_E(check, 0) + HYBRID_PART_E(check, 1)) + (HYBRID_PART_E(check, 2) + HYBRID_PART_E(check, 3))
            != 0.0) return HYBRID_PART_OFF_BAND;
    }
    /* the pieces' 6 once for each b in a sum (three in phi's, two in the gradient's and the Hessian's diagonal,
       one in its other entries), and the grid's spacing once for each derivative: each sum times the inverse */
    {
        const double f0 = 1.0 / 216.0, f1 = 1.0 / (36.0 * h), f2 = 1.0 / (36.0 * h * h), f3 = 1.0 / (6.0 * h * h);
        const hybrid_part_v4 g0 = HYBRID_PART_V4(f0, f1, f1, f1), g1 = HYBRID_PART_V4(f2, f3, f3, f2);
        const hybrid_part_v4 g2 = HYBRID_PART_V4(f3, f2, 0.0, 0.0);
        const hybrid_part_v4 s0 = HYBRID_PART_MUL(S[0], g0), s1 = HYBRID_PART_MUL(S[1], g1);
        const hybrid_part_v4 s2 = HYBRID_PART_MUL(S[2], g2);
        for (a = 0; a < 3; ++a) out[HYBRID_PART_OUT_P_X + a] = p[a];
        for (a = 0; a < 4; ++a) out[HYBRID_PART_OUT_PHI + a] = HYBRID_PART_E(s0, a);
        for (a = 0; a < 4; ++a) out[HYBRID_PART_OUT_H_XX + a] = HYBRID_PART_E(s1, a);
        for (a = 0; a < 2; ++a) out[HYBRID_PART_OUT_H_YZ + a] = HYBRID_PART_E(s2, a);
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
