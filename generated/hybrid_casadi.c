/* hybrid generated file: do not edit; change codegen/ and run `python -m hybrid regenerate`. body-sha256: 7a546d485365214bc8f923ddd9cb0f7ab04f0022460f58c8c7b60bd390c3c205 */
/* hybrid_casadi: hybrid force/velocity control kernels for a planar 2-link arm, derived by codegen/model.py.
   Emitted by the casadi backend of hybrid's codegen (SymPy 1.14.0, CasADi 3.8.2), generator version 5.
   Compile: cc -std=c99 -O2 -c hybrid_casadi.c (link with -lm). */
#include <math.h>

/* hybrid_sincos.c.j2: sin and cos of one double, inline, for the kernels CasADi prints (codegen/emit.py puts
   this text before them where they take a sine or a cosine; it compiles on its own after <math.h>).
   x = n pi/2 + r, |r| <= pi/4, with pi/2 in three parts (exact products for |n| < 2^20), then fdlibm's
   kernels on r: the same polynomials as the lanes' hl_sincos_poly (hybrid_lanes.h), within an ulp of the
   C library's sin and cos for |x| <= 200, two beyond (tests/test_templates.py). Beyond |x| = 1e5, or
   not finite, the C library's. Inline and without a call, a kernel keeps its values in registers across
   it, where a call would spill them; the sine and the cosine of one angle share their reduction and
   polynomials once the compiler has inlined both. */
static inline void hybrid_sincos(double x, double *sine, double *cosine) {
    const double magic = 6755399441055744.0; /* 1.5 * 2^52: adding it rounds to an integer */
    double t, n, r, z, s, c, p, hz, w, a, b;
    long long j;
    if (!(fabs(x) <= 1e5)) {
        *sine = sin(x);
        *cosine = cos(x);
        return;
    }
    t = x * 6.36619772367581382433e-01 + magic;
    n = t - magic;
    j = (long long)n & 3; /* the quadrant */
    r = ((x - n * 1.57079632673412561417e+00) - n * 6.07710050630396597660e-11) - n * 2.02226624879595063154e-21;
    z = r * r;
    s = r + r * z * (-1.66666666666666324348e-01 + z * (8.33333333332248946124e-03 + z * (-1.98412698298579493134e-04
        + z * (2.75573137070700676789e-06 + z * (-2.50507602534068634195e-08 + z * 1.58969099521155010221e-10)))));
    if (r == 0.0) s = r; /* sin(-0) = -0 */
    p = z * (4.16666666666666019037e-02 + z * (-1.38888888888741095749e-03 + z * (2.48015872894767294178e-05
        + z * (-2.75573143513906633035e-07 + z * (2.08757232129817482790e-09 + z * -1.13596475577881948265e-11)))));
    hz = 0.5 * z;
    w = 1.0 - hz;
    c = w + (((1.0 - w) - hz) + z * p);
    /* quadrant j: sin = (s, c, -s, -c)[j], cos = (c, -s, -c, s)[j] */
    a = (j & 1) ? c : s;
    b = (j & 1) ? s : c;
    *sine = (j & 2) ? -a : a;
    *cosine = ((j + 1) & 2) ? -b : b;
}
static inline double hybrid_sin(double x) {
    double s, c;
    hybrid_sincos(x, &s, &c);
    return s;
}
static inline double hybrid_cos(double x) {
    double s, c;
    hybrid_sincos(x, &s, &c);
    return c;
}
/* How to prefix internal symbols */
#ifdef CASADI_CODEGEN_PREFIX
  #define CASADI_NAMESPACE_CONCAT(NS, ID) _CASADI_NAMESPACE_CONCAT(NS, ID)
  #define _CASADI_NAMESPACE_CONCAT(NS, ID) NS ## ID
  #define CASADI_PREFIX(ID) CASADI_NAMESPACE_CONCAT(CODEGEN_PREFIX, ID)
#else
  #define CASADI_PREFIX(ID) hybrid_casadi__ ## ID
#endif

#include <math.h>

#ifndef casadi_real
#define casadi_real double
#endif

#ifndef casadi_int
#define casadi_int int
#endif

/* Add prefix to internal symbols */
#define casadi_f0 CASADI_PREFIX(f0)
#define casadi_f1 CASADI_PREFIX(f1)
#define casadi_f10 CASADI_PREFIX(f10)
#define casadi_f11 CASADI_PREFIX(f11)
#define casadi_f12 CASADI_PREFIX(f12)
#define casadi_f2 CASADI_PREFIX(f2)
#define casadi_f3 CASADI_PREFIX(f3)
#define casadi_f4 CASADI_PREFIX(f4)
#define casadi_f5 CASADI_PREFIX(f5)
#define casadi_f6 CASADI_PREFIX(f6)
#define casadi_f7 CASADI_PREFIX(f7)
#define casadi_f8 CASADI_PREFIX(f8)
#define casadi_f9 CASADI_PREFIX(f9)
#define casadi_fmax CASADI_PREFIX(fmax)
#define casadi_sq CASADI_PREFIX(sq)
static casadi_real casadi_sq(casadi_real x) { return x*x;}

static casadi_real casadi_fmax(casadi_real x, casadi_real y) {
/* Pre-c99 compatibility */
#if __STDC_VERSION__ < 199901L
  return x>y ? x : y;
#else
  return fmax(x, y);
#endif
}

static int casadi_f0(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  (void)arg; (void)iw; (void)mem; (void)w;
  casadi_real a0, a1, a2, a3, a4, a5, a6, a7, a8;
  a0=arg[2][0];
  a1=arg[0][0];
  a2=hybrid_cos(a1);
  a3=(a0*a2);
  a4=arg[2][1];
  a5=arg[0][1];
  a6=hybrid_cos(a5);
  a7=(a2*a6);
  a1=hybrid_sin(a1);
  a5=hybrid_sin(a5);
  a8=(a1*a5);
  a7=(a7-a8);
  a8=(a4*a7);
  a3=(a3+a8);
  res[0][0]=a3;
  a0=(a0*a1);
  a2=(a2*a5);
  a6=(a6*a1);
  a2=(a2+a6);
  a6=(a4*a2);
  a0=(a0+a6);
  res[0][1]=a0;
  a1=(-a0);
  res[1][0]=a1;
  a6=(-a6);
  res[1][1]=a6;
  res[1][2]=a3;
  res[1][3]=a8;
  a8=arg[1][0];
  a3=(a8*a3);
  a6=arg[1][1];
  a1=(a4*a6);
  a5=(a1*a7);
  a3=(a3+a5);
  a3=(a8*a3);
  a4=(a4*a8);
  a7=(a4*a7);
  a7=(a7+a5);
  a7=(a6*a7);
  a3=(a3+a7);
  a3=(-a3);
  res[2][0]=a3;
  a0=(a8*a0);
  a1=(a1*a2);
  a0=(a0+a1);
  a8=(a8*a0);
  a4=(a4*a2);
  a4=(a4+a1);
  a6=(a6*a4);
  a8=(a8+a6);
  a8=(-a8);
  res[2][1]=a8;
  return 0;
}

static int casadi_f1(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  (void)arg; (void)iw; (void)mem; (void)w;
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13;
  a00=arg[2][6];
  a01=arg[2][7];
  a00=(a00+a01);
  a02=arg[2][2];
  a03=arg[2][4];
  a04=casadi_sq(a03);
  a04=(a02*a04);
  a00=(a00+a04);
  a04=arg[2][3];
  a05=arg[2][0];
  a06=casadi_sq(a05);
  a07=arg[2][5];
  a08=casadi_sq(a07);
  a06=(a06+a08);
  a09=(2.*a05);
  a09=(a09*a07);
  a10=arg[0][1];
  a11=hybrid_cos(a10);
  a09=(a09*a11);
  a06=(a06+a09);
  a06=(a04*a06);
  a00=(a00+a06);
  res[0][0]=a00;
  a00=(a05*a07);
  a00=(a00*a11);
  a00=(a08+a00);
  a00=(a04*a00);
  a00=(a01+a00);
  res[0][1]=a00;
  res[0][2]=a00;
  a08=(a04*a08);
  a01=(a01+a08);
  res[0][3]=a01;
  a01=arg[2][8];
  a08=arg[1][0];
  a01=(a01*a08);
  a00=arg[2][10];
  a06=(a00*a04);
  a09=arg[0][0];
  a12=hybrid_cos(a09);
  a13=(a05*a12);
  a11=(a12*a11);
  a09=hybrid_sin(a09);
  a10=hybrid_sin(a10);
  a09=(a09*a10);
  a11=(a11-a09);
  a09=(a07*a11);
  a13=(a13+a09);
  a13=(a06*a13);
  a01=(a01+a13);
  a00=(a00*a02);
  a00=(a00*a03);
  a00=(a00*a12);
  a01=(a01+a00);
  a00=(a05*a04);
  a00=(a00*a07);
  a12=arg[1][1];
  a03=casadi_sq(a12);
  a03=(a00*a03);
  a03=(a03*a10);
  a01=(a01-a03);
  a03=-2.;
  a03=(a03*a05);
  a03=(a03*a04);
  a03=(a03*a07);
  a03=(a03*a08);
  a03=(a03*a12);
  a03=(a03*a10);
  a01=(a01+a03);
  res[1][0]=a01;
  a01=arg[2][9];
  a01=(a01*a12);
  a06=(a06*a07);
  a06=(a06*a11);
  a01=(a01+a06);
  a08=casadi_sq(a08);
  a00=(a00*a08);
  a00=(a00*a10);
  a01=(a01+a00);
  res[1][1]=a01;
  return 0;
}

static int casadi_f2(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  (void)arg; (void)iw; (void)mem; (void)w;
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  casadi_real a24, a25, a26, a27, a28;
  a00=arg[2][1];
  a01=arg[2][0];
  a02=arg[0][0];
  a03=hybrid_cos(a02);
  a04=(a01*a03);
  a05=arg[0][1];
  a06=hybrid_cos(a05);
  a07=(a03*a06);
  a02=hybrid_sin(a02);
  a05=hybrid_sin(a05);
  a08=(a02*a05);
  a07=(a07-a08);
  a08=(a00*a07);
  a09=(a04+a08);
  a10=(a00*a09);
  a11=(a03*a05);
  a12=(a06*a02);
  a11=(a11+a12);
  a10=(a10*a11);
  a02=(a01*a02);
  a12=(a00*a11);
  a02=(a02+a12);
  a08=(a08*a02);
  a10=(a10-a08);
  a08=(a00/a10);
  a12=(a08*a07);
  a13=arg[2][6];
  a14=arg[2][7];
  a13=(a13+a14);
  a15=arg[2][2];
  a16=arg[2][4];
  a17=casadi_sq(a16);
  a17=(a15*a17);
  a13=(a13+a17);
  a17=arg[2][3];
  a18=casadi_sq(a01);
  a19=arg[2][5];
  a20=casadi_sq(a19);
  a18=(a18+a20);
  a21=(2.*a01);
  a21=(a21*a19);
  a21=(a21*a06);
  a18=(a18+a21);
  a18=(a17*a18);
  a13=(a13+a18);
  a18=(a12*a13);
  a21=(a01*a19);
  a21=(a21*a06);
  a21=(a20+a21);
  a21=(a17*a21);
  a21=(a14+a21);
  a06=(a21/a10);
  a22=(a06*a09);
  a18=(a18-a22);
  a22=(a12*a18);
  a23=(a09/a10);
  a21=(a08*a21);
  a24=(a21*a07);
  a20=(a17*a20);
  a14=(a14+a20);
  a14=(a14/a10);
  a20=(a14*a09);
  a24=(a24-a20);
  a20=(a23*a24);
  a22=(a22-a20);
  res[0][0]=a22;
  a08=(a08*a11);
  a18=(a08*a18);
  a10=(a02/a10);
  a24=(a10*a24);
  a18=(a18-a24);
  res[0][1]=a18;
  a13=(a08*a13);
  a06=(a06*a02);
  a13=(a13-a06);
  a06=(a12*a13);
  a21=(a21*a11);
  a14=(a14*a02);
  a21=(a21-a14);
  a14=(a23*a21);
  a06=(a06-a14);
  res[0][2]=a06;
  a13=(a08*a13);
  a21=(a10*a21);
  a13=(a13-a21);
  res[0][3]=a13;
  a21=arg[1][0];
  a14=(a21*a09);
  a24=arg[1][1];
  a20=(a00*a24);
  a25=(a20*a07);
  a14=(a14+a25);
  a14=(a21*a14);
  a26=(a00*a21);
  a27=(a26*a07);
  a27=(a27+a25);
  a27=(a24*a27);
  a14=(a14+a27);
  a22=(a14*a22);
  a27=(a21*a02);
  a20=(a20*a11);
  a27=(a27+a20);
  a27=(a21*a27);
  a26=(a26*a11);
  a26=(a26+a20);
  a26=(a24*a26);
  a27=(a27+a26);
  a18=(a27*a18);
  a22=(a22+a18);
  a18=arg[2][9];
  a18=(a18*a24);
  a26=arg[2][10];
  a20=(a26*a17);
  a25=(a20*a19);
  a25=(a25*a07);
  a18=(a18+a25);
  a25=(a01*a17);
  a25=(a25*a19);
  a28=casadi_sq(a21);
  a28=(a25*a28);
  a28=(a28*a05);
  a18=(a18+a28);
  a23=(a23*a18);
  a22=(a22-a23);
  a23=arg[2][8];
  a23=(a23*a21);
  a28=(a19*a07);
  a04=(a04+a28);
  a20=(a20*a04);
  a23=(a23+a20);
  a26=(a26*a15);
  a26=(a26*a16);
  a26=(a26*a03);
  a23=(a23+a26);
  a26=casadi_sq(a24);
  a25=(a25*a26);
  a25=(a25*a05);
  a23=(a23-a25);
  a25=-2.;
  a25=(a25*a01);
  a25=(a25*a17);
  a25=(a25*a19);
  a25=(a25*a21);
  a25=(a25*a24);
  a25=(a25*a05);
  a23=(a23+a25);
  a12=(a12*a23);
  a22=(a22+a12);
  res[1][0]=a22;
  a14=(a14*a06);
  a27=(a27*a13);
  a14=(a14+a27);
  a10=(a10*a18);
  a14=(a14-a10);
  a08=(a08*a23);
  a14=(a14+a08);
  res[1][1]=a14;
  a14=(2.*a00);
  a08=(a14*a09);
  a08=(a08*a11);
  a14=(a14*a07);
  a14=(a14*a02);
  a08=(a08-a14);
  a09=casadi_sq(a09);
  a02=casadi_sq(a02);
  a09=(a09+a02);
  a00=casadi_sq(a00);
  a07=casadi_sq(a07);
  a07=(a00*a07);
  a09=(a09+a07);
  a11=casadi_sq(a11);
  a00=(a00*a11);
  a09=(a09+a00);
  a08=(a08/a09);
  res[2][0]=a08;
  return 0;
}

static int casadi_f3(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  (void)arg; (void)iw; (void)mem; (void)w;
  casadi_real a0, a1, a2, a3;
  a0=arg[2][3];
  a1=arg[2][2];
  a2=casadi_sq(a1);
  a3=casadi_sq(a0);
  a2=(a2+a3);
  a2=sqrt(a2);
  a0=(a0/a2);
  a3=(-a0);
  res[0][0]=a3;
  a1=(a1/a2);
  res[0][1]=a1;
  res[0][2]=a1;
  res[0][3]=a0;
  a0=0.;
  res[1][0]=a0;
  res[1][1]=a0;
  res[1][2]=a0;
  res[1][3]=a0;
  return 0;
}

static int casadi_f4(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  (void)arg; (void)iw; (void)mem; (void)w;
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  casadi_real a24, a25, a26, a27, a28, a29, a30, a31;
  a00=arg[4][1];
  a01=arg[4][0];
  a02=arg[0][0];
  a03=hybrid_cos(a02);
  a04=(a01*a03);
  a05=arg[0][1];
  a06=hybrid_cos(a05);
  a07=(a03*a06);
  a02=hybrid_sin(a02);
  a05=hybrid_sin(a05);
  a08=(a02*a05);
  a07=(a07-a08);
  a08=(a00*a07);
  a09=(a04+a08);
  a10=(a00*a09);
  a11=(a03*a05);
  a12=(a06*a02);
  a11=(a11+a12);
  a10=(a10*a11);
  a02=(a01*a02);
  a12=(a00*a11);
  a02=(a02+a12);
  a08=(a08*a02);
  a10=(a10-a08);
  a08=(a00/a10);
  a12=(a08*a07);
  a13=arg[4][8];
  a14=arg[1][0];
  a13=(a13*a14);
  a15=arg[4][7];
  a16=arg[4][3];
  a17=arg[4][5];
  a18=casadi_sq(a17);
  a19=(a01*a17);
  a19=(a19*a06);
  a19=(a18+a19);
  a19=(a16*a19);
  a19=(a15+a19);
  a20=(a09/a10);
  a21=(a14*a09);
  a22=arg[1][1];
  a23=(a00*a22);
  a24=(a23*a07);
  a21=(a21+a24);
  a21=(a14*a21);
  a25=(a00*a14);
  a26=(a25*a07);
  a26=(a26+a24);
  a26=(a22*a26);
  a21=(a21+a26);
  a26=arg[2][1];
  a24=arg[5][2];
  a27=(a26*a24);
  a28=casadi_sq(a24);
  a29=arg[5][3];
  a30=casadi_sq(a29);
  a28=(a28+a30);
  a28=sqrt(a28);
  a27=(a27/a28);
  a21=(a21+a27);
  a27=arg[2][0];
  a30=(a27*a29);
  a30=(a30/a28);
  a21=(a21-a30);
  a30=(a20*a21);
  a10=(a02/a10);
  a31=(a14*a02);
  a23=(a23*a11);
  a31=(a31+a23);
  a31=(a14*a31);
  a25=(a25*a11);
  a25=(a25+a23);
  a25=(a22*a25);
  a31=(a31+a25);
  a27=(a27*a24);
  a27=(a27/a28);
  a31=(a31+a27);
  a26=(a26*a29);
  a26=(a26/a28);
  a31=(a31+a26);
  a26=(a10*a31);
  a30=(a30+a26);
  a26=(a19*a30);
  a13=(a13-a26);
  a21=(a12*a21);
  a08=(a08*a11);
  a31=(a08*a31);
  a21=(a21+a31);
  a31=arg[4][6];
  a31=(a31+a15);
  a26=arg[4][2];
  a28=arg[4][4];
  a29=casadi_sq(a28);
  a29=(a26*a29);
  a31=(a31+a29);
  a29=casadi_sq(a01);
  a29=(a29+a18);
  a27=(2.*a01);
  a27=(a27*a17);
  a27=(a27*a06);
  a29=(a29+a27);
  a29=(a16*a29);
  a31=(a31+a29);
  a31=(a21*a31);
  a13=(a13+a31);
  a31=arg[3][0];
  a29=(a31*a02);
  a13=(a13+a29);
  a29=arg[3][1];
  a27=(a29*a09);
  a13=(a13-a27);
  a27=arg[4][10];
  a06=(a27*a16);
  a24=(a17*a07);
  a04=(a04+a24);
  a04=(a06*a04);
  a13=(a13+a04);
  a27=(a27*a26);
  a27=(a27*a28);
  a27=(a27*a03);
  a13=(a13+a27);
  a27=(a01*a16);
  a27=(a27*a17);
  a03=casadi_sq(a22);
  a03=(a27*a03);
  a03=(a03*a05);
  a13=(a13-a03);
  a03=-2.;
  a03=(a03*a01);
  a03=(a03*a16);
  a03=(a03*a17);
  a03=(a03*a14);
  a03=(a03*a22);
  a03=(a03*a05);
  a13=(a13+a03);
  a12=(a12*a13);
  a03=arg[4][9];
  a03=(a03*a22);
  a16=(a16*a18);
  a15=(a15+a16);
  a15=(a15*a30);
  a03=(a03-a15);
  a19=(a19*a21);
  a03=(a03+a19);
  a31=(a31*a00);
  a31=(a31*a11);
  a03=(a03+a31);
  a29=(a29*a00);
  a29=(a29*a07);
  a03=(a03-a29);
  a06=(a06*a17);
  a06=(a06*a07);
  a03=(a03+a06);
  a14=casadi_sq(a14);
  a27=(a27*a14);
  a27=(a27*a05);
  a03=(a03+a27);
  a20=(a20*a03);
  a12=(a12-a20);
  res[0][0]=a12;
  a08=(a08*a13);
  a10=(a10*a03);
  a08=(a08-a10);
  res[0][1]=a08;
  res[1][0]=a13;
  res[1][1]=a03;
  a03=(2.*a00);
  a13=(a03*a09);
  a13=(a13*a11);
  a03=(a03*a07);
  a03=(a03*a02);
  a13=(a13-a03);
  a09=casadi_sq(a09);
  a02=casadi_sq(a02);
  a09=(a09+a02);
  a00=casadi_sq(a00);
  a07=casadi_sq(a07);
  a07=(a00*a07);
  a09=(a09+a07);
  a11=casadi_sq(a11);
  a00=(a00*a11);
  a09=(a09+a00);
  a13=(a13/a09);
  res[2][0]=a13;
  return 0;
}

static int casadi_f5(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  (void)arg; (void)iw; (void)mem; (void)w;
  casadi_real a0, a1, a2, a3, a4, a5, a6, a7, a8;
  a0=arg[3][0];
  a1=arg[0][0];
  a2=hybrid_cos(a1);
  a3=(a0*a2);
  a4=arg[3][1];
  a5=arg[0][1];
  a6=hybrid_cos(a5);
  a7=(a2*a6);
  a1=hybrid_sin(a1);
  a5=hybrid_sin(a5);
  a8=(a1*a5);
  a7=(a7-a8);
  a8=(a4*a7);
  a3=(a3+a8);
  res[0][0]=a3;
  a0=(a0*a1);
  a2=(a2*a5);
  a6=(a6*a1);
  a2=(a2+a6);
  a6=(a4*a2);
  a0=(a0+a6);
  res[0][1]=a0;
  a6=arg[1][0];
  a0=(a6*a0);
  a1=arg[1][1];
  a4=(a4*a1);
  a2=(a4*a2);
  a0=(a0+a2);
  a2=(-a0);
  res[1][0]=a2;
  a6=(a6*a3);
  a4=(a4*a7);
  a6=(a6+a4);
  res[1][1]=a6;
  a4=arg[4][2];
  a7=casadi_sq(a4);
  a3=arg[4][3];
  a2=casadi_sq(a3);
  a7=(a7+a2);
  a7=sqrt(a7);
  a2=(a4/a7);
  a1=(a2*a6);
  a5=(a3/a7);
  a8=(a5*a0);
  a1=(a1+a8);
  res[2][0]=a1;
  a5=(a5*a6);
  a2=(a2*a0);
  a5=(a5-a2);
  res[2][1]=a5;
  a5=arg[2][1];
  a2=(a5*a4);
  a2=(a2/a7);
  a0=arg[2][0];
  a6=(a0*a3);
  a6=(a6/a7);
  a2=(a2-a6);
  res[3][0]=a2;
  a0=(a0*a4);
  a0=(a0/a7);
  a5=(a5*a3);
  a5=(a5/a7);
  a0=(a0+a5);
  res[3][1]=a0;
  return 0;
}

static int casadi_f6(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  (void)arg; (void)iw; (void)mem; (void)w;
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  casadi_real a24, a25, a26, a27, a28, a29, a30;
  a00=arg[0][2];
  res[0][0]=a00;
  a01=arg[0][3];
  res[0][1]=a01;
  a02=arg[2][7];
  a03=arg[2][3];
  a04=arg[2][5];
  a05=casadi_sq(a04);
  a06=(a03*a05);
  a06=(a02+a06);
  a07=arg[2][6];
  a07=(a07+a02);
  a08=arg[2][2];
  a09=arg[2][4];
  a10=casadi_sq(a09);
  a10=(a08*a10);
  a07=(a07+a10);
  a10=arg[2][0];
  a11=casadi_sq(a10);
  a11=(a11+a05);
  a12=(2.*a10);
  a13=(a12*a04);
  a14=arg[0][1];
  a15=hybrid_cos(a14);
  a13=(a13*a15);
  a11=(a11+a13);
  a11=(a03*a11);
  a07=(a07+a11);
  a11=(a06*a07);
  a13=(a10*a04);
  a13=(a13*a15);
  a05=(a05+a13);
  a05=(a03*a05);
  a02=(a02+a05);
  a05=casadi_sq(a02);
  a11=(a11-a05);
  a06=(a06/a11);
  a05=arg[1][0];
  a13=arg[0][0];
  a16=hybrid_cos(a13);
  a17=(a10*a16);
  a18=arg[2][1];
  a19=(a16*a15);
  a13=hybrid_sin(a13);
  a14=hybrid_sin(a14);
  a20=(a13*a14);
  a19=(a19-a20);
  a20=(a18*a19);
  a21=(a17+a20);
  a22=arg[3][1];
  a23=arg[0][5];
  a24=(a10*a13);
  a25=(a23-a24);
  a26=(a16*a14);
  a15=(a15*a13);
  a26=(a26+a15);
  a15=(a18*a26);
  a25=(a25-a15);
  a25=(a22*a25);
  a13=arg[3][2];
  a27=arg[0][7];
  a28=(a00*a21);
  a28=(a27-a28);
  a29=(a18*a01);
  a30=(a29*a19);
  a28=(a28-a30);
  a28=(a13*a28);
  a25=(a25+a28);
  a21=(a21*a25);
  a05=(a05+a21);
  a21=arg[0][4];
  a28=(a21-a17);
  a28=(a28-a20);
  a22=(a22*a28);
  a28=arg[0][6];
  a24=(a24+a15);
  a15=(a00*a24);
  a15=(a28+a15);
  a29=(a29*a26);
  a15=(a15+a29);
  a13=(a13*a15);
  a22=(a22+a13);
  a24=(a22*a24);
  a05=(a05-a24);
  a24=arg[2][8];
  a24=(a24*a00);
  a05=(a05-a24);
  a24=arg[2][10];
  a13=(a24*a03);
  a15=(a04*a19);
  a17=(a17+a15);
  a17=(a13*a17);
  a05=(a05-a17);
  a24=(a24*a08);
  a24=(a24*a09);
  a24=(a24*a16);
  a05=(a05-a24);
  a10=(a10*a03);
  a10=(a10*a04);
  a24=casadi_sq(a01);
  a24=(a10*a24);
  a24=(a24*a14);
  a05=(a05+a24);
  a12=(a12*a03);
  a12=(a12*a04);
  a12=(a12*a00);
  a12=(a12*a01);
  a12=(a12*a14);
  a05=(a05+a12);
  a06=(a06*a05);
  a02=(a02/a11);
  a12=arg[1][1];
  a03=arg[2][9];
  a03=(a03*a01);
  a12=(a12-a03);
  a03=(a18*a25);
  a03=(a03*a19);
  a12=(a12+a03);
  a18=(a18*a22);
  a18=(a18*a26);
  a12=(a12-a18);
  a13=(a13*a04);
  a13=(a13*a19);
  a12=(a12-a13);
  a00=casadi_sq(a00);
  a10=(a10*a00);
  a10=(a10*a14);
  a12=(a12-a10);
  a10=(a02*a12);
  a06=(a06-a10);
  res[0][2]=a06;
  a07=(a07/a11);
  a07=(a07*a12);
  a02=(a02*a05);
  a07=(a07-a02);
  res[0][3]=a07;
  res[0][4]=a28;
  res[0][5]=a27;
  a07=arg[4][2];
  a02=casadi_sq(a07);
  a05=arg[4][3];
  a12=casadi_sq(a05);
  a02=(a02+a12);
  a02=sqrt(a02);
  a12=(a07/a02);
  a11=arg[4][0];
  a21=(a21-a11);
  a21=(a12*a21);
  a11=(a05/a02);
  a06=arg[4][1];
  a23=(a23-a06);
  a23=(a11*a23);
  a21=(a21+a23);
  a23=0.;
  a06=(a21<a23);
  a10=arg[3][3];
  a10=(a10*a21);
  a21=arg[3][4];
  a14=(a07*a28);
  a14=(a14/a02);
  a00=(a05*a27);
  a00=(a00/a02);
  a14=(a14+a00);
  a21=(a21*a14);
  a10=(a10+a21);
  a10=(-a10);
  a23=casadi_fmax(a23,a10);
  a12=(a12*a23);
  a12=(a06?a12:0);
  a12=(a12-a22);
  a22=arg[3][5];
  a10=(a22*a05);
  a10=(a10/a02);
  a10=(a10*a23);
  a27=(a07*a27);
  a27=(a27/a02);
  a05=(a05*a28);
  a05=(a05/a02);
  a27=(a27-a05);
  a05=arg[3][6];
  a27=(a27/a05);
  a27=tanh(a27);
  a10=(a10*a27);
  a10=(a06?a10:0);
  a12=(a12+a10);
  a10=arg[3][0];
  a12=(a12/a10);
  res[0][6]=a12;
  a11=(a11*a23);
  a11=(a06?a11:0);
  a11=(a11-a25);
  a22=(a22*a07);
  a22=(a22/a02);
  a22=(a22*a23);
  a22=(a22*a27);
  a22=(-a22);
  a06=(a06?a22:0);
  a11=(a11+a06);
  a11=(a11/a10);
  res[0][7]=a11;
  return 0;
}

static int casadi_f7(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  (void)arg; (void)iw; (void)mem; (void)w;
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16;
  a00=arg[1][0];
  a01=arg[0][0];
  a02=hybrid_cos(a01);
  a03=(a00*a02);
  a04=arg[1][1];
  a05=arg[0][1];
  a06=hybrid_cos(a05);
  a07=(a02*a06);
  a01=hybrid_sin(a01);
  a05=hybrid_sin(a05);
  a08=(a01*a05);
  a07=(a07-a08);
  a08=(a04*a07);
  a09=(a03+a08);
  res[0][0]=a09;
  a00=(a00*a01);
  a02=(a02*a05);
  a06=(a06*a01);
  a02=(a02+a06);
  a06=(a04*a02);
  a01=(a00+a06);
  res[0][1]=a01;
  a05=arg[3][2];
  a10=casadi_sq(a05);
  a11=arg[3][3];
  a12=casadi_sq(a11);
  a10=(a10+a12);
  a10=sqrt(a10);
  a12=(a05/a10);
  a13=arg[0][2];
  a09=(a13*a09);
  a14=arg[0][3];
  a04=(a04*a14);
  a07=(a04*a07);
  a14=(a09+a07);
  a15=(a12*a14);
  a16=(a11/a10);
  a13=(a13*a01);
  a04=(a04*a02);
  a02=(a13+a04);
  a01=(a16*a02);
  a15=(a15+a01);
  res[0][2]=a15;
  a14=(a16*a14);
  a02=(a12*a02);
  a14=(a14-a02);
  res[0][3]=a14;
  a14=arg[2][1];
  a02=arg[0][4];
  a03=(a02-a03);
  a03=(a03-a08);
  a03=(a14*a03);
  a08=arg[2][2];
  a15=arg[0][6];
  a13=(a15+a13);
  a13=(a13+a04);
  a13=(a08*a13);
  a03=(a03+a13);
  res[0][4]=a03;
  a13=arg[0][5];
  a00=(a13-a00);
  a00=(a00-a06);
  a14=(a14*a00);
  a00=arg[0][7];
  a09=(a00-a09);
  a09=(a09-a07);
  a08=(a08*a09);
  a14=(a14+a08);
  res[0][5]=a14;
  a08=(a12*a14);
  a09=(a16*a03);
  a08=(a08-a09);
  res[0][6]=a08;
  a03=(a12*a03);
  a14=(a16*a14);
  a03=(a03+a14);
  res[0][7]=a03;
  res[0][8]=a02;
  res[0][9]=a13;
  a03=arg[3][0];
  a02=(a02-a03);
  a12=(a12*a02);
  a02=arg[3][1];
  a13=(a13-a02);
  a16=(a16*a13);
  a12=(a12+a16);
  a16=(-a12);
  res[0][10]=a16;
  a16=0.;
  a13=(a12<a16);
  a02=arg[2][3];
  a02=(a02*a12);
  a12=arg[2][4];
  a03=(a05*a15);
  a03=(a03/a10);
  a14=(a11*a00);
  a14=(a14/a10);
  a03=(a03+a14);
  a12=(a12*a03);
  a02=(a02+a12);
  a02=(-a02);
  a16=casadi_fmax(a16,a02);
  a02=(a13?a16:0);
  res[0][11]=a02;
  a02=arg[2][5];
  a02=(a02*a16);
  a05=(a05*a00);
  a05=(a05/a10);
  a11=(a11*a15);
  a11=(a11/a10);
  a05=(a05-a11);
  a11=arg[2][6];
  a11=(a05/a11);
  a11=tanh(a11);
  a02=(a02*a11);
  a02=(-a02);
  a13=(a13?a02:0);
  res[0][12]=a13;
  res[0][13]=a05;
  return 0;
}

static int casadi_f8(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  (void)arg; (void)iw; (void)mem; (void)w;
  casadi_real a0, a1, a2, a3, a4, a5, a6, a7;
  a0=arg[0][1];
  a1=arg[2][1];
  a0=(a0-a1);
  a1=arg[0][0];
  a2=arg[2][0];
  a1=(a1-a2);
  a2=casadi_sq(a1);
  a3=casadi_sq(a0);
  a2=(a2+a3);
  a2=sqrt(a2);
  a3=(a0/a2);
  a4=(-a3);
  res[0][0]=a4;
  a4=(a1/a2);
  res[0][1]=a4;
  res[0][2]=a4;
  res[0][3]=a3;
  a5=arg[1][1];
  a6=arg[1][0];
  a7=(a6/a2);
  a7=(a7*a1);
  a1=(a5/a2);
  a1=(a1*a0);
  a7=(a7+a1);
  a3=(a3*a7);
  a5=(a5-a3);
  a5=(a5/a2);
  a3=(-a5);
  res[1][0]=a3;
  a4=(a4*a7);
  a6=(a6-a4);
  a6=(a6/a2);
  res[1][1]=a6;
  res[1][2]=a6;
  res[1][3]=a5;
  return 0;
}

static int casadi_f9(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  (void)arg; (void)iw; (void)mem; (void)w;
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  casadi_real a24, a25, a26, a27, a28, a29, a30, a31, a32, a33, a34;
  a00=arg[4][1];
  a01=arg[4][0];
  a02=arg[0][0];
  a03=hybrid_cos(a02);
  a04=(a01*a03);
  a05=arg[0][1];
  a06=hybrid_cos(a05);
  a07=(a03*a06);
  a02=hybrid_sin(a02);
  a05=hybrid_sin(a05);
  a08=(a02*a05);
  a07=(a07-a08);
  a08=(a00*a07);
  a09=(a04+a08);
  a10=(a00*a09);
  a11=(a03*a05);
  a12=(a06*a02);
  a11=(a11+a12);
  a10=(a10*a11);
  a02=(a01*a02);
  a12=(a00*a11);
  a13=(a02+a12);
  a14=(a08*a13);
  a10=(a10-a14);
  a14=(a00/a10);
  a15=(a14*a07);
  a16=arg[4][8];
  a17=arg[1][0];
  a16=(a16*a17);
  a18=arg[4][7];
  a19=arg[4][3];
  a20=arg[4][5];
  a21=casadi_sq(a20);
  a22=(a01*a20);
  a22=(a22*a06);
  a22=(a21+a22);
  a22=(a19*a22);
  a22=(a18+a22);
  a23=(a09/a10);
  a24=(a17*a09);
  a25=arg[1][1];
  a26=(a00*a25);
  a27=(a26*a07);
  a24=(a24+a27);
  a28=(a17*a24);
  a29=(a00*a17);
  a30=(a29*a07);
  a30=(a30+a27);
  a30=(a25*a30);
  a28=(a28+a30);
  a30=arg[2][1];
  a27=arg[6][0];
  a31=arg[5][0];
  a31=(a04-a31);
  a31=(a31+a08);
  a08=casadi_sq(a31);
  a32=arg[5][1];
  a02=(a02-a32);
  a02=(a02+a12);
  a12=casadi_sq(a02);
  a08=(a08+a12);
  a08=sqrt(a08);
  a27=(a27/a08);
  a12=(a27*a24);
  a32=(a24/a08);
  a32=(a32*a02);
  a33=(a17*a13);
  a26=(a26*a11);
  a33=(a33+a26);
  a34=(a33/a08);
  a34=(a34*a31);
  a32=(a32-a34);
  a32=(a32/a08);
  a34=(a32*a02);
  a24=(a24-a34);
  a34=(a12*a24);
  a30=(a30-a34);
  a27=(a27*a33);
  a32=(a32*a31);
  a32=(a33+a32);
  a34=(a27*a32);
  a30=(a30-a34);
  a30=(a30/a08);
  a34=(a30*a31);
  a28=(a28+a34);
  a34=arg[2][0];
  a27=(a27*a24);
  a34=(a34-a27);
  a12=(a12*a32);
  a34=(a34+a12);
  a34=(a34/a08);
  a08=(a34*a02);
  a28=(a28-a08);
  a08=(a23*a28);
  a10=(a13/a10);
  a33=(a17*a33);
  a29=(a29*a11);
  a29=(a29+a26);
  a29=(a25*a29);
  a33=(a33+a29);
  a34=(a34*a31);
  a33=(a33+a34);
  a30=(a30*a02);
  a33=(a33+a30);
  a30=(a10*a33);
  a08=(a08+a30);
  a30=(a22*a08);
  a16=(a16-a30);
  a28=(a15*a28);
  a14=(a14*a11);
  a33=(a14*a33);
  a28=(a28+a33);
  a33=arg[4][6];
  a33=(a33+a18);
  a30=arg[4][2];
  a02=arg[4][4];
  a34=casadi_sq(a02);
  a34=(a30*a34);
  a33=(a33+a34);
  a34=casadi_sq(a01);
  a34=(a34+a21);
  a31=(2.*a01);
  a31=(a31*a20);
  a31=(a31*a06);
  a34=(a34+a31);
  a34=(a19*a34);
  a33=(a33+a34);
  a33=(a28*a33);
  a16=(a16+a33);
  a33=arg[3][0];
  a34=(a33*a13);
  a16=(a16+a34);
  a34=arg[3][1];
  a31=(a34*a09);
  a16=(a16-a31);
  a31=arg[4][10];
  a06=(a31*a19);
  a29=(a20*a07);
  a04=(a04+a29);
  a04=(a06*a04);
  a16=(a16+a04);
  a31=(a31*a30);
  a31=(a31*a02);
  a31=(a31*a03);
  a16=(a16+a31);
  a31=(a01*a19);
  a31=(a31*a20);
  a03=casadi_sq(a25);
  a03=(a31*a03);
  a03=(a03*a05);
  a16=(a16-a03);
  a03=-2.;
  a03=(a03*a01);
  a03=(a03*a19);
  a03=(a03*a20);
  a03=(a03*a17);
  a03=(a03*a25);
  a03=(a03*a05);
  a16=(a16+a03);
  a15=(a15*a16);
  a03=arg[4][9];
  a03=(a03*a25);
  a19=(a19*a21);
  a18=(a18+a19);
  a18=(a18*a08);
  a03=(a03-a18);
  a22=(a22*a28);
  a03=(a03+a22);
  a33=(a33*a00);
  a33=(a33*a11);
  a03=(a03+a33);
  a34=(a34*a00);
  a34=(a34*a07);
  a03=(a03-a34);
  a06=(a06*a20);
  a06=(a06*a07);
  a03=(a03+a06);
  a17=casadi_sq(a17);
  a31=(a31*a17);
  a31=(a31*a05);
  a03=(a03+a31);
  a23=(a23*a03);
  a15=(a15-a23);
  res[0][0]=a15;
  a14=(a14*a16);
  a10=(a10*a03);
  a14=(a14-a10);
  res[0][1]=a14;
  res[1][0]=a16;
  res[1][1]=a03;
  a03=(2.*a00);
  a16=(a03*a09);
  a16=(a16*a11);
  a03=(a03*a07);
  a03=(a03*a13);
  a16=(a16-a03);
  a09=casadi_sq(a09);
  a13=casadi_sq(a13);
  a09=(a09+a13);
  a00=casadi_sq(a00);
  a07=casadi_sq(a07);
  a07=(a00*a07);
  a09=(a09+a07);
  a11=casadi_sq(a11);
  a00=(a00*a11);
  a09=(a09+a00);
  a16=(a16/a09);
  res[2][0]=a16;
  return 0;
}

static int casadi_f10(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  (void)arg; (void)iw; (void)mem; (void)w;
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10;
  a00=arg[3][0];
  a01=arg[0][0];
  a02=hybrid_cos(a01);
  a03=(a00*a02);
  a04=arg[3][1];
  a05=arg[0][1];
  a06=hybrid_cos(a05);
  a07=(a02*a06);
  a01=hybrid_sin(a01);
  a05=hybrid_sin(a05);
  a08=(a01*a05);
  a07=(a07-a08);
  a08=(a04*a07);
  a09=(a03+a08);
  res[0][0]=a09;
  a00=(a00*a01);
  a02=(a02*a05);
  a06=(a06*a01);
  a02=(a02+a06);
  a06=(a04*a02);
  a01=(a00+a06);
  res[0][1]=a01;
  a05=arg[1][0];
  a01=(a05*a01);
  a10=arg[1][1];
  a04=(a04*a10);
  a02=(a04*a02);
  a01=(a01+a02);
  a02=(-a01);
  res[1][0]=a02;
  a05=(a05*a09);
  a04=(a04*a07);
  a05=(a05+a04);
  res[1][1]=a05;
  a04=arg[4][0];
  a03=(a03-a04);
  a03=(a03+a08);
  a08=casadi_sq(a03);
  a04=arg[4][1];
  a00=(a00-a04);
  a00=(a00+a06);
  a06=casadi_sq(a00);
  a08=(a08+a06);
  a08=sqrt(a08);
  a05=(a05/a08);
  a06=(a05*a03);
  a01=(a01/a08);
  a04=(a01*a00);
  a06=(a06+a04);
  res[2][0]=a06;
  a05=(a05*a00);
  a01=(a01*a03);
  a05=(a05-a01);
  res[2][1]=a05;
  a05=arg[2][1];
  a05=(a05/a08);
  a01=(a05*a03);
  a06=arg[2][0];
  a06=(a06/a08);
  a08=(a06*a00);
  a01=(a01-a08);
  res[3][0]=a01;
  a06=(a06*a03);
  a05=(a05*a00);
  a06=(a06+a05);
  res[3][1]=a06;
  return 0;
}

static int casadi_f11(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  (void)arg; (void)iw; (void)mem; (void)w;
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  casadi_real a24, a25, a26, a27, a28, a29, a30;
  a00=arg[0][2];
  res[0][0]=a00;
  a01=arg[0][3];
  res[0][1]=a01;
  a02=arg[2][7];
  a03=arg[2][3];
  a04=arg[2][5];
  a05=casadi_sq(a04);
  a06=(a03*a05);
  a06=(a02+a06);
  a07=arg[2][6];
  a07=(a07+a02);
  a08=arg[2][2];
  a09=arg[2][4];
  a10=casadi_sq(a09);
  a10=(a08*a10);
  a07=(a07+a10);
  a10=arg[2][0];
  a11=casadi_sq(a10);
  a11=(a11+a05);
  a12=(2.*a10);
  a13=(a12*a04);
  a14=arg[0][1];
  a15=hybrid_cos(a14);
  a13=(a13*a15);
  a11=(a11+a13);
  a11=(a03*a11);
  a07=(a07+a11);
  a11=(a06*a07);
  a13=(a10*a04);
  a13=(a13*a15);
  a05=(a05+a13);
  a05=(a03*a05);
  a02=(a02+a05);
  a05=casadi_sq(a02);
  a11=(a11-a05);
  a06=(a06/a11);
  a05=arg[1][0];
  a13=arg[0][0];
  a16=hybrid_cos(a13);
  a17=(a10*a16);
  a18=arg[2][1];
  a19=(a16*a15);
  a13=hybrid_sin(a13);
  a14=hybrid_sin(a14);
  a20=(a13*a14);
  a19=(a19-a20);
  a20=(a18*a19);
  a21=(a17+a20);
  a22=arg[3][1];
  a23=arg[0][5];
  a24=(a10*a13);
  a25=(a23-a24);
  a26=(a16*a14);
  a15=(a15*a13);
  a26=(a26+a15);
  a15=(a18*a26);
  a25=(a25-a15);
  a25=(a22*a25);
  a13=arg[3][2];
  a27=arg[0][7];
  a28=(a00*a21);
  a28=(a27-a28);
  a29=(a18*a01);
  a30=(a29*a19);
  a28=(a28-a30);
  a28=(a13*a28);
  a25=(a25+a28);
  a21=(a21*a25);
  a05=(a05+a21);
  a21=arg[0][4];
  a28=(a21-a17);
  a28=(a28-a20);
  a22=(a22*a28);
  a28=arg[0][6];
  a24=(a24+a15);
  a15=(a00*a24);
  a15=(a28+a15);
  a29=(a29*a26);
  a15=(a15+a29);
  a13=(a13*a15);
  a22=(a22+a13);
  a24=(a22*a24);
  a05=(a05-a24);
  a24=arg[2][8];
  a24=(a24*a00);
  a05=(a05-a24);
  a24=arg[2][10];
  a13=(a24*a03);
  a15=(a04*a19);
  a17=(a17+a15);
  a17=(a13*a17);
  a05=(a05-a17);
  a24=(a24*a08);
  a24=(a24*a09);
  a24=(a24*a16);
  a05=(a05-a24);
  a10=(a10*a03);
  a10=(a10*a04);
  a24=casadi_sq(a01);
  a24=(a10*a24);
  a24=(a24*a14);
  a05=(a05+a24);
  a12=(a12*a03);
  a12=(a12*a04);
  a12=(a12*a00);
  a12=(a12*a01);
  a12=(a12*a14);
  a05=(a05+a12);
  a06=(a06*a05);
  a02=(a02/a11);
  a12=arg[1][1];
  a03=arg[2][9];
  a03=(a03*a01);
  a12=(a12-a03);
  a03=(a18*a25);
  a03=(a03*a19);
  a12=(a12+a03);
  a18=(a18*a22);
  a18=(a18*a26);
  a12=(a12-a18);
  a13=(a13*a04);
  a13=(a13*a19);
  a12=(a12-a13);
  a00=casadi_sq(a00);
  a10=(a10*a00);
  a10=(a10*a14);
  a12=(a12-a10);
  a10=(a02*a12);
  a06=(a06-a10);
  res[0][2]=a06;
  a07=(a07/a11);
  a07=(a07*a12);
  a02=(a02*a05);
  a07=(a07-a02);
  res[0][3]=a07;
  res[0][4]=a28;
  res[0][5]=a27;
  a07=0.;
  a02=arg[4][2];
  a05=arg[4][0];
  a21=(a21-a05);
  a05=casadi_sq(a21);
  a12=arg[4][1];
  a23=(a23-a12);
  a12=casadi_sq(a23);
  a05=(a05+a12);
  a05=sqrt(a05);
  a02=(a02-a05);
  a12=(a07<a02);
  a11=(a21/a05);
  a06=arg[3][3];
  a06=(a06*a02);
  a02=arg[3][4];
  a28=(a28/a05);
  a10=(a28*a21);
  a27=(a27/a05);
  a14=(a27*a23);
  a10=(a10+a14);
  a02=(a02*a10);
  a06=(a06-a02);
  a07=casadi_fmax(a07,a06);
  a11=(a11*a07);
  a11=(a12?a11:0);
  a11=(a11-a22);
  a22=arg[3][5];
  a22=(a22/a05);
  a06=(a22*a23);
  a06=(a06*a07);
  a27=(a27*a21);
  a28=(a28*a23);
  a27=(a27-a28);
  a28=arg[3][6];
  a27=(a27/a28);
  a27=tanh(a27);
  a06=(a06*a27);
  a06=(a12?a06:0);
  a11=(a11+a06);
  a06=arg[3][0];
  a11=(a11/a06);
  res[0][6]=a11;
  a23=(a23/a05);
  a23=(a23*a07);
  a23=(a12?a23:0);
  a23=(a23-a25);
  a22=(a22*a21);
  a22=(a22*a07);
  a22=(a22*a27);
  a22=(-a22);
  a12=(a12?a22:0);
  a23=(a23+a12);
  a23=(a23/a06);
  res[0][7]=a23;
  return 0;
}

static int casadi_f12(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  (void)arg; (void)iw; (void)mem; (void)w;
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16;
  a00=arg[1][0];
  a01=arg[0][0];
  a02=hybrid_cos(a01);
  a03=(a00*a02);
  a04=arg[1][1];
  a05=arg[0][1];
  a06=hybrid_cos(a05);
  a07=(a02*a06);
  a01=hybrid_sin(a01);
  a05=hybrid_sin(a05);
  a08=(a01*a05);
  a07=(a07-a08);
  a08=(a04*a07);
  a09=(a03+a08);
  res[0][0]=a09;
  a00=(a00*a01);
  a02=(a02*a05);
  a06=(a06*a01);
  a02=(a02+a06);
  a06=(a04*a02);
  a01=(a00+a06);
  res[0][1]=a01;
  a05=arg[0][2];
  a09=(a05*a09);
  a10=arg[0][3];
  a04=(a04*a10);
  a07=(a04*a07);
  a10=(a09+a07);
  a11=arg[3][0];
  a12=(a03-a11);
  a12=(a12+a08);
  a13=casadi_sq(a12);
  a14=arg[3][1];
  a15=(a00-a14);
  a15=(a15+a06);
  a16=casadi_sq(a15);
  a13=(a13+a16);
  a13=sqrt(a13);
  a10=(a10/a13);
  a16=(a10*a12);
  a05=(a05*a01);
  a04=(a04*a02);
  a02=(a05+a04);
  a02=(a02/a13);
  a01=(a02*a15);
  a16=(a16+a01);
  res[0][2]=a16;
  a10=(a10*a15);
  a02=(a02*a12);
  a10=(a10-a02);
  res[0][3]=a10;
  a10=arg[2][1];
  a02=arg[0][4];
  a03=(a02-a03);
  a03=(a03-a08);
  a03=(a10*a03);
  a08=arg[2][2];
  a16=arg[0][6];
  a05=(a16+a05);
  a05=(a05+a04);
  a05=(a08*a05);
  a03=(a03+a05);
  res[0][4]=a03;
  a05=arg[0][5];
  a00=(a05-a00);
  a00=(a00-a06);
  a10=(a10*a00);
  a00=arg[0][7];
  a09=(a00-a09);
  a09=(a09-a07);
  a08=(a08*a09);
  a10=(a10+a08);
  res[0][5]=a10;
  a10=(a10/a13);
  a08=(a10*a12);
  a03=(a03/a13);
  a13=(a03*a15);
  a08=(a08-a13);
  res[0][6]=a08;
  a03=(a03*a12);
  a10=(a10*a15);
  a03=(a03+a10);
  res[0][7]=a03;
  res[0][8]=a02;
  res[0][9]=a05;
  a03=arg[3][2];
  a02=(a02-a11);
  a11=casadi_sq(a02);
  a05=(a05-a14);
  a14=casadi_sq(a05);
  a11=(a11+a14);
  a11=sqrt(a11);
  a03=(a03-a11);
  res[0][10]=a03;
  a14=0.;
  a10=(a14<a03);
  a15=arg[2][3];
  a15=(a15*a03);
  a03=arg[2][4];
  a16=(a16/a11);
  a12=(a16*a02);
  a00=(a00/a11);
  a11=(a00*a05);
  a12=(a12+a11);
  a03=(a03*a12);
  a15=(a15-a03);
  a14=casadi_fmax(a14,a15);
  a15=(a10?a14:0);
  res[0][11]=a15;
  a15=arg[2][5];
  a15=(a15*a14);
  a00=(a00*a02);
  a16=(a16*a05);
  a00=(a00-a16);
  a16=arg[2][6];
  a16=(a00/a16);
  a16=tanh(a16);
  a15=(a15*a16);
  a15=(-a15);
  a10=(a10?a15:0);
  res[0][12]=a10;
  res[0][13]=a00;
  return 0;
}

static void arm_kinematics_core(const double *q, const double *qd, const double *arm, double *r, double *J, double *Jdqd) {
    const double *arg[3];
    double *res[3];
    double w[9];
    arg[0] = q; arg[1] = qd; arg[2] = arm;
    res[0] = r; res[1] = J; res[2] = Jdqd;
    (void)casadi_f0(arg, res, 0, w, 0);
}

static void arm_dynamics_core(const double *q, const double *qd, const double *arm, double *B, double *n) {
    const double *arg[3];
    double *res[2];
    double w[14];
    arg[0] = q; arg[1] = qd; arg[2] = arm;
    res[0] = B; res[1] = n;
    (void)casadi_f1(arg, res, 0, w, 0);
}

static void operational_space_core(const double *q, const double *qd, const double *arm, double *Bo, double *no, double *cond) {
    const double *arg[3];
    double *res[3];
    double w[29];
    arg[0] = q; arg[1] = qd; arg[2] = arm;
    res[0] = Bo; res[1] = no; res[2] = cond;
    (void)casadi_f2(arg, res, 0, w, 0);
}

static void task_frame_plane_core(const double *r, const double *rd, const double *surface, double *R, double *Rd) {
    const double *arg[3];
    double *res[2];
    double w[4];
    arg[0] = r; arg[1] = rd; arg[2] = surface;
    res[0] = R; res[1] = Rd;
    (void)casadi_f3(arg, res, 0, w, 0);
}

static void decoupling_law_plane_core(const double *q, const double *qd, const double *a, const double *Fc, const double *arm, const double *surface, const double *opts, double *F, double *tau, double *cond) {
    const double *arg[7];
    double *res[3];
    double w[32];
    arg[0] = q; arg[1] = qd; arg[2] = a; arg[3] = Fc; arg[4] = arm; arg[5] = surface; arg[6] = opts;
    res[0] = F; res[1] = tau; res[2] = cond;
    (void)casadi_f4(arg, res, 0, w, 0);
}

static void task_measurement_plane_core(const double *q, const double *qd, const double *Fc, const double *arm, const double *surface, double *r, double *rd, double *v, double *f) {
    const double *arg[5];
    double *res[4];
    double w[9];
    arg[0] = q; arg[1] = qd; arg[2] = Fc; arg[3] = arm; arg[4] = surface;
    res[0] = r; res[1] = rd; res[2] = v; res[3] = f;
    (void)casadi_f5(arg, res, 0, w, 0);
}

static void plant_rhs_plane_core(const double *x, const double *tau, const double *arm, const double *plant, const double *surface, double *xdot) {
    const double *arg[5];
    double *res[1];
    double w[31];
    arg[0] = x; arg[1] = tau; arg[2] = arm; arg[3] = plant; arg[4] = surface;
    res[0] = xdot;
    (void)casadi_f6(arg, res, 0, w, 0);
}

static void plant_outputs_plane_core(const double *x, const double *arm, const double *plant, const double *surface, double *y) {
    const double *arg[4];
    double *res[1];
    double w[17];
    arg[0] = x; arg[1] = arm; arg[2] = plant; arg[3] = surface;
    res[0] = y;
    (void)casadi_f7(arg, res, 0, w, 0);
}

static void task_frame_circle_core(const double *r, const double *rd, const double *surface, double *R, double *Rd) {
    const double *arg[3];
    double *res[2];
    double w[8];
    arg[0] = r; arg[1] = rd; arg[2] = surface;
    res[0] = R; res[1] = Rd;
    (void)casadi_f8(arg, res, 0, w, 0);
}

static void decoupling_law_circle_core(const double *q, const double *qd, const double *a, const double *Fc, const double *arm, const double *surface, const double *opts, double *F, double *tau, double *cond) {
    const double *arg[7];
    double *res[3];
    double w[35];
    arg[0] = q; arg[1] = qd; arg[2] = a; arg[3] = Fc; arg[4] = arm; arg[5] = surface; arg[6] = opts;
    res[0] = F; res[1] = tau; res[2] = cond;
    (void)casadi_f9(arg, res, 0, w, 0);
}

static void task_measurement_circle_core(const double *q, const double *qd, const double *Fc, const double *arm, const double *surface, double *r, double *rd, double *v, double *f) {
    const double *arg[5];
    double *res[4];
    double w[11];
    arg[0] = q; arg[1] = qd; arg[2] = Fc; arg[3] = arm; arg[4] = surface;
    res[0] = r; res[1] = rd; res[2] = v; res[3] = f;
    (void)casadi_f10(arg, res, 0, w, 0);
}

static void plant_rhs_circle_core(const double *x, const double *tau, const double *arm, const double *plant, const double *surface, double *xdot) {
    const double *arg[5];
    double *res[1];
    double w[31];
    arg[0] = x; arg[1] = tau; arg[2] = arm; arg[3] = plant; arg[4] = surface;
    res[0] = xdot;
    (void)casadi_f11(arg, res, 0, w, 0);
}

static void plant_outputs_circle_core(const double *x, const double *arm, const double *plant, const double *surface, double *y) {
    const double *arg[4];
    double *res[1];
    double w[17];
    arg[0] = x; arg[1] = arm; arg[2] = plant; arg[3] = surface;
    res[0] = y;
    (void)casadi_f12(arg, res, 0, w, 0);
}

#include "hybrid_casadi.h"

static int all_finite(const double *v, int n) {
    int i;
    unsigned long long exponents_full = 0;
    union { double x; unsigned long long bits; } u;
    for (i = 0; i < n; ++i) {
        u.x = v[i];
        exponents_full += (u.bits & 0x7ff0000000000000ULL) == 0x7ff0000000000000ULL;
    }
    return exponents_full == 0;
}

#if defined(__GNUC__)
#define HYBRID_LANES 1
#include "hybrid_lanes.h"
HL_MAP1(hl_acos, acos)
HL_MAP1(hl_acosh, acosh)
HL_MAP1(hl_asin, asin)
HL_MAP1(hl_asinh, asinh)
HL_MAP1(hl_atan, atan)
HL_MAP1(hl_atanh, atanh)
HL_MAP1(hl_ceil, ceil)
HL_MAP1(hl_cosh, cosh)
HL_MAP1(hl_erf, erf)
HL_MAP1(hl_expm1, expm1)
HL_MAP1(hl_floor, floor)
HL_MAP1(hl_log, log)
HL_MAP1(hl_log1p, log1p)
HL_MAP1(hl_sinh, sinh)
HL_MAP1(hl_tan, tan)
HL_MAP2(hl_atan2, atan2)
HL_MAP2(hl_fmod, fmod)
HL_MAP2(hl_hypot, hypot)
HL_MAP2(hl_pow, pow)
#else
#define HYBRID_LANES 0
#endif

int hybrid_casadi_arm_kinematics(const double *q, const double *qd, const double *arm, double *r, double *J, double *Jdqd) {
    arm_kinematics_core(q, qd, arm, r, J, Jdqd);
    return (all_finite(r, 2) && all_finite(J, 4) && all_finite(Jdqd, 2)) ? HYBRID_OK : HYBRID_NONFINITE;
}

int hybrid_casadi_arm_dynamics(const double *q, const double *qd, const double *arm, double *B, double *n) {
    arm_dynamics_core(q, qd, arm, B, n);
    return (all_finite(B, 4) && all_finite(n, 2)) ? HYBRID_OK : HYBRID_NONFINITE;
}

int hybrid_casadi_operational_space(const double *q, const double *qd, const double *arm, double singular_tol, double *Bo, double *no) {
    double cond[1];
    operational_space_core(q, qd, arm, Bo, no, cond);
    if (fabs(cond[0]) < singular_tol) return HYBRID_SINGULAR;
    return (all_finite(Bo, 4) && all_finite(no, 2) && all_finite(cond, 1)) ? HYBRID_OK : HYBRID_NONFINITE;
}

int hybrid_casadi_task_frame_plane(const double *r, const double *rd, const double *surface, double *R, double *Rd) {
    task_frame_plane_core(r, rd, surface, R, Rd);
    return (all_finite(R, 4) && all_finite(Rd, 4)) ? HYBRID_OK : HYBRID_NONFINITE;
}

int hybrid_casadi_decoupling_law_plane(const double *q, const double *qd, const double *a, const double *Fc, const double *arm, const double *surface, const double *opts, double singular_tol, double *F, double *tau) {
    double cond[1];
    decoupling_law_plane_core(q, qd, a, Fc, arm, surface, opts, F, tau, cond);
    if (fabs(cond[0]) < singular_tol) return HYBRID_SINGULAR;
    return (all_finite(F, 2) && all_finite(tau, 2) && all_finite(cond, 1)) ? HYBRID_OK : HYBRID_NONFINITE;
}

#if HYBRID_LANES
#define DECOUPLING_LAW_PLANE_LANES_NPRE 22
static void decoupling_law_plane_lanes_pre(const hl_v *arm, const hl_v *surface, const hl_v *opts, hl_v *pre) {
    const hl_v v9 = arm[1];
    const hl_v v15 = arm[0];
    const hl_v v31 = surface[2];
    const hl_v v32 = v31 * v31;
    const hl_v v30 = surface[3];
    const hl_v v33 = v30 * v30;
    const hl_v v34 = v32 + v33;
    const hl_v v35 = hl_sqrt(v34);
    const hl_v v163 = 1.0 / v35;
    const hl_v v36 = v30 * v163;
    const hl_v v74 = arm[5];
    const hl_v v78 = v15 * v74;
    const hl_v v75 = v74 * v74;
    const hl_v v76 = v15 * v15;
    const hl_v v77 = v75 + v76;
    const hl_v v73 = arm[3];
    const hl_v v69 = arm[4];
    const hl_v v70 = v69 * v69;
    const hl_v v68 = arm[2];
    const hl_v v71 = v68 * v70;
    const hl_v v65 = arm[6];
    const hl_v v66 = arm[7];
    const hl_v v67 = v65 + v66;
    const hl_v v72 = v67 + v71;
    const hl_v v95 = arm[10];
    const hl_v v96 = v95 * v73;
    const hl_v v170 = v73 * v78;
    const hl_v v101 = arm[8];
    const hl_v v173 = v68 * v69;
    const hl_v v174 = v95 * v173;
    const hl_v v115 = hl_splat(-2.0);
    const hl_v v126 = v75 * v73;
    const hl_v v127 = v66 + v126;
    const hl_v v137 = arm[9];
    const hl_v v154 = v9 * v9;
    pre[0] = v9;
    pre[1] = v15;
    pre[2] = v31;
    pre[3] = v163;
    pre[4] = v36;
    pre[5] = v74;
    pre[6] = v78;
    pre[7] = v75;
    pre[8] = v77;
    pre[9] = v73;
    pre[10] = v68;
    pre[11] = v66;
    pre[12] = v72;
    pre[13] = v95;
    pre[14] = v96;
    pre[15] = v170;
    pre[16] = v101;
    pre[17] = v174;
    pre[18] = v115;
    pre[19] = v127;
    pre[20] = v137;
    pre[21] = v154;
    (void)arm;
    (void)surface;
    (void)opts;
    (void)pre;
}

static inline __attribute__((always_inline)) void decoupling_law_plane_lanes_core(const hl_v *q, const hl_v *qd, const hl_v *a, const hl_v *Fc, const hl_v *pre, hl_v *F, hl_v *tau, hl_v *cond, const int exact, hl_i *odd) {
    (void)q;
    (void)qd;
    (void)a;
    (void)Fc;
    (void)pre;
    (void)odd;
    const hl_v v0 = q[0];
    hl_v v5, v1;
    if (exact) hl_sincos(v0, &v5, &v1); else hl_sincos_poly(v0, &v5, &v1, odd);
    const hl_v v2 = q[1];
    hl_v v6, v3;
    if (exact) hl_sincos(v2, &v6, &v3); else hl_sincos_poly(v2, &v6, &v3, odd);
    const hl_v v4 = v1 * v3;
    const hl_v v7 = v5 * v6;
    const hl_v v8 = v4 - v7;
    const hl_v v9 = pre[0];
    const hl_v v10 = v8 * v9;
    const hl_v v15 = pre[1];
    const hl_v v16 = v1 * v15;
    const hl_v v17 = v16 + v10;
    const hl_v v11 = v1 * v6;
    const hl_v v12 = v5 * v3;
    const hl_v v13 = v11 + v12;
    const hl_v v14 = v13 * v9;
    const hl_v v18 = v14 * v17;
    const hl_v v19 = v5 * v15;
    const hl_v v20 = v14 + v19;
    const hl_v v21 = v20 * v10;
    const hl_v v22 = v18 - v21;
    const hl_v v162 = 1.0 / v22;
    const hl_v v23 = v10 * v162;
    const hl_v v24 = qd[0];
    const hl_v v27 = v17 * v24;
    const hl_v v25 = qd[1];
    const hl_v v26 = v10 * v25;
    const hl_v v28 = v26 + v27;
    const hl_v v29 = v24 * v28;
    const hl_v v40 = v10 * v24;
    const hl_v v41 = v26 + v40;
    const hl_v v42 = v25 * v41;
    const hl_v v31 = pre[2];
    const hl_v v163 = pre[3];
    const hl_v v36 = pre[4];
    const hl_v v37 = a[0];
    const hl_v v38 = v36 * v37;
    const hl_v v44 = a[1];
    const hl_v v164 = v31 * v44;
    const hl_v v46 = v163 * v164;
    const hl_v v165 = v46 - v38;
    const hl_v v166 = v165 + v42;
    const hl_v v47 = v29 + v166;
    const hl_v v48 = v47 * v23;
    const hl_v v51 = v20 * v24;
    const hl_v v50 = v14 * v25;
    const hl_v v52 = v50 + v51;
    const hl_v v53 = v24 * v52;
    const hl_v v55 = v14 * v24;
    const hl_v v56 = v50 + v55;
    const hl_v v57 = v25 * v56;
    const hl_v v49 = v36 * v44;
    const hl_v v167 = v31 * v37;
    const hl_v v60 = v163 * v167;
    const hl_v v168 = v49 + v60;
    const hl_v v169 = v168 + v57;
    const hl_v v61 = v53 + v169;
    const hl_v v62 = v14 * v162;
    const hl_v v63 = v61 * v62;
    const hl_v v64 = v48 + v63;
    const hl_v v74 = pre[5];
    const hl_v v78 = pre[6];
    const hl_v v79 = v78 * v3;
    const hl_v v80 = v79 + v79;
    const hl_v v75 = pre[7];
    const hl_v v77 = pre[8];
    const hl_v v81 = v77 + v80;
    const hl_v v73 = pre[9];
    const hl_v v82 = v73 * v81;
    const hl_v v66 = pre[11];
    const hl_v v72 = pre[12];
    const hl_v v83 = v72 + v82;
    const hl_v v84 = v64 * v83;
    const hl_v v97 = v8 * v74;
    const hl_v v98 = v16 + v97;
    const hl_v v96 = pre[14];
    const hl_v v99 = v96 * v98;
    const hl_v v104 = Fc[0];
    const hl_v v105 = v20 * v104;
    const hl_v v177 = v99 + v105;
    const hl_v v170 = pre[15];
    const hl_v v108 = v170 * v6;
    const hl_v v109 = v25 * v25;
    const hl_v v110 = v108 * v109;
    const hl_v v101 = pre[16];
    const hl_v v102 = v101 * v24;
    const hl_v v175 = v102 - v110;
    const hl_v v174 = pre[17];
    const hl_v v122 = v174 * v1;
    const hl_v v176 = v122 + v175;
    const hl_v v179 = v176 + v177;
    const hl_v v112 = Fc[1];
    const hl_v v113 = v17 * v112;
    const hl_v v171 = v24 * v25;
    const hl_v v115 = pre[18];
    const hl_v v172 = v115 * v171;
    const hl_v v118 = v172 * v108;
    const hl_v v178 = v118 - v113;
    const hl_v v180 = v178 + v179;
    const hl_v v181 = v180 + v84;
    const hl_v v85 = v17 * v162;
    const hl_v v86 = v47 * v85;
    const hl_v v87 = v20 * v162;
    const hl_v v88 = v61 * v87;
    const hl_v v89 = v86 + v88;
    const hl_v v90 = v75 + v79;
    const hl_v v91 = v73 * v90;
    const hl_v v92 = v66 + v91;
    const hl_v v93 = v89 * v92;
    const hl_v v123 = v181 - v93;
    tau[0] = v123;
    const hl_v v124 = v23 * v123;
    const hl_v v127 = pre[19];
    const hl_v v128 = v89 * v127;
    const hl_v v125 = v14 * v104;
    const hl_v v132 = v97 * v96;
    const hl_v v183 = v125 + v132;
    const hl_v v140 = v10 * v112;
    const hl_v v134 = v24 * v24;
    const hl_v v135 = v108 * v134;
    const hl_v v137 = pre[20];
    const hl_v v138 = v137 * v25;
    const hl_v v182 = v138 + v135;
    const hl_v v184 = v182 - v140;
    const hl_v v185 = v183 + v184;
    const hl_v v186 = v185 - v128;
    const hl_v v130 = v92 * v64;
    const hl_v v141 = v130 + v186;
    tau[1] = v141;
    const hl_v v142 = v85 * v141;
    const hl_v v143 = v124 - v142;
    F[0] = v143;
    const hl_v v144 = v62 * v123;
    const hl_v v145 = v87 * v141;
    const hl_v v146 = v144 - v145;
    F[1] = v146;
    const hl_v v148 = -v21;
    const hl_v v149 = v148 + v148;
    const hl_v v147 = v18 + v18;
    const hl_v v150 = v147 + v149;
    const hl_v v151 = v20 * v20;
    const hl_v v152 = v17 * v17;
    const hl_v v188 = v151 + v152;
    const hl_v v155 = v13 * v13;
    const hl_v v154 = pre[21];
    const hl_v v156 = v154 * v155;
    const hl_v v158 = v8 * v8;
    const hl_v v159 = v154 * v158;
    const hl_v v187 = v156 + v159;
    const hl_v v160 = v187 + v188;
    const hl_v v161 = v150 / v160;
    cond[0] = v161;
}

static __attribute__((noinline, cold)) void decoupling_law_plane_lanes_exact(const hl_v *q, const hl_v *qd, const hl_v *a, const hl_v *Fc, const hl_v *pre, hl_v *F, hl_v *tau, hl_v *cond) {
    decoupling_law_plane_lanes_core(q, qd, a, Fc, pre, F, tau, cond, 1, NULL);
}

static void decoupling_law_plane_lanes(const hl_v *q, const hl_v *qd, const hl_v *a, const hl_v *Fc, const hl_v *pre, hl_v *F, hl_v *tau, hl_v *cond) {
    hl_i odd = hl_splat(0.0) != 0.0;
    decoupling_law_plane_lanes_core(q, qd, a, Fc, pre, F, tau, cond, 0, &odd);
    if (hl_any(odd)) decoupling_law_plane_lanes_exact(q, qd, a, Fc, pre, F, tau, cond);
}

int hybrid_casadi_decoupling_law_plane_batch(int nstates, const double *q, const double *qd, const double *a, const double *Fc, const double *arm, const double *surface, const double *opts, double singular_tol, double *F, double *tau, int *status) {
    hl_v f_arm[11]; hl_v f_surface[4]; hl_v f_opts[1];
    hl_v pre[DECOUPLING_LAW_PLANE_LANES_NPRE];
    hl_v l_q[2] = {{0}}; hl_v l_qd[2] = {{0}}; hl_v l_a[2] = {{0}}; hl_v l_Fc[2] = {{0}}; hl_v o_F[2]; hl_v o_tau[2]; hl_v o_cond[1];
    long i;
    int j, l, st, failed = 0;
    for (j = 0; j < 11; ++j) f_arm[j] = hl_splat(arm[j]);
    for (j = 0; j < 4; ++j) f_surface[j] = hl_splat(surface[j]);
    for (j = 0; j < 1; ++j) f_opts[j] = hl_splat(opts[j]);
    decoupling_law_plane_lanes_pre(f_arm, f_surface, f_opts, pre);
    for (i = 0; i < nstates; i += HL_W) {
        hl_i bad;
        if (i + HL_W <= nstates) {
            for (j = 0; j < 2; ++j) {
                for (l = 0; l < HL_W; ++l) l_q[j][l] = q[(i + l) * 2 + j];
            }
            for (j = 0; j < 2; ++j) {
                for (l = 0; l < HL_W; ++l) l_qd[j][l] = qd[(i + l) * 2 + j];
            }
            for (j = 0; j < 2; ++j) {
                for (l = 0; l < HL_W; ++l) l_a[j][l] = a[(i + l) * 2 + j];
            }
            for (j = 0; j < 2; ++j) {
                for (l = 0; l < HL_W; ++l) l_Fc[j][l] = Fc[(i + l) * 2 + j];
            }
        } else {
            for (j = 0; j < 2; ++j) {
                for (l = 0; l < HL_W; ++l) l_q[j][l] = q[(i + l < nstates ? i + l : nstates - 1) * 2 + j];
            }
            for (j = 0; j < 2; ++j) {
                for (l = 0; l < HL_W; ++l) l_qd[j][l] = qd[(i + l < nstates ? i + l : nstates - 1) * 2 + j];
            }
            for (j = 0; j < 2; ++j) {
                for (l = 0; l < HL_W; ++l) l_a[j][l] = a[(i + l < nstates ? i + l : nstates - 1) * 2 + j];
            }
            for (j = 0; j < 2; ++j) {
                for (l = 0; l < HL_W; ++l) l_Fc[j][l] = Fc[(i + l < nstates ? i + l : nstates - 1) * 2 + j];
            }
        }
        decoupling_law_plane_lanes(l_q, l_qd, l_a, l_Fc, pre, o_F, o_tau, o_cond);
        hl_i g0 = hl_fabs(o_cond[0]) < singular_tol;
        bad = hl_not_finite(o_F, 2) | hl_not_finite(o_tau, 2) | hl_not_finite(o_cond, 1);
        for (l = 0; l < HL_W && i + l < nstates; ++l) {
            for (j = 0; j < 2; ++j) F[(i + l) * 2 + j] = o_F[j][l];
            for (j = 0; j < 2; ++j) tau[(i + l) * 2 + j] = o_tau[j][l];
            st = g0[l] ? HYBRID_SINGULAR : bad[l] ? HYBRID_NONFINITE : HYBRID_OK;
            status[i + l] = st;
            failed += st != HYBRID_OK;
        }
    }
    return failed;
}
#else
int hybrid_casadi_decoupling_law_plane_batch(int nstates, const double *q, const double *qd, const double *a, const double *Fc, const double *arm, const double *surface, const double *opts, double singular_tol, double *F, double *tau, int *status) {
    int i, failed = 0;
    for (i = 0; i < nstates; ++i) {
        status[i] = hybrid_casadi_decoupling_law_plane(q + (long)i * 2, qd + (long)i * 2, a + (long)i * 2, Fc + (long)i * 2, arm, surface, opts, singular_tol, F + (long)i * 2, tau + (long)i * 2);
        failed += status[i] != HYBRID_OK;
    }
    return failed;
}
#endif

int hybrid_casadi_task_measurement_plane(const double *q, const double *qd, const double *Fc, const double *arm, const double *surface, double *r, double *rd, double *v, double *f) {
    task_measurement_plane_core(q, qd, Fc, arm, surface, r, rd, v, f);
    return (all_finite(r, 2) && all_finite(rd, 2) && all_finite(v, 2) && all_finite(f, 2)) ? HYBRID_OK : HYBRID_NONFINITE;
}

int hybrid_casadi_plant_rhs_plane(const double *x, const double *tau, const double *arm, const double *plant, const double *surface, double *xdot) {
    plant_rhs_plane_core(x, tau, arm, plant, surface, xdot);
    return (all_finite(xdot, 8)) ? HYBRID_OK : HYBRID_NONFINITE;
}

int hybrid_casadi_plant_advance_plane(double *x, const double *tau, const double *arm, const double *plant, const double *surface, double h, int nsteps, double *trajectory, int *steps_done) {
    double k1[8], k2[8], k3[8], k4[8], xt[8];
    int i, step;
    for (step = 0; step < nsteps; ++step) {
        plant_rhs_plane_core(x, tau, arm, plant, surface, k1);
        for (i = 0; i < 8; ++i) xt[i] = x[i] + 0.5 * h * k1[i];
        plant_rhs_plane_core(xt, tau, arm, plant, surface, k2);
        for (i = 0; i < 8; ++i) xt[i] = x[i] + 0.5 * h * k2[i];
        plant_rhs_plane_core(xt, tau, arm, plant, surface, k3);
        for (i = 0; i < 8; ++i) xt[i] = x[i] + h * k3[i];
        plant_rhs_plane_core(xt, tau, arm, plant, surface, k4);
        for (i = 0; i < 8; ++i) xt[i] = x[i] + h / 6.0 * (k1[i] + 2.0 * (k2[i] + k3[i]) + k4[i]);
        if (!all_finite(xt, 8)) {
            if (steps_done) *steps_done = step;
            return HYBRID_NONFINITE;
        }
        for (i = 0; i < 8; ++i) x[i] = xt[i];
        if (trajectory) {
            for (i = 0; i < 8; ++i) trajectory[(long)step * 8 + i] = x[i];
        }
    }
    if (steps_done) *steps_done = nsteps;
    return HYBRID_OK;
}

int hybrid_casadi_plant_outputs_plane(const double *x, const double *arm, const double *plant, const double *surface, double *y) {
    plant_outputs_plane_core(x, arm, plant, surface, y);
    return (all_finite(y, 14)) ? HYBRID_OK : HYBRID_NONFINITE;
}

#if HYBRID_LANES
#define PLANT_OUTPUTS_PLANE_LANES_NPRE 13
static void plant_outputs_plane_lanes_pre(const hl_v *arm, const hl_v *plant, const hl_v *surface, hl_v *pre) {
    const hl_v v0 = arm[1];
    const hl_v v11 = arm[0];
    const hl_v v20 = surface[2];
    const hl_v v21 = v20 * v20;
    const hl_v v22 = surface[3];
    const hl_v v23 = v22 * v22;
    const hl_v v24 = v21 + v23;
    const hl_v v25 = hl_sqrt(v24);
    const hl_v v96 = 1.0 / v25;
    const hl_v v26 = v20 * v96;
    const hl_v v36 = v22 * v96;
    const hl_v v46 = plant[2];
    const hl_v v42 = plant[1];
    const hl_v v64 = surface[0];
    const hl_v v67 = surface[1];
    const hl_v v74 = plant[3];
    const hl_v v76 = plant[4];
    const hl_v v72 = hl_splat(0.0);
    const hl_v v85 = plant[5];
    const hl_v v90 = plant[6];
    const hl_v v97 = 1.0 / v90;
    pre[0] = v0;
    pre[1] = v11;
    pre[2] = v26;
    pre[3] = v36;
    pre[4] = v46;
    pre[5] = v42;
    pre[6] = v64;
    pre[7] = v67;
    pre[8] = v74;
    pre[9] = v76;
    pre[10] = v72;
    pre[11] = v85;
    pre[12] = v97;
    (void)arm;
    (void)plant;
    (void)surface;
    (void)pre;
}

static inline __attribute__((always_inline)) void plant_outputs_plane_lanes_core(const hl_v *x, const hl_v *pre, hl_v *y, const int exact, hl_i *odd) {
    (void)x;
    (void)pre;
    (void)odd;
    const hl_v v1 = x[0];
    hl_v v6, v2;
    if (exact) hl_sincos(v1, &v6, &v2); else hl_sincos_poly(v1, &v6, &v2, odd);
    const hl_v v3 = x[1];
    hl_v v7, v4;
    if (exact) hl_sincos(v3, &v7, &v4); else hl_sincos_poly(v3, &v7, &v4, odd);
    const hl_v v5 = v2 * v4;
    const hl_v v8 = v6 * v7;
    const hl_v v9 = v5 - v8;
    const hl_v v0 = pre[0];
    const hl_v v10 = v0 * v9;
    const hl_v v11 = pre[1];
    const hl_v v12 = v2 * v11;
    const hl_v v13 = v10 + v12;
    y[0] = v13;
    const hl_v v14 = v2 * v7;
    const hl_v v15 = v6 * v4;
    const hl_v v16 = v14 + v15;
    const hl_v v17 = v0 * v16;
    const hl_v v18 = v6 * v11;
    const hl_v v19 = v17 + v18;
    y[1] = v19;
    const hl_v v29 = x[2];
    const hl_v v30 = v13 * v29;
    const hl_v v27 = x[3];
    const hl_v v28 = v10 * v27;
    const hl_v v31 = v28 + v30;
    const hl_v v26 = pre[2];
    const hl_v v32 = v26 * v31;
    const hl_v v34 = v19 * v29;
    const hl_v v33 = v17 * v27;
    const hl_v v35 = v33 + v34;
    const hl_v v36 = pre[3];
    const hl_v v37 = v35 * v36;
    const hl_v v38 = v32 + v37;
    y[2] = v38;
    const hl_v v39 = v36 * v31;
    const hl_v v40 = v26 * v35;
    const hl_v v41 = v39 - v40;
    y[3] = v41;
    const hl_v v47 = x[6];
    const hl_v v48 = v35 + v47;
    const hl_v v46 = pre[4];
    const hl_v v49 = v46 * v48;
    const hl_v v43 = x[4];
    y[8] = v43;
    const hl_v v44 = v43 - v13;
    const hl_v v42 = pre[5];
    const hl_v v45 = v42 * v44;
    const hl_v v50 = v45 + v49;
    y[4] = v50;
    const hl_v v54 = x[7];
    const hl_v v55 = v54 - v31;
    const hl_v v56 = v46 * v55;
    const hl_v v51 = x[5];
    y[9] = v51;
    const hl_v v52 = v51 - v19;
    const hl_v v53 = v42 * v52;
    const hl_v v57 = v53 + v56;
    y[5] = v57;
    const hl_v v58 = v26 * v57;
    const hl_v v59 = v36 * v50;
    const hl_v v60 = v58 - v59;
    y[6] = v60;
    const hl_v v61 = v26 * v50;
    const hl_v v62 = v36 * v57;
    const hl_v v63 = v61 + v62;
    y[7] = v63;
    const hl_v v64 = pre[6];
    const hl_v v65 = v43 - v64;
    const hl_v v66 = v26 * v65;
    const hl_v v67 = pre[7];
    const hl_v v68 = v51 - v67;
    const hl_v v69 = v36 * v68;
    const hl_v v70 = v66 + v69;
    const hl_v v71 = -v70;
    y[10] = v71;
    const hl_v v74 = pre[8];
    const hl_v v75 = v70 * v74;
    const hl_v v77 = v26 * v47;
    const hl_v v78 = v36 * v54;
    const hl_v v79 = v77 + v78;
    const hl_v v76 = pre[9];
    const hl_v v80 = v76 * v79;
    const hl_v v81 = v75 + v80;
    const hl_v v82 = -v81;
    const hl_v v72 = pre[10];
    const hl_v v83 = hl_fmax(v72, v82);
    const hl_v v73 = hl_bool(v70 < v72);
    const hl_v v84 = hl_select(v73 != 0.0, v83, hl_splat(0.0));
    y[11] = v84;
    const hl_v v85 = pre[11];
    const hl_v v98 = v85 * v83;
    const hl_v v87 = v26 * v54;
    const hl_v v88 = v36 * v47;
    const hl_v v89 = v87 - v88;
    y[13] = v89;
    const hl_v v97 = pre[12];
    const hl_v v91 = v89 * v97;
    const hl_v v92 = (exact ? hl_tanh(v91) : hl_tanh_poly(v91, odd));
    const hl_v v93 = v98 * v92;
    const hl_v v94 = -v93;
    const hl_v v95 = hl_select(v73 != 0.0, v94, hl_splat(0.0));
    y[12] = v95;
}

static __attribute__((noinline, cold)) void plant_outputs_plane_lanes_exact(const hl_v *x, const hl_v *pre, hl_v *y) {
    plant_outputs_plane_lanes_core(x, pre, y, 1, NULL);
}

static void plant_outputs_plane_lanes(const hl_v *x, const hl_v *pre, hl_v *y) {
    hl_i odd = hl_splat(0.0) != 0.0;
    plant_outputs_plane_lanes_core(x, pre, y, 0, &odd);
    if (hl_any(odd)) plant_outputs_plane_lanes_exact(x, pre, y);
}

int hybrid_casadi_plant_outputs_plane_batch(int nstates, const double *x, const double *arm, const double *plant, const double *surface, double *y, int *status) {
    hl_v f_arm[11]; hl_v f_plant[7]; hl_v f_surface[4];
    hl_v pre[PLANT_OUTPUTS_PLANE_LANES_NPRE];
    hl_v l_x[8] = {{0}}; hl_v o_y[14];
    long i;
    int j, l, st, failed = 0;
    for (j = 0; j < 11; ++j) f_arm[j] = hl_splat(arm[j]);
    for (j = 0; j < 7; ++j) f_plant[j] = hl_splat(plant[j]);
    for (j = 0; j < 4; ++j) f_surface[j] = hl_splat(surface[j]);
    plant_outputs_plane_lanes_pre(f_arm, f_plant, f_surface, pre);
    for (i = 0; i < nstates; i += HL_W) {
        hl_i bad;
        if (i + HL_W <= nstates) {
            for (j = 0; j < 8; ++j) {
                for (l = 0; l < HL_W; ++l) l_x[j][l] = x[(i + l) * 8 + j];
            }
        } else {
            for (j = 0; j < 8; ++j) {
                for (l = 0; l < HL_W; ++l) l_x[j][l] = x[(i + l < nstates ? i + l : nstates - 1) * 8 + j];
            }
        }
        plant_outputs_plane_lanes(l_x, pre, o_y);
        bad = hl_not_finite(o_y, 14);
        for (l = 0; l < HL_W && i + l < nstates; ++l) {
            for (j = 0; j < 14; ++j) y[(i + l) * 14 + j] = o_y[j][l];
            st = bad[l] ? HYBRID_NONFINITE : HYBRID_OK;
            status[i + l] = st;
            failed += st != HYBRID_OK;
        }
    }
    return failed;
}
#else
int hybrid_casadi_plant_outputs_plane_batch(int nstates, const double *x, const double *arm, const double *plant, const double *surface, double *y, int *status) {
    int i, failed = 0;
    for (i = 0; i < nstates; ++i) {
        status[i] = hybrid_casadi_plant_outputs_plane(x + (long)i * 8, arm, plant, surface, y + (long)i * 14);
        failed += status[i] != HYBRID_OK;
    }
    return failed;
}
#endif

int hybrid_casadi_task_frame_circle(const double *r, const double *rd, const double *surface, double *R, double *Rd) {
    task_frame_circle_core(r, rd, surface, R, Rd);
    return (all_finite(R, 4) && all_finite(Rd, 4)) ? HYBRID_OK : HYBRID_NONFINITE;
}

int hybrid_casadi_decoupling_law_circle(const double *q, const double *qd, const double *a, const double *Fc, const double *arm, const double *surface, const double *opts, double singular_tol, double *F, double *tau) {
    double cond[1];
    decoupling_law_circle_core(q, qd, a, Fc, arm, surface, opts, F, tau, cond);
    if (fabs(cond[0]) < singular_tol) return HYBRID_SINGULAR;
    return (all_finite(F, 2) && all_finite(tau, 2) && all_finite(cond, 1)) ? HYBRID_OK : HYBRID_NONFINITE;
}

#if HYBRID_LANES
#define DECOUPLING_LAW_CIRCLE_LANES_NPRE 22
static void decoupling_law_circle_lanes_pre(const hl_v *arm, const hl_v *surface, const hl_v *opts, hl_v *pre) {
    const hl_v v9 = arm[1];
    const hl_v v15 = arm[0];
    const hl_v v32 = surface[0];
    const hl_v v30 = surface[1];
    const hl_v v43 = opts[0];
    const hl_v v94 = arm[5];
    const hl_v v98 = v15 * v94;
    const hl_v v95 = v94 * v94;
    const hl_v v96 = v15 * v15;
    const hl_v v97 = v95 + v96;
    const hl_v v93 = arm[3];
    const hl_v v89 = arm[4];
    const hl_v v90 = v89 * v89;
    const hl_v v88 = arm[2];
    const hl_v v91 = v88 * v90;
    const hl_v v85 = arm[6];
    const hl_v v86 = arm[7];
    const hl_v v87 = v85 + v86;
    const hl_v v92 = v87 + v91;
    const hl_v v115 = arm[10];
    const hl_v v116 = v115 * v93;
    const hl_v v190 = v93 * v98;
    const hl_v v121 = arm[8];
    const hl_v v193 = v88 * v89;
    const hl_v v194 = v115 * v193;
    const hl_v v135 = hl_splat(-2.0);
    const hl_v v146 = v95 * v93;
    const hl_v v147 = v86 + v146;
    const hl_v v157 = arm[9];
    const hl_v v174 = v9 * v9;
    pre[0] = v9;
    pre[1] = v15;
    pre[2] = v32;
    pre[3] = v30;
    pre[4] = v43;
    pre[5] = v94;
    pre[6] = v98;
    pre[7] = v95;
    pre[8] = v97;
    pre[9] = v93;
    pre[10] = v88;
    pre[11] = v86;
    pre[12] = v92;
    pre[13] = v115;
    pre[14] = v116;
    pre[15] = v190;
    pre[16] = v121;
    pre[17] = v194;
    pre[18] = v135;
    pre[19] = v147;
    pre[20] = v157;
    pre[21] = v174;
    (void)arm;
    (void)surface;
    (void)opts;
    (void)pre;
}

static inline __attribute__((always_inline)) void decoupling_law_circle_lanes_core(const hl_v *q, const hl_v *qd, const hl_v *a, const hl_v *Fc, const hl_v *pre, hl_v *F, hl_v *tau, hl_v *cond, const int exact, hl_i *odd) {
    (void)q;
    (void)qd;
    (void)a;
    (void)Fc;
    (void)pre;
    (void)odd;
    const hl_v v0 = q[0];
    hl_v v5, v1;
    if (exact) hl_sincos(v0, &v5, &v1); else hl_sincos_poly(v0, &v5, &v1, odd);
    const hl_v v2 = q[1];
    hl_v v6, v3;
    if (exact) hl_sincos(v2, &v6, &v3); else hl_sincos_poly(v2, &v6, &v3, odd);
    const hl_v v4 = v1 * v3;
    const hl_v v7 = v5 * v6;
    const hl_v v8 = v4 - v7;
    const hl_v v9 = pre[0];
    const hl_v v10 = v8 * v9;
    const hl_v v15 = pre[1];
    const hl_v v16 = v1 * v15;
    const hl_v v17 = v16 + v10;
    const hl_v v32 = pre[2];
    const hl_v v33 = v17 - v32;
    const hl_v v34 = v33 * v33;
    const hl_v v11 = v1 * v6;
    const hl_v v12 = v5 * v3;
    const hl_v v13 = v11 + v12;
    const hl_v v14 = v13 * v9;
    const hl_v v19 = v5 * v15;
    const hl_v v20 = v14 + v19;
    const hl_v v30 = pre[3];
    const hl_v v31 = v20 - v30;
    const hl_v v35 = v31 * v31;
    const hl_v v36 = v34 + v35;
    const hl_v v37 = hl_sqrt(v36);
    const hl_v v183 = 1.0 / v37;
    const hl_v v38 = v31 * v183;
    const hl_v v24 = qd[0];
    const hl_v v27 = v17 * v24;
    const hl_v v25 = qd[1];
    const hl_v v26 = v10 * v25;
    const hl_v v28 = v26 + v27;
    const hl_v v45 = v28 * v38;
    const hl_v v46 = v33 * v183;
    const hl_v v41 = v20 * v24;
    const hl_v v40 = v14 * v25;
    const hl_v v42 = v40 + v41;
    const hl_v v47 = v42 * v46;
    const hl_v v48 = v45 - v47;
    const hl_v v49 = v38 * v48;
    const hl_v v50 = v28 - v49;
    const hl_v v43 = pre[4];
    const hl_v v44 = v43 * v183;
    const hl_v v51 = v44 * v50;
    const hl_v v52 = v42 * v51;
    const hl_v v39 = a[0];
    const hl_v v184 = v39 - v52;
    const hl_v v54 = v46 * v48;
    const hl_v v55 = v42 + v54;
    const hl_v v56 = v44 * v55;
    const hl_v v57 = v28 * v56;
    const hl_v v58 = v57 + v184;
    const hl_v v59 = v38 * v58;
    const hl_v v29 = v24 * v28;
    const hl_v v61 = v10 * v24;
    const hl_v v62 = v26 + v61;
    const hl_v v63 = v25 * v62;
    const hl_v v186 = v63 + v29;
    const hl_v v187 = v186 - v59;
    const hl_v v66 = v42 * v56;
    const hl_v v65 = a[1];
    const hl_v v185 = v65 - v66;
    const hl_v v68 = v28 * v51;
    const hl_v v69 = v185 - v68;
    const hl_v v70 = v46 * v69;
    const hl_v v71 = v70 + v187;
    const hl_v v18 = v14 * v17;
    const hl_v v21 = v20 * v10;
    const hl_v v22 = v18 - v21;
    const hl_v v182 = 1.0 / v22;
    const hl_v v23 = v10 * v182;
    const hl_v v72 = v71 * v23;
    const hl_v v78 = v46 * v58;
    const hl_v v73 = v42 * v24;
    const hl_v v74 = v14 * v24;
    const hl_v v75 = v40 + v74;
    const hl_v v76 = v25 * v75;
    const hl_v v188 = v76 + v73;
    const hl_v v189 = v188 + v78;
    const hl_v v80 = v38 * v69;
    const hl_v v81 = v80 + v189;
    const hl_v v82 = v14 * v182;
    const hl_v v83 = v81 * v82;
    const hl_v v84 = v72 + v83;
    const hl_v v94 = pre[5];
    const hl_v v98 = pre[6];
    const hl_v v99 = v98 * v3;
    const hl_v v100 = v99 + v99;
    const hl_v v95 = pre[7];
    const hl_v v97 = pre[8];
    const hl_v v101 = v97 + v100;
    const hl_v v93 = pre[9];
    const hl_v v102 = v93 * v101;
    const hl_v v86 = pre[11];
    const hl_v v92 = pre[12];
    const hl_v v103 = v92 + v102;
    const hl_v v104 = v84 * v103;
    const hl_v v117 = v8 * v94;
    const hl_v v118 = v16 + v117;
    const hl_v v116 = pre[14];
    const hl_v v119 = v116 * v118;
    const hl_v v124 = Fc[0];
    const hl_v v125 = v20 * v124;
    const hl_v v197 = v119 + v125;
    const hl_v v190 = pre[15];
    const hl_v v128 = v190 * v6;
    const hl_v v129 = v25 * v25;
    const hl_v v130 = v128 * v129;
    const hl_v v121 = pre[16];
    const hl_v v122 = v121 * v24;
    const hl_v v195 = v122 - v130;
    const hl_v v194 = pre[17];
    const hl_v v142 = v194 * v1;
    const hl_v v196 = v142 + v195;
    const hl_v v199 = v196 + v197;
    const hl_v v132 = Fc[1];
    const hl_v v133 = v17 * v132;
    const hl_v v191 = v24 * v25;
    const hl_v v135 = pre[18];
    const hl_v v192 = v135 * v191;
    const hl_v v138 = v192 * v128;
    const hl_v v198 = v138 - v133;
    const hl_v v200 = v198 + v199;
    const hl_v v201 = v200 + v104;
    const hl_v v105 = v17 * v182;
    const hl_v v106 = v71 * v105;
    const hl_v v107 = v20 * v182;
    const hl_v v108 = v81 * v107;
    const hl_v v109 = v106 + v108;
    const hl_v v110 = v95 + v99;
    const hl_v v111 = v93 * v110;
    const hl_v v112 = v86 + v111;
    const hl_v v113 = v109 * v112;
    const hl_v v143 = v201 - v113;
    tau[0] = v143;
    const hl_v v144 = v23 * v143;
    const hl_v v147 = pre[19];
    const hl_v v148 = v109 * v147;
    const hl_v v145 = v14 * v124;
    const hl_v v152 = v117 * v116;
    const hl_v v203 = v145 + v152;
    const hl_v v160 = v10 * v132;
    const hl_v v154 = v24 * v24;
    const hl_v v155 = v128 * v154;
    const hl_v v157 = pre[20];
    const hl_v v158 = v157 * v25;
    const hl_v v202 = v158 + v155;
    const hl_v v204 = v202 - v160;
    const hl_v v205 = v203 + v204;
    const hl_v v206 = v205 - v148;
    const hl_v v150 = v112 * v84;
    const hl_v v161 = v150 + v206;
    tau[1] = v161;
    const hl_v v162 = v105 * v161;
    const hl_v v163 = v144 - v162;
    F[0] = v163;
    const hl_v v164 = v82 * v143;
    const hl_v v165 = v107 * v161;
    const hl_v v166 = v164 - v165;
    F[1] = v166;
    const hl_v v168 = -v21;
    const hl_v v169 = v168 + v168;
    const hl_v v167 = v18 + v18;
    const hl_v v170 = v167 + v169;
    const hl_v v171 = v20 * v20;
    const hl_v v172 = v17 * v17;
    const hl_v v208 = v171 + v172;
    const hl_v v175 = v13 * v13;
    const hl_v v174 = pre[21];
    const hl_v v176 = v174 * v175;
    const hl_v v178 = v8 * v8;
    const hl_v v179 = v174 * v178;
    const hl_v v207 = v176 + v179;
    const hl_v v180 = v207 + v208;
    const hl_v v181 = v170 / v180;
    cond[0] = v181;
}

static __attribute__((noinline, cold)) void decoupling_law_circle_lanes_exact(const hl_v *q, const hl_v *qd, const hl_v *a, const hl_v *Fc, const hl_v *pre, hl_v *F, hl_v *tau, hl_v *cond) {
    decoupling_law_circle_lanes_core(q, qd, a, Fc, pre, F, tau, cond, 1, NULL);
}

static void decoupling_law_circle_lanes(const hl_v *q, const hl_v *qd, const hl_v *a, const hl_v *Fc, const hl_v *pre, hl_v *F, hl_v *tau, hl_v *cond) {
    hl_i odd = hl_splat(0.0) != 0.0;
    decoupling_law_circle_lanes_core(q, qd, a, Fc, pre, F, tau, cond, 0, &odd);
    if (hl_any(odd)) decoupling_law_circle_lanes_exact(q, qd, a, Fc, pre, F, tau, cond);
}

int hybrid_casadi_decoupling_law_circle_batch(int nstates, const double *q, const double *qd, const double *a, const double *Fc, const double *arm, const double *surface, const double *opts, double singular_tol, double *F, double *tau, int *status) {
    hl_v f_arm[11]; hl_v f_surface[3]; hl_v f_opts[1];
    hl_v pre[DECOUPLING_LAW_CIRCLE_LANES_NPRE];
    hl_v l_q[2] = {{0}}; hl_v l_qd[2] = {{0}}; hl_v l_a[2] = {{0}}; hl_v l_Fc[2] = {{0}}; hl_v o_F[2]; hl_v o_tau[2]; hl_v o_cond[1];
    long i;
    int j, l, st, failed = 0;
    for (j = 0; j < 11; ++j) f_arm[j] = hl_splat(arm[j]);
    for (j = 0; j < 3; ++j) f_surface[j] = hl_splat(surface[j]);
    for (j = 0; j < 1; ++j) f_opts[j] = hl_splat(opts[j]);
    decoupling_law_circle_lanes_pre(f_arm, f_surface, f_opts, pre);
    for (i = 0; i < nstates; i += HL_W) {
        hl_i bad;
        if (i + HL_W <= nstates) {
            for (j = 0; j < 2; ++j) {
                for (l = 0; l < HL_W; ++l) l_q[j][l] = q[(i + l) * 2 + j];
            }
            for (j = 0; j < 2; ++j) {
                for (l = 0; l < HL_W; ++l) l_qd[j][l] = qd[(i + l) * 2 + j];
            }
            for (j = 0; j < 2; ++j) {
                for (l = 0; l < HL_W; ++l) l_a[j][l] = a[(i + l) * 2 + j];
            }
            for (j = 0; j < 2; ++j) {
                for (l = 0; l < HL_W; ++l) l_Fc[j][l] = Fc[(i + l) * 2 + j];
            }
        } else {
            for (j = 0; j < 2; ++j) {
                for (l = 0; l < HL_W; ++l) l_q[j][l] = q[(i + l < nstates ? i + l : nstates - 1) * 2 + j];
            }
            for (j = 0; j < 2; ++j) {
                for (l = 0; l < HL_W; ++l) l_qd[j][l] = qd[(i + l < nstates ? i + l : nstates - 1) * 2 + j];
            }
            for (j = 0; j < 2; ++j) {
                for (l = 0; l < HL_W; ++l) l_a[j][l] = a[(i + l < nstates ? i + l : nstates - 1) * 2 + j];
            }
            for (j = 0; j < 2; ++j) {
                for (l = 0; l < HL_W; ++l) l_Fc[j][l] = Fc[(i + l < nstates ? i + l : nstates - 1) * 2 + j];
            }
        }
        decoupling_law_circle_lanes(l_q, l_qd, l_a, l_Fc, pre, o_F, o_tau, o_cond);
        hl_i g0 = hl_fabs(o_cond[0]) < singular_tol;
        bad = hl_not_finite(o_F, 2) | hl_not_finite(o_tau, 2) | hl_not_finite(o_cond, 1);
        for (l = 0; l < HL_W && i + l < nstates; ++l) {
            for (j = 0; j < 2; ++j) F[(i + l) * 2 + j] = o_F[j][l];
            for (j = 0; j < 2; ++j) tau[(i + l) * 2 + j] = o_tau[j][l];
            st = g0[l] ? HYBRID_SINGULAR : bad[l] ? HYBRID_NONFINITE : HYBRID_OK;
            status[i + l] = st;
            failed += st != HYBRID_OK;
        }
    }
    return failed;
}
#else
int hybrid_casadi_decoupling_law_circle_batch(int nstates, const double *q, const double *qd, const double *a, const double *Fc, const double *arm, const double *surface, const double *opts, double singular_tol, double *F, double *tau, int *status) {
    int i, failed = 0;
    for (i = 0; i < nstates; ++i) {
        status[i] = hybrid_casadi_decoupling_law_circle(q + (long)i * 2, qd + (long)i * 2, a + (long)i * 2, Fc + (long)i * 2, arm, surface, opts, singular_tol, F + (long)i * 2, tau + (long)i * 2);
        failed += status[i] != HYBRID_OK;
    }
    return failed;
}
#endif

int hybrid_casadi_task_measurement_circle(const double *q, const double *qd, const double *Fc, const double *arm, const double *surface, double *r, double *rd, double *v, double *f) {
    task_measurement_circle_core(q, qd, Fc, arm, surface, r, rd, v, f);
    return (all_finite(r, 2) && all_finite(rd, 2) && all_finite(v, 2) && all_finite(f, 2)) ? HYBRID_OK : HYBRID_NONFINITE;
}

int hybrid_casadi_plant_rhs_circle(const double *x, const double *tau, const double *arm, const double *plant, const double *surface, double *xdot) {
    plant_rhs_circle_core(x, tau, arm, plant, surface, xdot);
    return (all_finite(xdot, 8)) ? HYBRID_OK : HYBRID_NONFINITE;
}

int hybrid_casadi_plant_advance_circle(double *x, const double *tau, const double *arm, const double *plant, const double *surface, double h, int nsteps, double *trajectory, int *steps_done) {
    double k1[8], k2[8], k3[8], k4[8], xt[8];
    int i, step;
    for (step = 0; step < nsteps; ++step) {
        plant_rhs_circle_core(x, tau, arm, plant, surface, k1);
        for (i = 0; i < 8; ++i) xt[i] = x[i] + 0.5 * h * k1[i];
        plant_rhs_circle_core(xt, tau, arm, plant, surface, k2);
        for (i = 0; i < 8; ++i) xt[i] = x[i] + 0.5 * h * k2[i];
        plant_rhs_circle_core(xt, tau, arm, plant, surface, k3);
        for (i = 0; i < 8; ++i) xt[i] = x[i] + h * k3[i];
        plant_rhs_circle_core(xt, tau, arm, plant, surface, k4);
        for (i = 0; i < 8; ++i) xt[i] = x[i] + h / 6.0 * (k1[i] + 2.0 * (k2[i] + k3[i]) + k4[i]);
        if (!all_finite(xt, 8)) {
            if (steps_done) *steps_done = step;
            return HYBRID_NONFINITE;
        }
        for (i = 0; i < 8; ++i) x[i] = xt[i];
        if (trajectory) {
            for (i = 0; i < 8; ++i) trajectory[(long)step * 8 + i] = x[i];
        }
    }
    if (steps_done) *steps_done = nsteps;
    return HYBRID_OK;
}

int hybrid_casadi_plant_outputs_circle(const double *x, const double *arm, const double *plant, const double *surface, double *y) {
    plant_outputs_circle_core(x, arm, plant, surface, y);
    return (all_finite(y, 14)) ? HYBRID_OK : HYBRID_NONFINITE;
}

#if HYBRID_LANES
#define PLANT_OUTPUTS_CIRCLE_LANES_NPRE 12
static void plant_outputs_circle_lanes_pre(const hl_v *arm, const hl_v *plant, const hl_v *surface, hl_v *pre) {
    const hl_v v0 = arm[1];
    const hl_v v11 = arm[0];
    const hl_v v25 = surface[0];
    const hl_v v28 = surface[1];
    const hl_v v48 = plant[2];
    const hl_v v44 = plant[1];
    const hl_v v68 = surface[2];
    const hl_v v80 = plant[4];
    const hl_v v78 = plant[3];
    const hl_v v76 = hl_splat(0.0);
    const hl_v v90 = plant[5];
    const hl_v v95 = plant[6];
    const hl_v v103 = 1.0 / v95;
    pre[0] = v0;
    pre[1] = v11;
    pre[2] = v25;
    pre[3] = v28;
    pre[4] = v48;
    pre[5] = v44;
    pre[6] = v68;
    pre[7] = v80;
    pre[8] = v78;
    pre[9] = v76;
    pre[10] = v90;
    pre[11] = v103;
    (void)arm;
    (void)plant;
    (void)surface;
    (void)pre;
}

static inline __attribute__((always_inline)) void plant_outputs_circle_lanes_core(const hl_v *x, const hl_v *pre, hl_v *y, const int exact, hl_i *odd) {
    (void)x;
    (void)pre;
    (void)odd;
    const hl_v v1 = x[0];
    hl_v v6, v2;
    if (exact) hl_sincos(v1, &v6, &v2); else hl_sincos_poly(v1, &v6, &v2, odd);
    const hl_v v3 = x[1];
    hl_v v7, v4;
    if (exact) hl_sincos(v3, &v7, &v4); else hl_sincos_poly(v3, &v7, &v4, odd);
    const hl_v v5 = v2 * v4;
    const hl_v v8 = v6 * v7;
    const hl_v v9 = v5 - v8;
    const hl_v v0 = pre[0];
    const hl_v v10 = v0 * v9;
    const hl_v v11 = pre[1];
    const hl_v v12 = v2 * v11;
    const hl_v v13 = v10 + v12;
    y[0] = v13;
    const hl_v v14 = v2 * v7;
    const hl_v v15 = v6 * v4;
    const hl_v v16 = v14 + v15;
    const hl_v v17 = v0 * v16;
    const hl_v v18 = v6 * v11;
    const hl_v v19 = v17 + v18;
    y[1] = v19;
    const hl_v v25 = pre[2];
    const hl_v v26 = v13 - v25;
    const hl_v v27 = v26 * v26;
    const hl_v v28 = pre[3];
    const hl_v v29 = v19 - v28;
    const hl_v v30 = v29 * v29;
    const hl_v v31 = v27 + v30;
    const hl_v v32 = hl_sqrt(v31);
    const hl_v v101 = 1.0 / v32;
    const hl_v v22 = x[2];
    const hl_v v23 = v13 * v22;
    const hl_v v20 = x[3];
    const hl_v v21 = v10 * v20;
    const hl_v v24 = v21 + v23;
    const hl_v v33 = v24 * v101;
    const hl_v v34 = v33 * v26;
    const hl_v v36 = v19 * v22;
    const hl_v v35 = v17 * v20;
    const hl_v v37 = v35 + v36;
    const hl_v v38 = v37 * v101;
    const hl_v v39 = v38 * v29;
    const hl_v v40 = v34 + v39;
    y[2] = v40;
    const hl_v v41 = v33 * v29;
    const hl_v v42 = v38 * v26;
    const hl_v v43 = v41 - v42;
    y[3] = v43;
    const hl_v v49 = x[6];
    const hl_v v50 = v37 + v49;
    const hl_v v48 = pre[4];
    const hl_v v51 = v48 * v50;
    const hl_v v45 = x[4];
    y[8] = v45;
    const hl_v v46 = v45 - v13;
    const hl_v v44 = pre[5];
    const hl_v v47 = v44 * v46;
    const hl_v v52 = v47 + v51;
    y[4] = v52;
    const hl_v v56 = x[7];
    const hl_v v57 = v56 - v24;
    const hl_v v58 = v48 * v57;
    const hl_v v53 = x[5];
    y[9] = v53;
    const hl_v v54 = v53 - v19;
    const hl_v v55 = v44 * v54;
    const hl_v v59 = v55 + v58;
    y[5] = v59;
    const hl_v v60 = v26 * v101;
    const hl_v v61 = v59 * v60;
    const hl_v v62 = v29 * v101;
    const hl_v v63 = v52 * v62;
    const hl_v v64 = v61 - v63;
    y[6] = v64;
    const hl_v v65 = v52 * v60;
    const hl_v v66 = v59 * v62;
    const hl_v v67 = v65 + v66;
    y[7] = v67;
    const hl_v v69 = v45 - v25;
    const hl_v v70 = v69 * v69;
    const hl_v v71 = v53 - v28;
    const hl_v v72 = v71 * v71;
    const hl_v v73 = v70 + v72;
    const hl_v v74 = hl_sqrt(v73);
    const hl_v v68 = pre[6];
    const hl_v v75 = v68 - v74;
    y[10] = v75;
    const hl_v v102 = 1.0 / v74;
    const hl_v v81 = v71 * v102;
    const hl_v v82 = v81 * v56;
    const hl_v v83 = v69 * v102;
    const hl_v v84 = v83 * v49;
    const hl_v v85 = v82 + v84;
    const hl_v v80 = pre[7];
    const hl_v v86 = v80 * v85;
    const hl_v v78 = pre[8];
    const hl_v v79 = v75 * v78;
    const hl_v v87 = v79 - v86;
    const hl_v v76 = pre[9];
    const hl_v v88 = hl_fmax(v76, v87);
    const hl_v v77 = hl_bool(v76 < v75);
    const hl_v v89 = hl_select(v77 != 0.0, v88, hl_splat(0.0));
    y[11] = v89;
    const hl_v v90 = pre[10];
    const hl_v v104 = v90 * v88;
    const hl_v v92 = v83 * v56;
    const hl_v v93 = v81 * v49;
    const hl_v v94 = v92 - v93;
    y[13] = v94;
    const hl_v v103 = pre[11];
    const hl_v v96 = v94 * v103;
    const hl_v v97 = (exact ? hl_tanh(v96) : hl_tanh_poly(v96, odd));
    const hl_v v98 = v104 * v97;
    const hl_v v99 = -v98;
    const hl_v v100 = hl_select(v77 != 0.0, v99, hl_splat(0.0));
    y[12] = v100;
}

static __attribute__((noinline, cold)) void plant_outputs_circle_lanes_exact(const hl_v *x, const hl_v *pre, hl_v *y) {
    plant_outputs_circle_lanes_core(x, pre, y, 1, NULL);
}

static void plant_outputs_circle_lanes(const hl_v *x, const hl_v *pre, hl_v *y) {
    hl_i odd = hl_splat(0.0) != 0.0;
    plant_outputs_circle_lanes_core(x, pre, y, 0, &odd);
    if (hl_any(odd)) plant_outputs_circle_lanes_exact(x, pre, y);
}

int hybrid_casadi_plant_outputs_circle_batch(int nstates, const double *x, const double *arm, const double *plant, const double *surface, double *y, int *status) {
    hl_v f_arm[11]; hl_v f_plant[7]; hl_v f_surface[3];
    hl_v pre[PLANT_OUTPUTS_CIRCLE_LANES_NPRE];
    hl_v l_x[8] = {{0}}; hl_v o_y[14];
    long i;
    int j, l, st, failed = 0;
    for (j = 0; j < 11; ++j) f_arm[j] = hl_splat(arm[j]);
    for (j = 0; j < 7; ++j) f_plant[j] = hl_splat(plant[j]);
    for (j = 0; j < 3; ++j) f_surface[j] = hl_splat(surface[j]);
    plant_outputs_circle_lanes_pre(f_arm, f_plant, f_surface, pre);
    for (i = 0; i < nstates; i += HL_W) {
        hl_i bad;
        if (i + HL_W <= nstates) {
            for (j = 0; j < 8; ++j) {
                for (l = 0; l < HL_W; ++l) l_x[j][l] = x[(i + l) * 8 + j];
            }
        } else {
            for (j = 0; j < 8; ++j) {
                for (l = 0; l < HL_W; ++l) l_x[j][l] = x[(i + l < nstates ? i + l : nstates - 1) * 8 + j];
            }
        }
        plant_outputs_circle_lanes(l_x, pre, o_y);
        bad = hl_not_finite(o_y, 14);
        for (l = 0; l < HL_W && i + l < nstates; ++l) {
            for (j = 0; j < 14; ++j) y[(i + l) * 14 + j] = o_y[j][l];
            st = bad[l] ? HYBRID_NONFINITE : HYBRID_OK;
            status[i + l] = st;
            failed += st != HYBRID_OK;
        }
    }
    return failed;
}
#else
int hybrid_casadi_plant_outputs_circle_batch(int nstates, const double *x, const double *arm, const double *plant, const double *surface, double *y, int *status) {
    int i, failed = 0;
    for (i = 0; i < nstates; ++i) {
        status[i] = hybrid_casadi_plant_outputs_circle(x + (long)i * 8, arm, plant, surface, y + (long)i * 14);
        failed += status[i] != HYBRID_OK;
    }
    return failed;
}
#endif
