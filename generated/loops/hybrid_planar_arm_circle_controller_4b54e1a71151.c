/* hybrid generated file: do not edit; change codegen/ and run `python -m hybrid regenerate`. body-sha256: 435ae4ecbafef408b23584f204e2ae24d2fa7f07c32659c47493e614c101747b */
/* hybrid_planar_arm_circle_controller_4b54e1a71151: the paper's closed loop on a circle: controller_step.
   Emitted by hybrid's codegen/closed_loop.py; it includes hybrid_lanes.h (in generated/: compile with -I there). */
#if !defined(__GNUC__)
#error "the compiled closed loop needs GCC or Clang (vector extensions)"
#endif
#define HL_W 2
#include "hybrid_lanes.h"
#define HYBRID_OK 0
#define HYBRID_SINGULAR 1
#define HYBRID_NONFINITE 2
#define HYBRID_FRAME_UNDEFINED 3
#define HYBRID_EULER_SINGULAR 4

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

#ifdef HL_PART
#define HL_APART __attribute__((visibility("hidden")))
#define HL_IN_PART(n) (HL_PART == (n))
#else
#define HL_APART static
#define HL_IN_PART(n) 1
#endif
#if HL_W > 1 && 1
#define HL_STAGE static inline __attribute__((always_inline))
#else
#define HL_STAGE static
#endif
#if HL_W > 2
#define HL_ROW static inline __attribute__((always_inline))
#else
#define HL_ROW static
#endif
#define PLANT_RHS_LANES_NPRE 28
#if HL_IN_PART(2)
HL_APART void plant_rhs_lanes_pre(const hl_v *arm, const hl_v *plant, const hl_v *surface, hl_v *pre) {
    const hl_v v18 = arm[1];
    const hl_v v20 = arm[0];
    const hl_v v33 = plant[2];
    const hl_v v23 = plant[1];
    const hl_v v3 = arm[5];
    const hl_v v5 = arm[3];
    const hl_v v61 = arm[10];
    const hl_v v62 = v61 * v5;
    const hl_v v55 = v20 * v3;
    const hl_v v174 = v5 * v55;
    const hl_v v67 = arm[8];
    const hl_v v75 = arm[2];
    const hl_v v176 = v61 * v75;
    const hl_v v77 = arm[4];
    const hl_v v177 = v77 * v176;
    const hl_v v4 = v3 * v3;
    const hl_v v85 = v20 * v20;
    const hl_v v86 = v4 + v85;
    const hl_v v82 = v77 * v77;
    const hl_v v83 = v75 * v82;
    const hl_v v2 = arm[7];
    const hl_v v80 = arm[6];
    const hl_v v81 = v80 + v2;
    const hl_v v84 = v81 + v83;
    const hl_v v6 = v4 * v5;
    const hl_v v7 = v2 + v6;
    const hl_v v108 = arm[9];
    const hl_v v122 = surface[0];
    const hl_v v125 = surface[1];
    const hl_v v135 = plant[4];
    const hl_v v121 = surface[2];
    const hl_v v133 = plant[3];
    const hl_v v120 = hl_splat(0.0);
    const hl_v v154 = plant[5];
    const hl_v v150 = plant[6];
    const hl_v v170 = 1.0 / v150;
    const hl_v v158 = plant[0];
    const hl_v v171 = 1.0 / v158;
    pre[0] = v18;
    pre[1] = v20;
    pre[2] = v33;
    pre[3] = v23;
    pre[4] = v3;
    pre[5] = v5;
    pre[6] = v61;
    pre[7] = v62;
    pre[8] = v55;
    pre[9] = v174;
    pre[10] = v67;
    pre[11] = v75;
    pre[12] = v177;
    pre[13] = v4;
    pre[14] = v86;
    pre[15] = v2;
    pre[16] = v84;
    pre[17] = v7;
    pre[18] = v108;
    pre[19] = v122;
    pre[20] = v125;
    pre[21] = v135;
    pre[22] = v121;
    pre[23] = v133;
    pre[24] = v120;
    pre[25] = v154;
    pre[26] = v170;
    pre[27] = v171;
    (void)arm;
    (void)plant;
    (void)surface;
    (void)pre;
}
#else
HL_APART void plant_rhs_lanes_pre(const hl_v *arm, const hl_v *plant, const hl_v *surface, hl_v *pre);
#endif

static inline __attribute__((always_inline)) void plant_rhs_lanes_core(const hl_v *x, const hl_v *tau, const hl_v *pre, hl_v *xdot, const hl_v *base, const int exact, hl_i *odd) {
    (void)x;
    (void)tau;
    (void)pre;
    (void)base;
    (void)odd;
    const hl_v v0 = x[2];
    xdot[0] = v0;
    const hl_v v1 = x[3];
    xdot[1] = v1;
    const hl_v v9 = x[1];
    hl_v v15, v10;
    if (exact) hl_sincos_near(v9, base + 3, &v15, &v10); else hl_sincos_near_poly(v9, base + 3, &v15, &v10, odd);
    const hl_v v11 = x[0];
    hl_v v14, v12;
    if (exact) hl_sincos_near(v11, base + 0, &v14, &v12); else hl_sincos_near_poly(v11, base + 0, &v14, &v12, odd);
    const hl_v v13 = v10 * v12;
    const hl_v v16 = v14 * v15;
    const hl_v v17 = v13 - v16;
    const hl_v v18 = pre[0];
    const hl_v v19 = v17 * v18;
    const hl_v v20 = pre[1];
    const hl_v v21 = v12 * v20;
    const hl_v v22 = v19 + v21;
    const hl_v v37 = v22 * v0;
    const hl_v v35 = v19 * v1;
    const hl_v v34 = x[7];
    xdot[5] = v34;
    const hl_v v172 = v34 - v35;
    const hl_v v38 = v172 - v37;
    const hl_v v33 = pre[2];
    const hl_v v39 = v33 * v38;
    const hl_v v25 = v14 * v10;
    const hl_v v26 = v15 * v12;
    const hl_v v27 = v25 + v26;
    const hl_v v28 = v18 * v27;
    const hl_v v29 = v14 * v20;
    const hl_v v30 = v28 + v29;
    const hl_v v24 = x[5];
    const hl_v v31 = v24 - v30;
    const hl_v v23 = pre[3];
    const hl_v v32 = v23 * v31;
    const hl_v v40 = v32 + v39;
    const hl_v v41 = v22 * v40;
    const hl_v v3 = pre[4];
    const hl_v v63 = v17 * v3;
    const hl_v v64 = v63 + v21;
    const hl_v v5 = pre[5];
    const hl_v v62 = pre[7];
    const hl_v v65 = v62 * v64;
    const hl_v v55 = pre[8];
    const hl_v v174 = pre[9];
    const hl_v v57 = v174 * v15;
    const hl_v v70 = v57 + v57;
    const hl_v v175 = v0 * v1;
    const hl_v v72 = v175 * v70;
    const hl_v v181 = v72 - v65;
    const hl_v v58 = v1 * v1;
    const hl_v v59 = v57 * v58;
    const hl_v v67 = pre[10];
    const hl_v v68 = v67 * v0;
    const hl_v v8 = tau[0];
    const hl_v v178 = v8 - v68;
    const hl_v v179 = v178 + v59;
    const hl_v v177 = pre[12];
    const hl_v v78 = v177 * v12;
    const hl_v v180 = v179 - v78;
    const hl_v v182 = v180 + v181;
    const hl_v v183 = v182 + v41;
    const hl_v v49 = v30 * v0;
    const hl_v v47 = v28 * v1;
    const hl_v v46 = x[6];
    xdot[4] = v46;
    const hl_v v173 = v46 + v47;
    const hl_v v50 = v49 + v173;
    const hl_v v51 = v33 * v50;
    const hl_v v43 = x[4];
    const hl_v v44 = v43 - v22;
    const hl_v v45 = v23 * v44;
    const hl_v v52 = v45 + v51;
    const hl_v v53 = v30 * v52;
    const hl_v v79 = v183 - v53;
    const hl_v v87 = v10 * v55;
    const hl_v v88 = v87 + v87;
    const hl_v v4 = pre[13];
    const hl_v v86 = pre[14];
    const hl_v v89 = v86 + v88;
    const hl_v v90 = v5 * v89;
    const hl_v v2 = pre[15];
    const hl_v v84 = pre[16];
    const hl_v v91 = v84 + v90;
    const hl_v v7 = pre[17];
    const hl_v v92 = v7 * v91;
    const hl_v v93 = v4 + v87;
    const hl_v v94 = v5 * v93;
    const hl_v v95 = v2 + v94;
    const hl_v v96 = v95 * v95;
    const hl_v v97 = v92 - v96;
    const hl_v v168 = 1.0 / v97;
    const hl_v v98 = v79 * v168;
    const hl_v v99 = v7 * v98;
    const hl_v v101 = v28 * v52;
    const hl_v v103 = v63 * v62;
    const hl_v v105 = v0 * v0;
    const hl_v v106 = v57 * v105;
    const hl_v v108 = pre[18];
    const hl_v v109 = v108 * v1;
    const hl_v v100 = tau[1];
    const hl_v v185 = v100 - v109;
    const hl_v v186 = v185 - v106;
    const hl_v v187 = v186 - v103;
    const hl_v v188 = v187 - v101;
    const hl_v v184 = v18 * v17;
    const hl_v v112 = v184 * v40;
    const hl_v v113 = v112 + v188;
    const hl_v v114 = v113 * v168;
    const hl_v v115 = v95 * v114;
    const hl_v v116 = v99 - v115;
    xdot[2] = v116;
    const hl_v v117 = v114 * v91;
    const hl_v v118 = v98 * v95;
    const hl_v v119 = v117 - v118;
    xdot[3] = v119;
    const hl_v v122 = pre[19];
    const hl_v v123 = v43 - v122;
    const hl_v v124 = v123 * v123;
    const hl_v v125 = pre[20];
    const hl_v v126 = v24 - v125;
    const hl_v v127 = v126 * v126;
    const hl_v v128 = v124 + v127;
    const hl_v v129 = hl_sqrt(v128);
    const hl_v v169 = 1.0 / v129;
    const hl_v v132 = v123 * v169;
    const hl_v v136 = v132 * v46;
    const hl_v v137 = v126 * v169;
    const hl_v v138 = v137 * v34;
    const hl_v v139 = v136 + v138;
    const hl_v v135 = pre[21];
    const hl_v v140 = v135 * v139;
    const hl_v v121 = pre[22];
    const hl_v v130 = v121 - v129;
    const hl_v v133 = pre[23];
    const hl_v v134 = v130 * v133;
    const hl_v v141 = v134 - v140;
    const hl_v v120 = pre[24];
    const hl_v v142 = hl_fmax(v120, v141);
    const hl_v v146 = v137 * v142;
    const hl_v v154 = pre[25];
    const hl_v v189 = v154 * v146;
    const hl_v v147 = v132 * v34;
    const hl_v v148 = v137 * v46;
    const hl_v v149 = v147 - v148;
    const hl_v v170 = pre[26];
    const hl_v v151 = v149 * v170;
    const hl_v v152 = (exact ? hl_tanh(v151) : hl_tanh_poly(v151, odd));
    const hl_v v155 = v189 * v152;
    const hl_v v131 = hl_bool(v120 < v130);
    const hl_v v156 = hl_select(v131 != 0.0, v155, hl_splat(0.0));
    const hl_v v143 = v132 * v142;
    const hl_v v144 = hl_select(v131 != 0.0, v143, hl_splat(0.0));
    const hl_v v190 = v144 - v52;
    const hl_v v157 = v190 + v156;
    const hl_v v171 = pre[27];
    const hl_v v159 = v157 * v171;
    xdot[6] = v159;
    const hl_v v191 = v154 * v143;
    const hl_v v163 = v191 * v152;
    const hl_v v164 = -v163;
    const hl_v v165 = hl_select(v131 != 0.0, v164, hl_splat(0.0));
    const hl_v v160 = hl_select(v131 != 0.0, v146, hl_splat(0.0));
    const hl_v v192 = v160 - v40;
    const hl_v v166 = v192 + v165;
    const hl_v v167 = v166 * v171;
    xdot[7] = v167;
}

#if HL_IN_PART(2)
HL_APART __attribute__((noinline, cold)) void plant_rhs_lanes_exact(const hl_v *x, const hl_v *tau, const hl_v *pre, hl_v *xdot, const hl_v *base) {
    plant_rhs_lanes_core(x, tau, pre, xdot, base, 1, NULL);
}
#else
HL_APART __attribute__((noinline, cold)) void plant_rhs_lanes_exact(const hl_v *x, const hl_v *tau, const hl_v *pre, hl_v *xdot, const hl_v *base);
#endif

HL_STAGE void plant_rhs_lanes(const hl_v *x, const hl_v *tau, const hl_v *pre, hl_v *xdot, const hl_v *base) {
    hl_i odd = hl_splat(0.0) != 0.0;
    plant_rhs_lanes_core(x, tau, pre, xdot, base, 0, &odd);
    if (hl_any(odd)) plant_rhs_lanes_exact(x, tau, pre, xdot, base);
}

#define PLANT_RHS_SIGNALS_LANES_NPRE 28
#if HL_IN_PART(2)
HL_APART void plant_rhs_signals_lanes_pre(const hl_v *arm, const hl_v *plant, const hl_v *surface, hl_v *pre) {
    const hl_v v18 = arm[1];
    const hl_v v20 = arm[0];
    const hl_v v33 = plant[2];
    const hl_v v23 = plant[1];
    const hl_v v3 = arm[5];
    const hl_v v5 = arm[3];
    const hl_v v61 = arm[10];
    const hl_v v62 = v61 * v5;
    const hl_v v55 = v20 * v3;
    const hl_v v197 = v5 * v55;
    const hl_v v67 = arm[8];
    const hl_v v75 = arm[2];
    const hl_v v199 = v61 * v75;
    const hl_v v77 = arm[4];
    const hl_v v200 = v77 * v199;
    const hl_v v4 = v3 * v3;
    const hl_v v85 = v20 * v20;
    const hl_v v86 = v4 + v85;
    const hl_v v82 = v77 * v77;
    const hl_v v83 = v75 * v82;
    const hl_v v2 = arm[7];
    const hl_v v80 = arm[6];
    const hl_v v81 = v80 + v2;
    const hl_v v84 = v81 + v83;
    const hl_v v6 = v4 * v5;
    const hl_v v7 = v2 + v6;
    const hl_v v108 = arm[9];
    const hl_v v122 = surface[0];
    const hl_v v125 = surface[1];
    const hl_v v135 = plant[4];
    const hl_v v121 = surface[2];
    const hl_v v133 = plant[3];
    const hl_v v120 = hl_splat(0.0);
    const hl_v v154 = plant[5];
    const hl_v v150 = plant[6];
    const hl_v v194 = 1.0 / v150;
    const hl_v v158 = plant[0];
    const hl_v v195 = 1.0 / v158;
    pre[0] = v18;
    pre[1] = v20;
    pre[2] = v33;
    pre[3] = v23;
    pre[4] = v3;
    pre[5] = v5;
    pre[6] = v61;
    pre[7] = v62;
    pre[8] = v55;
    pre[9] = v197;
    pre[10] = v67;
    pre[11] = v75;
    pre[12] = v200;
    pre[13] = v4;
    pre[14] = v86;
    pre[15] = v2;
    pre[16] = v84;
    pre[17] = v7;
    pre[18] = v108;
    pre[19] = v122;
    pre[20] = v125;
    pre[21] = v135;
    pre[22] = v121;
    pre[23] = v133;
    pre[24] = v120;
    pre[25] = v154;
    pre[26] = v194;
    pre[27] = v195;
    (void)arm;
    (void)plant;
    (void)surface;
    (void)pre;
}
#else
HL_APART void plant_rhs_signals_lanes_pre(const hl_v *arm, const hl_v *plant, const hl_v *surface, hl_v *pre);
#endif

static inline __attribute__((always_inline)) void plant_rhs_signals_lanes_core(const hl_v *x, const hl_v *tau, const hl_v *pre, hl_v *xdot, hl_v *s, hl_v *y, const hl_v *base, const int exact, hl_i *odd) {
    (void)x;
    (void)tau;
    (void)pre;
    (void)base;
    (void)odd;
    const hl_v v0 = x[2];
    xdot[0] = v0;
    const hl_v v1 = x[3];
    xdot[1] = v1;
    const hl_v v9 = x[1];
    hl_v v15, v10;
    if (exact) hl_sincos_near(v9, base + 3, &v15, &v10); else hl_sincos_near_poly(v9, base + 3, &v15, &v10, odd);
    const hl_v v11 = x[0];
    hl_v v14, v12;
    if (exact) hl_sincos_near(v11, base + 0, &v14, &v12); else hl_sincos_near_poly(v11, base + 0, &v14, &v12, odd);
    const hl_v v13 = v10 * v12;
    const hl_v v16 = v14 * v15;
    const hl_v v17 = v13 - v16;
    const hl_v v18 = pre[0];
    const hl_v v19 = v17 * v18;
    const hl_v v20 = pre[1];
    const hl_v v21 = v12 * v20;
    const hl_v v22 = v19 + v21;
    y[0] = v22;
    const hl_v v36 = v22 * v0;
    const hl_v v35 = v19 * v1;
    const hl_v v37 = v35 + v36;
    const hl_v v34 = x[7];
    xdot[5] = v34;
    const hl_v v38 = v34 - v37;
    const hl_v v33 = pre[2];
    const hl_v v39 = v33 * v38;
    const hl_v v25 = v14 * v10;
    const hl_v v26 = v15 * v12;
    const hl_v v27 = v25 + v26;
    const hl_v v28 = v18 * v27;
    const hl_v v29 = v14 * v20;
    const hl_v v30 = v28 + v29;
    y[1] = v30;
    const hl_v v24 = x[5];
    y[9] = v24;
    const hl_v v31 = v24 - v30;
    const hl_v v23 = pre[3];
    const hl_v v32 = v23 * v31;
    const hl_v v40 = v32 + v39;
    s[1] = v40;
    y[5] = v40;
    const hl_v v41 = v22 * v40;
    const hl_v v3 = pre[4];
    const hl_v v63 = v17 * v3;
    const hl_v v64 = v63 + v21;
    const hl_v v5 = pre[5];
    const hl_v v62 = pre[7];
    const hl_v v65 = v62 * v64;
    const hl_v v55 = pre[8];
    const hl_v v197 = pre[9];
    const hl_v v57 = v197 * v15;
    const hl_v v70 = v57 + v57;
    const hl_v v198 = v0 * v1;
    const hl_v v72 = v198 * v70;
    const hl_v v204 = v72 - v65;
    const hl_v v58 = v1 * v1;
    const hl_v v59 = v57 * v58;
    const hl_v v67 = pre[10];
    const hl_v v68 = v67 * v0;
    const hl_v v8 = tau[0];
    const hl_v v201 = v8 - v68;
    const hl_v v202 = v201 + v59;
    const hl_v v200 = pre[12];
    const hl_v v78 = v200 * v12;
    const hl_v v203 = v202 - v78;
    const hl_v v205 = v203 + v204;
    const hl_v v206 = v205 + v41;
    const hl_v v47 = v30 * v0;
    const hl_v v46 = v28 * v1;
    const hl_v v48 = v46 + v47;
    const hl_v v49 = x[6];
    xdot[4] = v49;
    const hl_v v50 = v48 + v49;
    const hl_v v51 = v33 * v50;
    const hl_v v43 = x[4];
    y[8] = v43;
    const hl_v v44 = v43 - v22;
    const hl_v v45 = v23 * v44;
    const hl_v v52 = v45 + v51;
    s[0] = v52;
    y[4] = v52;
    const hl_v v53 = v30 * v52;
    const hl_v v79 = v206 - v53;
    const hl_v v87 = v10 * v55;
    const hl_v v88 = v87 + v87;
    const hl_v v4 = pre[13];
    const hl_v v86 = pre[14];
    const hl_v v89 = v86 + v88;
    const hl_v v90 = v5 * v89;
    const hl_v v2 = pre[15];
    const hl_v v84 = pre[16];
    const hl_v v91 = v84 + v90;
    const hl_v v7 = pre[17];
    const hl_v v92 = v7 * v91;
    const hl_v v93 = v4 + v87;
    const hl_v v94 = v5 * v93;
    const hl_v v95 = v2 + v94;
    const hl_v v96 = v95 * v95;
    const hl_v v97 = v92 - v96;
    const hl_v v192 = 1.0 / v97;
    const hl_v v98 = v79 * v192;
    const hl_v v99 = v7 * v98;
    const hl_v v101 = v28 * v52;
    const hl_v v103 = v63 * v62;
    const hl_v v105 = v0 * v0;
    const hl_v v106 = v57 * v105;
    const hl_v v108 = pre[18];
    const hl_v v109 = v108 * v1;
    const hl_v v100 = tau[1];
    const hl_v v208 = v100 - v109;
    const hl_v v209 = v208 - v106;
    const hl_v v210 = v209 - v103;
    const hl_v v211 = v210 - v101;
    const hl_v v207 = v18 * v17;
    const hl_v v112 = v207 * v40;
    const hl_v v113 = v112 + v211;
    const hl_v v114 = v113 * v192;
    const hl_v v115 = v95 * v114;
    const hl_v v116 = v99 - v115;
    xdot[2] = v116;
    const hl_v v117 = v114 * v91;
    const hl_v v118 = v98 * v95;
    const hl_v v119 = v117 - v118;
    xdot[3] = v119;
    const hl_v v122 = pre[19];
    const hl_v v123 = v43 - v122;
    const hl_v v124 = v123 * v123;
    const hl_v v125 = pre[20];
    const hl_v v126 = v24 - v125;
    const hl_v v127 = v126 * v126;
    const hl_v v128 = v124 + v127;
    const hl_v v129 = hl_sqrt(v128);
    const hl_v v193 = 1.0 / v129;
    const hl_v v132 = v123 * v193;
    const hl_v v136 = v132 * v49;
    const hl_v v137 = v126 * v193;
    const hl_v v138 = v137 * v34;
    const hl_v v139 = v136 + v138;
    const hl_v v135 = pre[21];
    const hl_v v140 = v135 * v139;
    const hl_v v121 = pre[22];
    const hl_v v130 = v121 - v129;
    s[4] = v130;
    y[10] = v130;
    const hl_v v133 = pre[23];
    const hl_v v134 = v130 * v133;
    const hl_v v141 = v134 - v140;
    const hl_v v120 = pre[24];
    const hl_v v142 = hl_fmax(v120, v141);
    const hl_v v146 = v137 * v142;
    const hl_v v154 = pre[25];
    const hl_v v212 = v154 * v146;
    const hl_v v147 = v132 * v34;
    const hl_v v148 = v137 * v49;
    const hl_v v149 = v147 - v148;
    y[13] = v149;
    const hl_v v194 = pre[26];
    const hl_v v151 = v149 * v194;
    const hl_v v152 = (exact ? hl_tanh(v151) : hl_tanh_poly(v151, odd));
    const hl_v v155 = v212 * v152;
    const hl_v v131 = hl_bool(v120 < v130);
    const hl_v v156 = hl_select(v131 != 0.0, v155, hl_splat(0.0));
    const hl_v v143 = v132 * v142;
    const hl_v v144 = hl_select(v131 != 0.0, v143, hl_splat(0.0));
    const hl_v v213 = v144 - v52;
    const hl_v v157 = v213 + v156;
    const hl_v v195 = pre[27];
    const hl_v v159 = v157 * v195;
    xdot[6] = v159;
    const hl_v v162 = v152 * v154;
    const hl_v v163 = v143 * v162;
    const hl_v v164 = -v163;
    const hl_v v165 = hl_select(v131 != 0.0, v164, hl_splat(0.0));
    const hl_v v160 = hl_select(v131 != 0.0, v146, hl_splat(0.0));
    const hl_v v214 = v160 - v40;
    const hl_v v166 = v214 + v165;
    const hl_v v167 = v166 * v195;
    xdot[7] = v167;
    const hl_v v169 = v22 - v122;
    const hl_v v170 = v169 * v169;
    const hl_v v168 = v30 - v125;
    const hl_v v171 = v168 * v168;
    const hl_v v172 = v170 + v171;
    const hl_v v173 = hl_sqrt(v172);
    const hl_v v196 = 1.0 / v173;
    const hl_v v174 = v168 * v196;
    const hl_v v175 = v40 * v174;
    const hl_v v176 = v169 * v196;
    const hl_v v177 = v52 * v176;
    const hl_v v178 = v175 + v177;
    s[2] = v178;
    y[7] = v178;
    const hl_v v179 = v37 * v176;
    const hl_v v180 = v174 * v48;
    const hl_v v181 = v179 + v180;
    s[3] = v181;
    y[2] = v181;
    const hl_v v182 = hl_select(v131 != 0.0, v142, hl_splat(0.0));
    s[5] = v182;
    y[11] = v182;
    const hl_v v183 = v37 * v174;
    const hl_v v184 = v176 * v48;
    const hl_v v185 = v183 - v184;
    y[3] = v185;
    const hl_v v186 = v40 * v176;
    const hl_v v187 = v52 * v174;
    const hl_v v188 = v186 - v187;
    y[6] = v188;
    const hl_v v189 = v142 * v162;
    const hl_v v190 = -v189;
    const hl_v v191 = hl_select(v131 != 0.0, v190, hl_splat(0.0));
    y[12] = v191;
}

#if HL_IN_PART(2)
HL_APART __attribute__((noinline, cold)) void plant_rhs_signals_lanes_exact(const hl_v *x, const hl_v *tau, const hl_v *pre, hl_v *xdot, hl_v *s, hl_v *y, const hl_v *base) {
    plant_rhs_signals_lanes_core(x, tau, pre, xdot, s, y, base, 1, NULL);
}
#else
HL_APART __attribute__((noinline, cold)) void plant_rhs_signals_lanes_exact(const hl_v *x, const hl_v *tau, const hl_v *pre, hl_v *xdot, hl_v *s, hl_v *y, const hl_v *base);
#endif

HL_STAGE void plant_rhs_signals_lanes(const hl_v *x, const hl_v *tau, const hl_v *pre, hl_v *xdot, hl_v *s, hl_v *y, const hl_v *base) {
    hl_i odd = hl_splat(0.0) != 0.0;
    plant_rhs_signals_lanes_core(x, tau, pre, xdot, s, y, base, 0, &odd);
    if (hl_any(odd)) plant_rhs_signals_lanes_exact(x, tau, pre, xdot, s, y, base);
}

#define PLANT_OUTPUTS_LANES_NPRE 12
#if HL_IN_PART(2)
HL_APART void plant_outputs_lanes_pre(const hl_v *arm, const hl_v *plant, const hl_v *surface, hl_v *pre) {
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
#else
HL_APART void plant_outputs_lanes_pre(const hl_v *arm, const hl_v *plant, const hl_v *surface, hl_v *pre);
#endif

static inline __attribute__((always_inline)) void plant_outputs_lanes_core(const hl_v *x, const hl_v *pre, hl_v *y, const int exact, hl_i *odd) {
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

#if HL_IN_PART(2)
HL_APART __attribute__((noinline, cold)) void plant_outputs_lanes_exact(const hl_v *x, const hl_v *pre, hl_v *y) {
    plant_outputs_lanes_core(x, pre, y, 1, NULL);
}
#else
HL_APART __attribute__((noinline, cold)) void plant_outputs_lanes_exact(const hl_v *x, const hl_v *pre, hl_v *y);
#endif

#if HL_IN_PART(2)
HL_APART void plant_outputs_lanes(const hl_v *x, const hl_v *pre, hl_v *y) {
    hl_i odd = hl_splat(0.0) != 0.0;
    plant_outputs_lanes_core(x, pre, y, 0, &odd);
    if (hl_any(odd)) plant_outputs_lanes_exact(x, pre, y);
}
#else
HL_APART void plant_outputs_lanes(const hl_v *x, const hl_v *pre, hl_v *y);
#endif

#define CONTROLLER_STEP_LANES_NPRE 79
#if HL_IN_PART(2)
HL_APART void controller_step_lanes_pre(const hl_v *steps, const hl_v *gains, const hl_v *selection, const hl_v *robot, const hl_v *surface, const hl_v *e, const hl_v *options, const hl_v *posture, const hl_v *limits, const hl_v *sensor, const hl_v *fault, hl_v *pre) {
    const hl_v v23 = hl_splat(0.32);
    const hl_v v34 = hl_splat(0.45);
    const hl_v v37 = surface[0];
    const hl_v v15 = surface[3];
    const hl_v v13 = surface[2];
    const hl_v v14 = surface[5];
    const hl_v v50 = v14 * v13;
    const hl_v v46 = surface[1];
    const hl_v v17 = surface[4];
    const hl_v v16 = v15 * v15;
    const hl_v v18 = v17 * v17;
    const hl_v v19 = v16 + v18;
    const hl_v v20 = v14 * v14;
    const hl_v v21 = v19 + v20;
    const hl_v v739 = 1.0 / v21;
    const hl_v v54 = v15 * v739;
    const hl_v v58 = v17 * v739;
    const hl_v v22 = v14 * v739;
    const hl_v v2 = e[0];
    const hl_v v3 = v2 * v2;
    const hl_v v1 = e[1];
    const hl_v v4 = v1 * v1;
    const hl_v v5 = v3 + v4;
    const hl_v v6 = e[2];
    const hl_v v7 = v6 * v6;
    const hl_v v8 = v5 + v7;
    const hl_v v9 = hl_sqrt(v8);
    const hl_v v10 = 1.0 / v9;
    const hl_v v11 = hl_copysign(v10, v9);
    const hl_v v12 = v1 * v11;
    const hl_v v90 = v6 * v11;
    const hl_v v97 = v2 * v11;
    const hl_v v130 = steps[2];
    const hl_v v136 = steps[0];
    const hl_v v133 = steps[1];
    const hl_v v126 = selection[0];
    const hl_v v125 = hl_splat(1.0);
    const hl_v v127 = v125 - v126;
    const hl_v v191 = options[1];
    const hl_v v200 = gains[2];
    const hl_v v175 = gains[1];
    const hl_v v196 = options[3];
    const hl_v v176 = options[4];
    const hl_v v179 = hl_splat(0.0);
    const hl_v v180 = hl_bool(v175 != v179);
    const hl_v v129 = gains[0];
    const hl_v v182 = gains[3];
    const hl_v v183 = options[5];
    const hl_v v184 = v182 * v183;
    const hl_v v187 = hl_bool(v180 == 0.0);
    const hl_v v188 = hl_select(v187 != 0.0, v125, hl_splat(0.0));
    const hl_v v186 = hl_select(v180 != 0.0, v175, hl_splat(0.0));
    const hl_v v189 = v186 + v188;
    const hl_v v741 = 1.0 / v189;
    const hl_v v236 = options[0];
    const hl_v v385 = steps[5];
    const hl_v v390 = steps[3];
    const hl_v v387 = steps[4];
    const hl_v v381 = selection[1];
    const hl_v v382 = v125 - v381;
    const hl_v v430 = gains[6];
    const hl_v v410 = gains[5];
    const hl_v v413 = hl_bool(v410 != v179);
    const hl_v v384 = gains[4];
    const hl_v v415 = gains[7];
    const hl_v v416 = v415 * v183;
    const hl_v v419 = hl_bool(v413 == 0.0);
    const hl_v v420 = hl_select(v419 != 0.0, v125, hl_splat(0.0));
    const hl_v v418 = hl_select(v413 != 0.0, v410, hl_splat(0.0));
    const hl_v v421 = v418 + v420;
    const hl_v v742 = 1.0 / v421;
    const hl_v v483 = robot[28];
    const hl_v v485 = robot[29];
    const hl_v v526 = robot[12];
    const hl_v v515 = robot[11];
    const hl_v v516 = robot[10];
    const hl_v v544 = options[2];
    const hl_v v545 = v125 - v544;
    const hl_v v508 = robot[19];
    const hl_v v481 = robot[1];
    const hl_v v490 = robot[2];
    const hl_v v482 = robot[0];
    const hl_v v784 = v481 * v482;
    const hl_v v0 = robot[9];
    const hl_v v589 = robot[26];
    const hl_v v743 = 1.0 / v589;
    const hl_v v587 = robot[22];
    const hl_v v588 = hl_bool(v587 != v179);
    const hl_v v585 = robot[20];
    const hl_v v595 = robot[24];
    const hl_v v787 = v482 * v490;
    const hl_v v604 = limits[2];
    const hl_v v601 = limits[0];
    const hl_v v615 = -v601;
    const hl_v v599 = hl_splat(1.7976931348623157e+308);
    const hl_v v643 = robot[27];
    const hl_v v744 = 1.0 / v643;
    const hl_v v641 = robot[23];
    const hl_v v642 = hl_bool(v641 != v179);
    const hl_v v639 = robot[21];
    const hl_v v649 = robot[25];
    const hl_v v656 = limits[3];
    const hl_v v654 = limits[1];
    const hl_v v666 = -v654;
    const hl_v v709 = hl_splat(1e-12);
    const hl_v v723 = hl_splat(2.0);
    pre[0] = v23;
    pre[1] = v34;
    pre[2] = v37;
    pre[3] = v15;
    pre[4] = v13;
    pre[5] = v14;
    pre[6] = v50;
    pre[7] = v46;
    pre[8] = v17;
    pre[9] = v54;
    pre[10] = v58;
    pre[11] = v22;
    pre[12] = v12;
    pre[13] = v90;
    pre[14] = v97;
    pre[15] = v130;
    pre[16] = v136;
    pre[17] = v133;
    pre[18] = v126;
    pre[19] = v125;
    pre[20] = v127;
    pre[21] = v191;
    pre[22] = v200;
    pre[23] = v175;
    pre[24] = v196;
    pre[25] = v176;
    pre[26] = v179;
    pre[27] = v180;
    pre[28] = v129;
    pre[29] = v182;
    pre[30] = v183;
    pre[31] = v184;
    pre[32] = v741;
    pre[33] = v236;
    pre[34] = v385;
    pre[35] = v390;
    pre[36] = v387;
    pre[37] = v381;
    pre[38] = v382;
    pre[39] = v430;
    pre[40] = v410;
    pre[41] = v413;
    pre[42] = v384;
    pre[43] = v415;
    pre[44] = v416;
    pre[45] = v742;
    pre[46] = v483;
    pre[47] = v485;
    pre[48] = v526;
    pre[49] = v515;
    pre[50] = v516;
    pre[51] = v544;
    pre[52] = v545;
    pre[53] = v508;
    pre[54] = v481;
    pre[55] = v490;
    pre[56] = v482;
    pre[57] = v784;
    pre[58] = v0;
    pre[59] = v743;
    pre[60] = v587;
    pre[61] = v588;
    pre[62] = v585;
    pre[63] = v595;
    pre[64] = v787;
    pre[65] = v604;
    pre[66] = v601;
    pre[67] = v615;
    pre[68] = v599;
    pre[69] = v744;
    pre[70] = v641;
    pre[71] = v642;
    pre[72] = v639;
    pre[73] = v649;
    pre[74] = v656;
    pre[75] = v654;
    pre[76] = v666;
    pre[77] = v709;
    pre[78] = v723;
    (void)steps;
    (void)gains;
    (void)selection;
    (void)robot;
    (void)surface;
    (void)e;
    (void)options;
    (void)posture;
    (void)limits;
    (void)sensor;
    (void)fault;
    (void)pre;
}
#else
HL_APART void controller_step_lanes_pre(const hl_v *steps, const hl_v *gains, const hl_v *selection, const hl_v *robot, const hl_v *surface, const hl_v *e, const hl_v *options, const hl_v *posture, const hl_v *limits, const hl_v *sensor, const hl_v *fault, hl_v *pre);
#endif

static inline __attribute__((always_inline)) void controller_step_lanes_core(const hl_v *q, const hl_v *qd, const hl_v *Fc, const hl_v *integrals, const hl_v *last_torque, const hl_v *filter, const hl_v *estimate, const hl_v *t, const hl_v *yd_extra, const hl_v *yd_rate, const hl_v *target, const hl_v *pre, hl_v *tau, hl_v *integrals_next, hl_v *a, hl_v *y, hl_v *f, hl_v *saturated, hl_v *filter_next, hl_v *estimate_next, hl_v *contact_wrench, hl_v *frame, hl_v *cond, const int exact, hl_i *odd) {
    (void)q;
    (void)qd;
    (void)Fc;
    (void)integrals;
    (void)last_torque;
    (void)filter;
    (void)estimate;
    (void)t;
    (void)yd_extra;
    (void)yd_rate;
    (void)target;
    (void)pre;
    (void)odd;
    const hl_v v24 = q[0];
    hl_v v29, v25;
    if (exact) hl_sincos(v24, &v29, &v25); else hl_sincos_poly(v24, &v29, &v25, odd);
    const hl_v v26 = q[1];
    hl_v v30, v27;
    if (exact) hl_sincos(v26, &v30, &v27); else hl_sincos_poly(v26, &v30, &v27, odd);
    const hl_v v28 = v25 * v27;
    const hl_v v31 = v29 * v30;
    const hl_v v32 = v28 - v31;
    const hl_v v23 = pre[0];
    const hl_v v33 = v23 * v32;
    const hl_v v34 = pre[1];
    const hl_v v35 = v34 * v25;
    const hl_v v36 = v33 + v35;
    const hl_v v37 = pre[2];
    const hl_v v38 = v36 - v37;
    const hl_v v15 = pre[3];
    const hl_v v39 = v15 * v38;
    const hl_v v13 = pre[4];
    const hl_v v14 = pre[5];
    const hl_v v50 = pre[6];
    const hl_v v745 = v39 - v50;
    const hl_v v40 = v29 * v27;
    const hl_v v41 = v25 * v30;
    const hl_v v42 = v40 + v41;
    const hl_v v43 = v23 * v42;
    const hl_v v44 = v34 * v29;
    const hl_v v45 = v43 + v44;
    const hl_v v46 = pre[7];
    const hl_v v47 = v45 - v46;
    const hl_v v17 = pre[8];
    const hl_v v48 = v17 * v47;
    const hl_v v51 = v48 + v745;
    const hl_v v54 = pre[9];
    const hl_v v55 = v54 * v51;
    const hl_v v56 = v38 - v55;
    const hl_v v57 = v56 * v56;
    const hl_v v58 = pre[10];
    const hl_v v59 = v58 * v51;
    const hl_v v60 = v47 - v59;
    const hl_v v61 = v60 * v60;
    const hl_v v746 = v57 + v61;
    const hl_v v22 = pre[11];
    const hl_v v52 = v22 * v51;
    const hl_v v53 = v13 + v52;
    const hl_v v63 = v53 * v53;
    const hl_v v64 = v63 + v746;
    const hl_v v65 = hl_sqrt(v64);
    const hl_v v740 = 1.0 / v65;
    const hl_v v67 = v60 * v740;
    const hl_v v68 = v58 * v67;
    const hl_v v66 = v53 * v740;
    const hl_v v69 = v22 * v66;
    const hl_v v747 = v68 - v69;
    const hl_v v71 = v56 * v740;
    const hl_v v72 = v54 * v71;
    const hl_v v73 = v72 + v747;
    const hl_v v76 = v15 * v73;
    const hl_v v77 = v71 - v76;
    const hl_v v78 = v77 * v77;
    const hl_v v79 = v17 * v73;
    const hl_v v80 = v67 - v79;
    const hl_v v81 = v80 * v80;
    const hl_v v748 = v78 + v81;
    const hl_v v74 = v14 * v73;
    const hl_v v75 = v66 + v74;
    const hl_v v83 = v75 * v75;
    const hl_v v84 = v83 + v748;
    const hl_v v85 = hl_sqrt(v84);
    const hl_v v86 = 1.0 / v85;
    const hl_v v87 = hl_copysign(v86, v85);
    const hl_v v88 = v75 * v87;
    const hl_v v12 = pre[12];
    const hl_v v89 = v12 * v88;
    const hl_v v91 = v80 * v87;
    const hl_v v90 = pre[13];
    const hl_v v92 = v90 * v91;
    const hl_v v93 = v89 + v92;
    const hl_v v94 = v93 * v93;
    const hl_v v95 = v77 * v87;
    const hl_v v96 = v90 * v95;
    const hl_v v97 = pre[14];
    const hl_v v98 = v97 * v88;
    const hl_v v99 = v96 + v98;
    const hl_v v100 = v99 * v99;
    const hl_v v749 = v94 + v100;
    const hl_v v102 = v97 * v91;
    const hl_v v103 = v12 * v95;
    const hl_v v104 = v102 - v103;
    const hl_v v105 = v104 * v104;
    const hl_v v106 = v105 + v749;
    const hl_v v107 = hl_sqrt(v106);
    const hl_v v108 = 1.0 / v107;
    const hl_v v109 = hl_copysign(v108, v107);
    const hl_v v112 = v99 * v109;
    const hl_v v141 = Fc[1];
    contact_wrench[1] = v141;
    const hl_v v142 = v112 * v141;
    const hl_v v110 = v93 * v109;
    const hl_v v143 = Fc[0];
    contact_wrench[0] = v143;
    const hl_v v144 = v110 * v143;
    const hl_v v752 = v142 - v144;
    const hl_v v147 = Fc[2];
    contact_wrench[2] = v147;
    const hl_v v751 = v147 * v104;
    const hl_v v148 = v751 * v109;
    const hl_v v149 = v148 + v752;
    f[0] = v149;
    const hl_v v130 = pre[15];
    const hl_v v131 = t[0];
    const hl_v v132 = hl_bool(v130 <= v131);
    const hl_v v135 = hl_bool(v132 == 0.0);
    const hl_v v136 = pre[16];
    const hl_v v137 = hl_select(v135 != 0.0, v136, hl_splat(0.0));
    const hl_v v133 = pre[17];
    const hl_v v134 = hl_select(v132 != 0.0, v133, hl_splat(0.0));
    const hl_v v139 = yd_extra[0];
    const hl_v v750 = v139 + v134;
    const hl_v v140 = v137 + v750;
    const hl_v v150 = v140 - v149;
    const hl_v v126 = pre[18];
    const hl_v v151 = v126 * v150;
    const hl_v v152 = qd[0];
    const hl_v v153 = v34 * v152;
    const hl_v v154 = v30 * v153;
    const hl_v v155 = v42 * v154;
    const hl_v v156 = v27 * v153;
    const hl_v v157 = qd[1];
    const hl_v v158 = v152 + v157;
    const hl_v v159 = v23 * v158;
    const hl_v v160 = v156 + v159;
    const hl_v v161 = v32 * v160;
    const hl_v v162 = v155 + v161;
    const hl_v v163 = v112 * v162;
    const hl_v v164 = v32 * v154;
    const hl_v v165 = v41 + v40;
    const hl_v v166 = v165 * v160;
    const hl_v v167 = v164 - v166;
    const hl_v v168 = v110 * v167;
    const hl_v v169 = v163 - v168;
    y[0] = v169;
    const hl_v v170 = v140 - v169;
    const hl_v v125 = pre[19];
    const hl_v v127 = pre[20];
    const hl_v v171 = v127 * v170;
    const hl_v v172 = v151 + v171;
    const hl_v v191 = pre[21];
    const hl_v v192 = v191 * v172;
    const hl_v v197 = integrals[0];
    const hl_v v198 = v197 + v192;
    const hl_v v202 = v191 * v198;
    const hl_v v201 = integrals[1];
    const hl_v v203 = v201 + v202;
    const hl_v v204 = v127 * v203;
    const hl_v v200 = pre[22];
    const hl_v v205 = v200 * v204;
    const hl_v v175 = pre[23];
    const hl_v v199 = v175 * v198;
    const hl_v v206 = v199 + v205;
    const hl_v v207 = hl_fabs(v206);
    const hl_v v196 = pre[24];
    const hl_v v208 = hl_bool(v196 < v207);
    const hl_v v176 = pre[25];
    const hl_v v177 = hl_bool(v149 < v176);
    const hl_v v178 = v126 * v177;
    const hl_v v209 = hl_bool((v208 != 0.0) | (v178 != 0.0));
    const hl_v v211 = v125 - v209;
    const hl_v v212 = v211 * v198;
    const hl_v v210 = v209 * v197;
    const hl_v v213 = v210 + v212;
    const hl_v v179 = pre[26];
    filter_next[0] = v179;
    filter_next[1] = v179;
    filter_next[2] = v179;
    filter_next[3] = v179;
    filter_next[4] = v179;
    filter_next[5] = v179;
    filter_next[6] = v179;
    filter_next[7] = v179;
    filter_next[8] = v179;
    filter_next[9] = v179;
    filter_next[10] = v179;
    filter_next[11] = v179;
    filter_next[12] = v179;
    estimate_next[0] = v179;
    estimate_next[1] = v179;
    estimate_next[2] = v179;
    estimate_next[3] = v179;
    estimate_next[4] = v179;
    estimate_next[5] = v179;
    estimate_next[6] = v179;
    estimate_next[7] = v179;
    estimate_next[8] = v179;
    estimate_next[9] = v179;
    estimate_next[10] = v179;
    estimate_next[11] = v179;
    const hl_v v180 = pre[27];
    const hl_v v181 = v178 * v180;
    const hl_v v195 = hl_bool(v181 == 0.0);
    const hl_v v214 = hl_select(v195 != 0.0, v213, hl_splat(0.0));
    const hl_v v129 = pre[28];
    const hl_v v173 = v129 * v172;
    const hl_v v182 = pre[29];
    const hl_v v183 = pre[30];
    const hl_v v184 = pre[31];
    const hl_v v185 = v184 - v173;
    const hl_v v741 = pre[32];
    const hl_v v190 = v185 * v741;
    const hl_v v193 = v190 - v192;
    const hl_v v194 = hl_select(v181 != 0.0, v193, hl_splat(0.0));
    const hl_v v215 = v194 + v214;
    const hl_v v216 = v175 * v215;
    const hl_v v226 = v182 * v169;
    const hl_v v756 = v226 + v173;
    const hl_v v228 = v756 + v216;
    const hl_v v225 = v125 - v178;
    const hl_v v229 = v225 * v228;
    const hl_v v231 = v169 + v183;
    const hl_v v757 = v182 * v231;
    const hl_v v232 = v757 * v178;
    const hl_v v233 = v229 + v232;
    const hl_v v234 = v126 * v233;
    const hl_v v220 = v211 * v204;
    const hl_v v753 = v127 * v201;
    const hl_v v219 = v753 * v209;
    const hl_v v221 = v219 + v220;
    const hl_v v222 = v200 * v221;
    const hl_v v128 = yd_rate[0];
    const hl_v v754 = v128 + v173;
    const hl_v v755 = v754 + v222;
    const hl_v v223 = v755 + v216;
    const hl_v v224 = v127 * v223;
    const hl_v v235 = v224 - v234;
    a[0] = v235;
    const hl_v v759 = v740 * v66;
    const hl_v v255 = v65 + v65;
    const hl_v v250 = -v53;
    const hl_v v251 = v250 + v250;
    const hl_v v239 = v15 * v167;
    const hl_v v240 = v17 * v162;
    const hl_v v241 = v239 + v240;
    const hl_v v252 = v22 * v241;
    const hl_v v253 = v251 * v252;
    const hl_v v238 = v56 + v56;
    const hl_v v242 = v54 * v241;
    const hl_v v243 = v167 - v242;
    const hl_v v244 = v238 * v243;
    const hl_v v245 = v60 + v60;
    const hl_v v246 = v58 * v241;
    const hl_v v247 = v162 - v246;
    const hl_v v248 = v245 * v247;
    const hl_v v758 = v244 + v248;
    const hl_v v254 = v758 - v253;
    const hl_v v256 = v254 / v255;
    const hl_v v257 = v256 * v759;
    const hl_v v258 = v252 * v740;
    const hl_v v259 = v257 - v258;
    const hl_v v260 = v22 * v259;
    const hl_v v760 = v740 * v67;
    const hl_v v263 = v256 * v760;
    const hl_v v261 = v247 * v740;
    const hl_v v264 = v261 - v263;
    const hl_v v265 = v58 * v264;
    const hl_v v762 = v260 + v265;
    const hl_v v761 = v740 * v71;
    const hl_v v269 = v256 * v761;
    const hl_v v267 = v243 * v740;
    const hl_v v270 = v267 - v269;
    const hl_v v271 = v54 * v270;
    const hl_v v272 = v271 + v762;
    const hl_v v281 = v15 * v272;
    const hl_v v282 = v270 - v281;
    const hl_v v280 = v77 + v77;
    const hl_v v283 = v280 * v282;
    const hl_v v285 = v17 * v272;
    const hl_v v286 = v264 - v285;
    const hl_v v284 = v80 + v80;
    const hl_v v287 = v284 * v286;
    const hl_v v763 = v283 + v287;
    const hl_v v273 = v14 * v272;
    const hl_v v274 = v259 - v273;
    const hl_v v289 = -v75;
    const hl_v v290 = v289 + v289;
    const hl_v v291 = v290 * v274;
    const hl_v v292 = v291 + v763;
    const hl_v v293 = v85 + v85;
    const hl_v v294 = v292 / v293;
    const hl_v v277 = hl_sign(v86);
    const hl_v v276 = hl_copysign(v125, v85);
    const hl_v v764 = v276 * v277;
    const hl_v v765 = v294 * v764;
    const hl_v v279 = v86 / v85;
    const hl_v v296 = v765 * v279;
    const hl_v v297 = v75 * v296;
    const hl_v v275 = v87 * v274;
    const hl_v v298 = v275 + v297;
    const hl_v v299 = v12 * v298;
    const hl_v v301 = v80 * v296;
    const hl_v v300 = v87 * v286;
    const hl_v v302 = v300 - v301;
    const hl_v v303 = v90 * v302;
    const hl_v v304 = v299 - v303;
    const hl_v v310 = -v93;
    const hl_v v311 = v310 + v310;
    const hl_v v312 = v311 * v304;
    const hl_v v315 = v77 * v296;
    const hl_v v314 = v87 * v282;
    const hl_v v316 = v314 - v315;
    const hl_v v317 = v90 * v316;
    const hl_v v318 = v97 * v298;
    const hl_v v319 = v317 - v318;
    const hl_v v313 = v99 + v99;
    const hl_v v320 = v313 * v319;
    const hl_v v766 = v312 + v320;
    const hl_v v323 = v97 * v302;
    const hl_v v324 = v12 * v316;
    const hl_v v325 = v323 - v324;
    const hl_v v322 = v104 + v104;
    const hl_v v326 = v322 * v325;
    const hl_v v327 = v326 + v766;
    const hl_v v328 = v107 + v107;
    const hl_v v329 = v327 / v328;
    const hl_v v307 = hl_sign(v108);
    const hl_v v306 = hl_copysign(v125, v107);
    const hl_v v767 = v306 * v307;
    const hl_v v768 = v329 * v767;
    const hl_v v309 = v108 / v107;
    const hl_v v331 = v768 * v309;
    const hl_v v332 = v93 * v331;
    const hl_v v305 = v109 * v304;
    const hl_v v333 = v305 + v332;
    const hl_v v334 = v333 * v167;
    const hl_v v336 = v99 * v331;
    const hl_v v335 = v109 * v319;
    const hl_v v337 = v335 - v336;
    const hl_v v338 = v337 * v162;
    const hl_v v339 = v334 + v338;
    const hl_v v236 = pre[33];
    const hl_v v340 = v236 * v339;
    const hl_v v343 = v158 * v160;
    const hl_v v342 = v156 * v157;
    const hl_v v344 = v342 - v343;
    const hl_v v345 = v42 * v344;
    const hl_v v346 = v158 * v154;
    const hl_v v347 = v154 * v157;
    const hl_v v348 = v346 - v347;
    const hl_v v349 = v32 * v348;
    const hl_v v350 = v345 + v349;
    const hl_v v351 = v112 * v350;
    const hl_v v352 = v32 * v344;
    const hl_v v353 = v165 * v348;
    const hl_v v354 = v352 - v353;
    const hl_v v355 = v110 * v354;
    const hl_v v769 = v355 - v351;
    const hl_v v770 = v769 - v340;
    const hl_v v357 = v770 + v235;
    const hl_v v111 = v110 * v45;
    const hl_v v113 = v112 * v36;
    const hl_v v114 = v111 + v113;
    const hl_v v115 = v114 * v114;
    const hl_v v116 = v110 * v43;
    const hl_v v117 = v112 * v33;
    const hl_v v118 = v116 + v117;
    const hl_v v119 = v118 * v118;
    const hl_v v120 = v115 + v119;
    const hl_v v121 = hl_sqrt(v120);
    const hl_v v122 = 1.0 / v121;
    const hl_v v123 = hl_copysign(v122, v121);
    const hl_v v358 = v357 * v123;
    const hl_v v124 = v114 * v123;
    const hl_v v360 = v91 * v36;
    const hl_v v361 = v95 * v45;
    const hl_v v362 = v360 - v361;
    const hl_v v363 = v124 * v362;
    const hl_v v364 = v118 * v123;
    const hl_v v365 = v91 * v33;
    const hl_v v366 = v95 * v43;
    const hl_v v367 = v365 - v366;
    const hl_v v368 = v364 * v367;
    const hl_v v369 = v363 + v368;
    const hl_v v475 = v369 * v358;
    const hl_v v395 = v95 * v143;
    const hl_v v396 = v91 * v141;
    const hl_v v772 = v395 + v396;
    const hl_v v398 = v88 * v147;
    const hl_v v399 = v772 - v398;
    f[1] = v399;
    const hl_v v385 = pre[34];
    const hl_v v386 = hl_bool(v385 <= v131);
    const hl_v v389 = hl_bool(v386 == 0.0);
    const hl_v v390 = pre[35];
    const hl_v v391 = hl_select(v389 != 0.0, v390, hl_splat(0.0));
    const hl_v v387 = pre[36];
    const hl_v v388 = hl_select(v386 != 0.0, v387, hl_splat(0.0));
    const hl_v v393 = yd_extra[1];
    const hl_v v771 = v393 + v388;
    const hl_v v394 = v391 + v771;
    const hl_v v400 = v394 - v399;
    const hl_v v381 = pre[37];
    const hl_v v401 = v381 * v400;
    const hl_v v402 = v95 * v167;
    const hl_v v403 = v91 * v162;
    const hl_v v404 = v402 + v403;
    y[1] = v404;
    const hl_v v405 = v394 - v404;
    const hl_v v382 = pre[38];
    const hl_v v406 = v382 * v405;
    const hl_v v407 = v401 + v406;
    const hl_v v423 = v191 * v407;
    const hl_v v427 = integrals[2];
    const hl_v v428 = v427 + v423;
    const hl_v v432 = v191 * v428;
    const hl_v v431 = integrals[3];
    const hl_v v433 = v431 + v432;
    const hl_v v434 = v382 * v433;
    const hl_v v430 = pre[39];
    const hl_v v435 = v430 * v434;
    const hl_v v410 = pre[40];
    const hl_v v429 = v410 * v428;
    const hl_v v436 = v429 + v435;
    const hl_v v437 = hl_fabs(v436);
    const hl_v v438 = hl_bool(v196 < v437);
    const hl_v v411 = hl_bool(v399 < v176);
    const hl_v v412 = v381 * v411;
    const hl_v v439 = hl_bool((v438 != 0.0) | (v412 != 0.0));
    const hl_v v441 = v125 - v439;
    const hl_v v442 = v441 * v428;
    const hl_v v440 = v439 * v427;
    const hl_v v443 = v440 + v442;
    const hl_v v413 = pre[41];
    const hl_v v414 = v412 * v413;
    const hl_v v426 = hl_bool(v414 == 0.0);
    const hl_v v444 = hl_select(v426 != 0.0, v443, hl_splat(0.0));
    const hl_v v384 = pre[42];
    const hl_v v408 = v384 * v407;
    const hl_v v415 = pre[43];
    const hl_v v416 = pre[44];
    const hl_v v417 = v416 - v408;
    const hl_v v742 = pre[45];
    const hl_v v422 = v417 * v742;
    const hl_v v424 = v422 - v423;
    const hl_v v425 = hl_select(v414 != 0.0, v424, hl_splat(0.0));
    const hl_v v445 = v425 + v444;
    const hl_v v446 = v410 * v445;
    const hl_v v456 = v415 * v404;
    const hl_v v776 = v456 + v408;
    const hl_v v458 = v776 + v446;
    const hl_v v455 = v125 - v412;
    const hl_v v459 = v455 * v458;
    const hl_v v461 = v404 + v183;
    const hl_v v777 = v415 * v461;
    const hl_v v462 = v777 * v412;
    const hl_v v463 = v459 + v462;
    const hl_v v464 = v381 * v463;
    const hl_v v450 = v441 * v434;
    const hl_v v773 = v382 * v431;
    const hl_v v449 = v773 * v439;
    const hl_v v451 = v449 + v450;
    const hl_v v452 = v430 * v451;
    const hl_v v383 = yd_rate[1];
    const hl_v v774 = v383 + v408;
    const hl_v v775 = v774 + v452;
    const hl_v v453 = v775 + v446;
    const hl_v v454 = v382 * v453;
    const hl_v v465 = v454 - v464;
    a[1] = v465;
    const hl_v v466 = v316 * v167;
    const hl_v v467 = v302 * v162;
    const hl_v v468 = v466 + v467;
    const hl_v v469 = v236 * v468;
    const hl_v v471 = v95 * v354;
    const hl_v v472 = v91 * v350;
    const hl_v v778 = v471 + v472;
    const hl_v v779 = v778 + v469;
    const hl_v v780 = v465 - v779;
    const hl_v v476 = v780 - v475;
    const hl_v v370 = v369 * v124;
    const hl_v v371 = v362 - v370;
    const hl_v v372 = v371 * v371;
    const hl_v v373 = v369 * v364;
    const hl_v v374 = v367 - v373;
    const hl_v v375 = v374 * v374;
    const hl_v v376 = v372 + v375;
    const hl_v v377 = hl_sqrt(v376);
    const hl_v v378 = 1.0 / v377;
    const hl_v v379 = hl_copysign(v378, v377);
    const hl_v v477 = v476 * v379;
    const hl_v v781 = v371 * v379;
    const hl_v v478 = v477 * v781;
    const hl_v v359 = v124 * v358;
    const hl_v v479 = v359 + v478;
    const hl_v v520 = v34 * v479;
    const hl_v v483 = pre[46];
    const hl_v v484 = v29 * v483;
    const hl_v v485 = pre[47];
    const hl_v v486 = v25 * v485;
    const hl_v v487 = v484 - v486;
    const hl_v v521 = v487 + v520;
    const hl_v v532 = v30 * v521;
    const hl_v v788 = v374 * v379;
    const hl_v v511 = v477 * v788;
    const hl_v v509 = v364 * v358;
    const hl_v v789 = v509 + v511;
    const hl_v v513 = v479 + v789;
    const hl_v v526 = pre[48];
    const hl_v v535 = v513 * v526;
    const hl_v v496 = v25 * v483;
    const hl_v v497 = v29 * v485;
    const hl_v v498 = v496 + v497;
    const hl_v v517 = v152 * v153;
    const hl_v v518 = v498 + v517;
    const hl_v v533 = v27 * v518;
    const hl_v v515 = pre[49];
    const hl_v v793 = v515 * v158;
    const hl_v v538 = v158 * v793;
    const hl_v v794 = v538 + v533;
    const hl_v v795 = v794 + v535;
    const hl_v v539 = v532 - v795;
    const hl_v v516 = pre[50];
    const hl_v v540 = v516 * v539;
    const hl_v v548 = v126 * v140;
    const hl_v v558 = v110 * v548;
    const hl_v v550 = v381 * v394;
    const hl_v v557 = v95 * v550;
    const hl_v v559 = v557 - v558;
    const hl_v v544 = pre[51];
    const hl_v v560 = v544 * v559;
    const hl_v v545 = pre[52];
    const hl_v v561 = v545 * v143;
    const hl_v v562 = v560 + v561;
    const hl_v v566 = v25 * v562;
    const hl_v v549 = v112 * v548;
    const hl_v v551 = v91 * v550;
    const hl_v v552 = v549 + v551;
    const hl_v v553 = v544 * v552;
    const hl_v v554 = v545 * v141;
    const hl_v v555 = v553 + v554;
    const hl_v v567 = v29 * v555;
    const hl_v v568 = v566 + v567;
    const hl_v v574 = v27 * v568;
    const hl_v v556 = v25 * v555;
    const hl_v v563 = v29 * v562;
    const hl_v v564 = v556 - v563;
    const hl_v v575 = v30 * v564;
    const hl_v v799 = v574 + v575;
    const hl_v v577 = v540 - v799;
    const hl_v v578 = v30 * v577;
    const hl_v v522 = v27 * v521;
    const hl_v v524 = v513 * v515;
    const hl_v v519 = v30 * v518;
    const hl_v v790 = v526 * v158;
    const hl_v v528 = v158 * v790;
    const hl_v v791 = v519 - v528;
    const hl_v v792 = v791 + v524;
    const hl_v v529 = v522 + v792;
    const hl_v v530 = v516 * v529;
    const hl_v v565 = v27 * v564;
    const hl_v v569 = v30 * v568;
    const hl_v v570 = v565 - v569;
    const hl_v v579 = v530 - v570;
    const hl_v v580 = v27 * v579;
    const hl_v v581 = v578 + v580;
    const hl_v v582 = v34 * v581;
    const hl_v v531 = v515 * v530;
    const hl_v v508 = pre[53];
    const hl_v v514 = v508 * v513;
    const hl_v v571 = v23 * v570;
    const hl_v v546 = Fc[5];
    contact_wrench[5] = v546;
    const hl_v v547 = v545 * v546;
    const hl_v v796 = v547 + v571;
    const hl_v v797 = v514 - v796;
    const hl_v v798 = v797 + v531;
    const hl_v v541 = v526 * v540;
    const hl_v v573 = v798 - v541;
    const hl_v v481 = pre[54];
    const hl_v v488 = v479 * v481;
    const hl_v v782 = v152 * v152;
    const hl_v v490 = pre[55];
    const hl_v v492 = v490 * v782;
    const hl_v v783 = v487 - v492;
    const hl_v v493 = v783 + v488;
    const hl_v v784 = pre[57];
    const hl_v v495 = v784 * v493;
    const hl_v v0 = pre[58];
    const hl_v v480 = v0 * v479;
    const hl_v v743 = pre[59];
    const hl_v v590 = v152 * v743;
    const hl_v v591 = (exact ? hl_tanh(v590) : hl_tanh_poly(v590, odd));
    const hl_v v587 = pre[60];
    const hl_v v592 = v587 * v591;
    const hl_v v588 = pre[61];
    const hl_v v593 = hl_select(v588 != 0.0, v592, hl_splat(0.0));
    const hl_v v585 = pre[62];
    const hl_v v586 = v585 * v152;
    const hl_v v595 = pre[63];
    const hl_v v800 = v595 + v586;
    const hl_v v801 = v800 + v593;
    const hl_v v802 = v801 + v480;
    const hl_v v803 = v802 + v495;
    const hl_v v499 = v479 * v490;
    const hl_v v785 = v152 * v152;
    const hl_v v502 = v481 * v785;
    const hl_v v786 = v502 + v498;
    const hl_v v503 = v786 + v499;
    const hl_v v787 = pre[64];
    const hl_v v505 = v787 * v503;
    const hl_v v804 = v505 + v803;
    const hl_v v805 = v804 + v573;
    const hl_v v597 = v582 + v805;
    const hl_v v603 = last_torque[0];
    const hl_v v604 = pre[65];
    const hl_v v613 = v603 - v604;
    const hl_v v602 = last_torque[2];
    const hl_v v614 = hl_select(v602 != 0.0, v613, hl_splat(0.0));
    const hl_v v607 = hl_bool(v602 == 0.0);
    const hl_v v601 = pre[66];
    const hl_v v615 = pre[67];
    const hl_v v616 = hl_select(v607 != 0.0, v615, hl_splat(0.0));
    const hl_v v617 = v614 + v616;
    const hl_v v618 = hl_bool(v597 < v617);
    const hl_v v620 = hl_bool(v618 == 0.0);
    const hl_v v621 = hl_select(v620 != 0.0, v597, hl_splat(0.0));
    const hl_v v619 = hl_select(v618 != 0.0, v617, hl_splat(0.0));
    const hl_v v622 = v619 + v621;
    const hl_v v605 = v603 + v604;
    const hl_v v606 = hl_select(v602 != 0.0, v605, hl_splat(0.0));
    const hl_v v608 = hl_select(v607 != 0.0, v601, hl_splat(0.0));
    const hl_v v609 = v606 + v608;
    const hl_v v610 = hl_bool(v609 < v597);
    const hl_v v612 = hl_bool(v610 == 0.0);
    const hl_v v623 = hl_select(v612 != 0.0, v622, hl_splat(0.0));
    const hl_v v611 = hl_select(v610 != 0.0, v609, hl_splat(0.0));
    const hl_v v624 = v611 + v623;
    const hl_v v628 = hl_bool(v624 < v615);
    const hl_v v630 = hl_bool(v628 == 0.0);
    const hl_v v631 = hl_select(v630 != 0.0, v624, hl_splat(0.0));
    const hl_v v629 = hl_select(v628 != 0.0, v615, hl_splat(0.0));
    const hl_v v632 = v629 + v631;
    const hl_v v625 = hl_bool(v601 < v624);
    const hl_v v627 = hl_bool(v625 == 0.0);
    const hl_v v633 = hl_select(v627 != 0.0, v632, hl_splat(0.0));
    const hl_v v626 = hl_select(v625 != 0.0, v601, hl_splat(0.0));
    const hl_v v634 = v626 + v633;
    const hl_v v598 = hl_fabs(v597);
    const hl_v v599 = pre[68];
    const hl_v v600 = hl_bool(v598 <= v599);
    const hl_v v635 = hl_select(v600 != 0.0, v634, hl_splat(0.0));
    const hl_v v636 = hl_bool(v600 == 0.0);
    const hl_v v637 = hl_select(v636 != 0.0, v597, hl_splat(0.0));
    const hl_v v638 = v635 + v637;
    tau[0] = v638;
    const hl_v v744 = pre[69];
    const hl_v v644 = v157 * v744;
    const hl_v v645 = (exact ? hl_tanh(v644) : hl_tanh_poly(v644, odd));
    const hl_v v641 = pre[70];
    const hl_v v646 = v641 * v645;
    const hl_v v642 = pre[71];
    const hl_v v647 = hl_select(v642 != 0.0, v646, hl_splat(0.0));
    const hl_v v639 = pre[72];
    const hl_v v640 = v639 * v157;
    const hl_v v649 = pre[73];
    const hl_v v806 = v649 + v640;
    const hl_v v807 = v806 + v647;
    const hl_v v651 = v807 + v573;
    const hl_v v655 = last_torque[1];
    const hl_v v656 = pre[74];
    const hl_v v664 = v655 - v656;
    const hl_v v665 = hl_select(v602 != 0.0, v664, hl_splat(0.0));
    const hl_v v654 = pre[75];
    const hl_v v666 = pre[76];
    const hl_v v667 = hl_select(v607 != 0.0, v666, hl_splat(0.0));
    const hl_v v668 = v665 + v667;
    const hl_v v669 = hl_bool(v651 < v668);
    const hl_v v671 = hl_bool(v669 == 0.0);
    const hl_v v672 = hl_select(v671 != 0.0, v651, hl_splat(0.0));
    const hl_v v670 = hl_select(v669 != 0.0, v668, hl_splat(0.0));
    const hl_v v673 = v670 + v672;
    const hl_v v657 = v655 + v656;
    const hl_v v658 = hl_select(v602 != 0.0, v657, hl_splat(0.0));
    const hl_v v659 = hl_select(v607 != 0.0, v654, hl_splat(0.0));
    const hl_v v660 = v658 + v659;
    const hl_v v661 = hl_bool(v660 < v651);
    const hl_v v663 = hl_bool(v661 == 0.0);
    const hl_v v674 = hl_select(v663 != 0.0, v673, hl_splat(0.0));
    const hl_v v662 = hl_select(v661 != 0.0, v660, hl_splat(0.0));
    const hl_v v675 = v662 + v674;
    const hl_v v679 = hl_bool(v675 < v666);
    const hl_v v681 = hl_bool(v679 == 0.0);
    const hl_v v682 = hl_select(v681 != 0.0, v675, hl_splat(0.0));
    const hl_v v680 = hl_select(v679 != 0.0, v666, hl_splat(0.0));
    const hl_v v683 = v680 + v682;
    const hl_v v676 = hl_bool(v654 < v675);
    const hl_v v678 = hl_bool(v676 == 0.0);
    const hl_v v684 = hl_select(v678 != 0.0, v683, hl_splat(0.0));
    const hl_v v677 = hl_select(v676 != 0.0, v654, hl_splat(0.0));
    const hl_v v685 = v677 + v684;
    const hl_v v652 = hl_fabs(v651);
    const hl_v v653 = hl_bool(v652 <= v599);
    const hl_v v686 = hl_select(v653 != 0.0, v685, hl_splat(0.0));
    const hl_v v687 = hl_bool(v653 == 0.0);
    const hl_v v688 = hl_select(v687 != 0.0, v651, hl_splat(0.0));
    const hl_v v689 = v686 + v688;
    tau[1] = v689;
    const hl_v v690 = hl_bool(v638 != v597);
    const hl_v v691 = hl_bool(v689 != v651);
    const hl_v v692 = v690 + v691;
    const hl_v v693 = hl_bool(v179 < v692);
    saturated[0] = v693;
    const hl_v v695 = hl_bool(v693 == 0.0);
    const hl_v v696 = hl_select(v695 != 0.0, v215, hl_splat(0.0));
    const hl_v v694 = hl_select(v693 != 0.0, v197, hl_splat(0.0));
    const hl_v v697 = v694 + v696;
    integrals_next[0] = v697;
    const hl_v v699 = hl_select(v695 != 0.0, v221, hl_splat(0.0));
    const hl_v v698 = hl_select(v693 != 0.0, v201, hl_splat(0.0));
    const hl_v v700 = v698 + v699;
    integrals_next[1] = v700;
    const hl_v v702 = hl_select(v695 != 0.0, v445, hl_splat(0.0));
    const hl_v v701 = hl_select(v693 != 0.0, v427, hl_splat(0.0));
    const hl_v v703 = v701 + v702;
    integrals_next[2] = v703;
    const hl_v v705 = hl_select(v695 != 0.0, v451, hl_splat(0.0));
    const hl_v v704 = hl_select(v693 != 0.0, v431, hl_splat(0.0));
    const hl_v v706 = v704 + v705;
    integrals_next[3] = v706;
    const hl_v v707 = Fc[3];
    contact_wrench[3] = v707;
    const hl_v v708 = Fc[4];
    contact_wrench[4] = v708;
    const hl_v v709 = pre[77];
    const hl_v v710 = hl_bool(v709 < v85);
    const hl_v v711 = hl_bool(v85 <= v599);
    const hl_v v712 = hl_bool((v710 != 0.0) & (v711 != 0.0));
    const hl_v v713 = hl_select(v712 != 0.0, v107, hl_splat(0.0));
    const hl_v v714 = hl_bool(v712 == 0.0);
    const hl_v v715 = hl_fabs(v36);
    const hl_v v716 = hl_fabs(v45);
    const hl_v v717 = v715 + v716;
    const hl_v v718 = hl_bool(v717 <= v599);
    const hl_v v719 = hl_bool(v718 == 0.0);
    const hl_v v720 = hl_select(v719 != 0.0, v717, hl_splat(0.0));
    const hl_v v721 = hl_select(v714 != 0.0, v720, hl_splat(0.0));
    const hl_v v722 = v713 + v721;
    frame[0] = v722;
    const hl_v v810 = v123 * v369;
    const hl_v v731 = v810 * v379;
    const hl_v v732 = v731 * v731;
    const hl_v v733 = v379 * v379;
    const hl_v v729 = v123 * v123;
    const hl_v v811 = v729 + v733;
    const hl_v v735 = v811 + v732;
    const hl_v v724 = v362 * v362;
    const hl_v v727 = v367 * v367;
    const hl_v v808 = v724 + v727;
    const hl_v v809 = v808 + v115;
    const hl_v v728 = v119 + v809;
    const hl_v v736 = v728 * v735;
    const hl_v v737 = hl_sqrt(v736);
    const hl_v v723 = pre[78];
    const hl_v v738 = v723 / v737;
    cond[0] = v738;
}

#if HL_IN_PART(2)
HL_APART __attribute__((noinline, cold)) void controller_step_lanes_exact(const hl_v *q, const hl_v *qd, const hl_v *Fc, const hl_v *integrals, const hl_v *last_torque, const hl_v *filter, const hl_v *estimate, const hl_v *t, const hl_v *yd_extra, const hl_v *yd_rate, const hl_v *target, const hl_v *pre, hl_v *tau, hl_v *integrals_next, hl_v *a, hl_v *y, hl_v *f, hl_v *saturated, hl_v *filter_next, hl_v *estimate_next, hl_v *contact_wrench, hl_v *frame, hl_v *cond) {
    controller_step_lanes_core(q, qd, Fc, integrals, last_torque, filter, estimate, t, yd_extra, yd_rate, target, pre, tau, integrals_next, a, y, f, saturated, filter_next, estimate_next, contact_wrench, frame, cond, 1, NULL);
}
#else
HL_APART __attribute__((noinline, cold)) void controller_step_lanes_exact(const hl_v *q, const hl_v *qd, const hl_v *Fc, const hl_v *integrals, const hl_v *last_torque, const hl_v *filter, const hl_v *estimate, const hl_v *t, const hl_v *yd_extra, const hl_v *yd_rate, const hl_v *target, const hl_v *pre, hl_v *tau, hl_v *integrals_next, hl_v *a, hl_v *y, hl_v *f, hl_v *saturated, hl_v *filter_next, hl_v *estimate_next, hl_v *contact_wrench, hl_v *frame, hl_v *cond);
#endif

#if HL_IN_PART(2)
HL_APART void controller_step_lanes(const hl_v *q, const hl_v *qd, const hl_v *Fc, const hl_v *integrals, const hl_v *last_torque, const hl_v *filter, const hl_v *estimate, const hl_v *t, const hl_v *yd_extra, const hl_v *yd_rate, const hl_v *target, const hl_v *pre, hl_v *tau, hl_v *integrals_next, hl_v *a, hl_v *y, hl_v *f, hl_v *saturated, hl_v *filter_next, hl_v *estimate_next, hl_v *contact_wrench, hl_v *frame, hl_v *cond) {
    hl_i odd = hl_splat(0.0) != 0.0;
    controller_step_lanes_core(q, qd, Fc, integrals, last_torque, filter, estimate, t, yd_extra, yd_rate, target, pre, tau, integrals_next, a, y, f, saturated, filter_next, estimate_next, contact_wrench, frame, cond, 0, &odd);
    if (hl_any(odd)) controller_step_lanes_exact(q, qd, Fc, integrals, last_torque, filter, estimate, t, yd_extra, yd_rate, target, pre, tau, integrals_next, a, y, f, saturated, filter_next, estimate_next, contact_wrench, frame, cond);
}
#else
HL_APART void controller_step_lanes(const hl_v *q, const hl_v *qd, const hl_v *Fc, const hl_v *integrals, const hl_v *last_torque, const hl_v *filter, const hl_v *estimate, const hl_v *t, const hl_v *yd_extra, const hl_v *yd_rate, const hl_v *target, const hl_v *pre, hl_v *tau, hl_v *integrals_next, hl_v *a, hl_v *y, hl_v *f, hl_v *saturated, hl_v *filter_next, hl_v *estimate_next, hl_v *contact_wrench, hl_v *frame, hl_v *cond);
#endif

#define SAFE_STOP_LANES_NPRE 37
#if HL_IN_PART(2)
HL_APART void safe_stop_lanes_pre(const hl_v *robot, const hl_v *fault, const hl_v *limits, const hl_v *sample_time, hl_v *pre) {
    const hl_v v4 = fault[1];
    const hl_v v5 = v4 * v4;
    const hl_v v225 = 1.0 / v5;
    const hl_v v226 = 1.0 / v4;
    const hl_v v52 = robot[11];
    const hl_v v68 = robot[12];
    const hl_v v15 = robot[28];
    const hl_v v18 = robot[29];
    const hl_v v55 = hl_splat(0.45);
    const hl_v v53 = robot[10];
    const hl_v v41 = robot[19];
    const hl_v v12 = robot[1];
    const hl_v v23 = robot[2];
    const hl_v v13 = robot[0];
    const hl_v v232 = v12 * v13;
    const hl_v v0 = robot[9];
    const hl_v v92 = robot[20];
    const hl_v v103 = robot[24];
    const hl_v v97 = robot[26];
    const hl_v v227 = 1.0 / v97;
    const hl_v v94 = robot[22];
    const hl_v v95 = hl_splat(0.0);
    const hl_v v96 = hl_bool(v94 != v95);
    const hl_v v235 = v13 * v23;
    const hl_v v108 = sample_time[0];
    const hl_v v106 = fault[2];
    const hl_v v228 = 1.0 / v106;
    const hl_v v112 = hl_splat(1.0);
    const hl_v v131 = limits[2];
    const hl_v v128 = limits[0];
    const hl_v v142 = -v128;
    const hl_v v126 = hl_splat(1.7976931348623157e+308);
    const hl_v v170 = robot[27];
    const hl_v v229 = 1.0 / v170;
    const hl_v v168 = robot[23];
    const hl_v v169 = hl_bool(v168 != v95);
    const hl_v v166 = robot[21];
    const hl_v v176 = robot[25];
    const hl_v v191 = limits[3];
    const hl_v v189 = limits[1];
    const hl_v v201 = -v189;
    pre[0] = v225;
    pre[1] = v226;
    pre[2] = v52;
    pre[3] = v68;
    pre[4] = v15;
    pre[5] = v18;
    pre[6] = v55;
    pre[7] = v53;
    pre[8] = v41;
    pre[9] = v12;
    pre[10] = v23;
    pre[11] = v13;
    pre[12] = v232;
    pre[13] = v0;
    pre[14] = v92;
    pre[15] = v103;
    pre[16] = v227;
    pre[17] = v94;
    pre[18] = v95;
    pre[19] = v96;
    pre[20] = v235;
    pre[21] = v108;
    pre[22] = v106;
    pre[23] = v228;
    pre[24] = v112;
    pre[25] = v131;
    pre[26] = v128;
    pre[27] = v142;
    pre[28] = v126;
    pre[29] = v229;
    pre[30] = v168;
    pre[31] = v169;
    pre[32] = v166;
    pre[33] = v176;
    pre[34] = v191;
    pre[35] = v189;
    pre[36] = v201;
    (void)robot;
    (void)fault;
    (void)limits;
    (void)sample_time;
    (void)pre;
}
#else
HL_APART void safe_stop_lanes_pre(const hl_v *robot, const hl_v *fault, const hl_v *limits, const hl_v *sample_time, hl_v *pre);
#endif

static inline __attribute__((always_inline)) void safe_stop_lanes_core(const hl_v *q, const hl_v *qd, const hl_v *last_torque, const hl_v *fault_state, const hl_v *pre, hl_v *tau, hl_v *tau_offset_next, const int exact, hl_i *odd) {
    (void)q;
    (void)qd;
    (void)last_torque;
    (void)fault_state;
    (void)pre;
    (void)odd;
    const hl_v v225 = pre[0];
    const hl_v v1 = fault_state[4];
    const hl_v v2 = q[0];
    const hl_v v3 = v1 - v2;
    const hl_v v6 = v3 * v225;
    const hl_v v7 = qd[0];
    const hl_v v8 = v7 + v7;
    const hl_v v226 = pre[1];
    const hl_v v9 = v8 * v226;
    const hl_v v10 = v6 - v9;
    const hl_v v42 = fault_state[5];
    const hl_v v43 = q[1];
    const hl_v v44 = v42 - v43;
    const hl_v v45 = v44 * v225;
    const hl_v v46 = qd[1];
    const hl_v v47 = v46 + v46;
    const hl_v v48 = v47 * v226;
    const hl_v v236 = v45 - v48;
    const hl_v v50 = v10 + v236;
    const hl_v v52 = pre[2];
    const hl_v v65 = v50 * v52;
    const hl_v v67 = v7 + v46;
    const hl_v v68 = pre[3];
    const hl_v v238 = v68 * v67;
    const hl_v v70 = v67 * v238;
    const hl_v v239 = v65 - v70;
    hl_v v14, v17;
    if (exact) hl_sincos(v2, &v14, &v17); else hl_sincos_poly(v2, &v14, &v17, odd);
    const hl_v v15 = pre[4];
    const hl_v v29 = v17 * v15;
    const hl_v v18 = pre[5];
    const hl_v v30 = v14 * v18;
    const hl_v v31 = v29 + v30;
    const hl_v v237 = v7 * v7;
    const hl_v v55 = pre[6];
    const hl_v v57 = v55 * v237;
    const hl_v v58 = v31 + v57;
    hl_v v54, v60;
    if (exact) hl_sincos(v43, &v54, &v60); else hl_sincos_poly(v43, &v54, &v60, odd);
    const hl_v v59 = v54 * v58;
    const hl_v v240 = v239 + v59;
    const hl_v v61 = v55 * v10;
    const hl_v v16 = v14 * v15;
    const hl_v v19 = v17 * v18;
    const hl_v v20 = v16 - v19;
    const hl_v v62 = v20 + v61;
    const hl_v v63 = v60 * v62;
    const hl_v v71 = v63 + v240;
    const hl_v v53 = pre[7];
    const hl_v v72 = v53 * v71;
    const hl_v v73 = v52 * v72;
    const hl_v v41 = pre[8];
    const hl_v v51 = v41 * v50;
    const hl_v v244 = v51 + v73;
    const hl_v v74 = v54 * v62;
    const hl_v v77 = v50 * v68;
    const hl_v v241 = v52 * v67;
    const hl_v v80 = v67 * v241;
    const hl_v v242 = v80 + v77;
    const hl_v v243 = v74 - v242;
    const hl_v v75 = v60 * v58;
    const hl_v v81 = v243 - v75;
    const hl_v v82 = v53 * v81;
    const hl_v v83 = v68 * v82;
    const hl_v v85 = v244 - v83;
    const hl_v v12 = pre[9];
    const hl_v v21 = v10 * v12;
    const hl_v v230 = v7 * v7;
    const hl_v v23 = pre[10];
    const hl_v v25 = v23 * v230;
    const hl_v v231 = v21 - v25;
    const hl_v v26 = v231 + v20;
    const hl_v v232 = pre[12];
    const hl_v v28 = v232 * v26;
    const hl_v v0 = pre[13];
    const hl_v v11 = v0 * v10;
    const hl_v v92 = pre[14];
    const hl_v v93 = v92 * v7;
    const hl_v v103 = pre[15];
    const hl_v v245 = v103 + v93;
    const hl_v v246 = v245 + v11;
    const hl_v v227 = pre[16];
    const hl_v v98 = v7 * v227;
    const hl_v v99 = (exact ? hl_tanh(v98) : hl_tanh_poly(v98, odd));
    const hl_v v94 = pre[17];
    const hl_v v100 = v94 * v99;
    const hl_v v95 = pre[18];
    const hl_v v96 = pre[19];
    const hl_v v101 = hl_select(v96 != 0.0, v100, hl_splat(0.0));
    const hl_v v247 = v246 + v101;
    const hl_v v248 = v247 + v28;
    const hl_v v32 = v10 * v23;
    const hl_v v233 = v7 * v7;
    const hl_v v35 = v12 * v233;
    const hl_v v234 = v35 + v32;
    const hl_v v36 = v234 + v31;
    const hl_v v235 = pre[20];
    const hl_v v38 = v235 * v36;
    const hl_v v249 = v38 + v248;
    const hl_v v250 = v249 + v85;
    const hl_v v86 = v54 * v82;
    const hl_v v87 = v60 * v72;
    const hl_v v88 = v86 + v87;
    const hl_v v89 = v55 * v88;
    const hl_v v105 = v89 + v250;
    const hl_v v116 = fault_state[0];
    const hl_v v117 = v116 - v105;
    const hl_v v107 = fault_state[8];
    const hl_v v115 = hl_bool(v107 == v95);
    const hl_v v118 = hl_select(v115 != 0.0, v117, hl_splat(0.0));
    const hl_v v119 = hl_bool(v115 == 0.0);
    const hl_v v120 = hl_select(v119 != 0.0, v116, hl_splat(0.0));
    const hl_v v121 = v118 + v120;
    tau_offset_next[0] = v121;
    const hl_v v108 = pre[21];
    const hl_v v109 = v107 * v108;
    const hl_v v106 = pre[22];
    const hl_v v228 = pre[23];
    const hl_v v113 = v109 * v228;
    const hl_v v112 = pre[24];
    const hl_v v114 = v112 - v113;
    const hl_v v122 = v114 * v121;
    const hl_v v110 = hl_bool(v106 <= v109);
    const hl_v v111 = hl_bool(v110 == 0.0);
    const hl_v v123 = hl_select(v111 != 0.0, v122, hl_splat(0.0));
    const hl_v v124 = v105 + v123;
    const hl_v v130 = last_torque[0];
    const hl_v v131 = pre[25];
    const hl_v v140 = v130 - v131;
    const hl_v v129 = last_torque[2];
    const hl_v v141 = hl_select(v129 != 0.0, v140, hl_splat(0.0));
    const hl_v v134 = hl_bool(v129 == 0.0);
    const hl_v v128 = pre[26];
    const hl_v v142 = pre[27];
    const hl_v v143 = hl_select(v134 != 0.0, v142, hl_splat(0.0));
    const hl_v v144 = v141 + v143;
    const hl_v v145 = hl_bool(v124 < v144);
    const hl_v v147 = hl_bool(v145 == 0.0);
    const hl_v v148 = hl_select(v147 != 0.0, v124, hl_splat(0.0));
    const hl_v v146 = hl_select(v145 != 0.0, v144, hl_splat(0.0));
    const hl_v v149 = v146 + v148;
    const hl_v v132 = v130 + v131;
    const hl_v v133 = hl_select(v129 != 0.0, v132, hl_splat(0.0));
    const hl_v v135 = hl_select(v134 != 0.0, v128, hl_splat(0.0));
    const hl_v v136 = v133 + v135;
    const hl_v v137 = hl_bool(v136 < v124);
    const hl_v v139 = hl_bool(v137 == 0.0);
    const hl_v v150 = hl_select(v139 != 0.0, v149, hl_splat(0.0));
    const hl_v v138 = hl_select(v137 != 0.0, v136, hl_splat(0.0));
    const hl_v v151 = v138 + v150;
    const hl_v v155 = hl_bool(v151 < v142);
    const hl_v v157 = hl_bool(v155 == 0.0);
    const hl_v v158 = hl_select(v157 != 0.0, v151, hl_splat(0.0));
    const hl_v v156 = hl_select(v155 != 0.0, v142, hl_splat(0.0));
    const hl_v v159 = v156 + v158;
    const hl_v v152 = hl_bool(v128 < v151);
    const hl_v v154 = hl_bool(v152 == 0.0);
    const hl_v v160 = hl_select(v154 != 0.0, v159, hl_splat(0.0));
    const hl_v v153 = hl_select(v152 != 0.0, v128, hl_splat(0.0));
    const hl_v v161 = v153 + v160;
    const hl_v v125 = hl_fabs(v124);
    const hl_v v126 = pre[28];
    const hl_v v127 = hl_bool(v125 <= v126);
    const hl_v v162 = hl_select(v127 != 0.0, v161, hl_splat(0.0));
    const hl_v v163 = hl_bool(v127 == 0.0);
    const hl_v v164 = hl_select(v163 != 0.0, v124, hl_splat(0.0));
    const hl_v v165 = v162 + v164;
    tau[0] = v165;
    const hl_v v229 = pre[29];
    const hl_v v171 = v46 * v229;
    const hl_v v172 = (exact ? hl_tanh(v171) : hl_tanh_poly(v171, odd));
    const hl_v v168 = pre[30];
    const hl_v v173 = v168 * v172;
    const hl_v v169 = pre[31];
    const hl_v v174 = hl_select(v169 != 0.0, v173, hl_splat(0.0));
    const hl_v v166 = pre[32];
    const hl_v v167 = v166 * v46;
    const hl_v v176 = pre[33];
    const hl_v v251 = v176 + v167;
    const hl_v v252 = v251 + v174;
    const hl_v v178 = v252 + v85;
    const hl_v v179 = fault_state[1];
    const hl_v v180 = v179 - v178;
    const hl_v v181 = hl_select(v115 != 0.0, v180, hl_splat(0.0));
    const hl_v v182 = hl_select(v119 != 0.0, v179, hl_splat(0.0));
    const hl_v v183 = v181 + v182;
    tau_offset_next[1] = v183;
    const hl_v v184 = v114 * v183;
    const hl_v v185 = hl_select(v111 != 0.0, v184, hl_splat(0.0));
    const hl_v v186 = v178 + v185;
    const hl_v v190 = last_torque[1];
    const hl_v v191 = pre[34];
    const hl_v v199 = v190 - v191;
    const hl_v v200 = hl_select(v129 != 0.0, v199, hl_splat(0.0));
    const hl_v v189 = pre[35];
    const hl_v v201 = pre[36];
    const hl_v v202 = hl_select(v134 != 0.0, v201, hl_splat(0.0));
    const hl_v v203 = v200 + v202;
    const hl_v v204 = hl_bool(v186 < v203);
    const hl_v v206 = hl_bool(v204 == 0.0);
    const hl_v v207 = hl_select(v206 != 0.0, v186, hl_splat(0.0));
    const hl_v v205 = hl_select(v204 != 0.0, v203, hl_splat(0.0));
    const hl_v v208 = v205 + v207;
    const hl_v v192 = v190 + v191;
    const hl_v v193 = hl_select(v129 != 0.0, v192, hl_splat(0.0));
    const hl_v v194 = hl_select(v134 != 0.0, v189, hl_splat(0.0));
    const hl_v v195 = v193 + v194;
    const hl_v v196 = hl_bool(v195 < v186);
    const hl_v v198 = hl_bool(v196 == 0.0);
    const hl_v v209 = hl_select(v198 != 0.0, v208, hl_splat(0.0));
    const hl_v v197 = hl_select(v196 != 0.0, v195, hl_splat(0.0));
    const hl_v v210 = v197 + v209;
    const hl_v v214 = hl_bool(v210 < v201);
    const hl_v v216 = hl_bool(v214 == 0.0);
    const hl_v v217 = hl_select(v216 != 0.0, v210, hl_splat(0.0));
    const hl_v v215 = hl_select(v214 != 0.0, v201, hl_splat(0.0));
    const hl_v v218 = v215 + v217;
    const hl_v v211 = hl_bool(v189 < v210);
    const hl_v v213 = hl_bool(v211 == 0.0);
    const hl_v v219 = hl_select(v213 != 0.0, v218, hl_splat(0.0));
    const hl_v v212 = hl_select(v211 != 0.0, v189, hl_splat(0.0));
    const hl_v v220 = v212 + v219;
    const hl_v v187 = hl_fabs(v186);
    const hl_v v188 = hl_bool(v187 <= v126);
    const hl_v v221 = hl_select(v188 != 0.0, v220, hl_splat(0.0));
    const hl_v v222 = hl_bool(v188 == 0.0);
    const hl_v v223 = hl_select(v222 != 0.0, v186, hl_splat(0.0));
    const hl_v v224 = v221 + v223;
    tau[1] = v224;
}

#if HL_IN_PART(2)
HL_APART __attribute__((noinline, cold)) void safe_stop_lanes_exact(const hl_v *q, const hl_v *qd, const hl_v *last_torque, const hl_v *fault_state, const hl_v *pre, hl_v *tau, hl_v *tau_offset_next) {
    safe_stop_lanes_core(q, qd, last_torque, fault_state, pre, tau, tau_offset_next, 1, NULL);
}
#else
HL_APART __attribute__((noinline, cold)) void safe_stop_lanes_exact(const hl_v *q, const hl_v *qd, const hl_v *last_torque, const hl_v *fault_state, const hl_v *pre, hl_v *tau, hl_v *tau_offset_next);
#endif

#if HL_IN_PART(2)
HL_APART void safe_stop_lanes(const hl_v *q, const hl_v *qd, const hl_v *last_torque, const hl_v *fault_state, const hl_v *pre, hl_v *tau, hl_v *tau_offset_next) {
    hl_i odd = hl_splat(0.0) != 0.0;
    safe_stop_lanes_core(q, qd, last_torque, fault_state, pre, tau, tau_offset_next, 0, &odd);
    if (hl_any(odd)) safe_stop_lanes_exact(q, qd, last_torque, fault_state, pre, tau, tau_offset_next);
}
#else
HL_APART void safe_stop_lanes(const hl_v *q, const hl_v *qd, const hl_v *last_torque, const hl_v *fault_state, const hl_v *pre, hl_v *tau, hl_v *tau_offset_next);
#endif

#if HL_IN_PART(1)

typedef struct {
    int status[HL_W], sample[HL_W];
    hl_i alive;
} lanes_run;

/* a lane still running that meets `bad` stops with `status` at sample k */
static void flag(lanes_run *run, hl_i bad, int status, int k) {
    int l;
    bad &= run->alive;
    if (!hl_any(bad)) return;
    for (l = 0; l < HL_W; ++l) {
        if (bad[l]) {
            run->status[l] = status;
            run->sample[l] = k;
        }
    }
    run->alive &= ~bad;
}

/* the metrics' running sums and extremes (hybrid.metrics' definitions, updated row by row) */
typedef struct {
    hl_v peak, n_f, first_f, last_out_f, last_f, drop, n_v, dev, v_max, sum_fe, sum_ve, n_last, sum_f2, sum_v2,
        pen, in_prev, losses, t_out, touch, fd0, band, w_end, t_peak, t_last_out, t_last, tau[2];
} lanes_metrics;

/* the metrics' windows at a row (hybrid.metrics'): after the force step and before the next step or the
   end (in_f), after the speed step (in_v), the last 0.2 s (last), the first touch's (in_t, which the first
   touch itself opens); each window's edges as masks apart, and the references there */
typedef struct {
    hl_v Fd, vd, sgn, f_band;
    hl_i after_f, before_f_end, in_f, in_v, last, before_w_end, in_t;
    int any_f, any_v, any_last;
} lanes_window;

static inline void window_at(lanes_window *w, const lanes_metrics *mt, const hl_v *blk, long i, double h,
                             double end) {
    const hl_v fb = blk[131], fa = blk[132], fat = blk[133];
    const hl_v vb = blk[134], va = blk[135], vat = blk[136];
    const hl_v t = hl_splat((double)i * h), step = fa - fb;
    w->Fd = hl_select(t < fat, fb, fa);
    w->vd = hl_select(t < vat, vb, va);
    w->sgn = hl_select(step >= 0.0, hl_splat(1.0), hl_splat(-1.0));
    w->f_band = 0.02 * hl_select(fa != 0.0, hl_fabs(fa), hl_fabs(step));
    w->after_f = t >= fat;
    w->before_f_end = t < hl_select(vat > fat, vat, hl_splat(end));
    w->in_f = w->after_f & w->before_f_end;
    w->in_v = t >= vat;
    w->last = t >= end - 0.2;
    w->before_w_end = t < mt->w_end;
    w->in_t = (mt->touch >= 0.0) & w->before_w_end;
    w->any_f = hl_any(w->in_f);
    w->any_v = hl_any(w->in_v);
    w->any_last = hl_any(w->last);
}

/* the rows from `a`'s to `b`'s lie in the same windows, every lane: no window's edge falls between them (the
   edges are fixed but for the first touch's, which the touch itself opens) */
static inline int same_windows(const lanes_window *a, const lanes_window *b) {
    return !hl_any((a->after_f ^ b->after_f) | (a->before_f_end ^ b->before_f_end) | (a->in_v ^ b->in_v)
                   | (a->last ^ b->last) | (a->before_w_end ^ b->before_w_end));
}

/* what row i's signals change: extremes, sums, the rows out of a band, the contact's changes, the first
   touch. A window's updates are skipped on the rows where no lane is in it (they would leave each value as
   it is: a sum there only adds +0 to a sum that is never -0) */
HL_ROW void metrics_signals(lanes_metrics *mt, lanes_window *w, const hl_v *blk, const hl_v *s, long i,
                            double h) {
    const hl_v fb = blk[131], fa = blk[132], fat = blk[133];
    const double ti = (double)i * h;
    const hl_v t = hl_splat(ti), idx = hl_splat((double)i), Fd = w->Fd, vd = w->vd;
    const hl_v F = s[2], v = s[3], pen = s[4];
    const hl_i contact = s[5] > 0.0, first = contact & (mt->touch < 0.0);
    if (w->any_f) {
        mt->peak = hl_select(w->in_f & (w->sgn * F > mt->peak), w->sgn * F, mt->peak);
        mt->last_out_f = hl_select(w->in_f & (hl_fabs(F - fa) > w->f_band), idx, mt->last_out_f);
        mt->drop = hl_select(w->in_f & (vd - v > mt->drop), vd - v, mt->drop);
    }
    if (w->any_v) {
        mt->dev = hl_select(w->in_v & (hl_fabs(F - Fd) > mt->dev), hl_fabs(F - Fd), mt->dev);
        mt->v_max = hl_select(w->in_v & (v > mt->v_max), v, mt->v_max);
    }
    if (w->any_last) {
        mt->sum_fe += hl_select(w->last, Fd - F, hl_splat(0.0));
        mt->sum_ve += hl_select(w->last, vd - v, hl_splat(0.0));
    }
    mt->sum_f2 += (Fd - F) * (Fd - F);
    mt->sum_v2 += (vd - v) * (vd - v);
    mt->pen = hl_select(pen > mt->pen, pen, mt->pen);
    if (i > 0) {
        mt->losses += hl_select((mt->in_prev != 0.0) & ~contact, hl_splat(1.0), hl_splat(0.0));
        mt->t_out += hl_select(contact, hl_splat(0.0), hl_splat(ti - (double)(i - 1) * h));
    }
    mt->in_prev = hl_bool(contact);
    if (hl_any(first)) { /* its window lasts until the force reference next changes: past this row */
        mt->touch = hl_select(first, idx, mt->touch);
        mt->fd0 = hl_select(first, Fd, mt->fd0);
        mt->band = hl_select(first, 0.05 * hl_fabs(Fd), mt->band);
        mt->w_end = hl_select(first, hl_select((fa != fb) & (fat > t), fat, hl_splat(INFINITY)), mt->w_end);
        w->in_t |= first;
    }
    if (hl_any(w->in_t)) {
        mt->t_peak = hl_select(w->in_t & (F > mt->t_peak), F, mt->t_peak);
        mt->t_last_out = hl_select(w->in_t & (hl_fabs(F - mt->fd0) > mt->band), idx, mt->t_last_out);
    }
}

/* what the rows i0 .. i1, all in the windows of `w`, add up to: the counts, a window's first and last row */
static inline void metrics_rows(lanes_metrics *mt, const lanes_window *w, long i0, long i1) {
    const hl_v n = hl_splat((double)(i1 - i0 + 1)), zero = hl_splat(0.0);
    mt->n_f += hl_select(w->in_f, n, zero);
    mt->first_f = hl_select(w->in_f & (mt->first_f < 0.0), hl_splat((double)i0), mt->first_f);
    mt->last_f = hl_select(w->in_f, hl_splat((double)i1), mt->last_f);
    mt->n_v += hl_select(w->in_v, n, zero);
    mt->n_last += hl_select(w->last, n, zero);
    mt->t_last = hl_select(w->in_t, hl_splat((double)i1), mt->t_last);
}

/* the joints' peak torques (a torque held for a sample: once per sample) */
static inline void metrics_torque(lanes_metrics *mt, const hl_v *tau) {
    int j;
    for (j = 0; j < 2; ++j) {
        const hl_v a = hl_fabs(tau[j]);
        mt->tau[j] = hl_select(a > mt->tau[j], a, mt->tau[j]);
    }
}

/* one row's metrics, its windows its own */
static void metrics_row(lanes_metrics *mt, const hl_v *blk, const hl_v *s, const hl_v *tau, long i, double h,
                        double end) {
    lanes_window w;
    window_at(&w, mt, blk, i, h, end);
    metrics_signals(mt, &w, blk, s, i, h);
    metrics_rows(mt, &w, i, i);
    metrics_torque(mt, tau);
}

static void metrics_of_lane(const lanes_metrics *mt, const hl_v *blk, int l, long rows, double h, double *out) {
    const double fb = blk[131][l], fa = blk[132][l], vb = blk[134][l], va = blk[135][l];
    int j;
    for (j = 0; j < 6; ++j) out[j] = NAN;
    if (mt->n_f[l] > 0 && fa != fb) {
        const double step = fa - fb, sgn = step >= 0 ? 1.0 : -1.0;
        const double lo = mt->last_out_f[l], lf = mt->last_f[l], first = mt->first_f[l];
        out[0] = (sgn * mt->peak[l] - fa) * sgn;
        out[1] = 100 * out[0] / fabs(step);
        out[2] = lo < 0 ? 0.0 : lo == lf ? NAN : (lo + 1) * h - first * h;
        out[3] = mt->drop[l];
    }
    if (mt->n_v[l] > 0 && va != vb) {
        out[4] = mt->dev[l];
        out[5] = mt->v_max[l] - va;
    }
    out[6] = mt->sum_fe[l] / mt->n_last[l];
    out[7] = mt->sum_ve[l] / mt->n_last[l];
    out[8] = sqrt(mt->sum_f2[l] / (double)rows);
    out[9] = sqrt(mt->sum_v2[l] / (double)rows);
    out[10] = mt->pen[l];
    out[11] = mt->losses[l];
    out[12] = mt->t_out[l];
    out[13] = out[14] = out[15] = NAN;
    if (mt->touch[l] >= 0) {
        const double lo = mt->t_last_out[l], lt = mt->t_last[l], first = mt->touch[l];
        out[13] = first * h;
        out[14] = mt->t_peak[l] - mt->fd0[l];
        out[15] = lo < 0 ? 0.0 : lo == lt ? NAN : (lo + 1) * h - first * h;
    }
    for (j = 0; j < 2; ++j) out[16 + j] = mt->tau[j][l];
}

/* the row's state of each lane in `state` and torque of each lane in `torque`; NaN for the others (a lane
   that stopped) */
static void record_row(double *states, double *taus, int g, int used, long row, long rows, const hl_v *x,
                       const hl_v *tau, hl_i state, hl_i torque) {
    int l, j;
    for (l = 0; l < used; ++l) {
        const long at = (long)(g + l) * rows + row;
        if (states) for (j = 0; j < 8; ++j) states[at * 8 + j] = state[l] ? x[j][l] : NAN;
        if (taus) for (j = 0; j < 2; ++j) taus[at * 2 + j] = torque[l] ? tau[j][l] : NAN;
    }
}

/* the output row of each lane still running (NaN for the others) */
static void record_outputs_row(double *outputs, int g, int used, long row, long rows, const hl_v *y, hl_i alive) {
    int l, j;
    for (l = 0; l < used; ++l) {
        const long at = (long)(g + l) * rows + row;
        for (j = 0; j < 14; ++j) outputs[at * 14 + j] = alive[l] ? y[j][l] : NAN;
    }
}

/* the state and the output record at control sample k of each lane still running (NaN for the others) */
static void record_sample_row(double *samples, int g, int used, long k, long n_samples, const hl_v *x, const hl_v *y,
                              hl_i alive) {
    int l, j;
    for (l = 0; l < used; ++l) {
        double *at = samples + ((long)(g + l) * n_samples + k) * 22;
        for (j = 0; j < 8; ++j) at[j] = alive[l] ? x[j][l] : NAN;
        for (j = 0; j < 14; ++j) at[8 + j] = alive[l] ? y[j][l] : NAN;
    }
}

/* what a run keeps, where it keeps it: the test inline, the copy out of line (a call spills every vector
   register the loop holds, so a run that keeps nothing makes none) */
static inline void record(double *states, double *taus, int g, int used, long row, long rows, const hl_v *x,
                          const hl_v *tau, hl_i state, hl_i torque) {
    if (states || taus) record_row(states, taus, g, used, row, rows, x, tau, state, torque);
}
static inline void record_outputs(double *outputs, int g, int used, long row, long rows, const hl_v *y, hl_i alive) {
    if (outputs) record_outputs_row(outputs, g, used, row, rows, y, alive);
}
static inline void record_sample(double *samples, int g, int used, long k, long n_samples, const hl_v *x, const hl_v *y,
                                 hl_i alive) {
    if (samples) record_sample_row(samples, g, used, k, n_samples, x, y, alive);
}

/* the runs g .. g + used - 1 as one group of HL_W lanes (unused lanes repeat run g) */
static void run_lanes(int g, int used, const double *runs, const double *tables, int n_samples, int steps_per_sample,
                      double h, double sample_time, double singular_tol, double *metrics, int *status,
                      int *failed_sample, double *states, double *taus, double *outputs, double *samples) {
    hl_v pre_rhs[PLANT_RHS_LANES_NPRE], pre_out[PLANT_OUTPUTS_LANES_NPRE], pre_both[PLANT_RHS_SIGNALS_LANES_NPRE],
        pre_step[CONTROLLER_STEP_LANES_NPRE];
    hl_v blk[140], x[8], xt[8], k1[8], k2[8], k3[8], k4[8], s[6], fc[6], z[4], tv[1],
        zero[13], base[6], last[3], y[14];
    hl_v o_tau[2]; hl_v o_integrals_next[4]; hl_v o_a[2]; hl_v o_y[2]; hl_v o_f[2]; hl_v o_saturated[1]; hl_v o_filter_next[13]; hl_v o_estimate_next[12]; hl_v o_contact_wrench[6]; hl_v o_frame[1]; hl_v o_cond[1];
    /* the torque applied, the fault reaction's state (FAULT_STATE) and its safe state's torque */
    hl_v tq[2], fst[9], o_stop[2], o_offset[2], tsv[1], pre_stop[SAFE_STOP_LANES_NPRE];
    /* the lanes that react to faults (their sensor drops out), check timing, lost this sample's reading, refused
       the last sample, served one already, are in the safe state */
    hl_i reacts, timed, dropped, bad, failed, refused, served, on_time, enter, refused_prev, clocked, stopped;
    lanes_run run;
    lanes_metrics mt;
    lanes_window win, win_end;
    hl_i at_sample;
    const long rows = (long)n_samples * steps_per_sample + 1;
    const double end = (double)(rows - 1) * h;
    long row = 0;
    int i, j, l, k, steady;
    (void)singular_tol;
    (void)tables;
    for (l = 0; l < HL_W; ++l) {
        for (j = 0; j < 140; ++j) blk[j][l] = runs[(long)(g + (l < used ? l : 0)) * 140 + j];
        run.status[l] = HYBRID_OK;
        run.sample[l] = -1;
    }
    run.alive = hl_splat(0.0) == 0.0;
    mt.peak = mt.drop = mt.dev = mt.v_max = mt.pen = hl_splat(-INFINITY);
    mt.first_f = mt.last_out_f = mt.last_f = hl_splat(-1.0);
    mt.n_f = mt.n_v = mt.sum_fe = mt.sum_ve = mt.n_last = mt.sum_f2 = mt.sum_v2 = mt.in_prev = mt.losses = mt.t_out
        = hl_splat(0.0);
    mt.touch = mt.t_last_out = mt.t_last = hl_splat(-1.0);
    mt.fd0 = mt.band = hl_splat(0.0);
    mt.w_end = hl_splat(INFINITY);
    mt.t_peak = hl_splat(-INFINITY);
    for (j = 0; j < 2; ++j) mt.tau[j] = hl_splat(0.0);
    for (j = 0; j < 13; ++j) zero[j] = hl_splat(0.0);
    for (j = 0; j < 6; ++j) fc[j] = hl_splat(0.0);
    for (j = 0; j < 4; ++j) z[j] = hl_splat(0.0);
    for (j = 0; j <= 2; ++j) last[j] = hl_splat(0.0);
    for (j = 0; j < 9; ++j) fst[j] = hl_splat(0.0);
    reacts = blk[137] < INFINITY;
    timed = blk[139] >= 0.0;
    refused_prev = clocked = stopped = hl_splat(0.0) != 0.0;
    tsv[0] = hl_splat(sample_time);
    for (j = 0; j < 8; ++j) x[j] = blk[0 + j];
    for (j = 0; j < 6; ++j) base[j] = hl_splat(NAN);  /* none yet: the first step computes it */
    plant_rhs_lanes_pre(blk + 8, blk + 19, blk + 26, pre_rhs);
    plant_outputs_lanes_pre(blk + 8, blk + 19, blk + 26, pre_out);
    plant_rhs_signals_lanes_pre(blk + 8, blk + 19, blk + 26, pre_both);
    controller_step_lanes_pre(blk + 29, blk + 35, blk + 43, blk + 45, blk + 76, blk + 83, blk + 86, blk + 93, blk + 99, blk + 103, blk + 128, pre_step);
    safe_stop_lanes_pre(blk + 45, blk + 128, blk + 99, tsv, pre_stop);
    for (k = 0; k < n_samples && hl_any(run.alive); ++k) {
        /* the sensor's reading at the sample instant (a row's signals come with its step's first stage) */
        plant_outputs_lanes(x, pre_out, y);
        record_sample(samples, g, used, k, n_samples, x, y, run.alive);
        fc[0] = y[4];
        fc[1] = y[5];

        tv[0] = hl_splat(k * sample_time);
        /* a lost reading (the sensor's dropout): not a number */
        dropped = (tv[0] >= blk[137]) & (tv[0] < blk[138]);
        if (hl_any(dropped)) {
            for (j = 0; j < 2; ++j) fc[j] = hl_select(dropped, hl_splat(NAN), fc[j]);
        }
        /* the plant's sensor gives the wrench on the robot itself and the surface is told: no filter, no estimate */
        controller_step_lanes(x, x + 2, fc, z, last, zero, zero, tv, zero, zero, zero, pre_step, o_tau, o_integrals_next, o_a, o_y, o_f, o_saturated, o_filter_next, o_estimate_next, o_contact_wrench, o_frame, o_cond);
        at_sample = run.alive;  /* the lanes whose state this sample starts from is recorded */
        /* a guard tripped or an output not finite: a run that reacts to faults refuses the sample, another stops */
        bad = dropped;
        failed = hl_fabs(o_frame[0]) < 1e-06;
        flag(&run, failed & ~reacts, HYBRID_FRAME_UNDEFINED, k);
        bad |= failed;
        failed = hl_fabs(o_cond[0]) < singular_tol;
        flag(&run, failed & ~reacts, HYBRID_SINGULAR, k);
        bad |= failed;
        failed = hl_not_finite(o_tau, 2) | hl_not_finite(o_integrals_next, 4) | hl_not_finite(o_a, 2) | hl_not_finite(o_y, 2) | hl_not_finite(o_f, 2) | hl_not_finite(o_saturated, 1) | hl_not_finite(o_filter_next, 13) | hl_not_finite(o_estimate_next, 12) | hl_not_finite(o_contact_wrench, 6) | hl_not_finite(o_frame, 1) | hl_not_finite(o_cond, 1);
        flag(&run, failed & ~reacts, HYBRID_NONFINITE, k);
        bad |= failed;
        refused = bad & ~stopped;
        served = ~bad & ~stopped;
        /* the sample after a refused one is late (it is timed from the last one served): the integrals stay */
        on_time = served & ~(refused_prev & clocked & timed);
        for (j = 0; j < 4; ++j) z[j] = hl_select(on_time, o_integrals_next[j], z[j]);
        /* the torque applied: the law's, or at a refused sample the torque last written (0 before any); the rate
           limit starts from it at the next sample */
        for (j = 0; j < 2; ++j) last[j] = tq[j] = hl_select(served, o_tau[j], last[j]);
        last[2] = hl_select(served, hl_splat(1.0), last[2]);
        if (hl_any(reacts)) {
            /* the fault reaction (codegen/standalone_controller.py's): a faulted sample counts, one on time ends the
               count; fault_samples of them enter the safe state, for the rest of the run */
            fst[6] = hl_select(stopped, fst[6],
                                   hl_select(on_time, hl_splat(0.0), fst[6] + 1.0));
            enter = reacts & ~stopped & (fst[6] >= blk[128]);
            if (hl_any(enter)) {
                for (j = 0; j < 2; ++j) {
                    fst[0 + j] = hl_select(enter, tq[j], fst[0 + j]);
                    fst[4 + j] = hl_select(enter, x[j], fst[4 + j]);
                }
                fst[8] = hl_select(enter, hl_splat(0.0), fst[8]);
                fst[7] = hl_select(enter, hl_splat(1.0), fst[7]);
                stopped |= enter;
            }
            if (hl_any(stopped)) {
                safe_stop_lanes(x, x + 2, last, fst, pre_stop, o_stop, o_offset);
                for (j = 0; j < 2; ++j) {
                    last[j] = tq[j] = hl_select(stopped, o_stop[j], tq[j]);
                    fst[0 + j] = hl_select(stopped, o_offset[j], fst[0 + j]);
                }
                last[2] = hl_select(stopped, hl_splat(1.0), last[2]);
                fst[8] = hl_select(stopped, fst[8] + 1.0, fst[8]);
            }
        }
        /* fault_state's q_hold stays unused: the plant's joint positions are always finite */
        refused_prev = refused;
        clocked |= served | stopped;
        if (k == 0) record(states, taus, g, used, 0, rows, x, tq, hl_splat(0.0) == 0.0, run.alive);
        /* the metrics' windows: where no edge of theirs falls among the sample's rows, each row updates only
           what its signals change, and the counts are the sample's */
        window_at(&win, &mt, blk, row, h, end);
        window_at(&win_end, &mt, blk, row + steps_per_sample - 1, h, end);
        steady = same_windows(&win, &win_end);
        metrics_torque(&mt, tq);
        for (i = 0; i < steps_per_sample; ++i) {
            /* the joints' sin and cos the step's stages rotate from: its start's, or an earlier step's */
            hl_rebase(x, base, 2);
            plant_rhs_signals_lanes(x, tq, pre_both, k1, s, y, base);
            for (j = 0; j < 8; ++j) xt[j] = x[j] + 0.5 * h * k1[j];
            plant_rhs_lanes(xt, tq, pre_rhs, k2, base);
            for (j = 0; j < 8; ++j) xt[j] = x[j] + 0.5 * h * k2[j];
            plant_rhs_lanes(xt, tq, pre_rhs, k3, base);
            for (j = 0; j < 8; ++j) xt[j] = x[j] + h * k3[j];
            plant_rhs_lanes(xt, tq, pre_rhs, k4, base);
            for (j = 0; j < 8; ++j) x[j] = x[j] + h / 6.0 * (k1[j] + 2.0 * (k2[j] + k3[j]) + k4[j]);
            /* the row the step started from */
            if (!steady) window_at(&win, &mt, blk, row, h, end);
            metrics_signals(&mt, &win, blk, s, row, h);
            if (!steady) metrics_rows(&mt, &win, row, row);
            /* the row's output where its state is recorded (a sample's first row: before its controller's stop) */
            record_outputs(outputs, g, used, row, rows, y, i == 0 ? at_sample : run.alive);
            ++row;
            /* a state, or a signal the metrics read (a surface undefined where the tip is), not finite */
            flag(&run, hl_not_finite(x, 8) | hl_not_finite(s, 6), HYBRID_NONFINITE, k);
            /* a stopped lane restarts from its initial state: its numbers no longer matter, and they stay
               finite */
            if (hl_any(~run.alive)) {
                for (j = 0; j < 8; ++j) x[j] = hl_select(run.alive, x[j], blk[0 + j]);
            }
            record(states, taus, g, used, row, rows, x, tq, run.alive, run.alive);
        }
        if (steady) metrics_rows(&mt, &win, row - steps_per_sample, row - 1);
    }
    if (k > 0) { /* the last row */
        plant_outputs_lanes(x, pre_out, y);
        s[0] = y[4];
        s[1] = y[5];
        s[2] = y[7];
        s[3] = y[2];
        s[4] = y[10];
        s[5] = y[11];
        flag(&run, hl_not_finite(s, 6), HYBRID_NONFINITE, k - 1);
        metrics_row(&mt, blk, s, tq, row, h, end);
        record_outputs(outputs, g, used, row, rows, y, run.alive);
    }
    for (i = k; i < n_samples; ++i) record_sample(samples, g, used, i, n_samples, x, y, run.alive);  /* all stopped */
    while (++row < rows) { /* all stopped */
        record(states, taus, g, used, row, rows, x, tq, run.alive, run.alive);
        record_outputs(outputs, g, used, row, rows, y, run.alive);
    }
    for (l = 0; l < used; ++l) {
        status[g + l] = run.status[l];
        failed_sample[g + l] = run.sample[l];
        metrics_of_lane(&mt, blk, l, rows, h, metrics + (long)(g + l) * 18);
    }
}

int hybrid_planar_arm_circle_controller_4b54e1a71151_closed_loop(int nruns, const double *runs, const double *tables, int n_samples, int steps_per_sample, double h, double sample_time, double singular_tol, double *metrics, int *status, int *failed_sample, double *states, double *taus, double *outputs, double *samples) {
    int g;
    for (g = 0; g < nruns; g += HL_W) {
        run_lanes(g, nruns - g < HL_W ? nruns - g : HL_W, runs, tables, n_samples, steps_per_sample, h, sample_time,
                  singular_tol, metrics, status, failed_sample, states, taus, outputs, samples);
    }
    return HYBRID_OK;
}

int hybrid_planar_arm_circle_controller_4b54e1a71151_lanes(void) {
    return HL_W;
}
#else
int hybrid_planar_arm_circle_controller_4b54e1a71151_closed_loop(int nruns, const double *runs, const double *tables, int n_samples, int steps_per_sample, double h, double sample_time, double singular_tol, double *metrics, int *status, int *failed_sample, double *states, double *taus, double *outputs, double *samples);
int hybrid_planar_arm_circle_controller_4b54e1a71151_lanes(void);
#endif
