// The 6-D decoupling law F* and one control sample on a sphere, written by hand in C++ on Pinocchio +
// Eigen: what the benchmarks compare hybrid's generated C with (python -m hybrid bench; built and run by
// hybrid/bench/eigen_race.py). The equations are docs/conventions.md's (sections 4, 9 and 11), the
// same as hybrid's generated decoupling_law and controller_step compute, written the way a roboticist
// would on these libraries: Pinocchio's algorithms for the robot's terms, the task frame of the sphere
// and its rate in closed form, fixed-size Eigen matrices and Cholesky (LLT) or LU solves; no heap memory
// after the model and its data are built.
//
// Each part is a function of its own, never inlined in the build whose instructions are counted (HAND_COUNTED
// defined), so that the counts split by part; the timed build inlines as the compiler sees fit:
//
//   kinematics    forwardKinematics at q'' = 0, the tip's placement, computeJointJacobians,
//                 getFrameJacobian and getFrameClassicalAcceleration (LOCAL_WORLD_ALIGNED): J, J' q', v
//   dynamics      crba (B, upper triangle mirrored) and nonLinearEffects (n), the joints' friction added
//                 (each pass computes the joints' kinematics again: Pinocchio's computeAllTerms, one pass
//                 that also computes the centroidal terms, counts 15 % more instructions on the UR5)
//   sphere_frame  R_L (rows t1, t2, n) at the tip and its rate R_L' along the tip's velocity
//   operational   F* = Lambda (R^T (a - R' v) - J' q') + Jbar^T n - F_c, tau = J^T F* + (I - J^T Jbar^T) tau0
//                 through the Cholesky factors of B and of Lambda^-1 = J B^-1 J^T
//   inverse_dynamics  a square arm's (six joints) alternative: q''* = J^-1 (R^T (a - R' v) - J' q') by LU,
//                 tau = rnea(q, q', q''*) + friction - J^T F_c, F* = J^-T tau (no B at all)
//   conditioning  the guard 6 / (|J|_F |J^+|_F), |J^+|_F^2 = trace((J J^T)^-1)
//   loops         the six task-frame loops (PI^2 on velocity axes, impedance and integral on force axes)
//   limits        the torque's rate and magnitude limits (a bounded torque keeps the integrals)

#pragma once

#include "pinocchio/algorithm/crba.hpp"
#include "pinocchio/algorithm/frames.hpp"
#include "pinocchio/algorithm/jacobian.hpp"
#include "pinocchio/algorithm/kinematics.hpp"
#include "pinocchio/algorithm/rnea.hpp"

#include <Eigen/Cholesky>
#include <Eigen/LU>

#include <cfloat>
#include <cmath>

#ifdef HAND_COUNTED
#define HAND_PART __attribute__((noinline)) inline
#else
#define HAND_PART inline
#endif

namespace hand
{
  // the statuses of hybrid's generated functions
  enum Status
  {
    OK = 0,
    SINGULAR = 1,
    NONFINITE = 2,
    FRAME_UNDEFINED = 3
  };
  // below this |e x n| the task frame is undefined (hybrid's FRAME_TOL)
  constexpr double FRAME_TOL = 1e-6;

  typedef Eigen::Vector3d Vec3;
  typedef Eigen::Matrix3d Mat3;
  typedef Eigen::Matrix<double, 6, 1> Vec6;
  typedef Eigen::Matrix<double, 6, 6> Mat6;

  // the options array of the controller step (hybrid.spec.controller_step.OPTIONS)
  enum Option
  {
    CURVATURE = 0,
    SAMPLE_TIME = 1,
    KHATIB = 2,
    INTEGRAL_LIMIT = 3,
    LOSS_THRESHOLD = 4,
    APPROACH_SPEED = 5
  };

  template<int N>
  struct Arm
  {
    typedef Eigen::Matrix<double, N, 1> VecN;

    Arm(const pinocchio::Model & model, pinocchio::FrameIndex tip)
    : model(model)
    , data(model)
    , tip(tip)
    {
    }

    pinocchio::Model model;
    pinocchio::Data data;
    pinocchio::FrameIndex tip;
    // the joints' friction F_v q' + F_c tanh(q' / v_s) + tau_0 (conventions section 9)
    VecN damping, coulomb, offset, coulomb_speed;
    // a zero joint acceleration, for the kinematic pass at q'' = 0
    VecN zero = VecN::Zero();
  };

  // what the robot gives at (q, q'): the tip's position and twist, J, J' q', and (for the operational
  // form) B and n
  template<int N>
  struct Terms
  {
    Vec3 p;
    Vec6 v, Jdqd;
    Eigen::Matrix<double, 6, N> J = Eigen::Matrix<double, 6, N>::Zero();
    Eigen::Matrix<double, N, N> B;
    Eigen::Matrix<double, N, 1> n;
  };

  template<int N>
  using ConstVec = Eigen::Map<const Eigen::Matrix<double, N, 1>>;

  template<int N>
  inline Eigen::Matrix<double, N, 1> friction(const Arm<N> & arm, const ConstVec<N> & qd)
  {
    Eigen::Matrix<double, N, 1> tau = arm.damping.cwiseProduct(qd) + arm.offset;
    for (int i = 0; i < N; ++i)
      if (arm.coulomb[i] != 0.0) // no Coulomb friction on the joint: no tanh to take
        tau[i] += arm.coulomb[i] * std::tanh(qd[i] / arm.coulomb_speed[i]);
    return tau;
  }

  template<int N>
  HAND_PART void kinematics(Arm<N> & arm, const ConstVec<N> & q, const ConstVec<N> & qd, Terms<N> & t)
  {
    pinocchio::forwardKinematics(arm.model, arm.data, q, qd, arm.zero);
    t.p = pinocchio::updateFramePlacement(arm.model, arm.data, arm.tip).translation();
    pinocchio::computeJointJacobians(arm.model, arm.data);
    pinocchio::getFrameJacobian(arm.model, arm.data, arm.tip, pinocchio::LOCAL_WORLD_ALIGNED, t.J);
    t.Jdqd = pinocchio::getFrameClassicalAcceleration(
               arm.model, arm.data, arm.tip, pinocchio::LOCAL_WORLD_ALIGNED)
               .toVector();
    t.v.noalias() = t.J * qd;
  }

  template<int N>
  HAND_PART void dynamics(Arm<N> & arm, const ConstVec<N> & q, const ConstVec<N> & qd, Terms<N> & t)
  {
    pinocchio::crba(arm.model, arm.data, q);
    t.B = arm.data.M;
    t.B.template triangularView<Eigen::StrictlyLower>() = t.B.transpose(); // crba fills the upper triangle
    t.n = pinocchio::nonLinearEffects(arm.model, arm.data, q, qd) + friction(arm, qd);
  }

  // R_L (rows t1, t2, n) at p on the sphere (centre, radius) = surface and its rate along p' (conventions
  // section 9, differentiated by hand): n = (p - c) / |p - c|, n' = (I - n n^T) p' / |p - c|,
  // t1 = e x n / |e x n|, t1' = (I - t1 t1^T) (e x n') / |e x n|, t2 = n x t1, t2' = n' x t1 + n x t1'.
  // Returns |e x n|, 0 where the point has no normal (the sphere's centre).
  HAND_PART double sphere_frame(const Vec3 & p, const Vec3 & pd, const double * surface,
                                       const double * e_in, Mat3 & R, Mat3 & Rd)
  {
    const Vec3 d = p - Vec3(surface[0], surface[1], surface[2]);
    const double distance = d.norm();
    const Vec3 n = d / distance;
    const Vec3 nd = (pd - n * n.dot(pd)) / distance;
    const Vec3 e = Vec3(e_in[0], e_in[1], e_in[2]).normalized();
    const Vec3 c = e.cross(n);
    const double sine = c.norm();
    const Vec3 t1 = c / sine;
    Vec3 t1d = e.cross(nd);
    t1d = (t1d - t1 * t1.dot(t1d)) / sine;
    R.row(0) = t1;
    R.row(1) = n.cross(t1);
    R.row(2) = n;
    Rd.row(0) = t1d;
    Rd.row(1) = nd.cross(t1) + n.cross(t1d);
    Rd.row(2) = nd;
    return distance > 0.0 ? sine : 0.0;
  }

  // the task acceleration in base axes, R^T (a - kappa R' v) - J' q' (R = diag(R_L, R_L))
  inline Vec6 acceleration(const Mat3 & R, const Mat3 & Rd, const double * a_in, const Vec6 & v,
                           const Vec6 & Jdqd, double curvature)
  {
    Vec6 a = Eigen::Map<const Vec6>(a_in);
    if (curvature != 0.0)
    {
      a.head<3>() -= curvature * (Rd * v.head<3>());
      a.tail<3>() -= curvature * (Rd * v.tail<3>());
    }
    Vec6 b;
    b.head<3>().noalias() = R.transpose() * a.head<3>();
    b.tail<3>().noalias() = R.transpose() * a.tail<3>();
    return b - Jdqd;
  }

  // L^-1 X in place for the Cholesky factor L of a matrix, X's columns one by one: Eigen solves a matrix
  // right-hand side by its blocked path even at fixed sizes (about 1.5 times the instructions here)
  template<typename Factor, typename Matrix>
  inline void lower_solve(const Factor & factor, Matrix & X)
  {
    for (int j = 0; j < X.cols(); ++j)
      factor.matrixL().solveInPlace(X.col(j));
  }

  // F* = Lambda b + Jbar^T n - F_c and tau = J^T F* + (I - J^T Jbar^T) tau0 with B = L L^T,
  // Y = L^-1 J^T, Lambda^-1 = Y^T Y: Jbar^T n = Lambda Y^T L^-1 n (tau0 may be null: zero)
  template<int N>
  HAND_PART void operational(const Terms<N> & t, const Vec6 & b, const Vec6 & Fc, const double * tau0,
                             Vec6 & F, Eigen::Matrix<double, N, 1> & tau)
  {
    const Eigen::LLT<Eigen::Matrix<double, N, N>> B(t.B);
    Eigen::Matrix<double, N, 6> Y = t.J.transpose();
    lower_solve(B, Y);
    const Eigen::LLT<Mat6> inverse_Lambda(Y.transpose() * Y);
    const Eigen::Matrix<double, N, 1> u = B.matrixL().solve(t.n);
    F = inverse_Lambda.solve(b + Y.transpose() * u) - Fc;
    tau.noalias() = t.J.transpose() * F;
    if (tau0)
    {
      const ConstVec<N> tau_0(tau0);
      const Vec6 g = inverse_Lambda.solve(Y.transpose() * B.matrixL().solve(tau_0));
      tau += tau_0 - t.J.transpose() * g;
    }
  }

  // a square arm's law by inverse dynamics: q''* = J^-1 b, tau = B q''* + n - J^T F_c by RNEA,
  // F* = J^-T tau
  template<int N>
  HAND_PART void inverse_dynamics(Arm<N> & arm, const ConstVec<N> & q, const ConstVec<N> & qd,
                                  const Terms<N> & t, const Vec6 & b, const Vec6 & Fc, Vec6 & F,
                                  Eigen::Matrix<double, N, 1> & tau)
  {
    static_assert(N == 6, "the inverse-dynamics form needs a square Jacobian");
    const Eigen::PartialPivLU<Mat6> J(t.J);
    const Vec6 qdd = J.solve(b);
    tau = pinocchio::rnea(arm.model, arm.data, q, qd, qdd) + friction(arm, qd);
    tau.noalias() -= t.J.transpose() * Fc;
    F = J.transpose().solve(tau);
  }

  // 6 / (|J|_F |J^+|_F): 1 when J's singular values are equal, 0 at a rank loss
  template<int N>
  HAND_PART double conditioning(const Eigen::Matrix<double, 6, N> & J)
  {
    const Eigen::LLT<Mat6> JJt(J * J.transpose());
    Mat6 inverse_L = Mat6::Identity();
    lower_solve(JJt, inverse_L);
    return 6.0 / std::sqrt(J.squaredNorm() * inverse_L.squaredNorm());
  }

  template<int N>
  inline bool finite(const Eigen::Matrix<double, N, 1> & x)
  {
    bool ok = true;
    for (int i = 0; i < N; ++i)
      ok &= std::isfinite(x[i]);
    return ok;
  }

  // the forms of the law: the operational-space one (any arm), inverse dynamics (a square arm)
  enum Form
  {
    OPERATIONAL,
    INVERSE_DYNAMICS
  };

  template<int N, Form form>
  inline void law_terms(Arm<N> & arm, const ConstVec<N> & q, const ConstVec<N> & qd, Terms<N> & t)
  {
    kinematics(arm, q, qd, t);
    if (form == OPERATIONAL)
      dynamics(arm, q, qd, t);
  }

  template<int N, Form form>
  inline void law_of(Arm<N> & arm, const ConstVec<N> & q, const ConstVec<N> & qd, const Terms<N> & t,
                     const Vec6 & b, const Vec6 & Fc, const double * tau0, Vec6 & F,
                     Eigen::Matrix<double, N, 1> & tau)
  {
    if constexpr (form == INVERSE_DYNAMICS)
      inverse_dynamics(arm, q, qd, t, b, Fc, F, tau); // a square arm's torque has no null space: tau0 none
    else
      operational(t, b, Fc, tau0, F, tau);
  }

  // the decoupling law: hybrid's decoupling_law (its inputs and outputs; the same status)
  template<int N, Form form>
  int decoupling_law(Arm<N> & arm, const double * q_in, const double * qd_in, const double * a,
                     const double * Fc_in, const double * tau0, const double * surface, const double * e,
                     double curvature, double singular_tol, double * F_out, double * tau_out)
  {
    const ConstVec<N> q(q_in), qd(qd_in);
    Terms<N> t;
    law_terms<N, form>(arm, q, qd, t);
    Mat3 R, Rd;
    const double sine = sphere_frame(t.p, t.v.template head<3>(), surface, e, R, Rd);
    const Vec6 b = acceleration(R, Rd, a, t.v, t.Jdqd, curvature);
    Vec6 F;
    Eigen::Matrix<double, N, 1> tau;
    law_of<N, form>(arm, q, qd, t, b, Eigen::Map<const Vec6>(Fc_in), tau0, F, tau);
    const double cond = conditioning<N>(t.J);
    Eigen::Map<Vec6>{F_out} = F;
    Eigen::Map<Eigen::Matrix<double, N, 1>>{tau_out} = tau;
    if (std::fabs(sine) < FRAME_TOL)
      return FRAME_UNDEFINED;
    if (std::fabs(cond) < singular_tol)
      return SINGULAR;
    return finite<6>(F) && finite<N>(tau) && std::isfinite(sine) && std::isfinite(cond) ? OK : NONFINITE;
  }

  // the six loops in the task frame (conventions section 4, hybrid's codegen/controller_step.py): a per
  // axis and the integrals after the sample
  HAND_PART void loops(const Vec6 & y, const Vec6 & f, const Vec6 & yd, const double * yd_rate,
                              const double * z, const double * gains, const double * selection,
                              const double * options, Vec6 & a, double * z_next)
  {
    const double T = options[SAMPLE_TIME], limit = options[INTEGRAL_LIMIT];
    const double loss = options[LOSS_THRESHOLD], approach = options[APPROACH_SPEED];
    for (int i = 0; i < 6; ++i)
    {
      const double KP = gains[4 * i], KI = gains[4 * i + 1], KI2 = gains[4 * i + 2], KD = gains[4 * i + 3];
      const double z1 = z[2 * i], z2 = z[2 * i + 1];
      if (selection[i] != 0.0)
      { // force axis: impedance and integral; out of contact, approach with the integral kept in step
        const double e = yd[i] - f[i];
        const bool lost = f[i] < loss;
        double z1n = z1 + T * e;
        if (lost || std::fabs(KI * z1n) > limit)
          z1n = z1;
        if (lost && KI != 0.0)
          z1n = (KD * approach - KP * e) / KI - T * e;
        a[i] = lost ? -KD * (y[i] + approach) : -KP * e - KD * y[i] - KI * z1n;
        z_next[2 * i] = z1n;
        z_next[2 * i + 1] = 0.0;
      }
      else
      { // velocity axis: PI^2 with feedforward, conditional integration
        const double e = yd[i] - y[i];
        double z1n = z1 + T * e, z2n = z2 + T * z1n;
        if (std::fabs(KI * z1n + KI2 * z2n) > limit)
        {
          z1n = z1;
          z2n = z2;
        }
        a[i] = yd_rate[i] + KP * e + KI * z1n + KI2 * z2n;
        z_next[2 * i] = z1n;
        z_next[2 * i + 1] = z2n;
      }
    }
  }

  // the torque within its rate limit (once a torque was written) and its magnitude limit; whether one
  // bounded it
  template<int N>
  HAND_PART bool limits(const Eigen::Matrix<double, N, 1> & tau, const double * last, const double * bounds,
                        double * out)
  {
    const bool started = last[N] != 0.0;
    bool saturated = false;
    for (int j = 0; j < N; ++j)
    {
      const double tau_max = bounds[j], rate = bounds[N + j];
      const double lo = started ? last[j] - rate : -tau_max, hi = started ? last[j] + rate : tau_max;
      double x = tau[j];
      if (std::fabs(x) <= DBL_MAX) // a torque that is not finite stays as it is (and is reported so)
      {
        x = x > hi ? hi : (x < lo ? lo : x);
        x = x > tau_max ? tau_max : (x < -tau_max ? -tau_max : x);
      }
      saturated |= x != tau[j];
      out[j] = x;
    }
    return saturated;
  }

  // the step's inputs fixed between samples (hybrid's controller_step's parameters)
  struct StepConfig
  {
    const double *steps, *gains, *selection, *surface, *e, *options, *limits;
    double singular_tol;
  };

  // the step's outputs (hybrid's controller_step's; the filter's and the estimate's states are zero
  // without a force/torque sensor or an estimated surface)
  template<int N>
  struct StepOut
  {
    double tau[N], integrals_next[12], a[6], y[6], f[6], saturated, contact_wrench[6];
  };

  // one control sample: measurement, the loops, the law, the limits (hybrid's controller_step on a
  // sphere, the task frame at the tip, no position error, the wrench as measured)
  template<int N, Form form>
  int controller_step(Arm<N> & arm, const StepConfig & c, const double * q_in, const double * qd_in,
                      const double * Fc_in, const double * integrals, const double * last_torque, double t,
                      const double * yd_extra, const double * yd_rate, StepOut<N> & out)
  {
    const ConstVec<N> q(q_in), qd(qd_in);
    const Eigen::Map<const Vec6> Fc(Fc_in);
    Terms<N> terms;
    law_terms<N, form>(arm, q, qd, terms);
    Mat3 R, Rd;
    const double sine = sphere_frame(terms.p, terms.v.template head<3>(), c.surface, c.e, R, Rd);
    Vec6 y, f, yd, a;
    y << R * terms.v.template head<3>(), R * terms.v.template tail<3>();
    f << R * Fc.head<3>(), R * Fc.tail<3>();
    for (int i = 0; i < 6; ++i)
      yd[i] = (t >= c.steps[3 * i + 2] ? c.steps[3 * i + 1] : c.steps[3 * i]) + yd_extra[i];
    double z_next[12];
    loops(y, f, yd, yd_rate, integrals, c.gains, c.selection, c.options, a, z_next);
    Vec6 contact = Fc;
    if (c.options[KHATIB] != 0.0) // Khatib's scheme: the desired force R^T Sigma F_d in place of F_c
    {
      const Vec6 desired = yd.cwiseProduct(Eigen::Map<const Vec6>(c.selection));
      contact << R.transpose() * desired.head<3>(), R.transpose() * desired.tail<3>();
    }
    const Vec6 b = acceleration(R, Rd, a.data(), terms.v, terms.Jdqd, c.options[CURVATURE]);
    Vec6 F;
    Eigen::Matrix<double, N, 1> tau;
    law_of<N, form>(arm, q, qd, terms, b, contact, nullptr, F, tau);
    const double cond = conditioning<N>(terms.J);
    out.saturated = limits<N>(tau, last_torque, c.limits, out.tau);
    for (int i = 0; i < 12; ++i)
      out.integrals_next[i] = out.saturated ? integrals[i] : z_next[i];
    for (int i = 0; i < 6; ++i)
    {
      out.a[i] = a[i];
      out.y[i] = y[i];
      out.f[i] = f[i];
      out.contact_wrench[i] = Fc[i];
    }
    if (std::fabs(sine) < FRAME_TOL)
      return FRAME_UNDEFINED;
    if (std::fabs(cond) < c.singular_tol)
      return SINGULAR;
    bool ok = std::isfinite(sine) && std::isfinite(cond) && std::isfinite(out.saturated);
    for (double x : out.tau)
      ok &= std::isfinite(x);
    for (double x : out.integrals_next)
      ok &= std::isfinite(x);
    return ok && finite<6>(a) && finite<6>(y) && finite<6>(f) && finite<6>(Fc) ? OK : NONFINITE;
  }
} // namespace hand
