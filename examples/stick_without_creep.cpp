// Stick without creep (issue 15): one contact integrated by Moreau-Jean with the exact limit
// surface of the patch, beside the regularised (fractional) law and the engines' ellipsoid.
//
//   contensou-stick-without-creep [out_dir]
//
// Prints (1) the drift of a body held at rest for 10 s by a load inside the limit, (2) the
// motion a load just outside starts, (3) the stopping ratio v/(omega R) of the sliding-spinning
// uniform disk at four step sizes, (4) the fitted ellipsoid's radial error per profile, (5) the
// projection's convergence on random trials. With out_dir, writes sections of the limit
// surfaces (CSV) for examples/limit_surface_sections.gp.
#include <Eigen/LU>
#include <Eigen/QR>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "contensou/friction.hpp"

using namespace contensou;
using Vec3 = Eigen::Vector3d;

namespace {

ContactPatch seed(double kx = 0.0) {
  ContactPatch p = seed_tire_patch();
  p.profile.keep_negative = true;  // the seed's published series, slightly negative at the rim
  p.profile.kx = kx;
  return p;
}

// Drift [m, m, rad] after `seconds` of a body starting at rest under a constant load, with the
// set-valued law (Moreau-Jean), its ellipsoid, and the regularised fractional law (implicit
// Euler by Newton with the law's analytic Jacobian).
struct Drift {
  double exact = 0.0, ellipsoid = 0.0, fractional = 0.0;
};
Drift drift(const ContactPatch& p, const Vec3& load, double h, double seconds) {
  const LimitSurface s = make_limit_surface(p);
  const EllipsoidalLimitSurface e = fit_ellipsoid(s);
  const FractionalLaw<double> law = fractional_law_from_patch(p);
  const PlanarBody body{300.0, 300.0 * p.radius_m * p.radius_m / 2.0};
  const Vec3 m(body.mass, body.mass, body.inertia);
  const double R = p.radius_m;
  Vec3 se = Vec3::Zero(), xe = Vec3::Zero(), sl = Vec3::Zero(), xl = Vec3::Zero();
  Vec3 sf = Vec3::Zero(), xf = Vec3::Zero();
  const int n = static_cast<int>(std::lround(seconds / h));
  for (int i = 0; i < n; ++i) {
    se = moreau_jean_step(s, body, se, load, h).twist;
    xe += h * se;
    sl = moreau_jean_step(e, body, sl, load, h).twist;
    xl += h * sl;
    Vec3 v = sf;
    for (int k = 0; k < 40; ++k) {
      const auto fj = fractional_resultants_with_jacobian(law, {v[0], v[1], v[2]});
      const Vec3 r = m.cwiseProduct(v - sf) / h - load - fj.resultants.vector();
      const Eigen::Matrix3d J = Eigen::Matrix3d(m.asDiagonal()) / h - fj.jacobian;
      const Vec3 dv = J.lu().solve(r);
      v -= dv;
      if (dv.norm() <= 1e-16 * (1.0 + v.norm())) break;
    }
    sf = v;
    xf += h * sf;
  }
  // Displacement of a rim point: |x| + R |angle|.
  auto rim = [R](const Vec3& x) { return x.head<2>().norm() + R * std::abs(x[2]); };
  return {rim(xe), rim(xl), rim(xf)};
}

double farkas_ratio(const LimitSurface& s, double h, bool& together) {
  const PlanarBody body{1.0, 0.5};
  Vec3 tw(1.0, 0.0, 1.0);
  double ratio = 0.0;
  together = false;
  for (int i = 0; i < 1000000; ++i) {
    const ContactStep st = moreau_jean_step(s, body, tw, Vec3::Zero(), h);
    if (st.twist.norm() == 0.0) {
      together = tw[0] > 0.0 && tw[2] > 0.0;  // both were moving on the step before
      break;
    }
    ratio = st.twist[0] / (st.twist[2] * 1.0);
    tw = st.twist;
  }
  return ratio;
}

// The same disk with a step proportional to its speed, h = c (v + omega R) / (f g): by the
// homogeneity of the law the ratio then obeys an autonomous map whose fixed point is the
// continuous one to O(c). Returns the ratio once v + omega R < 1e-12.
double farkas_ratio_relative(const LimitSurface& s, double c) {
  const PlanarBody body{1.0, 0.5};
  Vec3 tw(1.0, 0.0, 1.0);
  while (tw[0] + tw[2] > 1e-12) {
    const ContactStep st = moreau_jean_step(s, body, tw, Vec3::Zero(), c * (tw[0] + tw[2]));
    if (st.twist.norm() == 0.0) break;
    tw = st.twist;
  }
  return tw[0] / tw[2];
}

// The fixed point of v/(omega R) from Contensou's closed forms (theory.md section 3): equal
// relative decay of v and omega R, F_par = 2 eps |Mz| / R for M = R = 1, I = 1/2.
double closed_form_ratio() {
  auto g = [](double e) {
    const double K = std::comp_ellint_1(e), E = std::comp_ellint_2(e);
    const double fpar = 4 / (3 * std::numbers::pi) * ((1 + e * e) * E - (1 - e * e) * K) / e;
    const double mz = 4 / (9 * std::numbers::pi) * ((4 - 2 * e * e) * E - (1 - e * e) * K);
    return fpar - 2 * e * mz;
  };
  double lo = 0.3, hi = 0.95;
  for (int i = 0; i < 100; ++i) {
    const double mid = 0.5 * (lo + hi);
    (g(lo) * g(mid) <= 0 ? hi : lo) = mid;
  }
  return 0.5 * (lo + hi);
}

// A section of a surface by the plane spanned by two unit wrench directions a, b (in scaled
// wrench coordinates (Fx, Fy, Mz/R)/(f N)): boundary points along rays, by the gauge.
template <class Surface>
void write_section(const std::string& file, const Surface& s, double fN, double R, const Vec3& a,
                   const Vec3& b) {
  std::ofstream out(file);
  out << "# section of the limit surface: columns a, b (wrench / (f N), torque / (f N R))\n";
  for (int i = 0; i <= 360; ++i) {
    const double th = 2 * std::numbers::pi * i / 360;
    const Vec3 d = std::cos(th) * a + std::sin(th) * b;  // scaled
    const Vec3 w(d[0] * fN, d[1] * fN, d[2] * fN * R);
    const double g = gauge(s, w).value;
    out << d.dot(a) / g << " " << d.dot(b) / g << "\n";
  }
}

}  // namespace

int main(int argc, char** argv) {
  const std::string dir = argc > 1 ? argv[1] : "";
  std::printf("Stick without creep: one contact, Moreau-Jean with the exact limit surface\n\n");

  // (1) Drift at rest, 10 s, seed tire, body 300 kg.
  {
    const ContactPatch p = seed();
    const double fN = p.friction * normal_load(p), R = p.radius_m;
    const double M0 = fractional_law_from_patch(p).M0;
    struct Case {
      const char* name;
      Vec3 load;
    } cases[] = {{"0.5 f N along x", Vec3(0.5 * fN, 0, 0)},
                 {"0.9 f N along x", Vec3(0.9 * fN, 0, 0)},
                 {"(0.3, 0.2) f N + 0.4 M0", Vec3(0.3 * fN, 0.2 * fN, 0.4 * M0)}};
    std::printf(
        "(1) drift after 10 s at rest (rim-point displacement |x| + R|angle| [m]), "
        "seed tire, N = %.0f N, 300 kg\n",
        normal_load(p));
    std::printf(
        "| load | gauge | step [s] | set-valued exact | set-valued ellipsoid | "
        "fractional (eps = 1e-4 m/s) |\n|---|---|---|---|---|---|\n");
    const LimitSurface s = make_limit_surface(p);
    for (const Case& c : cases)
      for (double h : {1e-2, 1e-3}) {
        const Drift d = drift(p, c.load, h, 10.0);
        std::printf("| %s | %.3f | %g | %.3g | %.3g | %.3g |\n", c.name, gauge(s, c.load).value, h,
                    d.exact, d.ellipsoid, d.fractional);
      }
    (void)R;
  }

  // (2) A load 2 % outside: the direction of the motion it starts.
  {
    const ContactPatch p = seed(0.14);
    const LimitSurface s = make_limit_surface(p);
    const double R = s.radius;
    const PlanarBody body{300.0, 300.0 * R * R};
    std::printf(
        "\n(2) load 2 %% outside the limit beyond the friction of kinematics n, first step "
        "(h = 1 ms): angle between the new twist and n (scaled twists)\n");
    for (const Vec3& n : {Vec3(1.0, 0.5, 3.0 / R), Vec3(0.0, 1.0, 0.2 / R), Vec3(0, 0, 1)}) {
      const Vec3 load = -1.02 * surface_point(s, -n);
      const ContactStep st = moreau_jean_step(s, body, Vec3::Zero(), load, 1e-3);
      const Vec3 a(st.twist[0], st.twist[1], st.twist[2] * R), b(n[0], n[1], n[2] * R);
      std::printf("  n = (%g, %g, %g): angle %.4f rad, |twist| = %.3g\n", n[0], n[1], n[2],
                  std::acos(std::min(1.0, a.normalized().dot(b.normalized()))), a.norm());
    }
  }

  // (3) The sliding-spinning uniform disk (M = R = f g = 1, I = 1/2, v0 = omega0 R = 1).
  {
    ContactPatch p;
    p.radius_m = 1.0;
    p.reference_pressure_pa = 1.0 / std::numbers::pi;
    p.friction = 1.0;
    const LimitSurface s = make_limit_surface(p);
    std::printf(
        "\n(3) sliding-spinning uniform disk: v/(omega R) on the last moving step "
        "(reference 0.6530, Farkas et al. 2003)\n");
    for (double h : {8e-3, 4e-3, 2e-3, 1e-3}) {
      bool together = false;
      const double r = farkas_ratio(s, h, together);
      std::printf("  h = %g: ratio %.5f (error %+.5f), both stop on the same step: %s\n", h, r,
                  r - 0.6530, together ? "yes" : "no");
    }
    const double ref = closed_form_ratio();
    for (double c : {0.04, 0.02, 0.01}) {
      const double r = farkas_ratio_relative(s, c);
      std::printf(
          "  relative step h = %g (v + omega R) / (f g): ratio %.9f (closed-form fixed "
          "point %.9f, difference %+.1e)\n",
          c, r, ref, r - ref);
    }
  }

  // (4) The ellipsoid against the exact surface.
  {
    std::printf(
        "\n(4) fitted ellipsoid (pure slide and pure spin matched) against the exact "
        "surface: radial error 1/g_E - 1 over 24 x 48 normals\n");
    std::printf(
        "| profile | kappa | L / R | max radial error | rms | worst normal (vx, vy, omega R) "
        "|\n|---|---|---|---|---|---|\n");
    ContactPatch u = seed();
    u.profile = uniform_profile();
    ContactPatch h = u;
    h.profile = hertz_profile();
    auto orthotropic = [](ContactPatch p, double kappa) {
      p.kappa = kappa;
      return p;
    };
    const std::pair<const char*, ContactPatch> rows[] = {
        {"uniform", u},
        {"Hertz", h},
        {"seed tire", seed()},
        {"seed tire, kx = 0.14", seed(0.14)},
        {"uniform, orthotropic", orthotropic(u, 0.5)},
        {"seed tire, orthotropic", orthotropic(seed(), 0.8)}};
    for (const auto& [name, p] : rows) {
      const LimitSurface s = make_limit_surface(p);
      const EllipsoidalLimitSurface e = fit_ellipsoid(s);
      const EllipsoidError err = ellipsoid_error(s, e, 24, 48);
      const Vec3 n(err.worst_normal[0], err.worst_normal[1], err.worst_normal[2] * s.radius);
      const Vec3 nn = n.normalized();
      std::printf("| %s | %.2f | %.4f | %.2f %% | %.2f %% | (%.2f, %.2f, %.2f) |\n", name, e.kappa,
                  e.torsional_length / s.radius, 100 * err.max_radial_error,
                  100 * err.rms_radial_error, nn[0], nn[1], nn[2]);
    }
  }

  // (5) Projection convergence on random trials (seed tire, kx = 0.14, random SPD metrics).
  {
    const LimitSurface s = make_limit_surface(seed(0.14));
    const double fN = s.force_scale, R = s.radius;
    std::mt19937 rng(11);
    std::normal_distribution<double> n01;
    int worst_it = 0, inside = 0, failed = 0;
    double worst_res = 0.0;
    const int trials = 2000;
    for (int i = 0; i < trials; ++i) {
      Eigen::Matrix3d B;
      for (int k = 0; k < 9; ++k) B(k / 3, k % 3) = n01(rng);
      const Vec3 sc(1.0, 1.0, 1.0 / R);
      const Eigen::Matrix3d G = sc.asDiagonal() *
                                (B * B.transpose() + 0.05 * Eigen::Matrix3d::Identity()) *
                                sc.asDiagonal();
      const double mag = std::pow(10.0, 4.0 * (i % 100) / 100.0 - 1.0);  // 0.1 ... 1000
      const Vec3 wt = mag * Vec3(n01(rng) * fN, n01(rng) * fN, n01(rng) * fN * R);
      const Projection pr = project(s, wt, G);
      inside += pr.inside;
      failed += !pr.converged;
      worst_it = std::max(worst_it, pr.iterations);
      worst_res = std::max(worst_res, pr.residual);
    }
    std::printf(
        "\n(5) projection, %d random trials (|w_t| 0.1 ... 1000 f N, random SPD "
        "metrics): %d inside, %d not converged, at most %d Newton iterations (gauge + "
        "projection), largest final |grad phi| / (f N + |w_t|) %.2g (tolerance 1e-10)\n",
        trials, inside, failed, worst_it, worst_res);
  }

  // (6) Extreme trials and ill-conditioned metrics: |w_t| from 1e-8 to 1e250 f N, metric
  // condition numbers 1 to 1e12 (eigenvectors random), 10 trials each. Optimality checked by
  // the variational inequality against 961 boundary samples w: the largest cosine between
  // w - w* and G (w_t - w*) (<= 0 for the exact projection).
  {
    ContactPatch p = seed(0.14);
    const LimitSurface s = make_limit_surface(p);
    const double fN = s.force_scale, R = s.radius;
    std::vector<Vec3> samples;
    for (int i = 0; i <= 30; ++i)
      for (int j = 0; j < 30; ++j) {
        const double th = std::numbers::pi * i / 30, ph = 2 * std::numbers::pi * j / 30;
        samples.push_back(surface_point(
            s, Vec3(std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph), std::cos(th) / R)));
      }
    std::mt19937 rng(5);
    std::normal_distribution<double> n01;
    std::printf("\n(6) extreme trials (|w_t| 1e-8 ... 1e250 f N) and metric condition numbers:\n");
    for (double cond : {1.0, 1e4, 1e8, 1e12}) {
      int n = 0, failed = 0, maxit = 0;
      double vi = -1.0;
      for (double mag : {1e-8, 1e-3, 1.0, 1e3, 1e8, 1e20, 1e60, 1e150, 1e250})
        for (int k = 0; k < 10; ++k) {
          Eigen::Matrix3d A;
          for (int q = 0; q < 9; ++q) A(q / 3, q % 3) = n01(rng);
          const Eigen::Matrix3d U = Eigen::HouseholderQR<Eigen::Matrix3d>(A).householderQ();
          const Vec3 sc(1.0, 1.0, 1.0 / R);
          Eigen::Matrix3d G = sc.asDiagonal() * U * Vec3(1.0, std::sqrt(cond), cond).asDiagonal() *
                              U.transpose() * sc.asDiagonal();
          G = 0.5 * (G + G.transpose());
          const Vec3 wt = mag * Vec3(n01(rng) * fN, n01(rng) * fN, n01(rng) * fN * R);
          const Projection pr = project(s, wt, G);
          ++n;
          failed += !pr.converged || !pr.wrench.allFinite();
          maxit = std::max(maxit, pr.iterations);
          if (pr.inside) continue;
          for (const Vec3& w : samples) {
            const Vec3 a = w - pr.wrench, b = G * (wt - pr.wrench);
            if (a.norm() > 0.0 && b.norm() > 0.0)
              vi = std::max(vi, a.dot(b) / (a.norm() * b.norm()));
          }
        }
      std::printf(
          "  cond %g: %d trials, %d not converged, at most %d iterations, largest "
          "variational-inequality cosine %.2g\n",
          cond, n, failed, maxit, vi);
    }
  }

  if (!dir.empty()) {
    std::filesystem::create_directories(dir);
    const Vec3 ex = Vec3::UnitX(), ey = Vec3::UnitY(), ez = Vec3::UnitZ();
    ContactPatch u = seed();
    u.profile = uniform_profile();
    ContactPatch h = u;
    h.profile = hertz_profile();
    const std::pair<std::string, ContactPatch> rows[] = {
        {"uniform", u}, {"hertz", h}, {"seed", seed()}, {"seed_kx", seed(0.14)}};
    for (const auto& [name, p] : rows) {
      const LimitSurface s = make_limit_surface(p);
      const EllipsoidalLimitSurface e = fit_ellipsoid(s);
      const double fN = s.force_scale, R = s.radius;
      write_section(dir + "/" + name + "_xz.dat", s, fN, R, ex, ez);
      write_section(dir + "/" + name + "_yz.dat", s, fN, R, ey, ez);
      write_section(dir + "/" + name + "_xy.dat", s, fN, R, ex, ey);
      write_section(dir + "/" + name + "_ellipsoid_xz.dat", e, fN, R, ex, ez);
    }
    std::printf("\nsections written to %s\n", dir.c_str());
  }
  return 0;
}
