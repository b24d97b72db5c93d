/* hybrid generated file: do not edit; change codegen/ and run `python -m hybrid regenerate`. body-sha256: f34c85525c9af1d26fc0169191ff73a0dd184b910bfea1dea77fdcc6e9638b05 */
#ifndef HYBRID_PLANAR_ARM_CIRCLE_CONTROLLER_4B54E1A71151_H
#define HYBRID_PLANAR_ARM_CIRCLE_CONTROLLER_4B54E1A71151_H
/* cdef-begin */
/* run nruns closed loops (rows of runs, blocks as the manifest's closed_loop.blocks), HL_W at a time: n_samples control samples of sample_time [s], steps_per_sample RK4 steps of h [s] each; writes metrics (nruns x closed_loop.metrics), status and failed_sample (-1, or the sample where a run stopped) per run, and states, taus and the output record (closed_loop.outputs) per step when not NULL (nruns x rows x size). */
int hybrid_planar_arm_circle_controller_4b54e1a71151_closed_loop(int nruns, const double *runs, int n_samples, int steps_per_sample, double h, double sample_time, double singular_tol, double *metrics, int *status, int *failed_sample, double *states, double *taus, double *outputs);
/* the runs per group: HL_W lanes (8 with AVX-512, 4 with AVX, else 2) */
int hybrid_planar_arm_circle_controller_4b54e1a71151_lanes(void);
/* cdef-end */
#endif
