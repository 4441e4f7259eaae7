// Basic numeric types shared by every module.
#pragma once
#include <Eigen/Dense>
#include <cstdint>

namespace rfmems {

using Real = double;
// 64-bit, matching SUNDIALS' sunindextype on Debian.
using Index = std::int64_t;

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;

}  // namespace rfmems
