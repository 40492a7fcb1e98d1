/// \file
/// Patch kinematics and friction resultants (theory.md section 1).
#pragma once

#include <Eigen/Core>

namespace contensou {

/// Sliding velocity of the tire material at the patch centre relative to the road [m/s],
/// and spin of the tire about the contact normal z relative to the road [rad/s].
template <class T = double>
struct Kinematics {
  T vx{0};     ///< sliding velocity along x [m/s]
  T vy{0};     ///< sliding velocity along y [m/s]
  T omega{0};  ///< spin about z [rad/s]
};

/// Friction acting on the tire: force [N] in the contact plane and torque about z through
/// the patch centre [N m]. Sliding along +x gives Fx < 0; spin omega > 0 gives Mz < 0.
template <class T = double>
struct Resultants {
  T Fx{0};  ///< force along x [N]
  T Fy{0};  ///< force along y [N]
  T Mz{0};  ///< torque about z through the patch centre [N m]

  /// (Fx, Fy, Mz) as a vector.
  Eigen::Matrix<T, 3, 1> vector() const { return {Fx, Fy, Mz}; }
};

/// Power of friction on the tire, F.v + Mz omega [W]; dissipation means it is <= 0.
template <class T>
T friction_power(const Resultants<T>& r, const Kinematics<T>& k) {
  return r.Fx * k.vx + r.Fy * k.vy + r.Mz * k.omega;
}

}  // namespace contensou
