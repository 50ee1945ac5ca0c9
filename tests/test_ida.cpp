// Cross-check of the BDF integrator against SUNDIALS IDA (an independent,
// variable-order variable-step BDF code) on the same mechanism: a four-bar
// under gravity, IDA on the index-1 form at tight tolerances.
#include <gtest/gtest.h>
#include <ida/ida.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

#include "integrator/bdf.h"
#include "mechanisms.h"
#include "multibody/constraints.h"
#include "multibody/kinematics.h"
#include "multibody/multibody_dae.h"

using namespace bdfcar;
using integ::Vec;

namespace {

// y = [q (2); v (2); lambda (1)], residual [q' - v; F(q, v, v', lambda); Phi''(q, v, v')].
int idaResidual(realtype t, N_Vector yy, N_Vector yp, N_Vector rr, void* user) {
  auto* dae = static_cast<mb::MultibodyDae*>(user);
  const int nv = dae->sizes().nv, nc = dae->sizes().nc;
  const double* y = N_VGetArrayPointer(yy);
  const double* yd = N_VGetArrayPointer(yp);
  double* r = N_VGetArrayPointer(rr);
  const Vec q = Eigen::Map<const Vec>(y, nv), v = Eigen::Map<const Vec>(y + nv, nv);
  const Vec lam = Eigen::Map<const Vec>(y + 2 * nv, nc);
  const Vec qd = Eigen::Map<const Vec>(yd, nv), a = Eigen::Map<const Vec>(yd + nv, nv);
  integ::Residual res;
  res.resize(dae->sizes());
  integ::Message msg;
  if (dae->residual(t, q, v, a, lam, res, true, msg) != integ::EvalStatus::Ok) return 1;
  Eigen::Map<Vec>(r, nv) = qd - v;
  Eigen::Map<Vec>(r + nv, nv) = res.F;
  Eigen::Map<Vec>(r + 2 * nv, nc) = res.phiDDot;
  return 0;
}

}  // namespace

TEST(CrossCheck, BdfAgreesWithSundialsIdaOnFourBarUnderGravity) {
  test::FourBar fb = test::fourBar(0.1, 0.35, 0.25, 0.3, 1.2);
  fb.model.gravity = Eigen::Vector3d(0, 0, -9.81);  // stand it up
  mb::MultibodyDae dae(fb.model);
  const int nv = 2, nc = 1, n = 2 * nv + nc;

  // Consistent initial state (q, v on the constraint manifolds).
  Vec q = mb::neutralPositions(fb.model), v(2);
  mb::Data d = mb::makeData(fb.model);
  mb::updatePositions(fb.model, q, d);
  Eigen::MatrixXd J(1, 2);
  mb::constraintJacobian(fb.model, d, J);
  v << 12.0, -12.0 * J(0, 0) / J(0, 1);

  // IDA at tight tolerance: the reference trajectory at four output times.
  integ::BdfOptions o;
  o.order = 3;
  o.newtonIterations = 0;
  o.atol = 1e-13;
  o.jacobianEvery = 1;
  o.rtol = 1e-11;
  integ::Message msg;
  Vec a0, lam0;
  {
    integ::BdfIntegrator init(dae, o);
    ASSERT_EQ(init.initialize(0, q, v, msg), integ::EvalStatus::Ok);
    a0 = init.current().a;
    lam0 = init.current().lambda;
  }
  SUNContext ctx;
  ASSERT_EQ(SUNContext_Create(nullptr, &ctx), 0);
  N_Vector yy = N_VNew_Serial(n, ctx), yp = N_VNew_Serial(n, ctx);
  double* y = N_VGetArrayPointer(yy);
  double* ydot = N_VGetArrayPointer(yp);
  for (int i = 0; i < nv; ++i) {
    y[i] = q(i);
    y[nv + i] = v(i);
    ydot[i] = v(i);
    ydot[nv + i] = a0(i);
  }
  y[2 * nv] = lam0(0);
  ydot[2 * nv] = 0;
  void* mem = IDACreate(ctx);
  ASSERT_EQ(IDAInit(mem, idaResidual, 0.0, yy, yp), IDA_SUCCESS);
  ASSERT_EQ(IDASStolerances(mem, 1e-12, 1e-13), IDA_SUCCESS);
  SUNMatrix A = SUNDenseMatrix(n, n, ctx);
  SUNLinearSolver LS = SUNLinSol_Dense(yy, A, ctx);
  ASSERT_EQ(IDASetLinearSolver(mem, LS, A), IDA_SUCCESS);
  ASSERT_EQ(IDASetUserData(mem, &dae), IDA_SUCCESS);
  ASSERT_EQ(IDASetMaxNumSteps(mem, 1000000), IDA_SUCCESS);
  // lambda is algebraic: keep it out of the local error test.
  N_Vector id = N_VNew_Serial(n, ctx);
  for (int i = 0; i < n; ++i) N_VGetArrayPointer(id)[i] = i < 2 * nv ? 1.0 : 0.0;
  ASSERT_EQ(IDASetId(mem, id), IDA_SUCCESS);
  ASSERT_EQ(IDASetSuppressAlg(mem, SUNTRUE), IDA_SUCCESS);
  const std::vector<double> outputs = {0.25, 0.5, 0.75, 1.0};
  std::vector<Vec> ref;
  double minQ = 0, maxQ = 0;
  for (double tout : outputs) {
    realtype tret;
    ASSERT_GE(IDASolve(mem, tout, &tret, yy, yp, IDA_NORMAL), 0);
    ref.push_back(Eigen::Map<const Vec>(y, 2 * nv));
    minQ = std::min(minQ, y[0]);
    maxQ = std::max(maxQ, y[0]);
  }
  // Our BDF3 at two step sizes: the largest difference to IDA over the outputs.
  auto difference = [&](double h) {
    integ::BdfIntegrator bdf(dae, o);
    integ::Message m2;
    EXPECT_EQ(bdf.initialize(0, q, v, m2), integ::EvalStatus::Ok);
    double worst = 0;
    for (size_t k = 0; k < outputs.size(); ++k) {
      while (bdf.current().t < outputs[k] - 0.5 * h) EXPECT_TRUE(bdf.step(h).ok());
      const Vec mine = (Vec(2 * nv) << bdf.current().q, bdf.current().v).finished();
      worst = std::max(worst, (mine - ref[k]).lpNorm<Eigen::Infinity>());
    }
    return worst;
  };
  const double coarse = difference(2.5e-4), fine = difference(1.25e-4);
  // A real motion: the crank swings through more than half a radian.
  EXPECT_GT(maxQ - minQ, 0.5);
  // The two codes agree, and the difference falls at third order (x8 per halving):
  // it is our truncation error, not a disagreement about the model.
  EXPECT_LT(fine, 3e-6) << "largest angle / rate difference to IDA";
  EXPECT_GT(coarse / fine, 6.0) << "coarse " << coarse << " fine " << fine;
  N_VDestroy(id);
  IDAFree(&mem);
  SUNLinSolFree(LS);
  SUNMatDestroy(A);
  N_VDestroy(yy);
  N_VDestroy(yp);
  SUNContext_Free(&ctx);
}
