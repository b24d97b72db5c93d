/* hybrid generated file: do not edit; change codegen/ and run `python -m hybrid regenerate`. body-sha256: acfcd8b475e4160ec684de04d45c771cc81155428cc0ede250cdc833c4d4afdb */
/* hybrid_planar_arm_circle_raibert_cr_57176b91a5fa: the paper's closed loop on a circle: raibert_craig_step.
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

#define RAIBERT_CRAIG_STEP_LANES_NPRE 77
#if HL_IN_PART(2)
HL_APART void raibert_craig_step_lanes_pre(const hl_v *steps, const hl_v *gains, const hl_v *selection, const hl_v *robot, const hl_v *surface, const hl_v *e, const hl_v *options, const hl_v *posture, const hl_v *limits, const hl_v *sensor, const hl_v *fault, hl_v *pre) {
    const hl_v v56 = hl_splat(0.32);
    const hl_v v64 = hl_splat(0.45);
    const hl_v v67 = surface[0];
    const hl_v v48 = surface[3];
    const hl_v v46 = surface[2];
    const hl_v v47 = surface[5];
    const hl_v v80 = v47 * v46;
    const hl_v v76 = surface[1];
    const hl_v v50 = surface[4];
    const hl_v v49 = v48 * v48;
    const hl_v v51 = v50 * v50;
    const hl_v v52 = v49 + v51;
    const hl_v v53 = v47 * v47;
    const hl_v v54 = v52 + v53;
    const hl_v v612 = 1.0 / v54;
    const hl_v v84 = v48 * v612;
    const hl_v v88 = v50 * v612;
    const hl_v v55 = v47 * v612;
    const hl_v v35 = e[0];
    const hl_v v36 = v35 * v35;
    const hl_v v34 = e[1];
    const hl_v v37 = v34 * v34;
    const hl_v v38 = v36 + v37;
    const hl_v v39 = e[2];
    const hl_v v40 = v39 * v39;
    const hl_v v41 = v38 + v40;
    const hl_v v42 = hl_sqrt(v41);
    const hl_v v43 = 1.0 / v42;
    const hl_v v44 = hl_copysign(v43, v42);
    const hl_v v45 = v34 * v44;
    const hl_v v120 = v39 * v44;
    const hl_v v127 = v35 * v44;
    const hl_v v150 = steps[2];
    const hl_v v156 = steps[0];
    const hl_v v153 = steps[1];
    const hl_v v146 = selection[0];
    const hl_v v145 = hl_splat(1.0);
    const hl_v v147 = v145 - v146;
    const hl_v v211 = options[1];
    const hl_v v220 = gains[2];
    const hl_v v195 = gains[1];
    const hl_v v216 = options[3];
    const hl_v v196 = options[4];
    const hl_v v199 = hl_splat(0.0);
    const hl_v v200 = hl_bool(v195 != v199);
    const hl_v v149 = gains[0];
    const hl_v v202 = gains[3];
    const hl_v v203 = options[5];
    const hl_v v204 = v202 * v203;
    const hl_v v207 = hl_bool(v200 == 0.0);
    const hl_v v208 = hl_select(v207 != 0.0, v145, hl_splat(0.0));
    const hl_v v206 = hl_select(v200 != 0.0, v195, hl_splat(0.0));
    const hl_v v209 = v206 + v208;
    const hl_v v614 = 1.0 / v209;
    const hl_v v257 = v147 * v147;
    const hl_v v270 = selection[1];
    const hl_v v271 = v145 - v270;
    const hl_v v272 = v271 * v147;
    const hl_v v286 = steps[5];
    const hl_v v291 = steps[3];
    const hl_v v288 = steps[4];
    const hl_v v331 = gains[6];
    const hl_v v311 = gains[5];
    const hl_v v314 = hl_bool(v311 != v199);
    const hl_v v285 = gains[4];
    const hl_v v316 = gains[7];
    const hl_v v317 = v316 * v203;
    const hl_v v320 = hl_bool(v314 == 0.0);
    const hl_v v321 = hl_select(v320 != 0.0, v145, hl_splat(0.0));
    const hl_v v319 = hl_select(v314 != 0.0, v311, hl_splat(0.0));
    const hl_v v322 = v319 + v321;
    const hl_v v615 = 1.0 / v322;
    const hl_v v370 = v271 * v271;
    const hl_v v33 = options[6];
    const hl_v v392 = v145 - v33;
    const hl_v v1 = robot[10];
    const hl_v v2 = robot[11];
    const hl_v v3 = v1 * v2;
    const hl_v v4 = v3 * v2;
    const hl_v v5 = robot[12];
    const hl_v v6 = v1 * v5;
    const hl_v v7 = v6 * v5;
    const hl_v v8 = v4 + v7;
    const hl_v v0 = robot[19];
    const hl_v v9 = v0 + v8;
    const hl_v v18 = hl_splat(0.2025);
    const hl_v v19 = v18 * v1;
    const hl_v v618 = v9 + v19;
    const hl_v v23 = robot[0];
    const hl_v v24 = robot[1];
    const hl_v v25 = v23 * v24;
    const hl_v v26 = v25 * v24;
    const hl_v v27 = robot[2];
    const hl_v v28 = v23 * v27;
    const hl_v v29 = v28 * v27;
    const hl_v v30 = v26 + v29;
    const hl_v v22 = robot[9];
    const hl_v v31 = v22 + v30;
    const hl_v v619 = v31 + v618;
    const hl_v v10 = hl_splat(0.9);
    const hl_v v616 = 1.0 / v149;
    const hl_v v617 = 1.0 / v285;
    const hl_v v432 = robot[28];
    const hl_v v434 = robot[29];
    const hl_v v645 = v23 * v24;
    const hl_v v462 = robot[24];
    const hl_v v646 = v23 * v27;
    const hl_v v471 = limits[2];
    const hl_v v468 = limits[0];
    const hl_v v482 = -v468;
    const hl_v v466 = hl_splat(1.7976931348623157e+308);
    const hl_v v523 = robot[25];
    const hl_v v530 = limits[3];
    const hl_v v528 = limits[1];
    const hl_v v540 = -v528;
    const hl_v v584 = hl_splat(1e-12);
    const hl_v v598 = hl_splat(2.0);
    pre[0] = v56;
    pre[1] = v64;
    pre[2] = v67;
    pre[3] = v48;
    pre[4] = v46;
    pre[5] = v47;
    pre[6] = v80;
    pre[7] = v76;
    pre[8] = v50;
    pre[9] = v84;
    pre[10] = v88;
    pre[11] = v55;
    pre[12] = v45;
    pre[13] = v120;
    pre[14] = v127;
    pre[15] = v150;
    pre[16] = v156;
    pre[17] = v153;
    pre[18] = v146;
    pre[19] = v145;
    pre[20] = v147;
    pre[21] = v211;
    pre[22] = v220;
    pre[23] = v195;
    pre[24] = v216;
    pre[25] = v196;
    pre[26] = v199;
    pre[27] = v200;
    pre[28] = v149;
    pre[29] = v202;
    pre[30] = v203;
    pre[31] = v204;
    pre[32] = v614;
    pre[33] = v257;
    pre[34] = v270;
    pre[35] = v271;
    pre[36] = v272;
    pre[37] = v286;
    pre[38] = v291;
    pre[39] = v288;
    pre[40] = v331;
    pre[41] = v311;
    pre[42] = v314;
    pre[43] = v285;
    pre[44] = v316;
    pre[45] = v317;
    pre[46] = v615;
    pre[47] = v370;
    pre[48] = v33;
    pre[49] = v392;
    pre[50] = v1;
    pre[51] = v2;
    pre[52] = v3;
    pre[53] = v5;
    pre[54] = v6;
    pre[55] = v9;
    pre[56] = v19;
    pre[57] = v23;
    pre[58] = v619;
    pre[59] = v10;
    pre[60] = v616;
    pre[61] = v617;
    pre[62] = v432;
    pre[63] = v434;
    pre[64] = v645;
    pre[65] = v462;
    pre[66] = v646;
    pre[67] = v471;
    pre[68] = v468;
    pre[69] = v482;
    pre[70] = v466;
    pre[71] = v523;
    pre[72] = v530;
    pre[73] = v528;
    pre[74] = v540;
    pre[75] = v584;
    pre[76] = v598;
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
HL_APART void raibert_craig_step_lanes_pre(const hl_v *steps, const hl_v *gains, const hl_v *selection, const hl_v *robot, const hl_v *surface, const hl_v *e, const hl_v *options, const hl_v *posture, const hl_v *limits, const hl_v *sensor, const hl_v *fault, hl_v *pre);
#endif

static inline __attribute__((always_inline)) void raibert_craig_step_lanes_core(const hl_v *q, const hl_v *qd, const hl_v *Fc, const hl_v *integrals, const hl_v *last_torque, const hl_v *filter, const hl_v *estimate, const hl_v *t, const hl_v *yd_extra, const hl_v *yd_rate, const hl_v *target, const hl_v *pre, hl_v *tau, hl_v *integrals_next, hl_v *a, hl_v *y, hl_v *f, hl_v *saturated, hl_v *filter_next, hl_v *estimate_next, hl_v *contact_wrench, hl_v *frame, hl_v *cond, const int exact, hl_i *odd) {
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
    const hl_v v11 = q[1];
    hl_v v14, v12;
    if (exact) hl_sincos(v11, &v14, &v12); else hl_sincos_poly(v11, &v14, &v12, odd);
    const hl_v v57 = q[0];
    hl_v v60, v58;
    if (exact) hl_sincos(v57, &v60, &v58); else hl_sincos_poly(v57, &v60, &v58, odd);
    const hl_v v59 = v58 * v12;
    const hl_v v61 = v60 * v14;
    const hl_v v62 = v59 - v61;
    const hl_v v56 = pre[0];
    const hl_v v63 = v56 * v62;
    const hl_v v64 = pre[1];
    const hl_v v65 = v64 * v58;
    const hl_v v66 = v63 + v65;
    const hl_v v67 = pre[2];
    const hl_v v68 = v66 - v67;
    const hl_v v48 = pre[3];
    const hl_v v69 = v48 * v68;
    const hl_v v46 = pre[4];
    const hl_v v47 = pre[5];
    const hl_v v80 = pre[6];
    const hl_v v620 = v69 - v80;
    const hl_v v70 = v60 * v12;
    const hl_v v71 = v58 * v14;
    const hl_v v72 = v70 + v71;
    const hl_v v73 = v56 * v72;
    const hl_v v74 = v64 * v60;
    const hl_v v75 = v73 + v74;
    const hl_v v76 = pre[7];
    const hl_v v77 = v75 - v76;
    const hl_v v50 = pre[8];
    const hl_v v78 = v50 * v77;
    const hl_v v81 = v78 + v620;
    const hl_v v84 = pre[9];
    const hl_v v85 = v84 * v81;
    const hl_v v86 = v68 - v85;
    const hl_v v87 = v86 * v86;
    const hl_v v88 = pre[10];
    const hl_v v89 = v88 * v81;
    const hl_v v90 = v77 - v89;
    const hl_v v91 = v90 * v90;
    const hl_v v621 = v87 + v91;
    const hl_v v55 = pre[11];
    const hl_v v82 = v55 * v81;
    const hl_v v83 = v46 + v82;
    const hl_v v93 = v83 * v83;
    const hl_v v94 = v93 + v621;
    const hl_v v95 = hl_sqrt(v94);
    const hl_v v613 = 1.0 / v95;
    const hl_v v97 = v90 * v613;
    const hl_v v98 = v88 * v97;
    const hl_v v96 = v83 * v613;
    const hl_v v99 = v55 * v96;
    const hl_v v622 = v98 - v99;
    const hl_v v101 = v86 * v613;
    const hl_v v102 = v84 * v101;
    const hl_v v103 = v102 + v622;
    const hl_v v106 = v48 * v103;
    const hl_v v107 = v101 - v106;
    const hl_v v108 = v107 * v107;
    const hl_v v109 = v50 * v103;
    const hl_v v110 = v97 - v109;
    const hl_v v111 = v110 * v110;
    const hl_v v623 = v108 + v111;
    const hl_v v104 = v47 * v103;
    const hl_v v105 = v96 + v104;
    const hl_v v113 = v105 * v105;
    const hl_v v114 = v113 + v623;
    const hl_v v115 = hl_sqrt(v114);
    const hl_v v116 = 1.0 / v115;
    const hl_v v117 = hl_copysign(v116, v115);
    const hl_v v118 = v105 * v117;
    const hl_v v45 = pre[12];
    const hl_v v119 = v45 * v118;
    const hl_v v121 = v110 * v117;
    const hl_v v120 = pre[13];
    const hl_v v122 = v120 * v121;
    const hl_v v123 = v119 + v122;
    const hl_v v124 = v123 * v123;
    const hl_v v125 = v107 * v117;
    const hl_v v126 = v120 * v125;
    const hl_v v127 = pre[14];
    const hl_v v128 = v127 * v118;
    const hl_v v129 = v126 + v128;
    const hl_v v130 = v129 * v129;
    const hl_v v624 = v124 + v130;
    const hl_v v132 = v127 * v121;
    const hl_v v133 = v45 * v125;
    const hl_v v134 = v132 - v133;
    const hl_v v135 = v134 * v134;
    const hl_v v136 = v135 + v624;
    const hl_v v137 = hl_sqrt(v136);
    const hl_v v138 = 1.0 / v137;
    const hl_v v139 = hl_copysign(v138, v137);
    const hl_v v142 = v129 * v139;
    const hl_v v161 = Fc[1];
    contact_wrench[1] = v161;
    const hl_v v162 = v142 * v161;
    const hl_v v140 = v123 * v139;
    const hl_v v163 = Fc[0];
    contact_wrench[0] = v163;
    const hl_v v164 = v140 * v163;
    const hl_v v627 = v162 - v164;
    const hl_v v167 = Fc[2];
    contact_wrench[2] = v167;
    const hl_v v626 = v167 * v134;
    const hl_v v168 = v626 * v139;
    const hl_v v169 = v168 + v627;
    f[0] = v169;
    const hl_v v150 = pre[15];
    const hl_v v151 = t[0];
    const hl_v v152 = hl_bool(v150 <= v151);
    const hl_v v155 = hl_bool(v152 == 0.0);
    const hl_v v156 = pre[16];
    const hl_v v157 = hl_select(v155 != 0.0, v156, hl_splat(0.0));
    const hl_v v153 = pre[17];
    const hl_v v154 = hl_select(v152 != 0.0, v153, hl_splat(0.0));
    const hl_v v159 = yd_extra[0];
    const hl_v v625 = v159 + v154;
    const hl_v v160 = v157 + v625;
    const hl_v v170 = v160 - v169;
    const hl_v v146 = pre[18];
    const hl_v v171 = v146 * v170;
    const hl_v v172 = qd[0];
    const hl_v v173 = v64 * v172;
    const hl_v v174 = v14 * v173;
    const hl_v v175 = v72 * v174;
    const hl_v v176 = v12 * v173;
    const hl_v v177 = qd[1];
    const hl_v v178 = v172 + v177;
    const hl_v v179 = v56 * v178;
    const hl_v v180 = v176 + v179;
    const hl_v v181 = v62 * v180;
    const hl_v v182 = v175 + v181;
    const hl_v v183 = v142 * v182;
    const hl_v v184 = v62 * v174;
    const hl_v v185 = v71 + v70;
    const hl_v v186 = v185 * v180;
    const hl_v v187 = v184 - v186;
    const hl_v v188 = v140 * v187;
    const hl_v v189 = v183 - v188;
    y[0] = v189;
    const hl_v v190 = v160 - v189;
    const hl_v v145 = pre[19];
    const hl_v v147 = pre[20];
    const hl_v v191 = v147 * v190;
    const hl_v v192 = v171 + v191;
    const hl_v v211 = pre[21];
    const hl_v v212 = v211 * v192;
    const hl_v v217 = integrals[0];
    const hl_v v218 = v217 + v212;
    const hl_v v222 = v211 * v218;
    const hl_v v221 = integrals[1];
    const hl_v v223 = v221 + v222;
    const hl_v v224 = v147 * v223;
    const hl_v v220 = pre[22];
    const hl_v v225 = v220 * v224;
    const hl_v v195 = pre[23];
    const hl_v v219 = v195 * v218;
    const hl_v v226 = v219 + v225;
    const hl_v v227 = hl_fabs(v226);
    const hl_v v216 = pre[24];
    const hl_v v228 = hl_bool(v216 < v227);
    const hl_v v196 = pre[25];
    const hl_v v197 = hl_bool(v169 < v196);
    const hl_v v198 = v146 * v197;
    const hl_v v229 = hl_bool((v228 != 0.0) | (v198 != 0.0));
    const hl_v v231 = v145 - v229;
    const hl_v v232 = v231 * v218;
    const hl_v v230 = v229 * v217;
    const hl_v v233 = v230 + v232;
    const hl_v v199 = pre[26];
    filter_next[0] = v199;
    filter_next[1] = v199;
    filter_next[2] = v199;
    filter_next[3] = v199;
    filter_next[4] = v199;
    filter_next[5] = v199;
    filter_next[6] = v199;
    filter_next[7] = v199;
    filter_next[8] = v199;
    filter_next[9] = v199;
    filter_next[10] = v199;
    filter_next[11] = v199;
    filter_next[12] = v199;
    estimate_next[0] = v199;
    estimate_next[1] = v199;
    estimate_next[2] = v199;
    estimate_next[3] = v199;
    estimate_next[4] = v199;
    estimate_next[5] = v199;
    estimate_next[6] = v199;
    estimate_next[7] = v199;
    estimate_next[8] = v199;
    estimate_next[9] = v199;
    estimate_next[10] = v199;
    estimate_next[11] = v199;
    const hl_v v200 = pre[27];
    const hl_v v201 = v198 * v200;
    const hl_v v215 = hl_bool(v201 == 0.0);
    const hl_v v234 = hl_select(v215 != 0.0, v233, hl_splat(0.0));
    const hl_v v149 = pre[28];
    const hl_v v193 = v149 * v192;
    const hl_v v202 = pre[29];
    const hl_v v203 = pre[30];
    const hl_v v204 = pre[31];
    const hl_v v205 = v204 - v193;
    const hl_v v614 = pre[32];
    const hl_v v210 = v205 * v614;
    const hl_v v213 = v210 - v212;
    const hl_v v214 = hl_select(v201 != 0.0, v213, hl_splat(0.0));
    const hl_v v235 = v214 + v234;
    const hl_v v236 = v195 * v235;
    const hl_v v246 = v202 * v189;
    const hl_v v631 = v246 + v193;
    const hl_v v248 = v631 + v236;
    const hl_v v245 = v145 - v198;
    const hl_v v249 = v245 * v248;
    const hl_v v251 = v189 + v203;
    const hl_v v632 = v202 * v251;
    const hl_v v252 = v632 * v198;
    const hl_v v253 = v249 + v252;
    const hl_v v254 = v146 * v253;
    const hl_v v240 = v231 * v224;
    const hl_v v628 = v147 * v221;
    const hl_v v239 = v628 * v229;
    const hl_v v241 = v239 + v240;
    const hl_v v242 = v220 * v241;
    const hl_v v148 = yd_rate[0];
    const hl_v v629 = v148 + v193;
    const hl_v v630 = v629 + v242;
    const hl_v v243 = v630 + v236;
    const hl_v v244 = v147 * v243;
    const hl_v v255 = v244 - v254;
    a[0] = v255;
    const hl_v v256 = v147 * v255;
    const hl_v v141 = v140 * v75;
    const hl_v v143 = v142 * v66;
    const hl_v v144 = v141 + v143;
    const hl_v v258 = v144 * v144;
    const hl_v v259 = v140 * v73;
    const hl_v v260 = v142 * v63;
    const hl_v v261 = v259 + v260;
    const hl_v v262 = v261 * v261;
    const hl_v v263 = v258 + v262;
    const hl_v v257 = pre[33];
    const hl_v v264 = v257 * v263;
    const hl_v v265 = v264 + v146;
    const hl_v v266 = hl_sqrt(v265);
    const hl_v v267 = 1.0 / v266;
    const hl_v v268 = hl_copysign(v267, v266);
    const hl_v v269 = v256 * v268;
    const hl_v v273 = v121 * v66;
    const hl_v v274 = v125 * v75;
    const hl_v v275 = v273 - v274;
    const hl_v v276 = v275 * v144;
    const hl_v v277 = v121 * v63;
    const hl_v v278 = v125 * v73;
    const hl_v v279 = v277 - v278;
    const hl_v v280 = v279 * v261;
    const hl_v v281 = v276 + v280;
    const hl_v v270 = pre[34];
    const hl_v v271 = pre[35];
    const hl_v v272 = pre[36];
    const hl_v v633 = v272 * v281;
    const hl_v v283 = v633 * v268;
    const hl_v v368 = v283 * v269;
    const hl_v v296 = v125 * v163;
    const hl_v v297 = v121 * v161;
    const hl_v v635 = v296 + v297;
    const hl_v v299 = v118 * v167;
    const hl_v v300 = v635 - v299;
    f[1] = v300;
    const hl_v v286 = pre[37];
    const hl_v v287 = hl_bool(v286 <= v151);
    const hl_v v290 = hl_bool(v287 == 0.0);
    const hl_v v291 = pre[38];
    const hl_v v292 = hl_select(v290 != 0.0, v291, hl_splat(0.0));
    const hl_v v288 = pre[39];
    const hl_v v289 = hl_select(v287 != 0.0, v288, hl_splat(0.0));
    const hl_v v294 = yd_extra[1];
    const hl_v v634 = v294 + v289;
    const hl_v v295 = v292 + v634;
    const hl_v v301 = v295 - v300;
    const hl_v v302 = v270 * v301;
    const hl_v v303 = v125 * v187;
    const hl_v v304 = v121 * v182;
    const hl_v v305 = v303 + v304;
    y[1] = v305;
    const hl_v v306 = v295 - v305;
    const hl_v v307 = v271 * v306;
    const hl_v v308 = v302 + v307;
    const hl_v v324 = v211 * v308;
    const hl_v v328 = integrals[2];
    const hl_v v329 = v328 + v324;
    const hl_v v333 = v211 * v329;
    const hl_v v332 = integrals[3];
    const hl_v v334 = v332 + v333;
    const hl_v v335 = v271 * v334;
    const hl_v v331 = pre[40];
    const hl_v v336 = v331 * v335;
    const hl_v v311 = pre[41];
    const hl_v v330 = v311 * v329;
    const hl_v v337 = v330 + v336;
    const hl_v v338 = hl_fabs(v337);
    const hl_v v339 = hl_bool(v216 < v338);
    const hl_v v312 = hl_bool(v300 < v196);
    const hl_v v313 = v270 * v312;
    const hl_v v340 = hl_bool((v339 != 0.0) | (v313 != 0.0));
    const hl_v v342 = v145 - v340;
    const hl_v v343 = v342 * v329;
    const hl_v v341 = v340 * v328;
    const hl_v v344 = v341 + v343;
    const hl_v v314 = pre[42];
    const hl_v v315 = v313 * v314;
    const hl_v v327 = hl_bool(v315 == 0.0);
    const hl_v v345 = hl_select(v327 != 0.0, v344, hl_splat(0.0));
    const hl_v v285 = pre[43];
    const hl_v v309 = v285 * v308;
    const hl_v v316 = pre[44];
    const hl_v v317 = pre[45];
    const hl_v v318 = v317 - v309;
    const hl_v v615 = pre[46];
    const hl_v v323 = v318 * v615;
    const hl_v v325 = v323 - v324;
    const hl_v v326 = hl_select(v315 != 0.0, v325, hl_splat(0.0));
    const hl_v v346 = v326 + v345;
    const hl_v v347 = v311 * v346;
    const hl_v v357 = v316 * v305;
    const hl_v v639 = v357 + v309;
    const hl_v v359 = v639 + v347;
    const hl_v v356 = v145 - v313;
    const hl_v v360 = v356 * v359;
    const hl_v v362 = v305 + v203;
    const hl_v v640 = v316 * v362;
    const hl_v v363 = v640 * v313;
    const hl_v v364 = v360 + v363;
    const hl_v v365 = v270 * v364;
    const hl_v v351 = v342 * v335;
    const hl_v v636 = v271 * v332;
    const hl_v v350 = v636 * v340;
    const hl_v v352 = v350 + v351;
    const hl_v v353 = v331 * v352;
    const hl_v v284 = yd_rate[1];
    const hl_v v637 = v284 + v309;
    const hl_v v638 = v637 + v353;
    const hl_v v354 = v638 + v347;
    const hl_v v355 = v271 * v354;
    const hl_v v366 = v355 - v365;
    a[1] = v366;
    const hl_v v367 = v271 * v366;
    const hl_v v369 = v367 - v368;
    const hl_v v376 = v283 * v283;
    const hl_v v371 = v275 * v275;
    const hl_v v372 = v279 * v279;
    const hl_v v373 = v371 + v372;
    const hl_v v370 = pre[47];
    const hl_v v374 = v370 * v373;
    const hl_v v641 = v270 + v374;
    const hl_v v377 = v641 - v376;
    const hl_v v378 = hl_sqrt(v377);
    const hl_v v379 = 1.0 / v378;
    const hl_v v380 = hl_copysign(v379, v378);
    const hl_v v642 = v369 * v380;
    const hl_v v382 = v380 * v642;
    const hl_v v383 = v283 * v382;
    const hl_v v384 = v269 - v383;
    const hl_v v643 = v147 * v268;
    const hl_v v386 = v643 * v384;
    const hl_v v387 = v144 * v386;
    const hl_v v388 = v271 * v382;
    const hl_v v389 = v275 * v388;
    const hl_v v390 = v387 + v389;
    const hl_v v33 = pre[48];
    const hl_v v391 = v33 * v390;
    const hl_v v393 = hl_sqrt(v263);
    const hl_v v394 = 1.0 / v393;
    const hl_v v395 = hl_copysign(v394, v393);
    const hl_v v397 = v256 * v395;
    const hl_v v396 = v144 * v395;
    const hl_v v399 = v396 * v275;
    const hl_v v400 = v261 * v395;
    const hl_v v401 = v400 * v279;
    const hl_v v402 = v399 + v401;
    const hl_v v414 = v402 * v397;
    const hl_v v415 = v367 - v414;
    const hl_v v403 = v402 * v396;
    const hl_v v404 = v275 - v403;
    const hl_v v405 = v404 * v404;
    const hl_v v406 = v402 * v400;
    const hl_v v407 = v279 - v406;
    const hl_v v408 = v407 * v407;
    const hl_v v409 = v405 + v408;
    const hl_v v410 = hl_sqrt(v409);
    const hl_v v411 = 1.0 / v410;
    const hl_v v412 = hl_copysign(v411, v410);
    const hl_v v416 = v415 * v412;
    const hl_v v644 = v404 * v412;
    const hl_v v417 = v416 * v644;
    const hl_v v398 = v396 * v397;
    const hl_v v418 = v398 + v417;
    const hl_v v392 = pre[49];
    const hl_v v419 = v392 * v418;
    const hl_v v420 = v391 + v419;
    const hl_v v1 = pre[50];
    const hl_v v2 = pre[51];
    const hl_v v3 = pre[52];
    const hl_v v5 = pre[53];
    const hl_v v6 = pre[54];
    const hl_v v9 = pre[55];
    const hl_v v619 = pre[58];
    const hl_v v13 = v12 * v3;
    const hl_v v15 = v14 * v6;
    const hl_v v16 = v13 - v15;
    const hl_v v10 = pre[59];
    const hl_v v17 = v10 * v16;
    const hl_v v32 = v619 + v17;
    const hl_v v421 = v32 * v420;
    const hl_v v616 = pre[60];
    const hl_v v422 = v255 * v616;
    const hl_v v423 = v422 - v160;
    const hl_v v424 = v144 * v423;
    const hl_v v425 = hl_select(v146 != 0.0, v424, hl_splat(0.0));
    const hl_v v617 = pre[61];
    const hl_v v426 = v366 * v617;
    const hl_v v427 = v426 - v295;
    const hl_v v428 = v275 * v427;
    const hl_v v429 = hl_select(v270 != 0.0, v428, hl_splat(0.0));
    const hl_v v432 = pre[62];
    const hl_v v433 = v60 * v432;
    const hl_v v434 = pre[63];
    const hl_v v435 = v58 * v434;
    const hl_v v436 = v433 - v435;
    const hl_v v450 = v14 * v436;
    const hl_v v439 = v58 * v432;
    const hl_v v440 = v60 * v434;
    const hl_v v441 = v439 + v440;
    const hl_v v451 = v12 * v441;
    const hl_v v452 = v450 - v451;
    const hl_v v453 = v1 * v452;
    const hl_v v456 = v14 * v453;
    const hl_v v445 = v14 * v441;
    const hl_v v446 = v12 * v436;
    const hl_v v447 = v445 + v446;
    const hl_v v448 = v1 * v447;
    const hl_v v457 = v12 * v448;
    const hl_v v458 = v456 + v457;
    const hl_v v459 = v64 * v458;
    const hl_v v449 = v2 * v448;
    const hl_v v454 = v5 * v453;
    const hl_v v455 = v449 - v454;
    const hl_v v645 = pre[64];
    const hl_v v438 = v645 * v436;
    const hl_v v462 = pre[65];
    const hl_v v647 = v462 + v438;
    const hl_v v646 = pre[66];
    const hl_v v443 = v646 * v441;
    const hl_v v648 = v443 + v647;
    const hl_v v649 = v648 + v455;
    const hl_v v650 = v459 + v649;
    const hl_v v651 = v650 + v429;
    const hl_v v652 = v651 + v425;
    const hl_v v464 = v652 + v421;
    const hl_v v470 = last_torque[0];
    const hl_v v471 = pre[67];
    const hl_v v480 = v470 - v471;
    const hl_v v469 = last_torque[2];
    const hl_v v481 = hl_select(v469 != 0.0, v480, hl_splat(0.0));
    const hl_v v474 = hl_bool(v469 == 0.0);
    const hl_v v468 = pre[68];
    const hl_v v482 = pre[69];
    const hl_v v483 = hl_select(v474 != 0.0, v482, hl_splat(0.0));
    const hl_v v484 = v481 + v483;
    const hl_v v485 = hl_bool(v464 < v484);
    const hl_v v487 = hl_bool(v485 == 0.0);
    const hl_v v488 = hl_select(v487 != 0.0, v464, hl_splat(0.0));
    const hl_v v486 = hl_select(v485 != 0.0, v484, hl_splat(0.0));
    const hl_v v489 = v486 + v488;
    const hl_v v472 = v470 + v471;
    const hl_v v473 = hl_select(v469 != 0.0, v472, hl_splat(0.0));
    const hl_v v475 = hl_select(v474 != 0.0, v468, hl_splat(0.0));
    const hl_v v476 = v473 + v475;
    const hl_v v477 = hl_bool(v476 < v464);
    const hl_v v479 = hl_bool(v477 == 0.0);
    const hl_v v490 = hl_select(v479 != 0.0, v489, hl_splat(0.0));
    const hl_v v478 = hl_select(v477 != 0.0, v476, hl_splat(0.0));
    const hl_v v491 = v478 + v490;
    const hl_v v495 = hl_bool(v491 < v482);
    const hl_v v497 = hl_bool(v495 == 0.0);
    const hl_v v498 = hl_select(v497 != 0.0, v491, hl_splat(0.0));
    const hl_v v496 = hl_select(v495 != 0.0, v482, hl_splat(0.0));
    const hl_v v499 = v496 + v498;
    const hl_v v492 = hl_bool(v468 < v491);
    const hl_v v494 = hl_bool(v492 == 0.0);
    const hl_v v500 = hl_select(v494 != 0.0, v499, hl_splat(0.0));
    const hl_v v493 = hl_select(v492 != 0.0, v468, hl_splat(0.0));
    const hl_v v501 = v493 + v500;
    const hl_v v465 = hl_fabs(v464);
    const hl_v v466 = pre[70];
    const hl_v v467 = hl_bool(v465 <= v466);
    const hl_v v502 = hl_select(v467 != 0.0, v501, hl_splat(0.0));
    const hl_v v503 = hl_bool(v467 == 0.0);
    const hl_v v504 = hl_select(v503 != 0.0, v464, hl_splat(0.0));
    const hl_v v505 = v502 + v504;
    tau[0] = v505;
    const hl_v v506 = v261 * v386;
    const hl_v v507 = v279 * v388;
    const hl_v v508 = v506 + v507;
    const hl_v v509 = v33 * v508;
    const hl_v v653 = v407 * v412;
    const hl_v v512 = v416 * v653;
    const hl_v v510 = v400 * v397;
    const hl_v v513 = v510 + v512;
    const hl_v v514 = v392 * v513;
    const hl_v v515 = v509 + v514;
    const hl_v v516 = v9 * v515;
    const hl_v v517 = v261 * v423;
    const hl_v v518 = hl_select(v146 != 0.0, v517, hl_splat(0.0));
    const hl_v v519 = v279 * v427;
    const hl_v v520 = hl_select(v270 != 0.0, v519, hl_splat(0.0));
    const hl_v v523 = pre[71];
    const hl_v v654 = v523 + v455;
    const hl_v v655 = v654 + v520;
    const hl_v v656 = v655 + v518;
    const hl_v v525 = v656 + v516;
    const hl_v v529 = last_torque[1];
    const hl_v v530 = pre[72];
    const hl_v v538 = v529 - v530;
    const hl_v v539 = hl_select(v469 != 0.0, v538, hl_splat(0.0));
    const hl_v v528 = pre[73];
    const hl_v v540 = pre[74];
    const hl_v v541 = hl_select(v474 != 0.0, v540, hl_splat(0.0));
    const hl_v v542 = v539 + v541;
    const hl_v v543 = hl_bool(v525 < v542);
    const hl_v v545 = hl_bool(v543 == 0.0);
    const hl_v v546 = hl_select(v545 != 0.0, v525, hl_splat(0.0));
    const hl_v v544 = hl_select(v543 != 0.0, v542, hl_splat(0.0));
    const hl_v v547 = v544 + v546;
    const hl_v v531 = v529 + v530;
    const hl_v v532 = hl_select(v469 != 0.0, v531, hl_splat(0.0));
    const hl_v v533 = hl_select(v474 != 0.0, v528, hl_splat(0.0));
    const hl_v v534 = v532 + v533;
    const hl_v v535 = hl_bool(v534 < v525);
    const hl_v v537 = hl_bool(v535 == 0.0);
    const hl_v v548 = hl_select(v537 != 0.0, v547, hl_splat(0.0));
    const hl_v v536 = hl_select(v535 != 0.0, v534, hl_splat(0.0));
    const hl_v v549 = v536 + v548;
    const hl_v v553 = hl_bool(v549 < v540);
    const hl_v v555 = hl_bool(v553 == 0.0);
    const hl_v v556 = hl_select(v555 != 0.0, v549, hl_splat(0.0));
    const hl_v v554 = hl_select(v553 != 0.0, v540, hl_splat(0.0));
    const hl_v v557 = v554 + v556;
    const hl_v v550 = hl_bool(v528 < v549);
    const hl_v v552 = hl_bool(v550 == 0.0);
    const hl_v v558 = hl_select(v552 != 0.0, v557, hl_splat(0.0));
    const hl_v v551 = hl_select(v550 != 0.0, v528, hl_splat(0.0));
    const hl_v v559 = v551 + v558;
    const hl_v v526 = hl_fabs(v525);
    const hl_v v527 = hl_bool(v526 <= v466);
    const hl_v v560 = hl_select(v527 != 0.0, v559, hl_splat(0.0));
    const hl_v v561 = hl_bool(v527 == 0.0);
    const hl_v v562 = hl_select(v561 != 0.0, v525, hl_splat(0.0));
    const hl_v v563 = v560 + v562;
    tau[1] = v563;
    const hl_v v564 = hl_bool(v505 != v464);
    const hl_v v565 = hl_bool(v563 != v525);
    const hl_v v566 = v564 + v565;
    const hl_v v567 = hl_bool(v199 < v566);
    saturated[0] = v567;
    const hl_v v569 = hl_bool(v567 == 0.0);
    const hl_v v570 = hl_select(v569 != 0.0, v235, hl_splat(0.0));
    const hl_v v568 = hl_select(v567 != 0.0, v217, hl_splat(0.0));
    const hl_v v571 = v568 + v570;
    integrals_next[0] = v571;
    const hl_v v573 = hl_select(v569 != 0.0, v241, hl_splat(0.0));
    const hl_v v572 = hl_select(v567 != 0.0, v221, hl_splat(0.0));
    const hl_v v574 = v572 + v573;
    integrals_next[1] = v574;
    const hl_v v576 = hl_select(v569 != 0.0, v346, hl_splat(0.0));
    const hl_v v575 = hl_select(v567 != 0.0, v328, hl_splat(0.0));
    const hl_v v577 = v575 + v576;
    integrals_next[2] = v577;
    const hl_v v579 = hl_select(v569 != 0.0, v352, hl_splat(0.0));
    const hl_v v578 = hl_select(v567 != 0.0, v332, hl_splat(0.0));
    const hl_v v580 = v578 + v579;
    integrals_next[3] = v580;
    const hl_v v581 = Fc[3];
    contact_wrench[3] = v581;
    const hl_v v582 = Fc[4];
    contact_wrench[4] = v582;
    const hl_v v583 = Fc[5];
    contact_wrench[5] = v583;
    const hl_v v584 = pre[75];
    const hl_v v585 = hl_bool(v584 < v115);
    const hl_v v586 = hl_bool(v115 <= v466);
    const hl_v v587 = hl_bool((v585 != 0.0) & (v586 != 0.0));
    const hl_v v588 = hl_select(v587 != 0.0, v137, hl_splat(0.0));
    const hl_v v589 = hl_bool(v587 == 0.0);
    const hl_v v590 = hl_fabs(v66);
    const hl_v v591 = hl_fabs(v75);
    const hl_v v592 = v590 + v591;
    const hl_v v593 = hl_bool(v592 <= v466);
    const hl_v v594 = hl_bool(v593 == 0.0);
    const hl_v v595 = hl_select(v594 != 0.0, v592, hl_splat(0.0));
    const hl_v v596 = hl_select(v589 != 0.0, v595, hl_splat(0.0));
    const hl_v v597 = v588 + v596;
    frame[0] = v597;
    const hl_v v659 = v395 * v402;
    const hl_v v604 = v659 * v412;
    const hl_v v605 = v604 * v604;
    const hl_v v606 = v412 * v412;
    const hl_v v602 = v395 * v395;
    const hl_v v660 = v602 + v606;
    const hl_v v608 = v660 + v605;
    const hl_v v657 = v371 + v372;
    const hl_v v658 = v657 + v258;
    const hl_v v601 = v262 + v658;
    const hl_v v609 = v601 * v608;
    const hl_v v610 = hl_sqrt(v609);
    const hl_v v598 = pre[76];
    const hl_v v611 = v598 / v610;
    cond[0] = v611;
}

#if HL_IN_PART(2)
HL_APART __attribute__((noinline, cold)) void raibert_craig_step_lanes_exact(const hl_v *q, const hl_v *qd, const hl_v *Fc, const hl_v *integrals, const hl_v *last_torque, const hl_v *filter, const hl_v *estimate, const hl_v *t, const hl_v *yd_extra, const hl_v *yd_rate, const hl_v *target, const hl_v *pre, hl_v *tau, hl_v *integrals_next, hl_v *a, hl_v *y, hl_v *f, hl_v *saturated, hl_v *filter_next, hl_v *estimate_next, hl_v *contact_wrench, hl_v *frame, hl_v *cond) {
    raibert_craig_step_lanes_core(q, qd, Fc, integrals, last_torque, filter, estimate, t, yd_extra, yd_rate, target, pre, tau, integrals_next, a, y, f, saturated, filter_next, estimate_next, contact_wrench, frame, cond, 1, NULL);
}
#else
HL_APART __attribute__((noinline, cold)) void raibert_craig_step_lanes_exact(const hl_v *q, const hl_v *qd, const hl_v *Fc, const hl_v *integrals, const hl_v *last_torque, const hl_v *filter, const hl_v *estimate, const hl_v *t, const hl_v *yd_extra, const hl_v *yd_rate, const hl_v *target, const hl_v *pre, hl_v *tau, hl_v *integrals_next, hl_v *a, hl_v *y, hl_v *f, hl_v *saturated, hl_v *filter_next, hl_v *estimate_next, hl_v *contact_wrench, hl_v *frame, hl_v *cond);
#endif

#if HL_IN_PART(2)
HL_APART void raibert_craig_step_lanes(const hl_v *q, const hl_v *qd, const hl_v *Fc, const hl_v *integrals, const hl_v *last_torque, const hl_v *filter, const hl_v *estimate, const hl_v *t, const hl_v *yd_extra, const hl_v *yd_rate, const hl_v *target, const hl_v *pre, hl_v *tau, hl_v *integrals_next, hl_v *a, hl_v *y, hl_v *f, hl_v *saturated, hl_v *filter_next, hl_v *estimate_next, hl_v *contact_wrench, hl_v *frame, hl_v *cond) {
    hl_i odd = hl_splat(0.0) != 0.0;
    raibert_craig_step_lanes_core(q, qd, Fc, integrals, last_torque, filter, estimate, t, yd_extra, yd_rate, target, pre, tau, integrals_next, a, y, f, saturated, filter_next, estimate_next, contact_wrench, frame, cond, 0, &odd);
    if (hl_any(odd)) raibert_craig_step_lanes_exact(q, qd, Fc, integrals, last_torque, filter, estimate, t, yd_extra, yd_rate, target, pre, tau, integrals_next, a, y, f, saturated, filter_next, estimate_next, contact_wrench, frame, cond);
}
#else
HL_APART void raibert_craig_step_lanes(const hl_v *q, const hl_v *qd, const hl_v *Fc, const hl_v *integrals, const hl_v *last_torque, const hl_v *filter, const hl_v *estimate, const hl_v *t, const hl_v *yd_extra, const hl_v *yd_rate, const hl_v *target, const hl_v *pre, hl_v *tau, hl_v *integrals_next, hl_v *a, hl_v *y, hl_v *f, hl_v *saturated, hl_v *filter_next, hl_v *estimate_next, hl_v *contact_wrench, hl_v *frame, hl_v *cond);
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
        pre_step[RAIBERT_CRAIG_STEP_LANES_NPRE];
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
    raibert_craig_step_lanes_pre(blk + 29, blk + 35, blk + 43, blk + 45, blk + 76, blk + 83, blk + 86, blk + 93, blk + 99, blk + 103, blk + 128, pre_step);
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
        raibert_craig_step_lanes(x, x + 2, fc, z, last, zero, zero, tv, zero, zero, zero, pre_step, o_tau, o_integrals_next, o_a, o_y, o_f, o_saturated, o_filter_next, o_estimate_next, o_contact_wrench, o_frame, o_cond);
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

int hybrid_planar_arm_circle_raibert_cr_57176b91a5fa_closed_loop(int nruns, const double *runs, const double *tables, int n_samples, int steps_per_sample, double h, double sample_time, double singular_tol, double *metrics, int *status, int *failed_sample, double *states, double *taus, double *outputs, double *samples) {
    int g;
    for (g = 0; g < nruns; g += HL_W) {
        run_lanes(g, nruns - g < HL_W ? nruns - g : HL_W, runs, tables, n_samples, steps_per_sample, h, sample_time,
                  singular_tol, metrics, status, failed_sample, states, taus, outputs, samples);
    }
    return HYBRID_OK;
}

int hybrid_planar_arm_circle_raibert_cr_57176b91a5fa_lanes(void) {
    return HL_W;
}
#else
int hybrid_planar_arm_circle_raibert_cr_57176b91a5fa_closed_loop(int nruns, const double *runs, const double *tables, int n_samples, int steps_per_sample, double h, double sample_time, double singular_tol, double *metrics, int *status, int *failed_sample, double *states, double *taus, double *outputs, double *samples);
int hybrid_planar_arm_circle_raibert_cr_57176b91a5fa_lanes(void);
#endif
