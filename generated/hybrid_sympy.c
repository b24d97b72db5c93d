/* hybrid generated file: do not edit; change codegen/ and run `python -m hybrid regenerate`. body-sha256: 6af10fde2e10db59557bcf7c31bf661d06904737ad4dc079331df44d3f6a82fb */
/* hybrid_sympy: hybrid force/velocity control kernels for a planar 2-link arm, derived by codegen/model.py.
   Emitted by the sympy backend of hybrid's codegen (SymPy 1.14.0), generator version 5.
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

int hybrid_sympy_decoupling_law_plane_batch(int nstates, const double *q, const double *qd, const double *a, const double *Fc, const double *arm, const double *surface, const double *opts, double singular_tol, double *F, double *tau, int *status) {
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
int hybrid_sympy_decoupling_law_plane_batch(int nstates, const double *q, const double *qd, const double *a, const double *Fc, const double *arm, const double *surface, const double *opts, double singular_tol, double *F, double *tau, int *status) {
    int i, failed = 0;
    for (i = 0; i < nstates; ++i) {
        status[i] = hybrid_sympy_decoupling_law_plane(q + (long)i * 2, qd + (long)i * 2, a + (long)i * 2, Fc + (long)i * 2, arm, surface, opts, singular_tol, F + (long)i * 2, tau + (long)i * 2);
        failed += status[i] != HYBRID_OK;
    }
    return failed;
}
#endif

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

int hybrid_sympy_plant_outputs_plane_batch(int nstates, const double *x, const double *arm, const double *plant, const double *surface, double *y, int *status) {
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
int hybrid_sympy_plant_outputs_plane_batch(int nstates, const double *x, const double *arm, const double *plant, const double *surface, double *y, int *status) {
    int i, failed = 0;
    for (i = 0; i < nstates; ++i) {
        status[i] = hybrid_sympy_plant_outputs_plane(x + (long)i * 8, arm, plant, surface, y + (long)i * 14);
        failed += status[i] != HYBRID_OK;
    }
    return failed;
}
#endif

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

int hybrid_sympy_decoupling_law_circle_batch(int nstates, const double *q, const double *qd, const double *a, const double *Fc, const double *arm, const double *surface, const double *opts, double singular_tol, double *F, double *tau, int *status) {
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
int hybrid_sympy_decoupling_law_circle_batch(int nstates, const double *q, const double *qd, const double *a, const double *Fc, const double *arm, const double *surface, const double *opts, double singular_tol, double *F, double *tau, int *status) {
    int i, failed = 0;
    for (i = 0; i < nstates; ++i) {
        status[i] = hybrid_sympy_decoupling_law_circle(q + (long)i * 2, qd + (long)i * 2, a + (long)i * 2, Fc + (long)i * 2, arm, surface, opts, singular_tol, F + (long)i * 2, tau + (long)i * 2);
        failed += status[i] != HYBRID_OK;
    }
    return failed;
}
#endif

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

int hybrid_sympy_plant_outputs_circle_batch(int nstates, const double *x, const double *arm, const double *plant, const double *surface, double *y, int *status) {
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
int hybrid_sympy_plant_outputs_circle_batch(int nstates, const double *x, const double *arm, const double *plant, const double *surface, double *y, int *status) {
    int i, failed = 0;
    for (i = 0; i < nstates; ++i) {
        status[i] = hybrid_sympy_plant_outputs_circle(x + (long)i * 8, arm, plant, surface, y + (long)i * 14);
        failed += status[i] != HYBRID_OK;
    }
    return failed;
}
#endif
