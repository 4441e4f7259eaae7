// exploratory
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <ctime>

#include "../support/ibm_couette_flow.hpp"

namespace rfmems {
namespace {
using namespace rfmems::test;

double cpu() { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }

TEST(IbmCouetteSecondOrder, Explore) {
  const Real kn = std::atof(std::getenv("KN"));
  const int m = std::atoi(std::getenv("M"));
  const int nv = std::atoi(std::getenv("NV"));
  const TransportOrder order =
      std::getenv("FIRST") ? TransportOrder::FirstOrder : TransportOrder::SecondOrder;
  double t0 = cpu();
  if (!std::getenv("NOBF")) {
    const Profile bf = body_fitted(kn, m, nv, order);
    std::printf("BF %s kn %g m %d nv %d: shear %.8e conv %d sweeps %d cpu %.2f\n",
                transport_order_name(order), kn, m, nv, bf.plate_shear, bf.converged,
                bf.iterations, cpu() - t0);
  }
  t0 = cpu();
  const Profile ib = immersed(kn, m, nv, order);
  std::printf("IB %s kn %g m %d nv %d: shear %.8e conv %d sweeps %d cpu %.2f\n",
              transport_order_name(order), kn, m, nv, ib.plate_shear, ib.converged, ib.iterations,
              cpu() - t0);
}

}  // namespace
}  // namespace rfmems
