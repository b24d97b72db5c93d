/* hybrid generated file: do not edit; change codegen/ and run `python -m hybrid regenerate`. body-sha256: af451228b6d47dd728a39902dbec08a7c42cf5e32cb0e13fa2c5b48524eaddab */
#ifndef HYBRID_SYMPY_H
#define HYBRID_SYMPY_H

/* Arrays of mixed quantities, element by element (SI units; see hybrid_sympy.json for each unit):
   arm[11] = {L1, L2, m1, m2, d1, d2, I1, I2, V1, V2, g}
   surface[4] = {p_x, p_y, n_x, n_y}
   opts[1] = {curvature}
   x[8] = {q1, q2, qd1, qd2, s_x, s_y, sd_x, sd_y}
   plant[7] = {m_s, K_s, D_s, k_e, d_e, gamma, v_eps}
   y[14] = {r_x, r_y, v_t, v_n, Fc_x, Fc_y, Fc_t, Fc_n, s_x, s_y, penetration, N, friction, sensor_v_t}
   surface[3] = {c_x, c_y, rho}
   Matrices are row-major. */

/* cdef-begin */
#define HYBRID_OK 0
#define HYBRID_SINGULAR 1
#define HYBRID_NONFINITE 2
#define HYBRID_FRAME_UNDEFINED 3
#define HYBRID_EULER_SINGULAR 4

/* tip position r = kin(q) [m], Jacobian J(q) (row-major), J'(q, q') q' [m/s^2].
   in: q[2], qd[2], arm[11]; out: r[2], J[4], Jdqd[2]. */
int hybrid_sympy_arm_kinematics(const double *q, const double *qd, const double *arm, double *r, double *J, double *Jdqd);

/* joint-space inertia B(q) [kg m^2] (row-major) and n(q, q') [N m].
   in: q[2], qd[2], arm[11]; out: B[4], n[2]. */
int hybrid_sympy_arm_dynamics(const double *q, const double *qd, const double *arm, double *B, double *n);

/* B_o = J^-T B J^-1 [kg], n_o = J^-T n - B_o J' q' [N].
   in: q[2], qd[2], arm[11]; out: Bo[4], no[2]. Returns HYBRID_SINGULAR when 2|det J|/|J|_F^2 < singular_tol. */
int hybrid_sympy_operational_space(const double *q, const double *qd, const double *arm, double singular_tol, double *Bo, double *no);

/* task-frame rotation R(r) and R'(r, r') [1/s] of a plane (row-major).
   in: r[2], rd[2], surface[4]; out: R[4], Rd[4]. */
int hybrid_sympy_task_frame_plane(const double *r, const double *rd, const double *surface, double *R, double *Rd);

/* decoupling law F*(r, r', a) [N] and tau = J^T F* [N m] on a plane.
   in: q[2], qd[2], a[2], Fc[2], arm[11], surface[4], opts[1]; out: F[2], tau[2]. Returns HYBRID_SINGULAR when 2|det J|/|J|_F^2 < singular_tol. */
int hybrid_sympy_decoupling_law_plane(const double *q, const double *qd, const double *a, const double *Fc, const double *arm, const double *surface, const double *opts, double singular_tol, double *F, double *tau);

/* decoupling_law_plane over nstates states: q, qd, a, Fc and the outputs are nstates rows (row-major); status[i] per state; returns how many states failed. */
int hybrid_sympy_decoupling_law_plane_batch(int nstates, const double *q, const double *qd, const double *a, const double *Fc, const double *arm, const double *surface, const double *opts, double singular_tol, double *F, double *tau, int *status);

/* what a controller measures: r, r', task velocity R r', task force R F_c.
   in: q[2], qd[2], Fc[2], arm[11], surface[4]; out: r[2], rd[2], v[2], f[2]. */
int hybrid_sympy_task_measurement_plane(const double *q, const double *qd, const double *Fc, const double *arm, const double *surface, double *r, double *rd, double *v, double *f);

/* plant state derivative x' = f(x, tau) on a plane.
   in: x[8], tau[2], arm[11], plant[7], surface[4]; out: xdot[8]. */
int hybrid_sympy_plant_rhs_plane(const double *x, const double *tau, const double *arm, const double *plant, const double *surface, double *xdot);

/* advance the state x[8] by nsteps classical RK4 steps of h [s] with the other inputs held constant (zero-order hold); if trajectory is not NULL it receives the state after each step (nsteps x 8, row-major). On HYBRID_NONFINITE, x keeps the last finite state and *steps_done says how many steps completed. */
int hybrid_sympy_plant_advance_plane(double *x, const double *tau, const double *arm, const double *plant, const double *surface, double h, int nsteps, double *trajectory, int *steps_done);

/* plant output record (PLANT_OUTPUTS).
   in: x[8], arm[11], plant[7], surface[4]; out: y[14]. */
int hybrid_sympy_plant_outputs_plane(const double *x, const double *arm, const double *plant, const double *surface, double *y);

/* plant_outputs_plane over nstates states: x and the outputs are nstates rows (row-major); status[i] per state; returns how many states failed. */
int hybrid_sympy_plant_outputs_plane_batch(int nstates, const double *x, const double *arm, const double *plant, const double *surface, double *y, int *status);

/* task-frame rotation R(r) and R'(r, r') [1/s] of a circle (row-major).
   in: r[2], rd[2], surface[3]; out: R[4], Rd[4]. */
int hybrid_sympy_task_frame_circle(const double *r, const double *rd, const double *surface, double *R, double *Rd);

/* decoupling law F*(r, r', a) [N] and tau = J^T F* [N m] on a circle.
   in: q[2], qd[2], a[2], Fc[2], arm[11], surface[3], opts[1]; out: F[2], tau[2]. Returns HYBRID_SINGULAR when 2|det J|/|J|_F^2 < singular_tol. */
int hybrid_sympy_decoupling_law_circle(const double *q, const double *qd, const double *a, const double *Fc, const double *arm, const double *surface, const double *opts, double singular_tol, double *F, double *tau);

/* decoupling_law_circle over nstates states: q, qd, a, Fc and the outputs are nstates rows (row-major); status[i] per state; returns how many states failed. */
int hybrid_sympy_decoupling_law_circle_batch(int nstates, const double *q, const double *qd, const double *a, const double *Fc, const double *arm, const double *surface, const double *opts, double singular_tol, double *F, double *tau, int *status);

/* what a controller measures: r, r', task velocity R r', task force R F_c.
   in: q[2], qd[2], Fc[2], arm[11], surface[3]; out: r[2], rd[2], v[2], f[2]. */
int hybrid_sympy_task_measurement_circle(const double *q, const double *qd, const double *Fc, const double *arm, const double *surface, double *r, double *rd, double *v, double *f);

/* plant state derivative x' = f(x, tau) on a circle.
   in: x[8], tau[2], arm[11], plant[7], surface[3]; out: xdot[8]. */
int hybrid_sympy_plant_rhs_circle(const double *x, const double *tau, const double *arm, const double *plant, const double *surface, double *xdot);

/* advance the state x[8] by nsteps classical RK4 steps of h [s] with the other inputs held constant (zero-order hold); if trajectory is not NULL it receives the state after each step (nsteps x 8, row-major). On HYBRID_NONFINITE, x keeps the last finite state and *steps_done says how many steps completed. */
int hybrid_sympy_plant_advance_circle(double *x, const double *tau, const double *arm, const double *plant, const double *surface, double h, int nsteps, double *trajectory, int *steps_done);

/* plant output record (PLANT_OUTPUTS).
   in: x[8], arm[11], plant[7], surface[3]; out: y[14]. */
int hybrid_sympy_plant_outputs_circle(const double *x, const double *arm, const double *plant, const double *surface, double *y);

/* plant_outputs_circle over nstates states: x and the outputs are nstates rows (row-major); status[i] per state; returns how many states failed. */
int hybrid_sympy_plant_outputs_circle_batch(int nstates, const double *x, const double *arm, const double *plant, const double *surface, double *y, int *status);
/* cdef-end */

#endif
