/* hybrid generated file: do not edit; change codegen/ and run `python -m hybrid regenerate`. body-sha256: f370fd3c9dc1265734d5ffa68b4e44cd048872c0d382f9a09c211902d3ea3652 */
#ifndef HYBRID_PLANAR_ARM_CIRCLE_CONTROLLER_STEP_LOOP_H
#define HYBRID_PLANAR_ARM_CIRCLE_CONTROLLER_STEP_LOOP_H
/* cdef-begin */
/* run nruns closed loops (rows of runs, blocks as the manifest's closed_loop.blocks), HL_W at a time: n_samples control samples of sample_time [s], steps_per_sample RK4 steps of h [s] each; with closed_loop.path_task, each run follows the path whose table starts at the row's path.table in tables (NULL otherwise); writes metrics (nruns x closed_loop.metrics), status and failed_sample (-1, or the sample where a run stopped) per run, states, taus and the output record (closed_loop.outputs) per step when not NULL (nruns x rows x size), and when samples is not NULL the state and the output record at each control sample (nruns x n_samples x (nx + outputs)). */
int hybrid_planar_arm_circle_controller_step_loop_closed_loop(int nruns, const double *runs, const double *tables, int n_samples, int steps_per_sample, double h, double sample_time, double singular_tol, double *metrics, int *status, int *failed_sample, double *states, double *taus, double *outputs, double *samples);
/* the runs per group: HL_W lanes (8 with AVX-512, 4 with AVX, else 2) */
int hybrid_planar_arm_circle_controller_step_loop_lanes(void);
/* cdef-end */
#endif
