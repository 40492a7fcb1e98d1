/// \file
/// The limit surface of the patch: the set of friction wrenches (Fx, Fy, Mz) the patch can
/// transmit, its support function (the dissipation power), and the projection onto it that a
/// set-valued (stick without creep) law needs in an implicit or time-stepping solver.
///
/// Goyal, Ruina & Papadopoulos (1991, "Planar sliding with dry friction", Wear 143): for
/// isotropic Coulomb friction with a fixed pressure sigma, the set C of wrenches the patch can
/// transmit is convex, and its support function is the dissipation power
///   D(v, omega) = integral_S f sigma |v + omega z x r| dS            (theory.md section 2)
/// which is convex, even and homogeneous of degree 1 in the twist s = (vx, vy, omega). The
/// friction wrench of a sliding patch is the maximum-dissipation point of C,
///   (Fx, Fy, Mz)(s) = -grad D(s)      (tau = -f sigma vc/|vc| = -grad_vc (f sigma |vc|)),
/// i.e. exactly the exact resultants of theory.md section 2 (verified in the tests by finite
/// differences of D). Since D is even, max_{w in C} w.d = D(d): the support function of C is D.
/// For sliding with spin this is Leine & Glocker's set-valued Coulomb-Contensou law (2003,
/// Eur. J. Mech. A/Solids 22): w in C, and -s in the normal cone of C at w.
///
/// Orthotropic friction (kappa != 1): the local set of tractions is the ellipse of semi-axes
/// f sigma, kappa f sigma; its support function is f sigma |D vc|, D = diag(1, kappa), so
///   D(v, omega) = integral_S f sigma |D vc| dS,
/// and the law that belongs to the set (maximum dissipation, its gradient) is the associated
/// tau = -f sigma D^2 vc/|D vc|. The library's default orthotropic law of theory.md section 2,
/// tau = -f sigma D vc/|vc|, reaches the same ellipse but not at its maximum-dissipation point
/// (it is not a gradient: its Jacobian is not symmetric), so the surface built here uses the
/// associated law (ExactModel::associated_orthotropy; the two agree for kappa = 1 and at pure
/// sliding along x or y). Scope: a constant coefficient, any profile, shift and kappa; a
/// speed-dependent f(w) makes D not homogeneous and is refused (InvalidArgument on
/// slip_speed_friction).
///
/// Units: twist (vx, vy, omega) [m/s, m/s, rad/s], wrench (Fx, Fy, Mz) [N, N, N m], D [W].
/// Internally the work is done in the scaled twist t = (vx, vy, omega R) and scaled wrench
/// W = (Fx, Fy, Mz / R) / (f N), in which C is of size 1 (pure slide |W| = 1, uniform pure
/// spin |W3| = 2/3).
#pragma once

#include <Eigen/Core>

#include "contensou/friction/contact_patch.hpp"
#include "contensou/friction/exact_resultants.hpp"
#include "contensou/friction/fractional_law.hpp"

namespace contensou {

/// The exact limit surface of a patch (build once, evaluate many times).
struct LimitSurface {
  ExactModel<double> model;    ///< the patch's exact model (associated orthotropy)
  double radius = 0.0;         ///< R [m] (integration radius of the model)
  double force_scale = 0.0;    ///< f N [N]
  double tolerance = 1e-12;    ///< of the exact integrals, relative to f N (and f N R)
  double hessian_step = 1e-4;  ///< central-difference step on the unit sphere of scaled twists
};

/// Throws InvalidArgument for a bad patch or a slip-speed friction law; the tolerance must be
/// in [1e-14, 1e-6]. kappa != 1 gives the associated law's surface (header comment).
LimitSurface make_limit_surface(const ContactPatch& patch, double tolerance = 1e-12);

/// D and its derivatives with respect to the twist (vx, vy, omega).
struct Dissipation {
  double value = 0.0;        ///< D [W]
  Eigen::Vector3d gradient;  ///< dD/ds = -(Fx, Fy, Mz)
  Eigen::Matrix3d hessian;   ///< d2D/ds2 (zero matrix at s = 0, where D is not smooth)
};

/// D(s) = -(F.v + Mz omega) (Euler's relation for a degree-1 function, with grad D = -wrench).
double dissipation(const LimitSurface& surface, const Eigen::Vector3d& twist);
/// Value, gradient (exact integrals, error <= tolerance f N) and Hessian (central differences
/// of the exact gradient along two directions orthogonal to the scaled twist t, step h =
/// hessian_step: error O(h^2) + O(tolerance / h), about 1e-8 relative to f N / |t| with the
/// defaults; H s = 0 holds exactly, as for any degree-1 function).
Dissipation dissipation_with_derivatives(const LimitSurface& surface, const Eigen::Vector3d& twist);

/// grad D templated on the scalar, for automatic differentiation: with T = ceres::Jet (or any
/// type exact_resultants accepts) its derivatives are the exact Hessian of D, d2D/ds2 = -dw/ds.
/// promote<T>(surface.model) gives the model.
template <class T>
Eigen::Matrix<T, 3, 1> dissipation_gradient(const ExactModel<T>& model, const Kinematics<T>& k,
                                            const ExactOptions& options = {}) {
  const Resultants<T> r = exact_resultants(model, k, options).resultants;
  return {-r.Fx, -r.Fy, -r.Mz};  // grad D = -(Fx, Fy, Mz) (Goyal et al. 1991)
}

/// The support function of C in direction d (a twist): max_{w in C} w.d = D(d).
double support(const LimitSurface& surface, const Eigen::Vector3d& direction);

/// The point of the surface whose outward normal is the twist direction n: grad D(n), the
/// friction wrench of a patch sliding with kinematics -n. For plotting, sample n on a sphere.
Eigen::Vector3d surface_point(const LimitSurface& surface, const Eigen::Vector3d& normal);

/// The gauge of C: the smallest g >= 0 with w in g C (w is inside iff g <= 1), and the outward
/// normal (unit scaled twist, returned as a twist direction) of the boundary point w / g.
/// Solved as min D(t) subject to W.t = 1 (convex, in a plane that misses 0): g = 1 / min.
struct Gauge {
  double value = 0.0;                                ///< g (dimensionless)
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();  ///< twist direction (unit in scaled t)
  int iterations = 0;                                ///< Newton iterations
};
/// The gauge of a wrench [N, N, N m]. Throws InvalidArgument for a non-finite wrench or an
/// invalid surface.
Gauge gauge(const LimitSurface& surface, const Eigen::Vector3d& wrench);

/// The projection of a trial wrench onto C in the metric G (symmetric positive definite):
///   w* = argmin_{w in C} (w - w_t)^T G (w - w_t),
/// solved through its dual over twists (Moreau): t* minimises the strongly convex
///   phi(t) = 1/2 t^T G^-1 t - w_t.t + D(t)
/// (0 iff w_t is inside), by Newton's method (Hessian of D from two forward differences of the
/// exact gradient in the plane orthogonal to t, as H t = 0; about 1e-6 relative, which only
/// slows the final convergence) with an Armijo line search started on the ray
/// of the gauge's normal where phi < 0 = phi(0), so that the iterates never reach the kink of D
/// at 0. Then w* = grad D(t*) (on the surface, normality exact) and twist = G (w* - w_t)
/// (= -t*), whose resultant is w* (maximum dissipation). A trial with gauge <= 1 +
/// inside_tolerance is returned unchanged, twist 0.
///
/// In a Moreau-Jean step with Delassus matrix A = h M^-1 (twist change per unit wrench) and
/// free twist s_free, G = A and w_t = -A^-1 s_free give the new twist s+ = twist = s_free + A w*.
struct ProjectionOptions {
  double tolerance = 1e-10;         ///< on |grad phi|, relative to f N + |w_t| (scaled wrenches)
  double inside_tolerance = 1e-10;  ///< on the gauge
  int max_iterations = 60;          ///< Newton iterations, at least 1
};
/// The result of project().
struct Projection {
  Eigen::Vector3d wrench = Eigen::Vector3d::Zero();  ///< w* [N, N, N m]
  Eigen::Vector3d twist = Eigen::Vector3d::Zero();   ///< G (w* - w_t); 0 if inside
  bool inside = false;                               ///< the trial was admissible (stick)
  double gauge = 0.0;                                ///< gauge of the trial
  double residual = 0.0;  ///< final |grad phi| / (f N + |w_t|), scaled (0 if inside)
  int iterations = 0;     ///< Newton iterations (gauge + projection)
  bool converged = true;  ///< the residual met the tolerance within max_iterations
};
/// The projection of `trial` [N, N, N m] onto C in the metric `metric` (above). Throws
/// InvalidArgument for a non-finite trial, a metric that is not symmetric positive definite,
/// or bad options (tolerance <= 0, inside_tolerance < 0, max_iterations < 1).
Projection project(const LimitSurface& surface, const Eigen::Vector3d& trial,
                   const Eigen::Matrix3d& metric, const ProjectionOptions& options = {});

/// The ellipsoid of the engines (MuJoCo's elliptic cone, cardillo's Coulomb-Contensou law):
///   (Fx / F)^2 + (Fy / (kappa F))^2 + (Mz / (F L))^2 <= 1,  F = force_limit,
/// L = torsional_length, support function D_E(s) = F sqrt(vx^2 + kappa^2 vy^2 + L^2 omega^2).
struct EllipsoidalLimitSurface {
  double force_limit = 0.0;       ///< F [N], along x
  double torsional_length = 0.0;  ///< L [m]
  double radius = 0.0;            ///< R [m], only for scaling
  double kappa = 1.0;             ///< Fy limit / Fx limit
};

/// Fitted to the exact surface by matching its extremes: F = |F| at pure sliding along x (f N,
/// any profile), kappa F at pure sliding along y, and F L = |Mz| at pure spin (M0 = 2 pi f R^3
/// p* A^2 for kappa = 1, theory.md section 4; for uniform pressure L = 2R/3, Hertz 3 pi R / 16;
/// for kappa != 1 and no shift, M0 times the mean of |D e| over directions e, (2/pi) E(1 -
/// kappa^2) with E the complete elliptic integral of parameter m, for kappa <= 1).
EllipsoidalLimitSurface fit_ellipsoid(const LimitSurface& surface);

/// The ellipsoid's support function D_E(d) [W] (closed form). Throws InvalidArgument for an
/// invalid ellipsoid or a non-finite direction.
double support(const EllipsoidalLimitSurface& surface, const Eigen::Vector3d& direction);
/// D_E and its gradient and Hessian in the twist (closed forms; zero Hessian at s = 0).
Dissipation dissipation_with_derivatives(const EllipsoidalLimitSurface& surface,
                                         const Eigen::Vector3d& twist);
/// The ellipsoid's boundary point with outward normal `normal` (a twist direction): grad D_E.
/// Throws InvalidArgument for a zero or non-finite normal.
Eigen::Vector3d surface_point(const EllipsoidalLimitSurface& surface,
                              const Eigen::Vector3d& normal);
/// The ellipsoid's gauge of a wrench (closed form) and the normal at w / g.
Gauge gauge(const EllipsoidalLimitSurface& surface, const Eigen::Vector3d& wrench);
/// The projection onto the ellipsoid in the metric G (the same contract as for the exact
/// surface).
Projection project(const EllipsoidalLimitSurface& surface, const Eigen::Vector3d& trial,
                   const Eigen::Matrix3d& metric, const ProjectionOptions& options = {});

/// How far the ellipsoid is from the exact surface: at n_theta x n_phi boundary points
/// grad D(n) of the exact surface (n on a sphere of scaled twists, denser near the poles), the
/// ellipsoid's radial extent along the same ray relative to the exact one, 1 / g_E(w) - 1.
struct EllipsoidError {
  double max_radial_error = 0.0;                           ///< max |1/g_E - 1|
  double rms_radial_error = 0.0;                           ///< root mean square of 1/g_E - 1
  Eigen::Vector3d worst_normal = Eigen::Vector3d::Zero();  ///< twist direction of the worst point
};
/// The ellipsoid's error against the exact surface (above). Throws InvalidArgument for
/// n_theta < 2 or n_phi < 1.
EllipsoidError ellipsoid_error(const LimitSurface& exact, const EllipsoidalLimitSurface& fit,
                               int n_theta = 24, int n_phi = 24);

/// The closed-form counterpart for the fractional law (theory.md section 4): its dissipation
/// power D_f(s) = -(F.v + Mz omega) and the gradient -(w + J^T s) from the analytic Jacobian.
/// The fractional law is not a gradient field (d Fx/d omega != d Mz/d vx in general), so its
/// wrench is not -grad D_f: it has no limit surface in the sense above; its wrench image of
/// the sphere is what surface_point gives for the exact law.
struct FractionalDissipation {
  double value = 0.0;                                  ///< D_f [W]
  Eigen::Vector3d gradient = Eigen::Vector3d::Zero();  ///< dD_f/ds
  Eigen::Vector3d wrench = Eigen::Vector3d::Zero();    ///< the law's (Fx, Fy, Mz)
};
/// D_f and its gradient at a twist (vx, vy, omega) [m/s, m/s, rad/s].
FractionalDissipation fractional_dissipation(const FractionalLaw<double>& law,
                                             const Eigen::Vector3d& twist);

/// One contact, one planar rigid body: Moreau-Jean (implicit Euler) step with the set-valued
/// law,  M (s+ - s) = h (applied + w),  w in C,  -s+ in N_C(w)  (Leine & Glocker 2003; the
/// projection above with G = A = h M^-1). The body's twist is that of the patch centre.
struct PlanarBody {
  double mass = 1.0;     ///< [kg]
  double inertia = 1.0;  ///< about z through the patch centre [kg m^2]
};
/// The result of moreau_jean_step.
struct ContactStep {
  Eigen::Vector3d twist = Eigen::Vector3d::Zero();   ///< s+ (exactly 0 when it sticks)
  Eigen::Vector3d wrench = Eigen::Vector3d::Zero();  ///< friction wrench over the step
  bool stick = false;                                ///< the trial was inside C: the patch sticks
  int iterations = 0;                                ///< Newton iterations of the projection
};
/// One step h = `step` [s] from twist `twist` under the applied wrench `applied` [N, N, N m].
/// Throws InvalidArgument for a non-positive mass, inertia or step, or non-finite input.
ContactStep moreau_jean_step(const LimitSurface& surface, const PlanarBody& body,
                             const Eigen::Vector3d& twist, const Eigen::Vector3d& applied,
                             double step, const ProjectionOptions& options = {});
/// The same step on the fitted ellipsoid.
ContactStep moreau_jean_step(const EllipsoidalLimitSurface& surface, const PlanarBody& body,
                             const Eigen::Vector3d& twist, const Eigen::Vector3d& applied,
                             double step, const ProjectionOptions& options = {});

}  // namespace contensou
