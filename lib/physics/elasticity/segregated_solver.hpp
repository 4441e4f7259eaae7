// The segregated baseline (thesis "Formulation 1"; Demirdzic & Muzaferija 1994, Jasak & Weller
// 2000): each displacement component is solved with only its primary Laplacian part implicit,
//
//   A_k du_k = -alpha R_k(u),   u <- u + du,
//
// where A_k holds kappa (e.S)/|d| per face and R is the full residual, so the transpose and
// trace terms and the non-orthogonal corrections are lagged (explicit). kappa = mu is the
// classical choice; kappa = 2 mu + lambda (Jasak & Weller) converges faster. The A_k are
// factorised once with KLU and reused: the fairest version of this method.
#pragma once
#include <vector>

#include "physics/elasticity/elasticity_operator.hpp"

namespace rfmems {

struct SegregatedOptions {
  enum class Diffusivity { Mu, TwoMuPlusLambda };
  Diffusivity diffusivity = Diffusivity::TwoMuPlusLambda;
  Real relaxation = 1.0;           // alpha
  Real relative_tolerance = 1e-8;  // on ||R||_inf / ||R(u0)||_inf
  int max_outer_iterations = 100000;
};

struct SegregatedStats {
  long outer_iterations = 0;
  Real initial_residual = 0, final_residual = 0;
  bool converged = false;
};

// Solves R(t, u) = 0 from u (overwritten).
SegregatedStats solve_segregated(ElasticityOperator& op, Real t, std::vector<Real>& u,
                                 const SegregatedOptions& options);

}  // namespace rfmems
