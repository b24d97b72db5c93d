/* hybrid generated file: do not edit; change codegen/ and run `python -m hybrid regenerate`. body-sha256: 4e9d07fdb44a6387ec599240c61b3c7124d300eb0154c3d99420e2a2d9415def */
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
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a15, a16, a17, a18, a19, a20, a22, a24, a28, a29;
  casadi_real a30, a31, a32, a33, a34, a35, a36, a37, a38, a39, a40, a42;
  casadi_real a43, a44, a45, a46, a47, a48, a49, a50;
  a01=arg[0][0];
  a02=hybrid_cos(a01);
  a08=hybrid_sin(a01);
  a05=arg[0][1];
  a06=hybrid_cos(a05);
  a09=hybrid_sin(a05);
  a10=(a08*a09);
  a16=(a02*a09);
  a07=(a02*a06);
  a11=(a07-a10);
  a17=(a06*a08);
  a18=(a16+a17);
  a00=arg[2][0];
  a03=(a00*a02);
  a15=(a00*a08);
  a04=arg[2][1];
  a12=(a04*a11);
  a13=(a03+a12);
  res[1][3]=a12;
  res[0][0]=a13;
  res[1][2]=a13;
  a19=(a04*a18);
  a20=(a15+a19);
  a24=(-a19);
  res[1][1]=a24;
  res[0][1]=a20;
  a22=(-a20);
  res[1][0]=a22;
  a28=arg[1][0];
  a29=(a28*a13);
  a42=(a28*a20);
  a35=(a04*a28);
  a36=(a35*a11);
  a46=(a35*a18);
  a30=arg[1][1];
  a31=(a04*a30);
  a32=(a31*a11);
  a43=(a31*a18);
  a44=(a42+a43);
  a47=(a46+a43);
  a33=(a29+a32);
  a37=(a36+a32);
  a38=(a30*a37);
  a48=(a30*a47);
  a34=(a28*a33);
  a45=(a28*a44);
  a49=(a45+a48);
  a39=(a34+a38);
  a40=(-a39);
  res[2][0]=a40;
  a50=(-a49);
  res[2][1]=a50;
  return 0;
}

static int casadi_f1(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  (void)arg; (void)iw; (void)mem; (void)w;
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a23, a24;
  casadi_real a25, a26, a27, a30, a31, a33, a34, a35, a36, a37, a38, a39;
  casadi_real a40, a41, a42, a43, a44, a45, a46, a47, a48, a49, a50, a51;
  casadi_real a52, a53, a54, a55, a56, a57, a58, a59, a60, a61, a62, a63;
  casadi_real a64, a65, a66, a67, a68, a70, a71, a72, a73, a74, a75, a76;
  casadi_real a77, a78;
  a16=arg[0][1];
  a17=hybrid_cos(a16);
  a43=hybrid_sin(a16);
  a38=arg[0][0];
  a39=hybrid_cos(a38);
  a42=hybrid_sin(a38);
  a44=(a42*a43);
  a41=(a39*a17);
  a45=(a41-a44);
  a09=arg[2][0];
  a40=(a09*a39);
  a14=(2.*a09);
  a10=casadi_sq(a09);
  a11=arg[2][5];
  a15=(a14*a11);
  a18=(a15*a17);
  a46=(a11*a45);
  a47=(a40+a46);
  a12=casadi_sq(a11);
  a13=(a10+a12);
  a19=(a13+a18);
  a23=(a09*a11);
  a24=(a23*a17);
  a25=(a12+a24);
  a61=-2.;
  a62=(a61*a09);
  a03=arg[2][2];
  a08=arg[2][3];
  a54=(a09*a08);
  a63=(a62*a08);
  a64=(a63*a11);
  a55=(a54*a11);
  a20=(a08*a19);
  a26=(a08*a25);
  a30=(a08*a12);
  a36=arg[2][10];
  a37=(a36*a08);
  a50=(a36*a03);
  a48=(a37*a47);
  a72=(a37*a11);
  a73=(a72*a45);
  a04=arg[2][4];
  a51=(a50*a04);
  a52=(a51*a39);
  a05=casadi_sq(a04);
  a06=(a03*a05);
  a33=arg[2][8];
  a34=arg[1][0];
  a35=(a33*a34);
  a49=(a35+a48);
  a53=(a49+a52);
  a65=(a64*a34);
  a75=casadi_sq(a34);
  a76=(a55*a75);
  a77=(a76*a43);
  a56=arg[1][1];
  a66=(a65*a56);
  a67=(a66*a43);
  a57=casadi_sq(a56);
  a58=(a55*a57);
  a59=(a58*a43);
  a60=(a53-a59);
  a68=(a60+a67);
  res[1][0]=a68;
  a00=arg[2][6];
  a01=arg[2][7];
  a02=(a00+a01);
  a07=(a02+a06);
  a21=(a07+a20);
  res[0][0]=a21;
  a27=(a01+a26);
  a31=(a01+a30);
  res[0][3]=a31;
  res[0][1]=a27;
  res[0][2]=a27;
  a70=arg[2][9];
  a71=(a70*a56);
  a74=(a71+a73);
  a78=(a74+a77);
  res[1][1]=a78;
  return 0;
}

static int casadi_f2(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  (void)arg; (void)iw; (void)mem; (void)w;
  casadi_real a000, a001, a002, a003, a004, a005, a006, a007, a008, a009, a010, a011;
  casadi_real a012, a013, a014, a015, a016, a017, a018, a019, a020, a021, a022, a023;
  casadi_real a024, a025, a026, a027, a028, a029, a030, a031, a032, a033, a034, a035;
  casadi_real a036, a037, a038, a039, a040, a041, a042, a043, a044, a045, a046, a047;
  casadi_real a048, a049, a050, a051, a052, a053, a054, a055, a056, a057, a058, a059;
  casadi_real a060, a061, a062, a063, a064, a066, a067, a068, a069, a070, a072, a073;
  casadi_real a074, a075, a076, a077, a078, a079, a080, a082, a083, a084, a086, a087;
  casadi_real a088, a089, a090, a091, a092, a093, a094, a095, a096, a097, a098, a099;
  casadi_real a100, a101, a102, a103, a104, a105, a106, a107, a108, a109, a110, a111;
  casadi_real a112, a113, a114, a115, a116, a117, a118, a119, a120, a121, a122, a123;
  casadi_real a124, a125, a126, a127, a128, a129, a130, a131, a132, a133, a134, a135;
  casadi_real a136, a137, a138, a139, a140, a141, a142, a143, a144, a145, a146, a147;
  casadi_real a149, a150, a151, a152, a153, a154, a155, a157, a158, a159, a160, a161;
  casadi_real a162, a163, a164, a165, a166, a167, a168, a169, a170, a171, a172, a173;
  a002=arg[0][0];
  a003=hybrid_cos(a002);
  a008=hybrid_sin(a002);
  a005=arg[0][1];
  a006=hybrid_cos(a005);
  a009=hybrid_sin(a005);
  a010=(a008*a009);
  a007=(a003*a006);
  a011=(a007-a010);
  a015=(a003*a009);
  a016=(a006*a008);
  a017=(a015+a016);
  a167=casadi_sq(a011);
  a170=casadi_sq(a017);
  a000=arg[2][1];
  a012=(a000*a011);
  a020=(a000*a017);
  a157=(2.*a000);
  a166=casadi_sq(a000);
  a168=(a166*a167);
  a171=(a166*a170);
  a160=(a157*a011);
  a001=arg[2][0];
  a019=(a001*a008);
  a021=(a019+a020);
  a161=(a160*a021);
  a004=(a001*a003);
  a013=(a004+a012);
  a022=(a012*a021);
  a158=(a157*a013);
  a159=(a158*a017);
  a162=(a159-a161);
  a039=(2.*a001);
  a014=(a000*a013);
  a018=(a014*a017);
  a023=(a018-a022);
  a035=casadi_sq(a001);
  a024=(a000/a023);
  a025=(a024*a011);
  a066=(a024*a017);
  a055=(a013/a023);
  a068=(a021/a023);
  a163=casadi_sq(a013);
  a164=casadi_sq(a021);
  a165=(a163+a164);
  a169=(a165+a168);
  a172=(a169+a171);
  a173=(a162/a172);
  res[2][0]=a173;
  a036=arg[2][5];
  a040=(a039*a036);
  a041=(a040*a006);
  a046=(a001*a036);
  a047=(a046*a006);
  a037=casadi_sq(a036);
  a038=(a035+a037);
  a042=(a038+a041);
  a048=(a037+a047);
  a126=(a036*a011);
  a127=(a004+a126);
  a030=arg[2][4];
  a031=casadi_sq(a030);
  a026=arg[2][6];
  a027=arg[2][7];
  a028=(a026+a027);
  a029=arg[2][2];
  a032=(a029*a031);
  a033=(a028+a032);
  a034=arg[2][3];
  a049=(a034*a048);
  a058=(a034*a037);
  a059=(a027+a058);
  a050=(a027+a049);
  a043=(a034*a042);
  a044=(a033+a043);
  a056=(a024*a050);
  a051=(a050/a023);
  a060=(a059/a023);
  a061=(a060*a013);
  a077=(a060*a021);
  a052=(a051*a013);
  a073=(a051*a021);
  a057=(a056*a011);
  a062=(a057-a061);
  a076=(a056*a017);
  a078=(a076-a077);
  a045=(a025*a044);
  a053=(a045-a052);
  a072=(a066*a044);
  a074=(a072-a073);
  a116=(a001*a034);
  a117=(a116*a036);
  a075=(a025*a074);
  a082=(a066*a074);
  a054=(a025*a053);
  a067=(a066*a053);
  a079=(a055*a078);
  a080=(a075-a079);
  a083=(a068*a078);
  a084=(a082-a083);
  res[0][3]=a084;
  res[0][2]=a080;
  a063=(a055*a062);
  a064=(a054-a063);
  a069=(a068*a062);
  a070=(a067-a069);
  res[0][1]=a070;
  res[0][0]=a064;
  a086=arg[1][0];
  a087=(a086*a013);
  a099=(a086*a021);
  a093=(a000*a086);
  a094=(a093*a011);
  a103=(a093*a017);
  a118=casadi_sq(a086);
  a119=(a117*a118);
  a120=(a119*a009);
  a088=arg[1][1];
  a089=(a000*a088);
  a100=(a089*a017);
  a090=(a089*a011);
  a091=(a087+a090);
  a095=(a094+a090);
  a101=(a099+a100);
  a104=(a103+a100);
  a105=(a088*a104);
  a102=(a086*a101);
  a106=(a102+a105);
  a096=(a088*a095);
  a092=(a086*a091);
  a097=(a092+a096);
  a098=(a097*a064);
  a149=(a097*a080);
  a107=(a106*a070);
  a150=(a106*a084);
  a151=(a149+a150);
  a108=(a098+a107);
  a134=casadi_sq(a088);
  a135=(a117*a134);
  a136=(a135*a009);
  a138=-2.;
  a139=(a138*a001);
  a140=(a139*a034);
  a141=(a140*a036);
  a142=(a141*a086);
  a143=(a142*a088);
  a144=(a143*a009);
  a111=arg[2][10];
  a112=(a111*a034);
  a130=(a111*a029);
  a131=(a130*a030);
  a132=(a131*a003);
  a113=(a112*a036);
  a128=(a112*a127);
  a114=(a113*a011);
  a124=arg[2][8];
  a125=(a124*a086);
  a129=(a125+a128);
  a133=(a129+a132);
  a137=(a133-a136);
  a145=(a137+a144);
  a146=(a025*a145);
  a154=(a066*a145);
  a109=arg[2][9];
  a110=(a109*a088);
  a115=(a110+a114);
  a121=(a115+a120);
  a122=(a055*a121);
  a152=(a068*a121);
  a153=(a151-a152);
  a123=(a108-a122);
  a147=(a123+a146);
  a155=(a153+a154);
  res[1][1]=a155;
  res[1][0]=a147;
  return 0;
}

static int casadi_f3(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  (void)arg; (void)iw; (void)mem; (void)w;
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a09, a13;
  a00=arg[2][3];
  a03=casadi_sq(a00);
  a01=arg[2][2];
  a02=casadi_sq(a01);
  a04=(a02+a03);
  a05=sqrt(a04);
  a06=(a00/a05);
  a09=(a01/a05);
  res[0][1]=a09;
  res[0][2]=a09;
  res[0][3]=a06;
  a07=(-a06);
  res[0][0]=a07;
  a13=0.;
  res[1][0]=a13;
  res[1][1]=a13;
  res[1][2]=a13;
  res[1][3]=a13;
  return 0;
}

static int casadi_f4(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  (void)arg; (void)iw; (void)mem; (void)w;
  casadi_real a000, a001, a002, a003, a004, a005, a006, a007, a008, a009, a010, a011;
  casadi_real a012, a013, a014, a015, a016, a017, a018, a019, a020, a021, a022, a023;
  casadi_real a024, a025, a026, a027, a028, a029, a030, a031, a032, a033, a034, a035;
  casadi_real a036, a037, a038, a039, a040, a041, a042, a043, a044, a045, a046, a047;
  casadi_real a048, a049, a050, a051, a052, a053, a054, a055, a056, a057, a058, a059;
  casadi_real a060, a061, a062, a063, a064, a065, a066, a067, a068, a069, a070, a071;
  casadi_real a072, a073, a074, a075, a076, a077, a078, a079, a080, a081, a082, a083;
  casadi_real a084, a085, a086, a087, a088, a089, a090, a091, a092, a093, a094, a095;
  casadi_real a096, a097, a098, a099, a100, a101, a102, a103, a104, a105, a106, a107;
  casadi_real a108, a109, a110, a111, a112, a113, a114, a115, a116, a117, a118, a119;
  casadi_real a120, a121, a122, a123, a124, a125, a126, a127, a128, a129, a130, a131;
  casadi_real a132, a133, a134, a135, a136, a137, a138, a139, a140, a141, a142, a143;
  casadi_real a144, a145, a146, a147, a148, a149, a150, a151, a152, a153, a154, a155;
  casadi_real a156, a157, a158, a160, a161, a162, a166, a167, a168, a169, a170, a171;
  casadi_real a172, a173, a174, a175, a176, a177, a178, a179, a180, a181, a182;
  a002=arg[0][0];
  a003=hybrid_cos(a002);
  a008=hybrid_sin(a002);
  a005=arg[0][1];
  a006=hybrid_cos(a005);
  a009=hybrid_sin(a005);
  a010=(a008*a009);
  a015=(a003*a009);
  a007=(a003*a006);
  a011=(a007-a010);
  a016=(a006*a008);
  a017=(a015+a016);
  a176=casadi_sq(a011);
  a179=casadi_sq(a017);
  a000=arg[4][1];
  a012=(a000*a011);
  a020=(a000*a017);
  a166=(2.*a000);
  a175=casadi_sq(a000);
  a177=(a175*a176);
  a180=(a175*a179);
  a169=(a166*a011);
  a001=arg[4][0];
  a019=(a001*a008);
  a021=(a019+a020);
  a170=(a169*a021);
  a004=(a001*a003);
  a013=(a004+a012);
  a022=(a012*a021);
  a167=(a166*a013);
  a168=(a167*a017);
  a171=(a168-a170);
  a014=(a000*a013);
  a018=(a014*a017);
  a023=(a018-a022);
  a097=(2.*a001);
  a095=casadi_sq(a001);
  a024=(a000/a023);
  a038=(a013/a023);
  a065=(a021/a023);
  a025=(a024*a011);
  a085=(a024*a017);
  a172=casadi_sq(a013);
  a173=casadi_sq(a021);
  a174=(a172+a173);
  a178=(a174+a177);
  a181=(a178+a180);
  a182=(a171/a181);
  res[2][0]=a182;
  a027=arg[1][0];
  a045=(a000*a027);
  a046=(a045*a011);
  a070=(a045*a017);
  a039=(a027*a013);
  a066=(a027*a021);
  a153=casadi_sq(a027);
  a040=arg[1][1];
  a041=(a000*a040);
  a042=(a041*a011);
  a067=(a041*a017);
  a068=(a066+a067);
  a071=(a070+a067);
  a043=(a039+a042);
  a047=(a046+a042);
  a048=(a040*a047);
  a044=(a027*a043);
  a049=(a044+a048);
  a072=(a040*a071);
  a069=(a027*a068);
  a073=(a069+a072);
  a123=casadi_sq(a040);
  a051=arg[5][2];
  a053=casadi_sq(a051);
  a054=arg[5][3];
  a055=casadi_sq(a054);
  a056=(a053+a055);
  a057=sqrt(a056);
  a050=arg[2][1];
  a052=(a050*a051);
  a058=(a052/a057);
  a059=(a049+a058);
  a077=(a050*a054);
  a078=(a077/a057);
  a060=arg[2][0];
  a074=(a060*a051);
  a061=(a060*a054);
  a075=(a074/a057);
  a076=(a073+a075);
  a062=(a061/a057);
  a063=(a059-a062);
  a079=(a076+a078);
  a080=(a065*a079);
  a086=(a085*a079);
  a064=(a038*a063);
  a081=(a064+a080);
  a084=(a025*a063);
  a087=(a084+a086);
  a031=arg[4][5];
  a098=(a097*a031);
  a099=(a098*a006);
  a033=(a001*a031);
  a034=(a033*a006);
  a032=casadi_sq(a031);
  a035=(a032+a034);
  a096=(a095+a032);
  a100=(a096+a099);
  a113=(a031*a011);
  a114=(a004+a113);
  a091=arg[4][4];
  a092=casadi_sq(a091);
  a029=arg[4][7];
  a030=arg[4][3];
  a036=(a030*a035);
  a037=(a029+a036);
  a101=(a030*a100);
  a138=(a030*a032);
  a139=(a029+a138);
  a140=(a139*a081);
  a082=(a037*a081);
  a142=(a037*a087);
  a121=(a001*a030);
  a122=(a121*a031);
  a124=(a122*a123);
  a154=(a122*a153);
  a125=(a124*a009);
  a155=(a154*a009);
  a088=arg[4][6];
  a089=(a088+a029);
  a090=arg[4][2];
  a093=(a090*a092);
  a094=(a089+a093);
  a102=(a094+a101);
  a103=(a087*a102);
  a026=arg[4][8];
  a028=(a026*a027);
  a083=(a028-a082);
  a104=(a083+a103);
  a105=arg[3][0];
  a106=(a105*a021);
  a107=(a104+a106);
  a144=(a105*a000);
  a145=(a144*a017);
  a127=-2.;
  a128=(a127*a001);
  a129=(a128*a030);
  a130=(a129*a031);
  a131=(a130*a027);
  a132=(a131*a040);
  a133=(a132*a009);
  a136=arg[4][9];
  a137=(a136*a040);
  a141=(a137-a140);
  a143=(a141+a142);
  a146=(a143+a145);
  a108=arg[3][1];
  a109=(a108*a013);
  a110=(a107-a109);
  a147=(a108*a000);
  a148=(a147*a011);
  a149=(a146-a148);
  a111=arg[4][10];
  a112=(a111*a030);
  a117=(a111*a090);
  a118=(a117*a091);
  a119=(a118*a003);
  a115=(a112*a114);
  a116=(a110+a115);
  a150=(a112*a031);
  a151=(a150*a011);
  a120=(a116+a119);
  a126=(a120-a125);
  a152=(a149+a151);
  a156=(a152+a155);
  a134=(a126+a133);
  a135=(a025*a134);
  a160=(a085*a134);
  res[1][0]=a134;
  a157=(a038*a156);
  a158=(a135-a157);
  res[0][0]=a158;
  a161=(a065*a156);
  a162=(a160-a161);
  res[0][1]=a162;
  res[1][1]=a156;
  return 0;
}

static int casadi_f5(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  (void)arg; (void)iw; (void)mem; (void)w;
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a15, a16, a17, a18, a19, a20, a22, a23, a24, a25;
  casadi_real a26, a27, a28, a30, a31, a32, a34, a35, a36, a37, a38, a39;
  casadi_real a40, a41, a42, a43, a44, a46, a47, a48, a50, a51, a52, a53;
  casadi_real a54, a55, a56, a58, a59, a60, a61, a62;
  a01=arg[0][0];
  a02=hybrid_cos(a01);
  a08=hybrid_sin(a01);
  a05=arg[0][1];
  a06=hybrid_cos(a05);
  a09=hybrid_sin(a05);
  a10=(a08*a09);
  a16=(a02*a09);
  a07=(a02*a06);
  a11=(a07-a10);
  a17=(a06*a08);
  a18=(a16+a17);
  a00=arg[3][0];
  a03=(a00*a02);
  a15=(a00*a08);
  a04=arg[3][1];
  a12=(a04*a11);
  a13=(a03+a12);
  res[0][0]=a13;
  a19=(a04*a18);
  a20=(a15+a19);
  res[0][1]=a20;
  a34=arg[4][2];
  a35=casadi_sq(a34);
  a36=arg[4][3];
  a37=casadi_sq(a36);
  a38=(a35+a37);
  a39=sqrt(a38);
  a40=(a34/a39);
  a42=(a36/a39);
  a24=arg[1][1];
  a25=(a04*a24);
  a26=(a25*a18);
  a31=(a25*a11);
  a22=arg[1][0];
  a23=(a22*a20);
  a30=(a22*a13);
  a32=(a30+a31);
  a27=(a23+a26);
  res[1][1]=a32;
  a43=(a42*a27);
  a46=(a42*a32);
  a41=(a40*a32);
  a44=(a41+a43);
  res[2][0]=a44;
  a47=(a40*a27);
  a48=(a46-a47);
  res[2][1]=a48;
  a28=(-a27);
  res[1][0]=a28;
  a50=arg[2][1];
  a51=(a50*a34);
  a60=(a50*a36);
  a61=(a60/a39);
  a52=(a51/a39);
  a53=arg[2][0];
  a54=(a53*a36);
  a58=(a53*a34);
  a59=(a58/a39);
  a55=(a54/a39);
  a56=(a52-a55);
  a62=(a59+a61);
  res[3][1]=a62;
  res[3][0]=a56;
  return 0;
}

static int casadi_f6(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  (void)arg; (void)iw; (void)mem; (void)w;
  casadi_real a000, a002, a004, a005, a006, a007, a008, a009, a010, a011, a012, a013;
  casadi_real a014, a015, a016, a017, a018, a019, a020, a021, a022, a023, a024, a025;
  casadi_real a026, a027, a028, a029, a030, a031, a032, a033, a034, a035, a036, a037;
  casadi_real a038, a039, a040, a041, a042, a043, a044, a045, a046, a047, a048, a049;
  casadi_real a050, a051, a052, a053, a054, a055, a056, a057, a058, a059, a060, a061;
  casadi_real a062, a063, a064, a065, a066, a067, a068, a069, a070, a071, a072, a073;
  casadi_real a074, a075, a076, a077, a078, a079, a080, a081, a082, a083, a084, a085;
  casadi_real a086, a087, a088, a089, a090, a091, a092, a093, a094, a095, a096, a097;
  casadi_real a098, a099, a100, a101, a102, a103, a104, a105, a106, a107, a108, a109;
  casadi_real a110, a111, a112, a113, a114, a115, a116, a117, a118, a119, a120, a121;
  casadi_real a122, a123, a124, a125, a126, a127, a128, a129, a131, a132, a133, a134;
  casadi_real a138, a139, a140, a141, a142, a143, a144, a145, a146, a147, a148, a149;
  casadi_real a150, a151, a152, a153, a154, a155, a156, a157, a158, a159, a160, a161;
  casadi_real a162, a163, a164, a165, a166, a167, a168, a169, a170, a171, a172, a173;
  casadi_real a174, a175, a176, a177, a178, a179, a180, a181, a182, a183, a184, a185;
  casadi_real a186, a188, a189, a190, a191, a192, a193, a194, a195, a196, a197, a198;
  a022=arg[0][1];
  a023=hybrid_cos(a022);
  a044=hybrid_sin(a022);
  a038=arg[0][0];
  a039=hybrid_cos(a038);
  a043=hybrid_sin(a038);
  a045=(a043*a044);
  a042=(a039*a023);
  a046=(a042-a045);
  a054=(a023*a043);
  a053=(a039*a044);
  a055=(a053+a054);
  a138=arg[4][2];
  a139=casadi_sq(a138);
  a140=arg[4][3];
  a141=casadi_sq(a140);
  a142=(a139+a141);
  a143=sqrt(a142);
  a144=(a138/a143);
  a148=(a140/a143);
  a060=arg[0][7];
  res[0][5]=a060;
  a174=(a138*a060);
  a175=(a174/a143);
  a160=(a140*a060);
  a161=(a160/a143);
  a074=arg[0][6];
  res[0][4]=a074;
  a176=(a140*a074);
  a177=(a176/a143);
  a178=(a175-a177);
  a158=(a138*a074);
  a159=(a158/a143);
  a162=(a159+a161);
  a179=arg[3][6];
  a180=(a178/a179);
  a181=tanh(a180);
  a017=arg[2][0];
  a051=(a017*a043);
  a040=(a017*a039);
  a020=(2.*a017);
  a018=casadi_sq(a017);
  a041=arg[2][1];
  a047=(a041*a046);
  a048=(a040+a047);
  a056=(a041*a055);
  a075=(a051+a056);
  a000=arg[0][2];
  res[0][0]=a000;
  a061=(a000*a048);
  a062=(a060-a061);
  a076=(a000*a075);
  a077=(a074+a076);
  a124=casadi_sq(a000);
  a002=arg[0][3];
  res[0][1]=a002;
  a063=(a041*a002);
  a064=(a063*a046);
  a065=(a062-a064);
  a078=(a063*a055);
  a079=(a077+a078);
  a099=casadi_sq(a002);
  a050=arg[0][5];
  a052=(a050-a051);
  a057=(a052-a056);
  a070=arg[0][4];
  a071=(a070-a040);
  a072=(a071-a047);
  a145=arg[4][0];
  a146=(a070-a145);
  a147=(a144*a146);
  a149=arg[4][1];
  a150=(a050-a149);
  a151=(a148*a150);
  a152=(a147+a151);
  a049=arg[3][1];
  a058=(a049*a057);
  a073=(a049*a072);
  a059=arg[3][2];
  a066=(a059*a065);
  a067=(a058+a066);
  a080=(a059*a079);
  a081=(a073+a080);
  a068=(a048*a067);
  a082=(a081*a075);
  a115=(a041*a067);
  a116=(a115*a046);
  a118=(a041*a081);
  a119=(a118*a055);
  a006=arg[2][5];
  a007=casadi_sq(a006);
  a019=(a018+a007);
  a021=(a020*a006);
  a024=(a021*a023);
  a025=(a019+a024);
  a029=(a017*a006);
  a030=(a029*a023);
  a031=(a007+a030);
  a089=(a006*a046);
  a090=(a040+a089);
  a155=arg[3][3];
  a156=(a155*a152);
  a157=arg[3][4];
  a163=(a157*a162);
  a164=(a156+a163);
  a165=(-a164);
  a013=arg[2][4];
  a014=casadi_sq(a013);
  a037=arg[1][0];
  a069=(a037+a068);
  a083=(a069-a082);
  a004=arg[2][7];
  a005=arg[2][3];
  a097=(a017*a005);
  a103=(a020*a005);
  a104=(a103*a006);
  a098=(a097*a006);
  a008=(a005*a007);
  a026=(a005*a025);
  a032=(a005*a031);
  a033=(a004+a032);
  a009=(a004+a008);
  a100=(a098*a099);
  a125=(a098*a124);
  a105=(a104*a000);
  a106=(a105*a002);
  a101=(a100*a044);
  a107=(a106*a044);
  a126=(a125*a044);
  a034=casadi_sq(a033);
  a010=arg[2][6];
  a011=(a010+a004);
  a012=arg[2][2];
  a015=(a012*a014);
  a016=(a011+a015);
  a027=(a016+a026);
  a028=(a009*a027);
  a035=(a028-a034);
  a036=(a009/a035);
  a110=(a033/a035);
  a131=(a027/a035);
  a084=arg[2][8];
  a085=(a084*a000);
  a086=(a083-a085);
  a087=arg[2][10];
  a088=(a087*a005);
  a093=(a087*a012);
  a094=(a093*a013);
  a095=(a094*a039);
  a091=(a088*a090);
  a092=(a086-a091);
  a121=(a088*a006);
  a122=(a121*a046);
  a096=(a092-a095);
  a102=(a096+a101);
  a108=(a102+a107);
  a109=(a036*a108);
  a133=(a110*a108);
  a112=arg[2][9];
  a113=(a112*a002);
  a170=arg[3][5];
  a191=(a170*a138);
  a171=(a170*a140);
  a192=(a191/a143);
  a172=(a171/a143);
  a111=arg[1][1];
  a114=(a111-a113);
  a117=(a114+a116);
  a120=(a117-a119);
  a123=(a120-a122);
  a127=(a123-a126);
  a128=(a110*a127);
  a132=(a131*a127);
  a134=(a132-a133);
  a129=(a109-a128);
  res[0][2]=a129;
  res[0][3]=a134;
  a153=0.;
  a166=casadi_fmax(a153,a165);
  a154=(a152<a153);
  a193=(a192*a166);
  a194=(a193*a181);
  a167=(a144*a166);
  a173=(a172*a166);
  a188=(a148*a166);
  a182=(a173*a181);
  a189=(a154?a188:0);
  a190=(a189-a067);
  a168=(a154?a167:0);
  a169=(a168-a081);
  a195=(-a194);
  a196=(a154?a195:0);
  a183=(a154?a182:0);
  a184=(a169+a183);
  a197=(a190+a196);
  a185=arg[3][0];
  a186=(a184/a185);
  a198=(a197/a185);
  res[0][7]=a198;
  res[0][6]=a186;
  return 0;
}

static int casadi_f7(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  (void)arg; (void)iw; (void)mem; (void)w;
  casadi_real a000, a001, a002, a003, a004, a005, a006, a007, a008, a009, a010, a011;
  casadi_real a012, a013, a015, a016, a017, a018, a019, a020, a022, a023, a024, a025;
  casadi_real a026, a027, a028, a029, a030, a031, a032, a033, a034, a035, a036, a037;
  casadi_real a038, a039, a040, a041, a043, a044, a045, a047, a048, a049, a050, a051;
  casadi_real a052, a053, a054, a055, a056, a057, a059, a060, a061, a062, a063, a064;
  casadi_real a065, a066, a067, a069, a070, a071, a073, a074, a075, a079, a080, a081;
  casadi_real a082, a083, a084, a085, a086, a088, a089, a090, a091, a092, a093, a094;
  casadi_real a095, a096, a097, a098, a099, a100, a101, a102, a104, a105, a106, a107;
  casadi_real a108, a109, a110, a111, a112, a113, a114, a115, a116;
  a001=arg[0][0];
  a002=hybrid_cos(a001);
  a008=hybrid_sin(a001);
  a005=arg[0][1];
  a006=hybrid_cos(a005);
  a009=hybrid_sin(a005);
  a010=(a008*a009);
  a016=(a002*a009);
  a007=(a002*a006);
  a011=(a007-a010);
  a017=(a006*a008);
  a018=(a016+a017);
  a022=arg[3][2];
  a023=casadi_sq(a022);
  a024=arg[3][3];
  a025=casadi_sq(a024);
  a026=(a023+a025);
  a027=sqrt(a026);
  a028=(a022/a027);
  a036=(a024/a027);
  a053=arg[0][6];
  a108=(a024*a053);
  a109=(a108/a027);
  a093=(a022*a053);
  a094=(a093/a027);
  a063=arg[0][7];
  a106=(a022*a063);
  a107=(a106/a027);
  a110=(a107-a109);
  a095=(a024*a063);
  a096=(a095/a027);
  a097=(a094+a096);
  res[0][13]=a110;
  a111=arg[2][6];
  a112=(a110/a111);
  a113=tanh(a112);
  a048=arg[0][4];
  res[0][8]=a048;
  a059=arg[0][5];
  res[0][9]=a059;
  a079=arg[3][0];
  a080=(a048-a079);
  a081=(a028*a080);
  a082=arg[3][1];
  a083=(a059-a082);
  a084=(a036*a083);
  a085=(a081+a084);
  a086=(-a085);
  res[0][10]=a086;
  a000=arg[1][0];
  a003=(a000*a002);
  a015=(a000*a008);
  a060=(a059-a015);
  a049=(a048-a003);
  a004=arg[1][1];
  a012=(a004*a011);
  a013=(a003+a012);
  a050=(a049-a012);
  res[0][0]=a013;
  a019=(a004*a018);
  a020=(a015+a019);
  a061=(a060-a019);
  res[0][1]=a020;
  a090=arg[2][3];
  a091=(a090*a085);
  a092=arg[2][4];
  a098=(a092*a097);
  a099=(a091+a098);
  a100=(-a099);
  a029=arg[0][2];
  a030=(a029*a013);
  a037=(a029*a020);
  a054=(a053+a037);
  a064=(a063-a030);
  a031=arg[0][3];
  a032=(a004*a031);
  a033=(a032*a011);
  a038=(a032*a018);
  a055=(a054+a038);
  a039=(a037+a038);
  a065=(a064-a033);
  a034=(a030+a033);
  a035=(a028*a034);
  a043=(a036*a034);
  a040=(a036*a039);
  a041=(a035+a040);
  res[0][2]=a041;
  a044=(a028*a039);
  a045=(a043-a044);
  res[0][3]=a045;
  a088=0.;
  a101=casadi_fmax(a088,a100);
  a089=(a085<a088);
  a102=(a089?a101:0);
  res[0][11]=a102;
  a047=arg[2][1];
  a051=(a047*a050);
  a062=(a047*a061);
  a052=arg[2][2];
  a056=(a052*a055);
  a066=(a052*a065);
  a067=(a062+a066);
  a057=(a051+a056);
  res[0][4]=a057;
  res[0][5]=a067;
  a070=(a036*a057);
  a073=(a028*a057);
  a069=(a028*a067);
  a074=(a036*a067);
  a075=(a073+a074);
  a071=(a069-a070);
  res[0][6]=a071;
  res[0][7]=a075;
  a104=arg[2][5];
  a105=(a104*a101);
  a114=(a105*a113);
  a115=(-a114);
  a116=(a089?a115:0);
  res[0][12]=a116;
  return 0;
}

static int casadi_f8(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  (void)arg; (void)iw; (void)mem; (void)w;
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a13, a17, a18, a19, a20, a21, a22, a23, a24, a25, a26, a27;
  casadi_real a29, a30, a31;
  a00=arg[0][1];
  a01=arg[2][1];
  a02=(a00-a01);
  a07=casadi_sq(a02);
  a03=arg[0][0];
  a04=arg[2][0];
  a05=(a03-a04);
  a06=casadi_sq(a05);
  a08=(a06+a07);
  a09=sqrt(a08);
  a10=(a02/a09);
  res[0][3]=a10;
  a13=(a05/a09);
  res[0][1]=a13;
  res[0][2]=a13;
  a11=(-a10);
  res[0][0]=a11;
  a17=arg[1][1];
  a21=(a17/a09);
  a22=(a21*a02);
  a18=arg[1][0];
  a19=(a18/a09);
  a20=(a19*a05);
  a23=(a20+a22);
  a24=(a10*a23);
  a25=(a17-a24);
  a29=(a13*a23);
  a30=(a18-a29);
  a26=(a25/a09);
  a31=(a30/a09);
  res[1][1]=a31;
  res[1][2]=a31;
  res[1][3]=a26;
  a27=(-a26);
  res[1][0]=a27;
  return 0;
}

static int casadi_f9(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  (void)arg; (void)iw; (void)mem; (void)w;
  casadi_real a000, a001, a002, a003, a004, a005, a006, a007, a008, a009, a010, a011;
  casadi_real a012, a013, a014, a015, a016, a017, a018, a019, a020, a021, a022, a023;
  casadi_real a024, a025, a026, a027, a028, a029, a030, a031, a032, a033, a034, a035;
  casadi_real a036, a037, a038, a039, a040, a041, a042, a043, a044, a045, a046, a047;
  casadi_real a048, a049, a050, a051, a052, a053, a054, a055, a056, a057, a058, a059;
  casadi_real a060, a061, a062, a063, a064, a065, a066, a067, a068, a069, a070, a071;
  casadi_real a072, a073, a074, a075, a076, a077, a078, a079, a080, a081, a082, a083;
  casadi_real a084, a085, a086, a087, a088, a089, a090, a091, a092, a093, a094, a095;
  casadi_real a096, a097, a098, a099, a100, a101, a102, a103, a104, a105, a106, a107;
  casadi_real a108, a109, a110, a111, a112, a113, a114, a115, a116, a117, a118, a119;
  casadi_real a120, a121, a122, a123, a124, a125, a126, a127, a128, a129, a130, a131;
  casadi_real a132, a133, a134, a135, a136, a137, a138, a139, a140, a141, a142, a143;
  casadi_real a144, a145, a146, a147, a148, a149, a150, a151, a152, a153, a154, a155;
  casadi_real a156, a157, a158, a159, a160, a161, a162, a163, a164, a165, a166, a167;
  casadi_real a168, a169, a170, a171, a172, a173, a174, a175, a176, a177, a178, a179;
  casadi_real a180, a181, a182, a184, a185, a186, a190, a191, a192, a193, a194, a195;
  casadi_real a196, a197, a198, a199, a200, a201, a202, a203, a204, a205, a206;
  a002=arg[0][0];
  a003=hybrid_cos(a002);
  a008=hybrid_sin(a002);
  a005=arg[0][1];
  a006=hybrid_cos(a005);
  a009=hybrid_sin(a005);
  a010=(a008*a009);
  a015=(a003*a009);
  a007=(a003*a006);
  a011=(a007-a010);
  a016=(a006*a008);
  a017=(a015+a016);
  a200=casadi_sq(a011);
  a203=casadi_sq(a017);
  a001=arg[4][0];
  a019=(a001*a008);
  a004=(a001*a003);
  a121=(2.*a001);
  a119=casadi_sq(a001);
  a000=arg[4][1];
  a012=(a000*a011);
  a020=(a000*a017);
  a021=(a019+a020);
  a013=(a004+a012);
  a014=(a000*a013);
  a018=(a014*a017);
  a022=(a012*a021);
  a023=(a018-a022);
  a024=(a000/a023);
  a038=(a013/a023);
  a094=(a021/a023);
  a025=(a024*a011);
  a109=(a024*a017);
  a196=casadi_sq(a013);
  a197=casadi_sq(a021);
  a198=(a196+a197);
  a190=(2.*a000);
  a199=casadi_sq(a000);
  a201=(a199*a200);
  a202=(a198+a201);
  a204=(a199*a203);
  a205=(a202+a204);
  a191=(a190*a013);
  a193=(a190*a011);
  a194=(a193*a021);
  a192=(a191*a017);
  a195=(a192-a194);
  a206=(a195/a205);
  res[2][0]=a206;
  a052=arg[5][0];
  a053=(a004-a052);
  a054=(a053+a012);
  a055=casadi_sq(a054);
  a056=arg[5][1];
  a057=(a019-a056);
  a058=(a057+a020);
  a059=casadi_sq(a058);
  a060=(a055+a059);
  a061=sqrt(a060);
  a040=arg[1][1];
  a041=(a000*a040);
  a042=(a041*a011);
  a067=(a041*a017);
  a147=casadi_sq(a040);
  a027=arg[1][0];
  a039=(a027*a013);
  a043=(a039+a042);
  a066=(a027*a021);
  a068=(a066+a067);
  a069=(a068/a061);
  a070=(a069*a054);
  a064=(a043/a061);
  a065=(a064*a058);
  a071=(a065-a070);
  a072=(a071/a061);
  a073=(a072*a058);
  a074=(a043-a073);
  a078=(a072*a054);
  a079=(a068+a078);
  a045=(a000*a027);
  a046=(a045*a011);
  a047=(a046+a042);
  a096=(a045*a017);
  a097=(a096+a067);
  a098=(a040*a097);
  a048=(a040*a047);
  a095=(a027*a068);
  a099=(a095+a098);
  a044=(a027*a043);
  a049=(a044+a048);
  a177=casadi_sq(a027);
  a051=arg[6][0];
  a062=(a051/a061);
  a063=(a062*a043);
  a077=(a062*a068);
  a086=(a077*a074);
  a075=(a063*a074);
  a080=(a077*a079);
  a088=(a063*a079);
  a050=arg[2][1];
  a076=(a050-a075);
  a081=(a076-a080);
  a082=(a081/a061);
  a083=(a082*a054);
  a084=(a049+a083);
  a102=(a082*a058);
  a085=arg[2][0];
  a087=(a085-a086);
  a089=(a087+a088);
  a090=(a089/a061);
  a100=(a090*a054);
  a101=(a099+a100);
  a091=(a090*a058);
  a092=(a084-a091);
  a103=(a101+a102);
  a104=(a094*a103);
  a110=(a109*a103);
  a093=(a038*a092);
  a105=(a093+a104);
  a108=(a025*a092);
  a111=(a108+a110);
  a031=arg[4][5];
  a122=(a121*a031);
  a123=(a122*a006);
  a033=(a001*a031);
  a034=(a033*a006);
  a032=casadi_sq(a031);
  a035=(a032+a034);
  a120=(a119+a032);
  a124=(a120+a123);
  a137=(a031*a011);
  a138=(a004+a137);
  a115=arg[4][4];
  a116=casadi_sq(a115);
  a029=arg[4][7];
  a030=arg[4][3];
  a036=(a030*a035);
  a037=(a029+a036);
  a125=(a030*a124);
  a162=(a030*a032);
  a163=(a029+a162);
  a164=(a163*a105);
  a106=(a037*a105);
  a166=(a037*a111);
  a145=(a001*a030);
  a146=(a145*a031);
  a148=(a146*a147);
  a178=(a146*a177);
  a149=(a148*a009);
  a179=(a178*a009);
  a112=arg[4][6];
  a113=(a112+a029);
  a114=arg[4][2];
  a117=(a114*a116);
  a118=(a113+a117);
  a126=(a118+a125);
  a127=(a111*a126);
  a026=arg[4][8];
  a028=(a026*a027);
  a107=(a028-a106);
  a128=(a107+a127);
  a129=arg[3][0];
  a130=(a129*a021);
  a131=(a128+a130);
  a168=(a129*a000);
  a169=(a168*a017);
  a151=-2.;
  a152=(a151*a001);
  a153=(a152*a030);
  a154=(a153*a031);
  a155=(a154*a027);
  a156=(a155*a040);
  a157=(a156*a009);
  a160=arg[4][9];
  a161=(a160*a040);
  a165=(a161-a164);
  a167=(a165+a166);
  a170=(a167+a169);
  a132=arg[3][1];
  a133=(a132*a013);
  a134=(a131-a133);
  a171=(a132*a000);
  a172=(a171*a011);
  a173=(a170-a172);
  a135=arg[4][10];
  a136=(a135*a030);
  a141=(a135*a114);
  a142=(a141*a115);
  a143=(a142*a003);
  a139=(a136*a138);
  a140=(a134+a139);
  a174=(a136*a031);
  a175=(a174*a011);
  a144=(a140+a143);
  a150=(a144-a149);
  a176=(a173+a175);
  a180=(a176+a179);
  a158=(a150+a157);
  a159=(a025*a158);
  a184=(a109*a158);
  res[1][0]=a158;
  a181=(a038*a180);
  a182=(a159-a181);
  res[0][0]=a182;
  a185=(a094*a180);
  a186=(a184-a185);
  res[0][1]=a186;
  res[1][1]=a180;
  return 0;
}

static int casadi_f10(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  (void)arg; (void)iw; (void)mem; (void)w;
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a15, a16, a17, a18, a19, a20, a22, a23, a24, a25;
  casadi_real a26, a27, a28, a30, a31, a32, a34, a35, a36, a37, a38, a39;
  casadi_real a40, a41, a42, a43, a44, a45, a46, a47, a48, a50, a51, a52;
  casadi_real a54, a55, a56, a57, a58, a59, a60, a62, a63, a64;
  a01=arg[0][0];
  a02=hybrid_cos(a01);
  a08=hybrid_sin(a01);
  a05=arg[0][1];
  a06=hybrid_cos(a05);
  a09=hybrid_sin(a05);
  a10=(a08*a09);
  a16=(a02*a09);
  a07=(a02*a06);
  a11=(a07-a10);
  a17=(a06*a08);
  a18=(a16+a17);
  a00=arg[3][0];
  a03=(a00*a02);
  a15=(a00*a08);
  a04=arg[3][1];
  a12=(a04*a11);
  a19=(a04*a18);
  a20=(a15+a19);
  res[0][1]=a20;
  a13=(a03+a12);
  res[0][0]=a13;
  a34=arg[4][0];
  a35=(a03-a34);
  a36=(a35+a12);
  a37=casadi_sq(a36);
  a38=arg[4][1];
  a39=(a15-a38);
  a40=(a39+a19);
  a41=casadi_sq(a40);
  a42=(a37+a41);
  a43=sqrt(a42);
  a24=arg[1][1];
  a25=(a04*a24);
  a26=(a25*a18);
  a31=(a25*a11);
  a22=arg[1][0];
  a23=(a22*a20);
  a30=(a22*a13);
  a32=(a30+a31);
  a27=(a23+a26);
  res[1][1]=a32;
  a44=(a32/a43);
  a46=(a27/a43);
  a28=(-a27);
  res[1][0]=a28;
  a47=(a46*a40);
  a51=(a46*a36);
  a45=(a44*a36);
  a48=(a45+a47);
  res[2][0]=a48;
  a50=(a44*a40);
  a52=(a50-a51);
  res[2][1]=a52;
  a54=arg[2][1];
  a55=(a54/a43);
  a56=(a55*a36);
  a63=(a55*a40);
  a57=arg[2][0];
  a58=(a57/a43);
  a59=(a58*a40);
  a62=(a58*a36);
  a64=(a62+a63);
  a60=(a56-a59);
  res[3][0]=a60;
  res[3][1]=a64;
  return 0;
}

static int casadi_f11(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  (void)arg; (void)iw; (void)mem; (void)w;
  casadi_real a000, a002, a004, a005, a006, a007, a008, a009, a010, a011, a012, a013;
  casadi_real a014, a015, a016, a017, a018, a019, a020, a021, a022, a023, a024, a025;
  casadi_real a026, a027, a028, a029, a030, a031, a032, a033, a034, a035, a036, a037;
  casadi_real a038, a039, a040, a041, a042, a043, a044, a045, a046, a047, a048, a049;
  casadi_real a050, a051, a052, a053, a054, a055, a056, a057, a058, a059, a060, a061;
  casadi_real a062, a063, a064, a065, a066, a067, a068, a069, a070, a071, a072, a073;
  casadi_real a074, a075, a076, a077, a078, a079, a080, a081, a082, a083, a084, a085;
  casadi_real a086, a087, a088, a089, a090, a091, a092, a093, a094, a095, a096, a097;
  casadi_real a098, a099, a100, a101, a102, a103, a104, a105, a106, a107, a108, a109;
  casadi_real a110, a111, a112, a113, a114, a115, a116, a117, a118, a119, a120, a121;
  casadi_real a122, a123, a124, a125, a126, a127, a128, a129, a131, a132, a133, a134;
  casadi_real a138, a139, a140, a141, a142, a143, a144, a145, a146, a147, a148, a149;
  casadi_real a150, a151, a152, a153, a154, a155, a156, a157, a158, a159, a160, a161;
  casadi_real a162, a163, a164, a165, a166, a167, a168, a169, a170, a171, a172, a173;
  casadi_real a174, a175, a176, a177, a178, a179, a181, a182, a183, a184, a185, a186;
  casadi_real a187, a188, a189, a190, a191;
  a022=arg[0][1];
  a023=hybrid_cos(a022);
  a044=hybrid_sin(a022);
  a038=arg[0][0];
  a039=hybrid_cos(a038);
  a043=hybrid_sin(a038);
  a045=(a043*a044);
  a042=(a039*a023);
  a046=(a042-a045);
  a054=(a023*a043);
  a053=(a039*a044);
  a055=(a053+a054);
  a050=arg[0][5];
  a070=arg[0][4];
  a140=arg[4][0];
  a141=(a070-a140);
  a142=casadi_sq(a141);
  a143=arg[4][1];
  a144=(a050-a143);
  a145=casadi_sq(a144);
  a146=(a142+a145);
  a147=sqrt(a146);
  a150=(a141/a147);
  a181=(a144/a147);
  a060=arg[0][7];
  res[0][5]=a060;
  a156=(a060/a147);
  a169=(a156*a141);
  a157=(a156*a144);
  a074=arg[0][6];
  res[0][4]=a074;
  a154=(a074/a147);
  a170=(a154*a144);
  a171=(a169-a170);
  a155=(a154*a141);
  a158=(a155+a157);
  a172=arg[3][6];
  a173=(a171/a172);
  a174=tanh(a173);
  a017=arg[2][0];
  a051=(a017*a043);
  a052=(a050-a051);
  a040=(a017*a039);
  a071=(a070-a040);
  a020=(2.*a017);
  a018=casadi_sq(a017);
  a041=arg[2][1];
  a047=(a041*a046);
  a072=(a071-a047);
  a048=(a040+a047);
  a056=(a041*a055);
  a075=(a051+a056);
  a057=(a052-a056);
  a000=arg[0][2];
  res[0][0]=a000;
  a061=(a000*a048);
  a062=(a060-a061);
  a076=(a000*a075);
  a077=(a074+a076);
  a124=casadi_sq(a000);
  a002=arg[0][3];
  res[0][1]=a002;
  a063=(a041*a002);
  a064=(a063*a046);
  a065=(a062-a064);
  a078=(a063*a055);
  a079=(a077+a078);
  a099=casadi_sq(a002);
  a049=arg[3][1];
  a058=(a049*a057);
  a073=(a049*a072);
  a059=arg[3][2];
  a066=(a059*a065);
  a067=(a058+a066);
  a080=(a059*a079);
  a081=(a073+a080);
  a068=(a048*a067);
  a082=(a081*a075);
  a115=(a041*a067);
  a116=(a115*a046);
  a118=(a041*a081);
  a119=(a118*a055);
  a006=arg[2][5];
  a007=casadi_sq(a006);
  a019=(a018+a007);
  a021=(a020*a006);
  a024=(a021*a023);
  a025=(a019+a024);
  a029=(a017*a006);
  a030=(a029*a023);
  a031=(a007+a030);
  a089=(a006*a046);
  a090=(a040+a089);
  a139=arg[4][2];
  a148=(a139-a147);
  a013=arg[2][4];
  a014=casadi_sq(a013);
  a037=arg[1][0];
  a069=(a037+a068);
  a083=(a069-a082);
  a151=arg[3][3];
  a152=(a151*a148);
  a153=arg[3][4];
  a159=(a153*a158);
  a160=(a152-a159);
  a004=arg[2][7];
  a005=arg[2][3];
  a097=(a017*a005);
  a103=(a020*a005);
  a104=(a103*a006);
  a098=(a097*a006);
  a008=(a005*a007);
  a026=(a005*a025);
  a032=(a005*a031);
  a033=(a004+a032);
  a009=(a004+a008);
  a100=(a098*a099);
  a125=(a098*a124);
  a105=(a104*a000);
  a106=(a105*a002);
  a101=(a100*a044);
  a107=(a106*a044);
  a126=(a125*a044);
  a034=casadi_sq(a033);
  a010=arg[2][6];
  a011=(a010+a004);
  a012=arg[2][2];
  a015=(a012*a014);
  a016=(a011+a015);
  a027=(a016+a026);
  a028=(a009*a027);
  a035=(a028-a034);
  a036=(a009/a035);
  a110=(a033/a035);
  a131=(a027/a035);
  a084=arg[2][8];
  a085=(a084*a000);
  a086=(a083-a085);
  a087=arg[2][10];
  a088=(a087*a005);
  a093=(a087*a012);
  a094=(a093*a013);
  a095=(a094*a039);
  a091=(a088*a090);
  a092=(a086-a091);
  a121=(a088*a006);
  a122=(a121*a046);
  a096=(a092-a095);
  a102=(a096+a101);
  a108=(a102+a107);
  a109=(a036*a108);
  a133=(a110*a108);
  a112=arg[2][9];
  a113=(a112*a002);
  a165=arg[3][5];
  a166=(a165/a147);
  a185=(a166*a141);
  a167=(a166*a144);
  a111=arg[1][1];
  a114=(a111-a113);
  a117=(a114+a116);
  a120=(a117-a119);
  a123=(a120-a122);
  a127=(a123-a126);
  a128=(a110*a127);
  a132=(a131*a127);
  a134=(a132-a133);
  a129=(a109-a128);
  res[0][2]=a129;
  res[0][3]=a134;
  a138=0.;
  a161=casadi_fmax(a138,a160);
  a149=(a138<a148);
  a186=(a185*a161);
  a187=(a186*a174);
  a162=(a150*a161);
  a168=(a167*a161);
  a182=(a181*a161);
  a175=(a168*a174);
  a183=(a149?a182:0);
  a184=(a183-a067);
  a163=(a149?a162:0);
  a164=(a163-a081);
  a188=(-a187);
  a189=(a149?a188:0);
  a176=(a149?a175:0);
  a177=(a164+a176);
  a190=(a184+a189);
  a178=arg[3][0];
  a179=(a177/a178);
  a191=(a190/a178);
  res[0][7]=a191;
  res[0][6]=a179;
  return 0;
}

static int casadi_f12(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  (void)arg; (void)iw; (void)mem; (void)w;
  casadi_real a000, a001, a002, a003, a004, a005, a006, a007, a008, a009, a010, a011;
  casadi_real a012, a013, a015, a016, a017, a018, a019, a020, a022, a023, a024, a025;
  casadi_real a026, a027, a028, a029, a030, a031, a032, a033, a034, a035, a036, a037;
  casadi_real a038, a039, a040, a041, a042, a043, a044, a045, a047, a048, a049, a051;
  casadi_real a052, a053, a054, a055, a056, a057, a058, a059, a060, a061, a063, a064;
  casadi_real a065, a066, a067, a068, a069, a070, a071, a073, a074, a075, a076, a077;
  casadi_real a079, a080, a081, a085, a086, a087, a088, a089, a090, a091, a092, a094;
  casadi_real a095, a096, a097, a098, a099, a100, a101, a102, a103, a104, a105, a106;
  casadi_real a107, a109, a110, a111, a112, a113, a114, a115, a116, a117, a118, a119;
  a001=arg[0][0];
  a002=hybrid_cos(a001);
  a008=hybrid_sin(a001);
  a005=arg[0][1];
  a006=hybrid_cos(a005);
  a009=hybrid_sin(a005);
  a010=(a008*a009);
  a016=(a002*a009);
  a007=(a002*a006);
  a011=(a007-a010);
  a017=(a006*a008);
  a018=(a016+a017);
  a028=arg[3][0];
  a032=arg[3][1];
  a052=arg[0][4];
  res[0][8]=a052;
  a086=(a052-a028);
  a087=casadi_sq(a086);
  a063=arg[0][5];
  res[0][9]=a063;
  a088=(a063-a032);
  a089=casadi_sq(a088);
  a090=(a087+a089);
  a091=sqrt(a090);
  a057=arg[0][6];
  a099=(a057/a091);
  a112=(a099*a088);
  a100=(a099*a086);
  a067=arg[0][7];
  a101=(a067/a091);
  a111=(a101*a086);
  a113=(a111-a112);
  a102=(a101*a088);
  a103=(a100+a102);
  res[0][13]=a113;
  a114=arg[2][6];
  a115=(a113/a114);
  a116=tanh(a115);
  a000=arg[1][0];
  a003=(a000*a002);
  a015=(a000*a008);
  a033=(a015-a032);
  a029=(a003-a028);
  a064=(a063-a015);
  a053=(a052-a003);
  a004=arg[1][1];
  a012=(a004*a011);
  a013=(a003+a012);
  a030=(a029+a012);
  a054=(a053-a012);
  res[0][0]=a013;
  a019=(a004*a018);
  a020=(a015+a019);
  a034=(a033+a019);
  a065=(a064-a019);
  res[0][1]=a020;
  a035=casadi_sq(a034);
  a031=casadi_sq(a030);
  a036=(a031+a035);
  a037=sqrt(a036);
  a022=arg[0][2];
  a023=(a022*a013);
  a040=(a022*a020);
  a058=(a057+a040);
  a068=(a067-a023);
  a024=arg[0][3];
  a025=(a004*a024);
  a026=(a025*a011);
  a041=(a025*a018);
  a059=(a058+a041);
  a042=(a040+a041);
  a069=(a068-a026);
  a027=(a023+a026);
  a038=(a027/a037);
  a043=(a042/a037);
  a044=(a043*a034);
  a048=(a043*a030);
  a039=(a038*a030);
  a045=(a039+a044);
  res[0][2]=a045;
  a047=(a038*a034);
  a049=(a047-a048);
  res[0][3]=a049;
  a085=arg[3][2];
  a092=(a085-a091);
  res[0][10]=a092;
  a096=arg[2][3];
  a097=(a096*a092);
  a098=arg[2][4];
  a104=(a098*a103);
  a105=(a097-a104);
  a051=arg[2][1];
  a055=(a051*a054);
  a066=(a051*a065);
  a056=arg[2][2];
  a060=(a056*a059);
  a070=(a056*a069);
  a071=(a066+a070);
  a061=(a055+a060);
  res[0][4]=a061;
  a075=(a061/a037);
  a073=(a071/a037);
  res[0][5]=a071;
  a074=(a073*a030);
  a080=(a073*a034);
  a076=(a075*a034);
  a079=(a075*a030);
  a081=(a079+a080);
  a077=(a074-a076);
  res[0][6]=a077;
  res[0][7]=a081;
  a094=0.;
  a106=casadi_fmax(a094,a105);
  a095=(a094<a092);
  a107=(a095?a106:0);
  res[0][11]=a107;
  a109=arg[2][5];
  a110=(a109*a106);
  a117=(a110*a116);
  a118=(-a117);
  a119=(a095?a118:0);
  res[0][12]=a119;
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
