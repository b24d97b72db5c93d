/* hybrid generated file: do not edit; change codegen/ and run `python -m hybrid regenerate`. body-sha256: 4fc99412472a3ed2ca1d8bc5ae0755217d0199745d5e651c7024c97bbec8fa9a */
/* hybrid_lanes.h: the SIMD lanes of hybrid's generated C (GCC's or Clang's vector extensions): hl_v, a
   vector of HL_W doubles, one state per lane; hl_i, its masks; selects, tests and the vector polynomials
   (sin, cos, exp, tanh) with the C library's value for a lane whose argument they do not cover.
   Included by every unit that evaluates kernels in lanes (a build may define HL_W first); compiles on its
   own. The generator's source of it is codegen/templates/hybrid_lanes.h.j2. */
#ifndef HYBRID_LANES_H
#define HYBRID_LANES_H
#include <math.h>
#include <string.h>

#ifndef HL_W /* a build may fix it (1: one run at a time) */
#if defined(__AVX512F__)
#define HL_W 8
#elif defined(__AVX__)
#define HL_W 4
#else
#define HL_W 2
#endif
#endif
typedef double hl_v __attribute__((vector_size(HL_W * 8)));
typedef long long hl_i __attribute__((vector_size(HL_W * 8)));

static inline hl_v hl_splat(double c) {
    hl_v r = {0};
    int l;
    for (l = 0; l < HL_W; ++l) r[l] = c;
    return r;
}
static inline hl_v hl_select(hl_i m, hl_v a, hl_v b) { return (hl_v)((m & (hl_i)a) | (~m & (hl_i)b)); }
static inline hl_v hl_bool(hl_i m) { return hl_select(m, hl_splat(1.0), hl_splat(0.0)); }
/* whether any lane of a mask is set: one instruction where the vector extension has it */
#if defined(__AVX512F__) && HL_W == 8
#include <immintrin.h>
static inline int hl_any(hl_i m) { return _mm512_test_epi64_mask((__m512i)m, (__m512i)m) != 0; }
#elif defined(__AVX__) && HL_W == 4
#include <immintrin.h>
static inline int hl_any(hl_i m) { return !_mm256_testz_si256((__m256i)m, (__m256i)m); }
#elif defined(__SSE4_1__) && HL_W == 2
#include <smmintrin.h> /* not immintrin.h: that one takes a sixth of a second to compile */
static inline int hl_any(hl_i m) { return !_mm_testz_si128((__m128i)m, (__m128i)m); }
#else
static inline int hl_any(hl_i m) {
    long long acc = 0;
    int l;
    for (l = 0; l < HL_W; ++l) acc |= m[l];
    return acc != 0;
}
#endif
/* the lanes where any of v[0 .. n-1] is NaN or infinite: a sum of v[i] - v[i], 0 where all are finite and
   NaN where one is not, then one comparison */
static inline hl_i hl_not_finite(const hl_v *v, int n) {
    hl_v sum = hl_splat(0.0);
    int i;
    for (i = 0; i < n; ++i) sum += v[i] - v[i];
    return sum != 0.0;
}
static inline hl_v hl_fabs(hl_v x) { return (hl_v)((hl_i)x & ~(hl_i)hl_splat(-0.0)); }
static inline hl_v hl_copysign(hl_v x, hl_v y) {
    hl_i s = (hl_i)hl_splat(-0.0);
    return (hl_v)(((hl_i)x & ~s) | ((hl_i)y & s));
}
/* CasADi's sign: -1, 1, or x itself (0 and NaN) */
static inline hl_v hl_sign(hl_v x) {
    return hl_select(x < 0.0, hl_splat(-1.0), hl_select(x > 0.0, hl_splat(1.0), x));
}
/* C99 fmax/fmin: a NaN argument loses to a number */
static inline hl_v hl_fmax(hl_v a, hl_v b) { return hl_select((a > b) | (b != b), a, b); }
static inline hl_v hl_fmin(hl_v a, hl_v b) { return hl_select((a < b) | (b != b), a, b); }
static inline hl_v hl_sqrt(hl_v x) {
    hl_v r = x;
    int l;
    for (l = 0; l < HL_W; ++l) r[l] = __builtin_sqrt(x[l]);
    return r;
}
#define HL_MAP1(name, f) static inline hl_v name(hl_v x) { \
    hl_v r = x; int l; for (l = 0; l < HL_W; ++l) r[l] = f(x[l]); return r; }
#define HL_MAP2(name, f) static inline hl_v name(hl_v x, hl_v y) { \
    hl_v r = x; int l; for (l = 0; l < HL_W; ++l) r[l] = f(x[l], y[l]); return r; }

/* Each of sincos, exp and tanh comes twice: hl_<f>_poly is the vector polynomial alone, which marks
   in *odd the lanes it does not cover (a large or non-finite argument) and gives them meaningless
   numbers; hl_<f> gives those lanes the C library's value, so no lane depends on its neighbours. A
   kernel runs on the polynomials and, when a lane is odd, once again on the exact functions: its hot
   path makes no call, and keeps its values in registers. */

/* sin and cos: x = n pi/2 + r, |r| <= pi/4, in three parts of pi/2 (exact products for
   |n| < 2^20), then fdlibm's kernels on r; odd: beyond |x| = 1e5, or not finite */
static inline void hl_sincos_poly(hl_v x, hl_v *sine, hl_v *cosine, hl_i *odd) {
    const double magic = 6755399441055744.0; /* 1.5 * 2^52: adding it rounds to an integer */
    const hl_i big = ~(hl_fabs(x) <= 1e5), sign = (hl_i)hl_splat(-0.0);
    hl_v t, n, r, z, s, c, p, hz, w, y = hl_select(big, hl_splat(0.0), x);
    hl_i j;
    t = y * 6.36619772367581382433e-01 + magic;
    n = t - magic;
    j = (hl_i)t & 3; /* the quadrant, from the integer's low bits */
    r = ((y - n * 1.57079632673412561417e+00) - n * 6.07710050630396597660e-11) - n * 2.02226624879595063154e-21;
    z = r * r;
    s = r + r * z * (-1.66666666666666324348e-01 + z * (8.33333333332248946124e-03 + z * (-1.98412698298579493134e-04
        + z * (2.75573137070700676789e-06 + z * (-2.50507602534068634195e-08 + z * 1.58969099521155010221e-10)))));
    s = hl_select(r == 0.0, r, s); /* sin(-0) = -0 */
    p = z * (4.16666666666666019037e-02 + z * (-1.38888888888741095749e-03 + z * (2.48015872894767294178e-05
        + z * (-2.75573143513906633035e-07 + z * (2.08757232129817482790e-09 + z * -1.13596475577881948265e-11)))));
    hz = 0.5 * z;
    w = 1.0 - hz;
    c = w + (((1.0 - w) - hz) + z * p);
    /* quadrant j: sin = (s, c, -s, -c)[j], cos = (c, -s, -c, s)[j] */
    *sine = (hl_v)((hl_i)hl_select((j & 1) != 0, c, s) ^ (((j & 2) != 0) & sign));
    *cosine = (hl_v)((hl_i)hl_select((j & 1) != 0, s, c) ^ ((((j + 1) & 2) != 0) & sign));
    *odd |= big;
}
static inline void hl_sincos(hl_v x, hl_v *sine, hl_v *cosine) {
    hl_i big = hl_splat(0.0) != 0.0;
    int l;
    hl_sincos_poly(x, sine, cosine, &big);
    if (hl_any(big)) {
        for (l = 0; l < HL_W; ++l) {
            if (big[l]) {
                (*sine)[l] = sin(x[l]);
                (*cosine)[l] = cos(x[l]);
            }
        }
    }
}
/* sin and cos of x near x0, from base = (x0, sin x0, cos x0): x0's rotated by d = x - x0 with Taylor
   polynomials of sin d (to d^5) and cos d - 1 (to d^6), whose truncation is below 4e-19 for |d| <= 2^-7; a
   lane farther from x0 (or not finite) takes the polynomials (_near_poly, odd as they say) or hl_sincos
   (_near); within 2 * 2^-52 of sin x and cos x, absolute. The stages of RK4 steps are this near a base
   that hl_rebase keeps within 2^-8 of their start. (The span trades the polynomials' length, which every
   stage pays and waits on, against how often a base is computed: 2^-8 rad is tens of steps at a joint
   speed of 1 rad/s.) */
static inline hl_i hl_rotate(hl_v x, const hl_v *base, hl_v *sine, hl_v *cosine) {
    const hl_v d = x - base[0], d2 = d * d;
    const hl_v sd = d + d * d2 * (-1.0 / 6 + d2 * (1.0 / 120));
    const hl_v cm = d2 * (-0.5 + d2 * (1.0 / 24 + d2 * (-1.0 / 720)));
    /* one product per sum: the compiler's fused multiply-adds are then the same for any lane count */
    *sine = (base[1] + base[1] * cm) + base[2] * sd;
    *cosine = (base[2] + base[2] * cm) - base[1] * sd;
    return ~(hl_fabs(d) <= 0x1p-7);
}
/* base[3 j .. 3 j + 2] = (x0, sin x0, cos x0) for x[j], j < n: a lane whose angles have moved more than 2^-8
   from its base (or whose base is not a number yet) takes its angles as its new base, computed once for the
   steps that follow; a lane's base depends on its own angles alone */
static inline void hl_rebase(const hl_v *x, hl_v *base, int n) {
    hl_i far = hl_splat(0.0) != 0.0;
    int j;
    for (j = 0; j < n; ++j) far |= ~(hl_fabs(x[j] - base[3 * j]) <= 0x1p-8);
    if (hl_any(far)) {
        for (j = 0; j < n; ++j) {
            hl_v sine, cosine;
            hl_sincos(x[j], &sine, &cosine);
            base[3 * j] = hl_select(far, x[j], base[3 * j]);
            base[3 * j + 1] = hl_select(far, sine, base[3 * j + 1]);
            base[3 * j + 2] = hl_select(far, cosine, base[3 * j + 2]);
        }
    }
}
static inline void hl_sincos_near_poly(hl_v x, const hl_v *base, hl_v *sine, hl_v *cosine, hl_i *odd) {
    const hl_i far = hl_rotate(x, base, sine, cosine);
    if (hl_any(far)) {
        hl_v s, c;
        hl_i o = hl_splat(0.0) != 0.0;
        hl_sincos_poly(x, &s, &c, &o);
        *odd |= o & far;
        *sine = hl_select(far, s, *sine);
        *cosine = hl_select(far, c, *cosine);
    }
}
static inline void hl_sincos_near(hl_v x, const hl_v *base, hl_v *sine, hl_v *cosine) {
    const hl_i far = hl_rotate(x, base, sine, cosine);
    if (hl_any(far)) {
        hl_v s, c;
        hl_sincos(x, &s, &c);
        *sine = hl_select(far, s, *sine);
        *cosine = hl_select(far, c, *cosine);
    }
}

/* exp: x = n ln2 + r (ln2 in two parts, |r| <= ln2 / 2), exp(r) by its Taylor polynomial of degree
   13 (truncation below 5e-18; no division), times 2^n; odd: beyond |x| = 700, or not finite */
/* 1/k!, k = 0 .. 12 */
static const double hl_exp_taylor[13] = {1.0, 1.0, 0.5, 1.0 / 6, 1.0 / 24, 1.0 / 120, 1.0 / 720, 1.0 / 5040,
    1.0 / 40320, 1.0 / 362880, 1.0 / 3628800, 1.0 / 39916800, 1.0 / 479001600};
static inline __attribute__((always_inline)) hl_v hl_exp_poly(hl_v x, hl_i *odd) {
    const double magic = 6755399441055744.0;
    const hl_i big = ~(hl_fabs(x) <= 700.0);
    hl_v t, n, r, y = hl_select(big, hl_splat(0.0), x);
    hl_i k;
    int l;
    t = y * 1.44269504088896338700e+00 + magic;
    n = t - magic;
    k = ((hl_i)t - (hl_i)hl_splat(magic)) + 1023;
    r = (y - n * 6.93147180369123816490e-01) - n * 1.90821492927058770002e-10;
    y = hl_splat(1.0 / 6227020800.0); /* 1/13! */
    for (l = 12; l >= 0; --l) y = hl_exp_taylor[l] + r * y;
    *odd |= big;
    return y * (hl_v)(k << 52);
}
/* the exact form of a one-argument polynomial hl_<f>_poly: its odd lanes take the C library's f */
#define HL_EXACT1(name, f) static inline hl_v name(hl_v x) { \
    hl_i odd = hl_splat(0.0) != 0.0; hl_v r = name##_poly(x, &odd); int l; \
    if (hl_any(odd)) for (l = 0; l < HL_W; ++l) if (odd[l]) r[l] = f(x[l]); \
    return r; }
HL_EXACT1(hl_exp, exp)

/* tanh: 1 - 2 / (exp(2|x|) + 1) with the sign of x, and Cephes' rational form where |x| < 0.625
   (computed only when a lane needs it); from |x| = 20 on that is +-1 exactly, so where every lane is
   there (a friction law sliding) hl_tanh_poly takes a short path, and the rest (a lane below: a joint's
   friction near rest) is laid out of its way, inline all the same, exp with it: a call in a kernel's
   middle spills every vector register it holds (the UR5's loop, whose seven tanh a stage all take the
   rest, ran 8 % faster without the calls, to the same bits); odd: not a number */
static inline __attribute__((always_inline)) hl_v hl_tanh_below(hl_v x, hl_i *odd) {
    const hl_i small = hl_fabs(x) < 0.625;
    hl_v ax = hl_fabs(x), r;
    ax = hl_select(ax > 20.0, hl_splat(20.0), ax); /* a NaN stays NaN */
    if (hl_any(~(ax >= 20.0))) {
        r = hl_copysign(1.0 - 2.0 / (hl_exp_poly(2.0 * ax, odd) + 1.0), x);
    } else {
        r = hl_copysign(hl_splat(1.0), x); /* 2 / (exp(40) + 1) < 2^-54: 1 - it rounds to 1 */
    }
    if (hl_any(small)) {
        const hl_v z = x * x;
        r = hl_select(small, x + x * z * ((-9.64399179425052238628e-01 * z - 9.92877231001918586564e+01) * z
            - 1.61468768441708447952e+03) / (((z + 1.12811678491632931402e+02) * z + 2.23548839060100448583e+03) * z
            + 4.84406305325125486048e+03), r);
    }
    return hl_select(x == 0.0, x, r); /* tanh(-0) = -0 */
}
static inline __attribute__((always_inline)) hl_v hl_tanh_poly(hl_v x, hl_i *odd) {
    if (__builtin_expect(hl_any(~(hl_fabs(x) >= 20.0)), 0)) return hl_tanh_below(x, odd); /* a NaN is below */
    return hl_copysign(hl_splat(1.0), x);
}
HL_EXACT1(hl_tanh, tanh)
#endif
