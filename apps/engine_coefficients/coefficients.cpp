#include "coefficients.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

#include "contensou/friction/error.hpp"
#include "contensou/friction/exact_law.hpp"
#include "contensou/friction/exact_resultants.hpp"
#include "contensou/friction/pressure_profile.hpp"

namespace contensou::engines {

namespace {
std::string num(double x) {
  std::ostringstream s;
  s.precision(6);
  s << x;
  return s.str();
}

struct Curves {
  std::vector<double> psi, force, torque;  // F_par / F0 and |Mz| / M0 of the exact integrals
};

Curves exact_curves(const ContactPatch& patch, const Grid& g) {
  const ExactModel<double> model = make_exact_model(patch);
  const double N = normal_load(patch), R = patch.radius_m;
  const double F0 = patch.friction * N, M0 = spin_torque_per_load(patch) * N;
  // The exact law (exact_law.hpp): the exact resultants (theory.md section 2) from tables built
  // once, within a certified bound `achieved` of the integrals relative to f N and f N R, the
  // integrator's own tolerance here. A build that misses it (it says so) leaves the points to the
  // adaptive integrator.
  constexpr double kTolerance = 1e-9;
  ExactLawOptions options;
  options.tolerance = kTolerance;
  const ExactLaw law = make_exact_law(model, options);
  Curves c;
  for (int i = 0; i < g.points; ++i) {
    const double psi =
        g.psi_min * std::pow(g.psi_max / g.psi_min, static_cast<double>(i) / (g.points - 1));
    const double omega = 1.0 / R;  // u = omega R = 1, v = psi
    const Kinematics<double> k{psi, 0.0, omega};
    const Resultants<double> r = law.reached ? exact_law_resultants(law, k)
                                             : exact_resultants(model, k, {kTolerance}).resultants;
    c.psi.push_back(psi);
    c.force.push_back(-r.Fx / F0);
    c.torque.push_back(-r.Mz / M0);
  }
  return c;
}
}  // namespace

ContactPatch named_patch(const std::string& profile, double radius, double friction) {
  // The coefficients are computed at N = 1 N, p* = 1 / (2 pi R^2 A^1): R^2 must stay a double.
  if (!(std::isfinite(radius) && radius >= 1e-100 && radius <= 1e100))
    throw InvalidArgument("--radius", format_value(radius),
                          "must be a positive number [m] within 1e-100 ... 1e100");
  if (!(friction > 0 && friction <= 100.0))
    throw InvalidArgument("--friction", format_value(friction),
                          "must lie in (0, 100] (a friction coefficient)");
  PressureProfile shape;
  if (profile == "uniform")
    shape = uniform_profile();
  else if (profile == "hertz")
    shape = hertz_profile();
  else if (profile == "seed-tire")
    shape = seed_tire_profile();
  else
    throw InvalidArgument("--profile", "'" + profile + "'", "use uniform, hertz or seed-tire");
  return ContactPatch::from_normal_load(radius, 1.0, shape, friction);  // N = 1 N
}

double spin_torque_per_load(const ContactPatch& patch) {
  // M0 / N = 2 pi f R^3 p* A^2 / (2 pi R^2 p* A^1) (theory.md section 4).
  return patch.friction * patch.radius_m * moment(patch.profile, 2) / moment(patch.profile, 1);
}

std::vector<EngineCoefficient> engine_coefficients(const ContactPatch& patch, Grid grid) {
  validate(patch);
  if (!(grid.psi_min > 0 && grid.psi_max > grid.psi_min && grid.points >= 2))
    throw InvalidArgument("psi grid",
                          format_value(grid.psi_min) + " .. " + format_value(grid.psi_max),
                          "need 0 < psi_min < psi_max and at least 2 points");
  const Curves ex = exact_curves(patch, grid);
  const double f = patch.friction, R = patch.radius_m, m0 = spin_torque_per_load(patch);
  const std::size_t n = ex.psi.size();

  // The elliptic cone under maximum dissipation (header), errors and squared-error cost.
  struct Fit {
    double force = 0, torque = 0, cost = 0;
  };
  auto elliptic = [&](double c) {
    Fit e;
    const double mu_t = c * f * R;
    for (std::size_t i = 0; i < n; ++i) {
      const double s = std::hypot(ex.psi[i], c);
      const double df = ex.psi[i] / s - ex.force[i], dm = mu_t * c / s / m0 - ex.torque[i];
      e.force = std::max(e.force, std::abs(df));
      e.torque = std::max(e.torque, std::abs(dm));
      e.cost += df * df + dm * dm;
    }
    return e;
  };
  const double c_spin = m0 / (f * R);
  double c_ls = c_spin, best = elliptic(c_spin).cost;
  for (int i = 0; i <= 2000; ++i) {  // log grid over [c_spin / 4, 4 c_spin]
    const double c = c_spin * std::pow(16.0, i / 2000.0) / 4.0;
    const double cost = elliptic(c).cost;
    if (cost < best) best = cost, c_ls = c;
  }
  std::vector<EngineCoefficient> rows;
  for (auto [label, c] :
       {std::pair{"pure spin: mu_t N = M0", c_spin}, std::pair{"least squares over psi", c_ls}}) {
    const Fit e = elliptic(c);
    const double mu_t = c * f * R;
    rows.push_back({"MuJoCo (condim 4, elliptic cone)", "friction[1] (torsional)", "m", label, mu_t,
                    e.force, e.torque,
                    "<geom condim=\"4\" friction=\"" + num(f) + " " + num(mu_t) +
                        " 0\"/>  <option cone=\"elliptic\"/>"});
  }
  // Sliding-independent torque bounds: F = F0 and M = M0 whenever sliding and spinning.
  double ef = 0, em = 0;
  for (std::size_t i = 0; i < n; ++i) {
    ef = std::max(ef, std::abs(1.0 - ex.force[i]));
    em = std::max(em, std::abs(1.0 - ex.torque[i]));
  }
  rows.push_back(
      {"Chrono", "spinning friction coefficient", "m", "pure spin: mu_s N = M0", m0, ef, em,
       "material->SetFriction(" + num(f) + "); material->SetSpinningFriction(" + num(m0) + ");"});
  rows.push_back({"Bullet", "spinningFriction", "m", "pure spin: spinningFriction N = M0", m0, ef,
                  em,
                  "<contact><lateral_friction value=\"" + num(f) +
                      "\"/><spinning_friction value=\"" + num(m0) + "\"/></contact>  (URDF)"});
  const double a = m0 / (3.0 * std::numbers::pi / 16.0 * f);
  rows.push_back(
      {"Gazebo (ODE)", "torsional patch_radius", "m", "pure spin: (3 pi/16) f a N = M0", a, ef, em,
       "<friction><torsional><coefficient>" + num(f) +
           "</coefficient><use_patch_radius>true</use_patch_radius><patch_radius>" + num(a) +
           "</patch_radius></torsional><ode><mu>" + num(f) + "</mu></ode></friction>  (SDF)"});
  return rows;
}

}  // namespace contensou::engines
