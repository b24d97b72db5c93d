/* hybrid generated file: do not edit; change codegen/ and run `python -m hybrid regenerate`. body-sha256: b505399dea5760d6aa46d29b22af48c60b7206328fc925f9e4e63d99aa0f3802 */
/* hybrid_sympy: hybrid force/velocity control kernels for a planar 2-link arm, derived by codegen/model.py.
   Emitted by the sympy backend of hybrid's codegen (SymPy 1.14.0), generator version 3.
   Compile: cc -std=c99 -O2 -c hybrid_sympy.c (link with -lm). */
#include <math.h>

static void arm_kinematics_core(const double *q, const double *qd, const double *arm, double *r, double *J, double *Jdqd) {
    const double q0 = q[0];
    const double q1 = q[1];
    const double qd0 = qd[0];
    const double qd1 = qd[1];
    const double arm0 = arm[0];
    const double arm1 = arm[1];
    const double x0 = cos(q0);
    const double x1 = sin(q0);
    const double x2 = sin(q1);
    const double x3 = cos(q1);
    const double x4 = arm1*(x0*x3 - x1*x2);
    const double x5 = arm0*x0 + x4;
    const double x6 = arm1*(x0*x2 + x1*x3);
    const double x7 = arm0*x1 + x6;
    const double x8 = -x7;
    const double x9 = qd1*x4;
    const double x10 = qd1*x6;
    r[0] = x5;
    r[1] = x7;
    J[0] = x8;
    J[1] = -x6;
    J[2] = x5;
    J[3] = x4;
    Jdqd[0] = qd0*(-qd0*x5 - x9) + qd1*(-qd0*x4 - x9);
    Jdqd[1] = qd0*(qd0*x8 - x10) + qd1*(-qd0*x6 - x10);
}

static void arm_dynamics_core(const double *q, const double *qd, const double *arm, double *B, double *n) {
    const double q0 = q[0];
    const double q1 = q[1];
    const double qd0 = qd[0];
    const double qd1 = qd[1];
    const double arm0 = arm[0];
    const double arm2 = arm[2];
    const double arm3 = arm[3];
    const double arm4 = arm[4];
    const double arm5 = arm[5];
    const double arm6 = arm[6];
    const double arm7 = arm[7];
    const double arm8 = arm[8];
    const double arm9 = arm[9];
    const double arm10 = arm[10];
    const double x0 = (arm5)*(arm5);
    const double x1 = cos(q1);
    const double x2 = arm0*arm5;
    const double x3 = x1*x2;
    const double x4 = arm3*(x0 + x3) + arm7;
    const double x5 = cos(q0);
    const double x6 = sin(q1);
    const double x7 = arm5*(x1*x5 - x6*sin(q0));
    const double x8 = arm10*arm3;
    const double x9 = arm3*x2*x6;
    B[0] = arm2*(arm4)*(arm4) + arm3*((arm0)*(arm0) + x0 + 2*x3) + arm6 + arm7;
    B[1] = x4;
    B[2] = x4;
    B[3] = arm3*x0 + arm7;
    n[0] = arm10*arm2*arm4*x5 + arm8*qd0 - 2*qd0*qd1*x9 - (qd1)*(qd1)*x9 + x8*(arm0*x5 + x7);
    n[1] = arm9*qd1 + (qd0)*(qd0)*x9 + x7*x8;
}

static void operational_space_core(const double *q, const double *qd, const double *arm, double *Bo, double *no, double *cond) {
    const double q0 = q[0];
    const double q1 = q[1];
    const double qd0 = qd[0];
    const double qd1 = qd[1];
    const double arm0 = arm[0];
    const double arm1 = arm[1];
    const double arm2 = arm[2];
    const double arm3 = arm[3];
    const double arm4 = arm[4];
    const double arm5 = arm[5];
    const double arm6 = arm[6];
    const double arm7 = arm[7];
    const double arm8 = arm[8];
    const double arm9 = arm[9];
    const double arm10 = arm[10];
    const double x0 = (arm5)*(arm5);
    const double x1 = arm3*x0 + arm7;
    const double x2 = cos(q0);
    const double x3 = arm0*x2;
    const double x4 = sin(q0);
    const double x5 = sin(q1);
    const double x6 = cos(q1);
    const double x7 = x2*x6 - x4*x5;
    const double x8 = arm1*x7;
    const double x9 = x3 + x8;
    const double x10 = -x9;
    const double x11 = x2*x5 + x4*x6;
    const double x12 = arm1*x11;
    const double x13 = x12*x9;
    const double x14 = -arm0*x4 - x12;
    const double x15 = x14*x8;
    const double x16 = 1.0/(x13 + x15);
    const double x17 = x10*x16;
    const double x18 = arm0*arm5;
    const double x19 = x18*x6;
    const double x20 = arm3*(x0 + x19) + arm7;
    const double x21 = x16*x8;
    const double x22 = x1*x17 + x20*x21;
    const double x23 = arm2*(arm4)*(arm4) + arm3*((arm0)*(arm0) + x0 + 2*x19) + arm6 + arm7;
    const double x24 = x17*x20 + x21*x23;
    const double x25 = x17*x22 + x21*x24;
    const double x26 = x14*x16;
    const double x27 = x12*x16;
    const double x28 = x22*x26 + x24*x27;
    const double x29 = x1*x26 + x20*x27;
    const double x30 = x20*x26 + x23*x27;
    const double x31 = x17*x29 + x21*x30;
    const double x32 = x26*x29 + x27*x30;
    const double x33 = qd1*x8;
    const double x34 = qd0*(qd0*x10 - x33) + qd1*(-qd0*x8 - x33);
    const double x35 = qd1*x12;
    const double x36 = qd0*(qd0*x14 - x35) + qd1*(-qd0*x12 - x35);
    const double x37 = arm5*x7;
    const double x38 = arm10*arm3;
    const double x39 = arm3*x18*x5;
    const double x40 = arm9*qd1 + (qd0)*(qd0)*x39 + x37*x38;
    const double x41 = arm10*arm2*arm4*x2 + arm8*qd0 - 2*qd0*qd1*x39 - (qd1)*(qd1)*x39 + x38*(x3 + x37);
    const double x42 = (arm1)*(arm1);
    Bo[0] = x25;
    Bo[1] = x28;
    Bo[2] = x31;
    Bo[3] = x32;
    no[0] = x17*x40 + x21*x41 - x25*x34 - x28*x36;
    no[1] = x26*x40 + x27*x41 - x31*x34 - x32*x36;
    cond[0] = (2*x13 + 2*x15)/((x11)*(x11)*x42 + (x14)*(x14) + x42*(x7)*(x7) + (x9)*(x9));
}

static void task_frame_plane_core(const double *r, const double *rd, const double *surface, double *R, double *Rd) {
    (void)r;  /* not needed by this kernel */
    (void)rd;  /* not needed by this kernel */
    const double surface2 = surface[2];
    const double surface3 = surface[3];
    const double x0 = 1.0/sqrt((surface2)*(surface2) + (surface3)*(surface3));
    const double x1 = surface3*x0;
    const double x2 = surface2*x0;
    R[0] = -x1;
    R[1] = x2;
    R[2] = x2;
    R[3] = x1;
    Rd[0] = 0;
    Rd[1] = 0;
    Rd[2] = 0;
    Rd[3] = 0;
}

static void decoupling_law_plane_core(const double *q, const double *qd, const double *a, const double *Fc, const double *arm, const double *surface, const double *opts, double *F, double *tau, double *cond) {
    const double q0 = q[0];
    const double q1 = q[1];
    const double qd0 = qd[0];
    const double qd1 = qd[1];
    const double a0 = a[0];
    const double a1 = a[1];
    const double Fc0 = Fc[0];
    const double Fc1 = Fc[1];
    const double arm0 = arm[0];
    const double arm1 = arm[1];
    const double arm2 = arm[2];
    const double arm3 = arm[3];
    const double arm4 = arm[4];
    const double arm5 = arm[5];
    const double arm6 = arm[6];
    const double arm7 = arm[7];
    const double arm8 = arm[8];
    const double arm9 = arm[9];
    const double arm10 = arm[10];
    const double surface2 = surface[2];
    const double surface3 = surface[3];
    (void)opts;  /* not needed by this kernel */
    const double x0 = (arm5)*(arm5);
    const double x1 = cos(q0);
    const double x2 = arm0*x1;
    const double x3 = sin(q0);
    const double x4 = sin(q1);
    const double x5 = cos(q1);
    const double x6 = x1*x5 - x3*x4;
    const double x7 = arm1*x6;
    const double x8 = x2 + x7;
    const double x9 = -x8;
    const double x10 = qd1*x7;
    const double x11 = 1.0/sqrt((surface2)*(surface2) + (surface3)*(surface3));
    const double x12 = surface3*x11;
    const double x13 = -a0*x12 + a1*surface2*x11 - qd0*(qd0*x9 - x10) - qd1*(-qd0*x7 - x10);
    const double x14 = x1*x4 + x3*x5;
    const double x15 = arm1*x14;
    const double x16 = x15*x8;
    const double x17 = -arm0*x3 - x15;
    const double x18 = x17*x7;
    const double x19 = 1.0/(x16 + x18);
    const double x20 = x19*x9;
    const double x21 = qd1*x15;
    const double x22 = a0*surface2*x11 + a1*x12 - qd0*(qd0*x17 - x21) - qd1*(-qd0*x15 - x21);
    const double x23 = x17*x19;
    const double x24 = x13*x20 + x22*x23;
    const double x25 = arm0*arm5;
    const double x26 = x25*x5;
    const double x27 = arm3*(x0 + x26) + arm7;
    const double x28 = x19*x7;
    const double x29 = x15*x19;
    const double x30 = x13*x28 + x22*x29;
    const double x31 = arm5*x6;
    const double x32 = arm10*arm3;
    const double x33 = arm3*x25*x4;
    const double x34 = Fc0*x15 - Fc1*x7 + arm9*qd1 + (qd0)*(qd0)*x33 + x24*(arm3*x0 + arm7) + x27*x30 + x31*x32;
    const double x35 = -Fc0*x17 - Fc1*x8 + arm10*arm2*arm4*x1 + arm8*qd0 - 2*qd0*qd1*x33 - (qd1)*(qd1)*x33 + x24*x27 + x30*(arm2*(arm4)*(arm4) + arm3*((arm0)*(arm0) + x0 + 2*x26) + arm6 + arm7) + x32*(x2 + x31);
    const double x36 = (arm1)*(arm1);
    F[0] = x20*x34 + x28*x35;
    F[1] = x23*x34 + x29*x35;
    tau[0] = x35;
    tau[1] = x34;
    cond[0] = (2*x16 + 2*x18)/((x14)*(x14)*x36 + (x17)*(x17) + x36*(x6)*(x6) + (x8)*(x8));
}

static void task_measurement_plane_core(const double *q, const double *qd, const double *Fc, const double *arm, const double *surface, double *r, double *rd, double *v, double *f) {
    const double q0 = q[0];
    const double q1 = q[1];
    const double qd0 = qd[0];
    const double qd1 = qd[1];
    const double Fc0 = Fc[0];
    const double Fc1 = Fc[1];
    const double arm0 = arm[0];
    const double arm1 = arm[1];
    const double surface2 = surface[2];
    const double surface3 = surface[3];
    const double x0 = cos(q0);
    const double x1 = sin(q0);
    const double x2 = sin(q1);
    const double x3 = cos(q1);
    const double x4 = arm1*(x0*x3 - x1*x2);
    const double x5 = arm0*x0 + x4;
    const double x6 = arm1*(x0*x2 + x1*x3);
    const double x7 = arm0*x1 + x6;
    const double x8 = -qd0*x7 - qd1*x6;
    const double x9 = qd0*x5 + qd1*x4;
    const double x10 = 1.0/sqrt((surface2)*(surface2) + (surface3)*(surface3));
    const double x11 = surface2*x10;
    const double x12 = surface3*x10;
    r[0] = x5;
    r[1] = x7;
    rd[0] = x8;
    rd[1] = x9;
    v[0] = x11*x9 - x12*x8;
    v[1] = x11*x8 + x12*x9;
    f[0] = -Fc0*x12 + Fc1*surface2*x10;
    f[1] = Fc0*x11 + Fc1*x12;
}

static void plant_rhs_plane_core(const double *x, const double *tau, const double *arm, const double *plant, const double *surface, double *xdot) {
    const double x0 = x[0];
    const double x1 = x[1];
    const double x2 = x[2];
    const double x3 = x[3];
    const double x4 = x[4];
    const double x5 = x[5];
    const double x6 = x[6];
    const double x7 = x[7];
    const double tau0 = tau[0];
    const double tau1 = tau[1];
    const double arm0 = arm[0];
    const double arm1 = arm[1];
    const double arm2 = arm[2];
    const double arm3 = arm[3];
    const double arm4 = arm[4];
    const double arm5 = arm[5];
    const double arm6 = arm[6];
    const double arm7 = arm[7];
    const double arm8 = arm[8];
    const double arm9 = arm[9];
    const double arm10 = arm[10];
    const double plant0 = plant[0];
    const double plant1 = plant[1];
    const double plant2 = plant[2];
    const double plant3 = plant[3];
    const double plant4 = plant[4];
    const double plant5 = plant[5];
    const double plant6 = plant[6];
    const double surface0 = surface[0];
    const double surface1 = surface[1];
    const double surface2 = surface[2];
    const double surface3 = surface[3];
    const double x8 = (arm5)*(arm5);
    const double x9 = arm3*x8 + arm7;
    const double x10 = cos(x1);
    const double x11 = arm0*arm5;
    const double x12 = x10*x11;
    const double x13 = arm3*(x12 + x8) + arm7;
    const double x14 = arm2*(arm4)*(arm4) + arm3*((arm0)*(arm0) + 2*x12 + x8) + arm6 + arm7;
    const double x15 = 1.0/(-(x13)*(x13) + x14*x9);
    const double x16 = cos(x0);
    const double x17 = arm0*x16;
    const double x18 = sin(x0);
    const double x19 = sin(x1);
    const double x20 = x10*x16 - x18*x19;
    const double x21 = arm1*x20;
    const double x22 = x17 + x21;
    const double x23 = -x5;
    const double x24 = arm1*(x10*x18 + x16*x19);
    const double x25 = arm0*x18 + x24;
    const double x26 = plant1*(-x23 - x25) + plant2*(-x2*x22 - x21*x3 + x7);
    const double x27 = -x4;
    const double x28 = -x25;
    const double x29 = plant1*(-x22 - x27) + plant2*(-x2*x28 + x24*x3 + x6);
    const double x30 = arm5*x20;
    const double x31 = arm10*arm3;
    const double x32 = arm3*x11*x19;
    const double x33 = x15*(-arm10*arm2*arm4*x16 - arm8*x2 + tau0 + 2*x2*x3*x32 + x22*x26 + x28*x29 + (x3)*(x3)*x32 - x31*(x17 + x30));
    const double x34 = -x13;
    const double x35 = x15*(arm1*x20*x26 - arm9*x3 + tau1 - (x2)*(x2)*x32 - x24*x29 - x30*x31);
    const double x36 = 1.0/(plant0);
    const double x37 = 1.0/sqrt((surface2)*(surface2) + (surface3)*(surface3));
    const double x38 = surface2*x37;
    const double x39 = surface3*x37;
    const double x40 = x38*(-surface0 - x27) + x39*(-surface1 - x23);
    const double x41 = ((x40 < 0) ? (
   fmax(0, -plant3*x40 + plant4*(-x38*x6 - x39*x7))
)
: (
   0
));
    const double x42 = tanh((x38*x7 - x39*x6)/plant6);
    xdot[0] = x2;
    xdot[1] = x3;
    xdot[2] = x33*x9 + x34*x35;
    xdot[3] = x14*x35 + x33*x34;
    xdot[4] = x6;
    xdot[5] = x7;
    xdot[6] = x36*(plant5*surface3*x37*x41*x42 + surface2*x37*x41 - x29);
    xdot[7] = x36*(-plant5*x38*x41*x42 + surface3*x37*x41 - x26);
}

static void plant_outputs_plane_core(const double *x, const double *arm, const double *plant, const double *surface, double *y) {
    const double x0 = x[0];
    const double x1 = x[1];
    const double x2 = x[2];
    const double x3 = x[3];
    const double x4 = x[4];
    const double x5 = x[5];
    const double x6 = x[6];
    const double x7 = x[7];
    const double arm0 = arm[0];
    const double arm1 = arm[1];
    const double plant1 = plant[1];
    const double plant2 = plant[2];
    const double plant3 = plant[3];
    const double plant4 = plant[4];
    const double plant5 = plant[5];
    const double plant6 = plant[6];
    const double surface0 = surface[0];
    const double surface1 = surface[1];
    const double surface2 = surface[2];
    const double surface3 = surface[3];
    const double x8 = cos(x0);
    const double x9 = sin(x0);
    const double x10 = sin(x1);
    const double x11 = cos(x1);
    const double x12 = arm1*(-x10*x9 + x11*x8);
    const double x13 = arm0*x8 + x12;
    const double x14 = arm1*(x10*x8 + x11*x9);
    const double x15 = arm0*x9 + x14;
    const double x16 = x12*x3 + x13*x2;
    const double x17 = 1.0/sqrt((surface2)*(surface2) + (surface3)*(surface3));
    const double x18 = surface2*x17;
    const double x19 = x14*x3 + x15*x2;
    const double x20 = -x19;
    const double x21 = surface3*x17;
    const double x22 = -x4;
    const double x23 = plant1*(-x13 - x22) + plant2*(x19 + x6);
    const double x24 = -x5;
    const double x25 = plant1*(-x15 - x24) + plant2*(-x16 + x7);
    const double x26 = x18*(-surface0 - x22) + x21*(-surface1 - x24);
    const double x27 = -x26;
    const double x28 = ((x26 < 0) ? (
   fmax(0, plant3*x27 + plant4*(-x18*x6 - x21*x7))
)
: (
   0
));
    const double x29 = x18*x7 - x21*x6;
    y[0] = x13;
    y[1] = x15;
    y[2] = x16*x18 - x20*x21;
    y[3] = x16*x21 + x18*x20;
    y[4] = x23;
    y[5] = x25;
    y[6] = x18*x25 - x21*x23;
    y[7] = x18*x23 + x21*x25;
    y[8] = x4;
    y[9] = x5;
    y[10] = x27;
    y[11] = x28;
    y[12] = -plant5*x28*tanh(x29/plant6);
    y[13] = x29;
}

static void task_frame_circle_core(const double *r, const double *rd, const double *surface, double *R, double *Rd) {
    const double r0 = r[0];
    const double r1 = r[1];
    const double rd0 = rd[0];
    const double rd1 = rd[1];
    const double surface0 = surface[0];
    const double surface1 = surface[1];
    const double x0 = r0 - surface0;
    const double x1 = r1 - surface1;
    const double x2 = 1.0/sqrt((x0)*(x0) + (x1)*(x1));
    const double x3 = x1*x2;
    const double x4 = x0*x2;
    const double x5 = rd0*x4 + rd1*x3;
    const double x6 = x2*(rd1 - x3*x5);
    const double x7 = x2*(rd0 - x4*x5);
    R[0] = -x3;
    R[1] = x4;
    R[2] = x4;
    R[3] = x3;
    Rd[0] = -x6;
    Rd[1] = x7;
    Rd[2] = x7;
    Rd[3] = x6;
}

static void decoupling_law_circle_core(const double *q, const double *qd, const double *a, const double *Fc, const double *arm, const double *surface, const double *opts, double *F, double *tau, double *cond) {
    const double q0 = q[0];
    const double q1 = q[1];
    const double qd0 = qd[0];
    const double qd1 = qd[1];
    const double a0 = a[0];
    const double a1 = a[1];
    const double Fc0 = Fc[0];
    const double Fc1 = Fc[1];
    const double arm0 = arm[0];
    const double arm1 = arm[1];
    const double arm2 = arm[2];
    const double arm3 = arm[3];
    const double arm4 = arm[4];
    const double arm5 = arm[5];
    const double arm6 = arm[6];
    const double arm7 = arm[7];
    const double arm8 = arm[8];
    const double arm9 = arm[9];
    const double arm10 = arm[10];
    const double surface0 = surface[0];
    const double surface1 = surface[1];
    const double opts0 = opts[0];
    const double x0 = (arm5)*(arm5);
    const double x1 = cos(q0);
    const double x2 = arm0*x1;
    const double x3 = sin(q0);
    const double x4 = sin(q1);
    const double x5 = cos(q1);
    const double x6 = x1*x5 - x3*x4;
    const double x7 = arm1*x6;
    const double x8 = x2 + x7;
    const double x9 = -x8;
    const double x10 = qd1*x7;
    const double x11 = x1*x4 + x3*x5;
    const double x12 = arm1*x11;
    const double x13 = arm0*x3 + x12;
    const double x14 = -x13;
    const double x15 = qd1*x12;
    const double x16 = -qd0*x14 + x15;
    const double x17 = -x16;
    const double x18 = qd0*x8 + x10;
    const double x19 = -surface0 + x8;
    const double x20 = -surface1 + x13;
    const double x21 = 1.0/sqrt((x19)*(x19) + (x20)*(x20));
    const double x22 = x20*x21;
    const double x23 = x19*x21;
    const double x24 = x17*x23 + x18*x22;
    const double x25 = opts0*x21;
    const double x26 = x25*(x18 - x22*x24);
    const double x27 = x25*(-x16 - x23*x24);
    const double x28 = a0 + x17*x26 - x18*x27;
    const double x29 = a1 - x17*x27 - x18*x26;
    const double x30 = -qd0*(qd0*x9 - x10) - qd1*(-qd0*x7 - x10) + x19*x21*x29 - x22*x28;
    const double x31 = x12*x8;
    const double x32 = x14*x7;
    const double x33 = 1.0/(x31 + x32);
    const double x34 = x33*x9;
    const double x35 = -qd0*x17 - qd1*(-qd0*x12 - x15) + x19*x21*x28 + x20*x21*x29;
    const double x36 = x14*x33;
    const double x37 = x30*x34 + x35*x36;
    const double x38 = arm0*arm5;
    const double x39 = x38*x5;
    const double x40 = arm3*(x0 + x39) + arm7;
    const double x41 = x33*x7;
    const double x42 = x12*x33;
    const double x43 = x30*x41 + x35*x42;
    const double x44 = arm5*x6;
    const double x45 = arm10*arm3;
    const double x46 = arm3*x38*x4;
    const double x47 = Fc0*x12 - Fc1*x7 + arm9*qd1 + (qd0)*(qd0)*x46 + x37*(arm3*x0 + arm7) + x40*x43 + x44*x45;
    const double x48 = -Fc0*x14 - Fc1*x8 + arm10*arm2*arm4*x1 + arm8*qd0 - 2*qd0*qd1*x46 - (qd1)*(qd1)*x46 + x37*x40 + x43*(arm2*(arm4)*(arm4) + arm3*((arm0)*(arm0) + x0 + 2*x39) + arm6 + arm7) + x45*(x2 + x44);
    const double x49 = (arm1)*(arm1);
    F[0] = x34*x47 + x41*x48;
    F[1] = x36*x47 + x42*x48;
    tau[0] = x48;
    tau[1] = x47;
    cond[0] = (2*x31 + 2*x32)/((x11)*(x11)*x49 + (x14)*(x14) + x49*(x6)*(x6) + (x8)*(x8));
}

static void task_measurement_circle_core(const double *q, const double *qd, const double *Fc, const double *arm, const double *surface, double *r, double *rd, double *v, double *f) {
    const double q0 = q[0];
    const double q1 = q[1];
    const double qd0 = qd[0];
    const double qd1 = qd[1];
    const double Fc0 = Fc[0];
    const double Fc1 = Fc[1];
    const double arm0 = arm[0];
    const double arm1 = arm[1];
    const double surface0 = surface[0];
    const double surface1 = surface[1];
    const double x0 = cos(q0);
    const double x1 = sin(q0);
    const double x2 = sin(q1);
    const double x3 = cos(q1);
    const double x4 = arm1*(x0*x3 - x1*x2);
    const double x5 = arm0*x0 + x4;
    const double x6 = arm1*(x0*x2 + x1*x3);
    const double x7 = arm0*x1 + x6;
    const double x8 = -qd0*x7 - qd1*x6;
    const double x9 = qd0*x5 + qd1*x4;
    const double x10 = -surface0 + x5;
    const double x11 = -surface1 + x7;
    const double x12 = 1.0/sqrt((x10)*(x10) + (x11)*(x11));
    const double x13 = x12*x9;
    const double x14 = x12*x8;
    const double x15 = x11*x12;
    r[0] = x5;
    r[1] = x7;
    rd[0] = x8;
    rd[1] = x9;
    v[0] = x10*x13 - x11*x14;
    v[1] = x10*x14 + x11*x13;
    f[0] = -Fc0*x15 + Fc1*x10*x12;
    f[1] = Fc0*x10*x12 + Fc1*x15;
}

static void plant_rhs_circle_core(const double *x, const double *tau, const double *arm, const double *plant, const double *surface, double *xdot) {
    const double x0 = x[0];
    const double x1 = x[1];
    const double x2 = x[2];
    const double x3 = x[3];
    const double x4 = x[4];
    const double x5 = x[5];
    const double x6 = x[6];
    const double x7 = x[7];
    const double tau0 = tau[0];
    const double tau1 = tau[1];
    const double arm0 = arm[0];
    const double arm1 = arm[1];
    const double arm2 = arm[2];
    const double arm3 = arm[3];
    const double arm4 = arm[4];
    const double arm5 = arm[5];
    const double arm6 = arm[6];
    const double arm7 = arm[7];
    const double arm8 = arm[8];
    const double arm9 = arm[9];
    const double arm10 = arm[10];
    const double plant0 = plant[0];
    const double plant1 = plant[1];
    const double plant2 = plant[2];
    const double plant3 = plant[3];
    const double plant4 = plant[4];
    const double plant5 = plant[5];
    const double plant6 = plant[6];
    const double surface0 = surface[0];
    const double surface1 = surface[1];
    const double surface2 = surface[2];
    const double x8 = (arm5)*(arm5);
    const double x9 = arm3*x8 + arm7;
    const double x10 = cos(x1);
    const double x11 = arm0*arm5;
    const double x12 = x10*x11;
    const double x13 = arm3*(x12 + x8) + arm7;
    const double x14 = arm2*(arm4)*(arm4) + arm3*((arm0)*(arm0) + 2*x12 + x8) + arm6 + arm7;
    const double x15 = 1.0/(-(x13)*(x13) + x14*x9);
    const double x16 = cos(x0);
    const double x17 = arm0*x16;
    const double x18 = sin(x0);
    const double x19 = sin(x1);
    const double x20 = x10*x16 - x18*x19;
    const double x21 = arm1*x20;
    const double x22 = x17 + x21;
    const double x23 = -x5;
    const double x24 = arm1*(x10*x18 + x16*x19);
    const double x25 = arm0*x18 + x24;
    const double x26 = plant1*(-x23 - x25) + plant2*(-x2*x22 - x21*x3 + x7);
    const double x27 = -x4;
    const double x28 = -x25;
    const double x29 = plant1*(-x22 - x27) + plant2*(-x2*x28 + x24*x3 + x6);
    const double x30 = arm5*x20;
    const double x31 = arm10*arm3;
    const double x32 = arm3*x11*x19;
    const double x33 = x15*(-arm10*arm2*arm4*x16 - arm8*x2 + tau0 + 2*x2*x3*x32 + x22*x26 + x28*x29 + (x3)*(x3)*x32 - x31*(x17 + x30));
    const double x34 = -x13;
    const double x35 = x15*(arm1*x20*x26 - arm9*x3 + tau1 - (x2)*(x2)*x32 - x24*x29 - x30*x31);
    const double x36 = 1.0/(plant0);
    const double x37 = -surface0 - x27;
    const double x38 = -surface1 - x23;
    const double x39 = sqrt((x37)*(x37) + (x38)*(x38));
    const double x40 = 1.0/(x39);
    const double x41 = surface2 - x39;
    const double x42 = x37*x40;
    const double x43 = x38*x40;
    const double x44 = ((x41 > 0) ? (
   fmax(0, plant3*x41 + plant4*(-x42*x6 - x43*x7))
)
: (
   0
));
    const double x45 = tanh((x37*x40*x7 - x43*x6)/plant6);
    xdot[0] = x2;
    xdot[1] = x3;
    xdot[2] = x33*x9 + x34*x35;
    xdot[3] = x14*x35 + x33*x34;
    xdot[4] = x6;
    xdot[5] = x7;
    xdot[6] = x36*(plant5*x38*x40*x44*x45 - x29 + x37*x40*x44);
    xdot[7] = x36*(-plant5*x42*x44*x45 - x26 + x38*x40*x44);
}

static void plant_outputs_circle_core(const double *x, const double *arm, const double *plant, const double *surface, double *y) {
    const double x0 = x[0];
    const double x1 = x[1];
    const double x2 = x[2];
    const double x3 = x[3];
    const double x4 = x[4];
    const double x5 = x[5];
    const double x6 = x[6];
    const double x7 = x[7];
    const double arm0 = arm[0];
    const double arm1 = arm[1];
    const double plant1 = plant[1];
    const double plant2 = plant[2];
    const double plant3 = plant[3];
    const double plant4 = plant[4];
    const double plant5 = plant[5];
    const double plant6 = plant[6];
    const double surface0 = surface[0];
    const double surface1 = surface[1];
    const double surface2 = surface[2];
    const double x8 = cos(x0);
    const double x9 = sin(x0);
    const double x10 = sin(x1);
    const double x11 = cos(x1);
    const double x12 = arm1*(-x10*x9 + x11*x8);
    const double x13 = arm0*x8 + x12;
    const double x14 = arm1*(x10*x8 + x11*x9);
    const double x15 = arm0*x9 + x14;
    const double x16 = -surface0 + x13;
    const double x17 = -surface1 + x15;
    const double x18 = 1.0/sqrt((x16)*(x16) + (x17)*(x17));
    const double x19 = x12*x3 + x13*x2;
    const double x20 = x18*x19;
    const double x21 = x14*x3 + x15*x2;
    const double x22 = -x18*x21;
    const double x23 = -x4;
    const double x24 = plant1*(-x13 - x23) + plant2*(x21 + x6);
    const double x25 = -x5;
    const double x26 = plant1*(-x15 - x25) + plant2*(-x19 + x7);
    const double x27 = x16*x18;
    const double x28 = x17*x18;
    const double x29 = -surface0 - x23;
    const double x30 = -surface1 - x25;
    const double x31 = sqrt((x29)*(x29) + (x30)*(x30));
    const double x32 = surface2 - x31;
    const double x33 = 1.0/(x31);
    const double x34 = x30*x33;
    const double x35 = ((x32 > 0) ? (
   fmax(0, plant3*x32 + plant4*(-x29*x33*x6 - x34*x7))
)
: (
   0
));
    const double x36 = x29*x33*x7 - x34*x6;
    y[0] = x13;
    y[1] = x15;
    y[2] = x16*x20 - x17*x22;
    y[3] = x16*x22 + x17*x20;
    y[4] = x24;
    y[5] = x26;
    y[6] = -x24*x28 + x26*x27;
    y[7] = x24*x27 + x26*x28;
    y[8] = x4;
    y[9] = x5;
    y[10] = x32;
    y[11] = x35;
    y[12] = -plant5*x35*tanh(x36/plant6);
    y[13] = x36;
}

#include "hybrid_sympy.h"

static int all_finite(const double *v, int n) {
    int i;
    for (i = 0; i < n; ++i) {
        if (!isfinite(v[i])) return 0;
    }
    return 1;
}

int hybrid_sympy_arm_kinematics(const double *q, const double *qd, const double *arm, double *r, double *J, double *Jdqd) {
    arm_kinematics_core(q, qd, arm, r, J, Jdqd);
    return (all_finite(r, 2) && all_finite(J, 4) && all_finite(Jdqd, 2)) ? HYBRID_OK : HYBRID_NONFINITE;
}

int hybrid_sympy_arm_dynamics(const double *q, const double *qd, const double *arm, double *B, double *n) {
    arm_dynamics_core(q, qd, arm, B, n);
    return (all_finite(B, 4) && all_finite(n, 2)) ? HYBRID_OK : HYBRID_NONFINITE;
}

int hybrid_sympy_operational_space(const double *q, const double *qd, const double *arm, double singular_tol, double *Bo, double *no) {
    double cond[1];
    operational_space_core(q, qd, arm, Bo, no, cond);
    if (fabs(cond[0]) < singular_tol) return HYBRID_SINGULAR;
    return (all_finite(Bo, 4) && all_finite(no, 2) && all_finite(cond, 1)) ? HYBRID_OK : HYBRID_NONFINITE;
}

int hybrid_sympy_task_frame_plane(const double *r, const double *rd, const double *surface, double *R, double *Rd) {
    task_frame_plane_core(r, rd, surface, R, Rd);
    return (all_finite(R, 4) && all_finite(Rd, 4)) ? HYBRID_OK : HYBRID_NONFINITE;
}

int hybrid_sympy_decoupling_law_plane(const double *q, const double *qd, const double *a, const double *Fc, const double *arm, const double *surface, const double *opts, double singular_tol, double *F, double *tau) {
    double cond[1];
    decoupling_law_plane_core(q, qd, a, Fc, arm, surface, opts, F, tau, cond);
    if (fabs(cond[0]) < singular_tol) return HYBRID_SINGULAR;
    return (all_finite(F, 2) && all_finite(tau, 2) && all_finite(cond, 1)) ? HYBRID_OK : HYBRID_NONFINITE;
}

int hybrid_sympy_decoupling_law_plane_batch(int nstates, const double *q, const double *qd, const double *a, const double *Fc, const double *arm, const double *surface, const double *opts, double singular_tol, double *F, double *tau, int *status) {
    int i, failed = 0;
    for (i = 0; i < nstates; ++i) {
        status[i] = hybrid_sympy_decoupling_law_plane(q + (long)i * 2, qd + (long)i * 2, a + (long)i * 2, Fc + (long)i * 2, arm, surface, opts, singular_tol, F + (long)i * 2, tau + (long)i * 2);
        failed += status[i] != HYBRID_OK;
    }
    return failed;
}

int hybrid_sympy_task_measurement_plane(const double *q, const double *qd, const double *Fc, const double *arm, const double *surface, double *r, double *rd, double *v, double *f) {
    task_measurement_plane_core(q, qd, Fc, arm, surface, r, rd, v, f);
    return (all_finite(r, 2) && all_finite(rd, 2) && all_finite(v, 2) && all_finite(f, 2)) ? HYBRID_OK : HYBRID_NONFINITE;
}

int hybrid_sympy_plant_rhs_plane(const double *x, const double *tau, const double *arm, const double *plant, const double *surface, double *xdot) {
    plant_rhs_plane_core(x, tau, arm, plant, surface, xdot);
    return (all_finite(xdot, 8)) ? HYBRID_OK : HYBRID_NONFINITE;
}

int hybrid_sympy_plant_advance_plane(double *x, const double *tau, const double *arm, const double *plant, const double *surface, double h, int nsteps, double *trajectory, int *steps_done) {
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

int hybrid_sympy_plant_outputs_plane(const double *x, const double *arm, const double *plant, const double *surface, double *y) {
    plant_outputs_plane_core(x, arm, plant, surface, y);
    return (all_finite(y, 14)) ? HYBRID_OK : HYBRID_NONFINITE;
}

int hybrid_sympy_plant_outputs_plane_batch(int nstates, const double *x, const double *arm, const double *plant, const double *surface, double *y, int *status) {
    int i, failed = 0;
    for (i = 0; i < nstates; ++i) {
        status[i] = hybrid_sympy_plant_outputs_plane(x + (long)i * 8, arm, plant, surface, y + (long)i * 14);
        failed += status[i] != HYBRID_OK;
    }
    return failed;
}

int hybrid_sympy_task_frame_circle(const double *r, const double *rd, const double *surface, double *R, double *Rd) {
    task_frame_circle_core(r, rd, surface, R, Rd);
    return (all_finite(R, 4) && all_finite(Rd, 4)) ? HYBRID_OK : HYBRID_NONFINITE;
}

int hybrid_sympy_decoupling_law_circle(const double *q, const double *qd, const double *a, const double *Fc, const double *arm, const double *surface, const double *opts, double singular_tol, double *F, double *tau) {
    double cond[1];
    decoupling_law_circle_core(q, qd, a, Fc, arm, surface, opts, F, tau, cond);
    if (fabs(cond[0]) < singular_tol) return HYBRID_SINGULAR;
    return (all_finite(F, 2) && all_finite(tau, 2) && all_finite(cond, 1)) ? HYBRID_OK : HYBRID_NONFINITE;
}

int hybrid_sympy_decoupling_law_circle_batch(int nstates, const double *q, const double *qd, const double *a, const double *Fc, const double *arm, const double *surface, const double *opts, double singular_tol, double *F, double *tau, int *status) {
    int i, failed = 0;
    for (i = 0; i < nstates; ++i) {
        status[i] = hybrid_sympy_decoupling_law_circle(q + (long)i * 2, qd + (long)i * 2, a + (long)i * 2, Fc + (long)i * 2, arm, surface, opts, singular_tol, F + (long)i * 2, tau + (long)i * 2);
        failed += status[i] != HYBRID_OK;
    }
    return failed;
}

int hybrid_sympy_task_measurement_circle(const double *q, const double *qd, const double *Fc, const double *arm, const double *surface, double *r, double *rd, double *v, double *f) {
    task_measurement_circle_core(q, qd, Fc, arm, surface, r, rd, v, f);
    return (all_finite(r, 2) && all_finite(rd, 2) && all_finite(v, 2) && all_finite(f, 2)) ? HYBRID_OK : HYBRID_NONFINITE;
}

int hybrid_sympy_plant_rhs_circle(const double *x, const double *tau, const double *arm, const double *plant, const double *surface, double *xdot) {
    plant_rhs_circle_core(x, tau, arm, plant, surface, xdot);
    return (all_finite(xdot, 8)) ? HYBRID_OK : HYBRID_NONFINITE;
}

int hybrid_sympy_plant_advance_circle(double *x, const double *tau, const double *arm, const double *plant, const double *surface, double h, int nsteps, double *trajectory, int *steps_done) {
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

int hybrid_sympy_plant_outputs_circle(const double *x, const double *arm, const double *plant, const double *surface, double *y) {
    plant_outputs_circle_core(x, arm, plant, surface, y);
    return (all_finite(y, 14)) ? HYBRID_OK : HYBRID_NONFINITE;
}

int hybrid_sympy_plant_outputs_circle_batch(int nstates, const double *x, const double *arm, const double *plant, const double *surface, double *y, int *status) {
    int i, failed = 0;
    for (i = 0; i < nstates; ++i) {
        status[i] = hybrid_sympy_plant_outputs_circle(x + (long)i * 8, arm, plant, surface, y + (long)i * 14);
        failed += status[i] != HYBRID_OK;
    }
    return failed;
}
