/* hybrid generated file: do not edit; change codegen/ and run `python -m hybrid regenerate`. body-sha256: 092e23bfe95fc93fc81df6c1013e901f54a734b3326a8d2c5ce4425af090d215 */
/* hybrid_casadi: hybrid force/velocity control kernels for a planar 2-link arm, derived by codegen/model.py.
   Emitted by the casadi backend of hybrid's codegen (SymPy 1.14.0, CasADi 3.8.2), generator version 3.
   Compile: cc -std=c99 -O2 -c hybrid_casadi.c (link with -lm). */
#include <math.h>

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
  a0=arg[2]? arg[2][0] : 0;
  a1=arg[0]? arg[0][0] : 0;
  a2=cos(a1);
  a3=(a0*a2);
  a4=arg[2]? arg[2][1] : 0;
  a5=arg[0]? arg[0][1] : 0;
  a6=cos(a5);
  a7=(a2*a6);
  a1=sin(a1);
  a5=sin(a5);
  a8=(a1*a5);
  a7=(a7-a8);
  a8=(a4*a7);
  a3=(a3+a8);
  if (res[0]!=0) res[0][0]=a3;
  a0=(a0*a1);
  a2=(a2*a5);
  a6=(a6*a1);
  a2=(a2+a6);
  a6=(a4*a2);
  a0=(a0+a6);
  if (res[0]!=0) res[0][1]=a0;
  a1=(-a0);
  if (res[1]!=0) res[1][0]=a1;
  a6=(-a6);
  if (res[1]!=0) res[1][1]=a6;
  if (res[1]!=0) res[1][2]=a3;
  if (res[1]!=0) res[1][3]=a8;
  a8=arg[1]? arg[1][0] : 0;
  a3=(a8*a3);
  a6=arg[1]? arg[1][1] : 0;
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
  if (res[2]!=0) res[2][0]=a3;
  a0=(a8*a0);
  a1=(a1*a2);
  a0=(a0+a1);
  a8=(a8*a0);
  a4=(a4*a2);
  a4=(a4+a1);
  a6=(a6*a4);
  a8=(a8+a6);
  a8=(-a8);
  if (res[2]!=0) res[2][1]=a8;
  return 0;
}

static int casadi_f1(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  (void)arg; (void)iw; (void)mem; (void)w;
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13;
  a00=arg[2]? arg[2][6] : 0;
  a01=arg[2]? arg[2][7] : 0;
  a00=(a00+a01);
  a02=arg[2]? arg[2][2] : 0;
  a03=arg[2]? arg[2][4] : 0;
  a04=casadi_sq(a03);
  a04=(a02*a04);
  a00=(a00+a04);
  a04=arg[2]? arg[2][3] : 0;
  a05=arg[2]? arg[2][0] : 0;
  a06=casadi_sq(a05);
  a07=arg[2]? arg[2][5] : 0;
  a08=casadi_sq(a07);
  a06=(a06+a08);
  a09=(2.*a05);
  a09=(a09*a07);
  a10=arg[0]? arg[0][1] : 0;
  a11=cos(a10);
  a09=(a09*a11);
  a06=(a06+a09);
  a06=(a04*a06);
  a00=(a00+a06);
  if (res[0]!=0) res[0][0]=a00;
  a00=(a05*a07);
  a00=(a00*a11);
  a00=(a08+a00);
  a00=(a04*a00);
  a00=(a01+a00);
  if (res[0]!=0) res[0][1]=a00;
  if (res[0]!=0) res[0][2]=a00;
  a08=(a04*a08);
  a01=(a01+a08);
  if (res[0]!=0) res[0][3]=a01;
  a01=arg[2]? arg[2][8] : 0;
  a08=arg[1]? arg[1][0] : 0;
  a01=(a01*a08);
  a00=arg[2]? arg[2][10] : 0;
  a06=(a00*a04);
  a09=arg[0]? arg[0][0] : 0;
  a12=cos(a09);
  a13=(a05*a12);
  a11=(a12*a11);
  a09=sin(a09);
  a10=sin(a10);
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
  a12=arg[1]? arg[1][1] : 0;
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
  if (res[1]!=0) res[1][0]=a01;
  a01=arg[2]? arg[2][9] : 0;
  a01=(a01*a12);
  a06=(a06*a07);
  a06=(a06*a11);
  a01=(a01+a06);
  a08=casadi_sq(a08);
  a00=(a00*a08);
  a00=(a00*a10);
  a01=(a01+a00);
  if (res[1]!=0) res[1][1]=a01;
  return 0;
}

static int casadi_f2(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  (void)arg; (void)iw; (void)mem; (void)w;
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  casadi_real a24, a25, a26, a27, a28;
  a00=arg[2]? arg[2][1] : 0;
  a01=arg[2]? arg[2][0] : 0;
  a02=arg[0]? arg[0][0] : 0;
  a03=cos(a02);
  a04=(a01*a03);
  a05=arg[0]? arg[0][1] : 0;
  a06=cos(a05);
  a07=(a03*a06);
  a02=sin(a02);
  a05=sin(a05);
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
  a13=arg[2]? arg[2][6] : 0;
  a14=arg[2]? arg[2][7] : 0;
  a13=(a13+a14);
  a15=arg[2]? arg[2][2] : 0;
  a16=arg[2]? arg[2][4] : 0;
  a17=casadi_sq(a16);
  a17=(a15*a17);
  a13=(a13+a17);
  a17=arg[2]? arg[2][3] : 0;
  a18=casadi_sq(a01);
  a19=arg[2]? arg[2][5] : 0;
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
  if (res[0]!=0) res[0][0]=a22;
  a08=(a08*a11);
  a18=(a08*a18);
  a10=(a02/a10);
  a24=(a10*a24);
  a18=(a18-a24);
  if (res[0]!=0) res[0][1]=a18;
  a13=(a08*a13);
  a06=(a06*a02);
  a13=(a13-a06);
  a06=(a12*a13);
  a21=(a21*a11);
  a14=(a14*a02);
  a21=(a21-a14);
  a14=(a23*a21);
  a06=(a06-a14);
  if (res[0]!=0) res[0][2]=a06;
  a13=(a08*a13);
  a21=(a10*a21);
  a13=(a13-a21);
  if (res[0]!=0) res[0][3]=a13;
  a21=arg[1]? arg[1][0] : 0;
  a14=(a21*a09);
  a24=arg[1]? arg[1][1] : 0;
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
  a18=arg[2]? arg[2][9] : 0;
  a18=(a18*a24);
  a26=arg[2]? arg[2][10] : 0;
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
  a23=arg[2]? arg[2][8] : 0;
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
  if (res[1]!=0) res[1][0]=a22;
  a14=(a14*a06);
  a27=(a27*a13);
  a14=(a14+a27);
  a10=(a10*a18);
  a14=(a14-a10);
  a08=(a08*a23);
  a14=(a14+a08);
  if (res[1]!=0) res[1][1]=a14;
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
  if (res[2]!=0) res[2][0]=a08;
  return 0;
}

static int casadi_f3(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  (void)arg; (void)iw; (void)mem; (void)w;
  casadi_real a0, a1, a2, a3;
  a0=arg[2]? arg[2][3] : 0;
  a1=arg[2]? arg[2][2] : 0;
  a2=casadi_sq(a1);
  a3=casadi_sq(a0);
  a2=(a2+a3);
  a2=sqrt(a2);
  a0=(a0/a2);
  a3=(-a0);
  if (res[0]!=0) res[0][0]=a3;
  a1=(a1/a2);
  if (res[0]!=0) res[0][1]=a1;
  if (res[0]!=0) res[0][2]=a1;
  if (res[0]!=0) res[0][3]=a0;
  a0=0.;
  if (res[1]!=0) res[1][0]=a0;
  if (res[1]!=0) res[1][1]=a0;
  if (res[1]!=0) res[1][2]=a0;
  if (res[1]!=0) res[1][3]=a0;
  return 0;
}

static int casadi_f4(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  (void)arg; (void)iw; (void)mem; (void)w;
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  casadi_real a24, a25, a26, a27, a28, a29, a30, a31;
  a00=arg[4]? arg[4][1] : 0;
  a01=arg[4]? arg[4][0] : 0;
  a02=arg[0]? arg[0][0] : 0;
  a03=cos(a02);
  a04=(a01*a03);
  a05=arg[0]? arg[0][1] : 0;
  a06=cos(a05);
  a07=(a03*a06);
  a02=sin(a02);
  a05=sin(a05);
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
  a13=arg[4]? arg[4][8] : 0;
  a14=arg[1]? arg[1][0] : 0;
  a13=(a13*a14);
  a15=arg[4]? arg[4][7] : 0;
  a16=arg[4]? arg[4][3] : 0;
  a17=arg[4]? arg[4][5] : 0;
  a18=casadi_sq(a17);
  a19=(a01*a17);
  a19=(a19*a06);
  a19=(a18+a19);
  a19=(a16*a19);
  a19=(a15+a19);
  a20=(a09/a10);
  a21=(a14*a09);
  a22=arg[1]? arg[1][1] : 0;
  a23=(a00*a22);
  a24=(a23*a07);
  a21=(a21+a24);
  a21=(a14*a21);
  a25=(a00*a14);
  a26=(a25*a07);
  a26=(a26+a24);
  a26=(a22*a26);
  a21=(a21+a26);
  a26=arg[2]? arg[2][1] : 0;
  a24=arg[5]? arg[5][2] : 0;
  a27=(a26*a24);
  a28=casadi_sq(a24);
  a29=arg[5]? arg[5][3] : 0;
  a30=casadi_sq(a29);
  a28=(a28+a30);
  a28=sqrt(a28);
  a27=(a27/a28);
  a21=(a21+a27);
  a27=arg[2]? arg[2][0] : 0;
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
  a31=arg[4]? arg[4][6] : 0;
  a31=(a31+a15);
  a26=arg[4]? arg[4][2] : 0;
  a28=arg[4]? arg[4][4] : 0;
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
  a31=arg[3]? arg[3][0] : 0;
  a29=(a31*a02);
  a13=(a13+a29);
  a29=arg[3]? arg[3][1] : 0;
  a27=(a29*a09);
  a13=(a13-a27);
  a27=arg[4]? arg[4][10] : 0;
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
  a03=arg[4]? arg[4][9] : 0;
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
  if (res[0]!=0) res[0][0]=a12;
  a08=(a08*a13);
  a10=(a10*a03);
  a08=(a08-a10);
  if (res[0]!=0) res[0][1]=a08;
  if (res[1]!=0) res[1][0]=a13;
  if (res[1]!=0) res[1][1]=a03;
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
  if (res[2]!=0) res[2][0]=a13;
  return 0;
}

static int casadi_f5(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  (void)arg; (void)iw; (void)mem; (void)w;
  casadi_real a0, a1, a2, a3, a4, a5, a6, a7, a8;
  a0=arg[3]? arg[3][0] : 0;
  a1=arg[0]? arg[0][0] : 0;
  a2=cos(a1);
  a3=(a0*a2);
  a4=arg[3]? arg[3][1] : 0;
  a5=arg[0]? arg[0][1] : 0;
  a6=cos(a5);
  a7=(a2*a6);
  a1=sin(a1);
  a5=sin(a5);
  a8=(a1*a5);
  a7=(a7-a8);
  a8=(a4*a7);
  a3=(a3+a8);
  if (res[0]!=0) res[0][0]=a3;
  a0=(a0*a1);
  a2=(a2*a5);
  a6=(a6*a1);
  a2=(a2+a6);
  a6=(a4*a2);
  a0=(a0+a6);
  if (res[0]!=0) res[0][1]=a0;
  a6=arg[1]? arg[1][0] : 0;
  a0=(a6*a0);
  a1=arg[1]? arg[1][1] : 0;
  a4=(a4*a1);
  a2=(a4*a2);
  a0=(a0+a2);
  a2=(-a0);
  if (res[1]!=0) res[1][0]=a2;
  a6=(a6*a3);
  a4=(a4*a7);
  a6=(a6+a4);
  if (res[1]!=0) res[1][1]=a6;
  a4=arg[4]? arg[4][2] : 0;
  a7=casadi_sq(a4);
  a3=arg[4]? arg[4][3] : 0;
  a2=casadi_sq(a3);
  a7=(a7+a2);
  a7=sqrt(a7);
  a2=(a4/a7);
  a1=(a2*a6);
  a5=(a3/a7);
  a8=(a5*a0);
  a1=(a1+a8);
  if (res[2]!=0) res[2][0]=a1;
  a5=(a5*a6);
  a2=(a2*a0);
  a5=(a5-a2);
  if (res[2]!=0) res[2][1]=a5;
  a5=arg[2]? arg[2][1] : 0;
  a2=(a5*a4);
  a2=(a2/a7);
  a0=arg[2]? arg[2][0] : 0;
  a6=(a0*a3);
  a6=(a6/a7);
  a2=(a2-a6);
  if (res[3]!=0) res[3][0]=a2;
  a0=(a0*a4);
  a0=(a0/a7);
  a5=(a5*a3);
  a5=(a5/a7);
  a0=(a0+a5);
  if (res[3]!=0) res[3][1]=a0;
  return 0;
}

static int casadi_f6(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  (void)arg; (void)iw; (void)mem; (void)w;
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  casadi_real a24, a25, a26, a27, a28, a29, a30;
  a00=arg[0]? arg[0][2] : 0;
  if (res[0]!=0) res[0][0]=a00;
  a01=arg[0]? arg[0][3] : 0;
  if (res[0]!=0) res[0][1]=a01;
  a02=arg[2]? arg[2][7] : 0;
  a03=arg[2]? arg[2][3] : 0;
  a04=arg[2]? arg[2][5] : 0;
  a05=casadi_sq(a04);
  a06=(a03*a05);
  a06=(a02+a06);
  a07=arg[2]? arg[2][6] : 0;
  a07=(a07+a02);
  a08=arg[2]? arg[2][2] : 0;
  a09=arg[2]? arg[2][4] : 0;
  a10=casadi_sq(a09);
  a10=(a08*a10);
  a07=(a07+a10);
  a10=arg[2]? arg[2][0] : 0;
  a11=casadi_sq(a10);
  a11=(a11+a05);
  a12=(2.*a10);
  a13=(a12*a04);
  a14=arg[0]? arg[0][1] : 0;
  a15=cos(a14);
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
  a05=arg[1]? arg[1][0] : 0;
  a13=arg[0]? arg[0][0] : 0;
  a16=cos(a13);
  a17=(a10*a16);
  a18=arg[2]? arg[2][1] : 0;
  a19=(a16*a15);
  a13=sin(a13);
  a14=sin(a14);
  a20=(a13*a14);
  a19=(a19-a20);
  a20=(a18*a19);
  a21=(a17+a20);
  a22=arg[3]? arg[3][1] : 0;
  a23=arg[0]? arg[0][5] : 0;
  a24=(a10*a13);
  a25=(a23-a24);
  a26=(a16*a14);
  a15=(a15*a13);
  a26=(a26+a15);
  a15=(a18*a26);
  a25=(a25-a15);
  a25=(a22*a25);
  a13=arg[3]? arg[3][2] : 0;
  a27=arg[0]? arg[0][7] : 0;
  a28=(a00*a21);
  a28=(a27-a28);
  a29=(a18*a01);
  a30=(a29*a19);
  a28=(a28-a30);
  a28=(a13*a28);
  a25=(a25+a28);
  a21=(a21*a25);
  a05=(a05+a21);
  a21=arg[0]? arg[0][4] : 0;
  a28=(a21-a17);
  a28=(a28-a20);
  a22=(a22*a28);
  a28=arg[0]? arg[0][6] : 0;
  a24=(a24+a15);
  a15=(a00*a24);
  a15=(a28+a15);
  a29=(a29*a26);
  a15=(a15+a29);
  a13=(a13*a15);
  a22=(a22+a13);
  a24=(a22*a24);
  a05=(a05-a24);
  a24=arg[2]? arg[2][8] : 0;
  a24=(a24*a00);
  a05=(a05-a24);
  a24=arg[2]? arg[2][10] : 0;
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
  a12=arg[1]? arg[1][1] : 0;
  a03=arg[2]? arg[2][9] : 0;
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
  if (res[0]!=0) res[0][2]=a06;
  a07=(a07/a11);
  a07=(a07*a12);
  a02=(a02*a05);
  a07=(a07-a02);
  if (res[0]!=0) res[0][3]=a07;
  if (res[0]!=0) res[0][4]=a28;
  if (res[0]!=0) res[0][5]=a27;
  a07=arg[4]? arg[4][2] : 0;
  a02=casadi_sq(a07);
  a05=arg[4]? arg[4][3] : 0;
  a12=casadi_sq(a05);
  a02=(a02+a12);
  a02=sqrt(a02);
  a12=(a07/a02);
  a11=arg[4]? arg[4][0] : 0;
  a21=(a21-a11);
  a21=(a12*a21);
  a11=(a05/a02);
  a06=arg[4]? arg[4][1] : 0;
  a23=(a23-a06);
  a23=(a11*a23);
  a21=(a21+a23);
  a23=0.;
  a06=(a21<a23);
  a10=arg[3]? arg[3][3] : 0;
  a10=(a10*a21);
  a21=arg[3]? arg[3][4] : 0;
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
  a22=arg[3]? arg[3][5] : 0;
  a10=(a22*a05);
  a10=(a10/a02);
  a10=(a10*a23);
  a27=(a07*a27);
  a27=(a27/a02);
  a05=(a05*a28);
  a05=(a05/a02);
  a27=(a27-a05);
  a05=arg[3]? arg[3][6] : 0;
  a27=(a27/a05);
  a27=tanh(a27);
  a10=(a10*a27);
  a10=(a06?a10:0);
  a12=(a12+a10);
  a10=arg[3]? arg[3][0] : 0;
  a12=(a12/a10);
  if (res[0]!=0) res[0][6]=a12;
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
  if (res[0]!=0) res[0][7]=a11;
  return 0;
}

static int casadi_f7(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  (void)arg; (void)iw; (void)mem; (void)w;
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16;
  a00=arg[1]? arg[1][0] : 0;
  a01=arg[0]? arg[0][0] : 0;
  a02=cos(a01);
  a03=(a00*a02);
  a04=arg[1]? arg[1][1] : 0;
  a05=arg[0]? arg[0][1] : 0;
  a06=cos(a05);
  a07=(a02*a06);
  a01=sin(a01);
  a05=sin(a05);
  a08=(a01*a05);
  a07=(a07-a08);
  a08=(a04*a07);
  a09=(a03+a08);
  if (res[0]!=0) res[0][0]=a09;
  a00=(a00*a01);
  a02=(a02*a05);
  a06=(a06*a01);
  a02=(a02+a06);
  a06=(a04*a02);
  a01=(a00+a06);
  if (res[0]!=0) res[0][1]=a01;
  a05=arg[3]? arg[3][2] : 0;
  a10=casadi_sq(a05);
  a11=arg[3]? arg[3][3] : 0;
  a12=casadi_sq(a11);
  a10=(a10+a12);
  a10=sqrt(a10);
  a12=(a05/a10);
  a13=arg[0]? arg[0][2] : 0;
  a09=(a13*a09);
  a14=arg[0]? arg[0][3] : 0;
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
  if (res[0]!=0) res[0][2]=a15;
  a14=(a16*a14);
  a02=(a12*a02);
  a14=(a14-a02);
  if (res[0]!=0) res[0][3]=a14;
  a14=arg[2]? arg[2][1] : 0;
  a02=arg[0]? arg[0][4] : 0;
  a03=(a02-a03);
  a03=(a03-a08);
  a03=(a14*a03);
  a08=arg[2]? arg[2][2] : 0;
  a15=arg[0]? arg[0][6] : 0;
  a13=(a15+a13);
  a13=(a13+a04);
  a13=(a08*a13);
  a03=(a03+a13);
  if (res[0]!=0) res[0][4]=a03;
  a13=arg[0]? arg[0][5] : 0;
  a00=(a13-a00);
  a00=(a00-a06);
  a14=(a14*a00);
  a00=arg[0]? arg[0][7] : 0;
  a09=(a00-a09);
  a09=(a09-a07);
  a08=(a08*a09);
  a14=(a14+a08);
  if (res[0]!=0) res[0][5]=a14;
  a08=(a12*a14);
  a09=(a16*a03);
  a08=(a08-a09);
  if (res[0]!=0) res[0][6]=a08;
  a03=(a12*a03);
  a14=(a16*a14);
  a03=(a03+a14);
  if (res[0]!=0) res[0][7]=a03;
  if (res[0]!=0) res[0][8]=a02;
  if (res[0]!=0) res[0][9]=a13;
  a03=arg[3]? arg[3][0] : 0;
  a02=(a02-a03);
  a12=(a12*a02);
  a02=arg[3]? arg[3][1] : 0;
  a13=(a13-a02);
  a16=(a16*a13);
  a12=(a12+a16);
  a16=(-a12);
  if (res[0]!=0) res[0][10]=a16;
  a16=0.;
  a13=(a12<a16);
  a02=arg[2]? arg[2][3] : 0;
  a02=(a02*a12);
  a12=arg[2]? arg[2][4] : 0;
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
  if (res[0]!=0) res[0][11]=a02;
  a02=arg[2]? arg[2][5] : 0;
  a02=(a02*a16);
  a05=(a05*a00);
  a05=(a05/a10);
  a11=(a11*a15);
  a11=(a11/a10);
  a05=(a05-a11);
  a11=arg[2]? arg[2][6] : 0;
  a11=(a05/a11);
  a11=tanh(a11);
  a02=(a02*a11);
  a02=(-a02);
  a13=(a13?a02:0);
  if (res[0]!=0) res[0][12]=a13;
  if (res[0]!=0) res[0][13]=a05;
  return 0;
}

static int casadi_f8(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  (void)arg; (void)iw; (void)mem; (void)w;
  casadi_real a0, a1, a2, a3, a4, a5, a6, a7;
  a0=arg[0]? arg[0][1] : 0;
  a1=arg[2]? arg[2][1] : 0;
  a0=(a0-a1);
  a1=arg[0]? arg[0][0] : 0;
  a2=arg[2]? arg[2][0] : 0;
  a1=(a1-a2);
  a2=casadi_sq(a1);
  a3=casadi_sq(a0);
  a2=(a2+a3);
  a2=sqrt(a2);
  a3=(a0/a2);
  a4=(-a3);
  if (res[0]!=0) res[0][0]=a4;
  a4=(a1/a2);
  if (res[0]!=0) res[0][1]=a4;
  if (res[0]!=0) res[0][2]=a4;
  if (res[0]!=0) res[0][3]=a3;
  a5=arg[1]? arg[1][1] : 0;
  a6=arg[1]? arg[1][0] : 0;
  a7=(a6/a2);
  a7=(a7*a1);
  a1=(a5/a2);
  a1=(a1*a0);
  a7=(a7+a1);
  a3=(a3*a7);
  a5=(a5-a3);
  a5=(a5/a2);
  a3=(-a5);
  if (res[1]!=0) res[1][0]=a3;
  a4=(a4*a7);
  a6=(a6-a4);
  a6=(a6/a2);
  if (res[1]!=0) res[1][1]=a6;
  if (res[1]!=0) res[1][2]=a6;
  if (res[1]!=0) res[1][3]=a5;
  return 0;
}

static int casadi_f9(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  (void)arg; (void)iw; (void)mem; (void)w;
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  casadi_real a24, a25, a26, a27, a28, a29, a30, a31, a32, a33, a34;
  a00=arg[4]? arg[4][1] : 0;
  a01=arg[4]? arg[4][0] : 0;
  a02=arg[0]? arg[0][0] : 0;
  a03=cos(a02);
  a04=(a01*a03);
  a05=arg[0]? arg[0][1] : 0;
  a06=cos(a05);
  a07=(a03*a06);
  a02=sin(a02);
  a05=sin(a05);
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
  a16=arg[4]? arg[4][8] : 0;
  a17=arg[1]? arg[1][0] : 0;
  a16=(a16*a17);
  a18=arg[4]? arg[4][7] : 0;
  a19=arg[4]? arg[4][3] : 0;
  a20=arg[4]? arg[4][5] : 0;
  a21=casadi_sq(a20);
  a22=(a01*a20);
  a22=(a22*a06);
  a22=(a21+a22);
  a22=(a19*a22);
  a22=(a18+a22);
  a23=(a09/a10);
  a24=(a17*a09);
  a25=arg[1]? arg[1][1] : 0;
  a26=(a00*a25);
  a27=(a26*a07);
  a24=(a24+a27);
  a28=(a17*a24);
  a29=(a00*a17);
  a30=(a29*a07);
  a30=(a30+a27);
  a30=(a25*a30);
  a28=(a28+a30);
  a30=arg[2]? arg[2][1] : 0;
  a27=arg[6]? arg[6][0] : 0;
  a31=arg[5]? arg[5][0] : 0;
  a31=(a04-a31);
  a31=(a31+a08);
  a08=casadi_sq(a31);
  a32=arg[5]? arg[5][1] : 0;
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
  a34=arg[2]? arg[2][0] : 0;
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
  a33=arg[4]? arg[4][6] : 0;
  a33=(a33+a18);
  a30=arg[4]? arg[4][2] : 0;
  a02=arg[4]? arg[4][4] : 0;
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
  a33=arg[3]? arg[3][0] : 0;
  a34=(a33*a13);
  a16=(a16+a34);
  a34=arg[3]? arg[3][1] : 0;
  a31=(a34*a09);
  a16=(a16-a31);
  a31=arg[4]? arg[4][10] : 0;
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
  a03=arg[4]? arg[4][9] : 0;
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
  if (res[0]!=0) res[0][0]=a15;
  a14=(a14*a16);
  a10=(a10*a03);
  a14=(a14-a10);
  if (res[0]!=0) res[0][1]=a14;
  if (res[1]!=0) res[1][0]=a16;
  if (res[1]!=0) res[1][1]=a03;
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
  if (res[2]!=0) res[2][0]=a16;
  return 0;
}

static int casadi_f10(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  (void)arg; (void)iw; (void)mem; (void)w;
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10;
  a00=arg[3]? arg[3][0] : 0;
  a01=arg[0]? arg[0][0] : 0;
  a02=cos(a01);
  a03=(a00*a02);
  a04=arg[3]? arg[3][1] : 0;
  a05=arg[0]? arg[0][1] : 0;
  a06=cos(a05);
  a07=(a02*a06);
  a01=sin(a01);
  a05=sin(a05);
  a08=(a01*a05);
  a07=(a07-a08);
  a08=(a04*a07);
  a09=(a03+a08);
  if (res[0]!=0) res[0][0]=a09;
  a00=(a00*a01);
  a02=(a02*a05);
  a06=(a06*a01);
  a02=(a02+a06);
  a06=(a04*a02);
  a01=(a00+a06);
  if (res[0]!=0) res[0][1]=a01;
  a05=arg[1]? arg[1][0] : 0;
  a01=(a05*a01);
  a10=arg[1]? arg[1][1] : 0;
  a04=(a04*a10);
  a02=(a04*a02);
  a01=(a01+a02);
  a02=(-a01);
  if (res[1]!=0) res[1][0]=a02;
  a05=(a05*a09);
  a04=(a04*a07);
  a05=(a05+a04);
  if (res[1]!=0) res[1][1]=a05;
  a04=arg[4]? arg[4][0] : 0;
  a03=(a03-a04);
  a03=(a03+a08);
  a08=casadi_sq(a03);
  a04=arg[4]? arg[4][1] : 0;
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
  if (res[2]!=0) res[2][0]=a06;
  a05=(a05*a00);
  a01=(a01*a03);
  a05=(a05-a01);
  if (res[2]!=0) res[2][1]=a05;
  a05=arg[2]? arg[2][1] : 0;
  a05=(a05/a08);
  a01=(a05*a03);
  a06=arg[2]? arg[2][0] : 0;
  a06=(a06/a08);
  a08=(a06*a00);
  a01=(a01-a08);
  if (res[3]!=0) res[3][0]=a01;
  a06=(a06*a03);
  a05=(a05*a00);
  a06=(a06+a05);
  if (res[3]!=0) res[3][1]=a06;
  return 0;
}

static int casadi_f11(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  (void)arg; (void)iw; (void)mem; (void)w;
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  casadi_real a24, a25, a26, a27, a28, a29, a30;
  a00=arg[0]? arg[0][2] : 0;
  if (res[0]!=0) res[0][0]=a00;
  a01=arg[0]? arg[0][3] : 0;
  if (res[0]!=0) res[0][1]=a01;
  a02=arg[2]? arg[2][7] : 0;
  a03=arg[2]? arg[2][3] : 0;
  a04=arg[2]? arg[2][5] : 0;
  a05=casadi_sq(a04);
  a06=(a03*a05);
  a06=(a02+a06);
  a07=arg[2]? arg[2][6] : 0;
  a07=(a07+a02);
  a08=arg[2]? arg[2][2] : 0;
  a09=arg[2]? arg[2][4] : 0;
  a10=casadi_sq(a09);
  a10=(a08*a10);
  a07=(a07+a10);
  a10=arg[2]? arg[2][0] : 0;
  a11=casadi_sq(a10);
  a11=(a11+a05);
  a12=(2.*a10);
  a13=(a12*a04);
  a14=arg[0]? arg[0][1] : 0;
  a15=cos(a14);
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
  a05=arg[1]? arg[1][0] : 0;
  a13=arg[0]? arg[0][0] : 0;
  a16=cos(a13);
  a17=(a10*a16);
  a18=arg[2]? arg[2][1] : 0;
  a19=(a16*a15);
  a13=sin(a13);
  a14=sin(a14);
  a20=(a13*a14);
  a19=(a19-a20);
  a20=(a18*a19);
  a21=(a17+a20);
  a22=arg[3]? arg[3][1] : 0;
  a23=arg[0]? arg[0][5] : 0;
  a24=(a10*a13);
  a25=(a23-a24);
  a26=(a16*a14);
  a15=(a15*a13);
  a26=(a26+a15);
  a15=(a18*a26);
  a25=(a25-a15);
  a25=(a22*a25);
  a13=arg[3]? arg[3][2] : 0;
  a27=arg[0]? arg[0][7] : 0;
  a28=(a00*a21);
  a28=(a27-a28);
  a29=(a18*a01);
  a30=(a29*a19);
  a28=(a28-a30);
  a28=(a13*a28);
  a25=(a25+a28);
  a21=(a21*a25);
  a05=(a05+a21);
  a21=arg[0]? arg[0][4] : 0;
  a28=(a21-a17);
  a28=(a28-a20);
  a22=(a22*a28);
  a28=arg[0]? arg[0][6] : 0;
  a24=(a24+a15);
  a15=(a00*a24);
  a15=(a28+a15);
  a29=(a29*a26);
  a15=(a15+a29);
  a13=(a13*a15);
  a22=(a22+a13);
  a24=(a22*a24);
  a05=(a05-a24);
  a24=arg[2]? arg[2][8] : 0;
  a24=(a24*a00);
  a05=(a05-a24);
  a24=arg[2]? arg[2][10] : 0;
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
  a12=arg[1]? arg[1][1] : 0;
  a03=arg[2]? arg[2][9] : 0;
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
  if (res[0]!=0) res[0][2]=a06;
  a07=(a07/a11);
  a07=(a07*a12);
  a02=(a02*a05);
  a07=(a07-a02);
  if (res[0]!=0) res[0][3]=a07;
  if (res[0]!=0) res[0][4]=a28;
  if (res[0]!=0) res[0][5]=a27;
  a07=0.;
  a02=arg[4]? arg[4][2] : 0;
  a05=arg[4]? arg[4][0] : 0;
  a21=(a21-a05);
  a05=casadi_sq(a21);
  a12=arg[4]? arg[4][1] : 0;
  a23=(a23-a12);
  a12=casadi_sq(a23);
  a05=(a05+a12);
  a05=sqrt(a05);
  a02=(a02-a05);
  a12=(a07<a02);
  a11=(a21/a05);
  a06=arg[3]? arg[3][3] : 0;
  a06=(a06*a02);
  a02=arg[3]? arg[3][4] : 0;
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
  a22=arg[3]? arg[3][5] : 0;
  a22=(a22/a05);
  a06=(a22*a23);
  a06=(a06*a07);
  a27=(a27*a21);
  a28=(a28*a23);
  a27=(a27-a28);
  a28=arg[3]? arg[3][6] : 0;
  a27=(a27/a28);
  a27=tanh(a27);
  a06=(a06*a27);
  a06=(a12?a06:0);
  a11=(a11+a06);
  a06=arg[3]? arg[3][0] : 0;
  a11=(a11/a06);
  if (res[0]!=0) res[0][6]=a11;
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
  if (res[0]!=0) res[0][7]=a23;
  return 0;
}

static int casadi_f12(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  (void)arg; (void)iw; (void)mem; (void)w;
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16;
  a00=arg[1]? arg[1][0] : 0;
  a01=arg[0]? arg[0][0] : 0;
  a02=cos(a01);
  a03=(a00*a02);
  a04=arg[1]? arg[1][1] : 0;
  a05=arg[0]? arg[0][1] : 0;
  a06=cos(a05);
  a07=(a02*a06);
  a01=sin(a01);
  a05=sin(a05);
  a08=(a01*a05);
  a07=(a07-a08);
  a08=(a04*a07);
  a09=(a03+a08);
  if (res[0]!=0) res[0][0]=a09;
  a00=(a00*a01);
  a02=(a02*a05);
  a06=(a06*a01);
  a02=(a02+a06);
  a06=(a04*a02);
  a01=(a00+a06);
  if (res[0]!=0) res[0][1]=a01;
  a05=arg[0]? arg[0][2] : 0;
  a09=(a05*a09);
  a10=arg[0]? arg[0][3] : 0;
  a04=(a04*a10);
  a07=(a04*a07);
  a10=(a09+a07);
  a11=arg[3]? arg[3][0] : 0;
  a12=(a03-a11);
  a12=(a12+a08);
  a13=casadi_sq(a12);
  a14=arg[3]? arg[3][1] : 0;
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
  if (res[0]!=0) res[0][2]=a16;
  a10=(a10*a15);
  a02=(a02*a12);
  a10=(a10-a02);
  if (res[0]!=0) res[0][3]=a10;
  a10=arg[2]? arg[2][1] : 0;
  a02=arg[0]? arg[0][4] : 0;
  a03=(a02-a03);
  a03=(a03-a08);
  a03=(a10*a03);
  a08=arg[2]? arg[2][2] : 0;
  a16=arg[0]? arg[0][6] : 0;
  a05=(a16+a05);
  a05=(a05+a04);
  a05=(a08*a05);
  a03=(a03+a05);
  if (res[0]!=0) res[0][4]=a03;
  a05=arg[0]? arg[0][5] : 0;
  a00=(a05-a00);
  a00=(a00-a06);
  a10=(a10*a00);
  a00=arg[0]? arg[0][7] : 0;
  a09=(a00-a09);
  a09=(a09-a07);
  a08=(a08*a09);
  a10=(a10+a08);
  if (res[0]!=0) res[0][5]=a10;
  a10=(a10/a13);
  a08=(a10*a12);
  a03=(a03/a13);
  a13=(a03*a15);
  a08=(a08-a13);
  if (res[0]!=0) res[0][6]=a08;
  a03=(a03*a12);
  a10=(a10*a15);
  a03=(a03+a10);
  if (res[0]!=0) res[0][7]=a03;
  if (res[0]!=0) res[0][8]=a02;
  if (res[0]!=0) res[0][9]=a05;
  a03=arg[3]? arg[3][2] : 0;
  a02=(a02-a11);
  a11=casadi_sq(a02);
  a05=(a05-a14);
  a14=casadi_sq(a05);
  a11=(a11+a14);
  a11=sqrt(a11);
  a03=(a03-a11);
  if (res[0]!=0) res[0][10]=a03;
  a14=0.;
  a10=(a14<a03);
  a15=arg[2]? arg[2][3] : 0;
  a15=(a15*a03);
  a03=arg[2]? arg[2][4] : 0;
  a16=(a16/a11);
  a12=(a16*a02);
  a00=(a00/a11);
  a11=(a00*a05);
  a12=(a12+a11);
  a03=(a03*a12);
  a15=(a15-a03);
  a14=casadi_fmax(a14,a15);
  a15=(a10?a14:0);
  if (res[0]!=0) res[0][11]=a15;
  a15=arg[2]? arg[2][5] : 0;
  a15=(a15*a14);
  a00=(a00*a02);
  a16=(a16*a05);
  a00=(a00-a16);
  a16=arg[2]? arg[2][6] : 0;
  a16=(a00/a16);
  a16=tanh(a16);
  a15=(a15*a16);
  a15=(-a15);
  a10=(a10?a15:0);
  if (res[0]!=0) res[0][12]=a10;
  if (res[0]!=0) res[0][13]=a00;
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
    for (i = 0; i < n; ++i) {
        if (!isfinite(v[i])) return 0;
    }
    return 1;
}

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

int hybrid_casadi_decoupling_law_plane_batch(int nstates, const double *q, const double *qd, const double *a, const double *Fc, const double *arm, const double *surface, const double *opts, double singular_tol, double *F, double *tau, int *status) {
    int i, failed = 0;
    for (i = 0; i < nstates; ++i) {
        status[i] = hybrid_casadi_decoupling_law_plane(q + (long)i * 2, qd + (long)i * 2, a + (long)i * 2, Fc + (long)i * 2, arm, surface, opts, singular_tol, F + (long)i * 2, tau + (long)i * 2);
        failed += status[i] != HYBRID_OK;
    }
    return failed;
}

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

int hybrid_casadi_plant_outputs_plane_batch(int nstates, const double *x, const double *arm, const double *plant, const double *surface, double *y, int *status) {
    int i, failed = 0;
    for (i = 0; i < nstates; ++i) {
        status[i] = hybrid_casadi_plant_outputs_plane(x + (long)i * 8, arm, plant, surface, y + (long)i * 14);
        failed += status[i] != HYBRID_OK;
    }
    return failed;
}

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

int hybrid_casadi_decoupling_law_circle_batch(int nstates, const double *q, const double *qd, const double *a, const double *Fc, const double *arm, const double *surface, const double *opts, double singular_tol, double *F, double *tau, int *status) {
    int i, failed = 0;
    for (i = 0; i < nstates; ++i) {
        status[i] = hybrid_casadi_decoupling_law_circle(q + (long)i * 2, qd + (long)i * 2, a + (long)i * 2, Fc + (long)i * 2, arm, surface, opts, singular_tol, F + (long)i * 2, tau + (long)i * 2);
        failed += status[i] != HYBRID_OK;
    }
    return failed;
}

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

int hybrid_casadi_plant_outputs_circle_batch(int nstates, const double *x, const double *arm, const double *plant, const double *surface, double *y, int *status) {
    int i, failed = 0;
    for (i = 0; i < nstates; ++i) {
        status[i] = hybrid_casadi_plant_outputs_circle(x + (long)i * 8, arm, plant, surface, y + (long)i * 14);
        failed += status[i] != HYBRID_OK;
    }
    return failed;
}
