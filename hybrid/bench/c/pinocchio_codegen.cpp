// Pinocchio's own code generation (CppADCodeGen) for a serial arm: the C sources the benchmarks compare
// the generated dynamics with (python -m hybrid bench; hybrid/bench/pinocchio_codegen.py builds this program).
//
//   pinocchio_codegen URDF FOLDER TIP JOINT...
//
// reads the URDF, holds every joint not named among JOINT... at its neutral position (as
// hybrid.Robot.from_urdf keeps the chain to TIP), and writes into FOLDER the zero-order forward
// sources of four functions, each of one input vector x and one output vector y:
//
//   rnea   x = (q, v, a)    y = tau                           (pinocchio::rnea; CodeGenRNEA)
//   aba    x = (q, v, tau)  y = ddq                           (pinocchio::aba; CodeGenABA)
//   crba   x = q            y = M(i, j), i <= j, row by row   (pinocchio::crba; CodeGenCRBA)
//   terms  x = (q, v)       y = (p, R, J, J'v, M, nle)        (below: what hybrid's robot_terms returns)
//
// Pinocchio ships code generators for the first three; "terms" is built the same way (a CodeGenBase)
// from Pinocchio's algorithms: the tip frame's placement (R row-major), its Jacobian and classical
// acceleration in LOCAL_WORLD_ALIGNED (linear rows first; J row-major), the joint-space inertia
// (row-major, whole) and the nonlinear effects. The sources are C; the benchmark compiles them.

#include "pinocchio/codegen/cppadcg-algo.hpp"  // first: it declares the CppAD scalar's traits

#include <cppad/cg/model/save_files_model_library_processor.hpp>

#include "pinocchio/algorithm/frames.hpp"
#include "pinocchio/algorithm/jacobian.hpp"
#include "pinocchio/algorithm/kinematics.hpp"
#include "pinocchio/algorithm/model.hpp"
#include "pinocchio/parsers/urdf.hpp"

#include <algorithm>
#include <iostream>
#include <string>
#include <vector>

namespace
{
  typedef double Scalar;
  typedef pinocchio::ModelTpl<Scalar> Model;

  // The tip frame's placement, Jacobian and classical acceleration, the inertia and the nonlinear effects.
  struct CodeGenTerms : public pinocchio::CodeGenBase<Scalar>
  {
    typedef pinocchio::CodeGenBase<Scalar> Base;

    CodeGenTerms(const Model & model, const pinocchio::FrameIndex tip)
    : Base(model, model.nq + model.nv, 3 + 9 + 7 * model.nv + 6 + model.nv * model.nv, "terms", "cg_terms_eval")
    , tip(tip)
    {
      Base::build_jacobian = false;
    }

    void buildMap()
    {
      CppAD::Independent(ad_X);
      const Eigen::Index nq = ad_model.nq, nv = ad_model.nv;
      const ADConfigVectorType q = ad_X.head(nq);
      const ADTangentVectorType v = ad_X.segment(nq, nv);

      pinocchio::forwardKinematics(ad_model, ad_data, q, v, ADTangentVectorType::Zero(nv));
      pinocchio::computeJointJacobians(ad_model, ad_data);
      pinocchio::updateFramePlacement(ad_model, ad_data, tip);
      ADMatrixXs J = ADMatrixXs::Zero(6, nv);
      pinocchio::getFrameJacobian(ad_model, ad_data, tip, pinocchio::LOCAL_WORLD_ALIGNED, J);
      const auto acc = pinocchio::getFrameClassicalAcceleration(
        ad_model, ad_data, tip, pinocchio::LOCAL_WORLD_ALIGNED);
      pinocchio::crba(ad_model, ad_data, q, pinocchio::Convention::WORLD);
      pinocchio::nonLinearEffects(ad_model, ad_data, q, v);

      Eigen::Index k = 0;
      const auto & placement = ad_data.oMf[tip];
      for (Eigen::Index i = 0; i < 3; ++i)
        ad_Y[k++] = placement.translation()[i];
      for (Eigen::Index i = 0; i < 3; ++i)
        for (Eigen::Index j = 0; j < 3; ++j)
          ad_Y[k++] = placement.rotation()(i, j);
      for (Eigen::Index i = 0; i < 6; ++i)
        for (Eigen::Index j = 0; j < nv; ++j)
          ad_Y[k++] = J(i, j);
      for (Eigen::Index i = 0; i < 3; ++i)
        ad_Y[k++] = acc.linear()[i];
      for (Eigen::Index i = 0; i < 3; ++i)
        ad_Y[k++] = acc.angular()[i];
      for (Eigen::Index i = 0; i < nv; ++i)  // crba fills the upper triangle
        for (Eigen::Index j = 0; j < nv; ++j)
          ad_Y[k++] = i <= j ? ad_data.M(i, j) : ad_data.M(j, i);
      for (Eigen::Index i = 0; i < nv; ++i)
        ad_Y[k++] = ad_data.nle[i];

      ad_fun.Dependent(ad_X, ad_Y);
      ad_fun.optimize("no_compare_op");
    }

    const pinocchio::FrameIndex tip;
  };

  // The function's value alone (no derivatives), its sources written to folder.
  template<typename Generator>
  void write_sources(Generator & generator, const std::string & folder)
  {
    generator.build_jacobian_off();
    generator.initLib();
    CppAD::cg::ModelLibraryCSourceGen<Scalar> library(generator.codeGenerator());
    CppAD::cg::SaveFilesModelLibraryProcessor<Scalar>::saveLibrarySourcesTo(library, folder);
  }

  // Pinocchio's generators with their Jacobians off (the benchmark times the value alone).
  template<typename Generator>
  struct ValueOnly : public Generator
  {
    template<typename... Args>
    explicit ValueOnly(Args &&... args)
    : Generator(std::forward<Args>(args)...)
    {
    }

    void build_jacobian_off()
    {
      Generator::build_jacobian = false;
    }
  };
} // namespace

int main(int argc, char ** argv)
{
  if (argc < 5)
  {
    std::cerr << "usage: " << argv[0] << " URDF FOLDER TIP JOINT...\n";
    return 2;
  }
  const std::string urdf = argv[1], folder = argv[2], tip_name = argv[3];
  const std::vector<std::string> chain(argv + 4, argv + argc);

  Model full;
  pinocchio::urdf::buildModel(urdf, full);
  std::vector<pinocchio::JointIndex> locked;
  for (pinocchio::JointIndex j = 1; j < (pinocchio::JointIndex)full.njoints; ++j)
    if (std::find(chain.begin(), chain.end(), full.names[j]) == chain.end())
      locked.push_back(j);
  const Model model = pinocchio::buildReducedModel(full, locked, pinocchio::neutral(full));
  if (model.nq != (int)chain.size() || model.nv != (int)chain.size() || !model.existFrame(tip_name))
  {
    std::cerr << urdf << ": the joints named are not " << chain.size()
              << " one-degree-of-freedom joints of a model with the frame " << tip_name << "\n";
    return 1;
  }

  ValueOnly<pinocchio::CodeGenRNEA<Scalar>> rnea(model);
  ValueOnly<pinocchio::CodeGenABA<Scalar>> aba(model);
  ValueOnly<pinocchio::CodeGenCRBA<Scalar>> crba(model);
  ValueOnly<CodeGenTerms> terms(model, model.getFrameId(tip_name));
  write_sources(rnea, folder);
  write_sources(aba, folder);
  write_sources(crba, folder);
  write_sources(terms, folder);
  return 0;
}
