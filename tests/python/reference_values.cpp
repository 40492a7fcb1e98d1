// Reference values for the Python tests (tests/python/test_friction.py): the exact resultants
// and the fractional law of a few patches at a few kinematics, computed here in C++ through
// the library's own API and printed with 17 significant digits. The Python package must give
// the same numbers through its vectorised calls.
#include <cstdio>
#include <string>
#include <vector>

#include "contensou/friction.hpp"

using namespace contensou;

namespace {

struct Case {
  std::string name;
  ContactPatch patch;
};

std::vector<Case> cases() {
  std::vector<Case> out;
  ContactPatch uniform;
  uniform.radius_m = 0.1;
  uniform.reference_pressure_pa = 1.0e5;
  uniform.friction = 0.4;
  uniform.profile = uniform_profile();
  out.push_back({"uniform", uniform});

  ContactPatch hertz = uniform;
  hertz.profile = hertz_profile();
  hertz.profile.kx = 0.1;
  hertz.profile.ky = -0.05;
  hertz.kappa = 0.8;
  out.push_back({"hertz_shifted", hertz});

  ContactPatch seed = seed_tire_patch();
  seed.profile.kx = 0.14;
  out.push_back({"seed_tire", seed});

  ContactPatch cosine = uniform;
  cosine.profile = cosine_series_profile(0.5, {0.6, 0.3, 0.1});
  out.push_back({"cosine_series", cosine});

  ContactPatch table = uniform;
  table.profile = tabulated_profile({0.0, 0.25, 0.5, 0.75, 1.0}, {1.0, 0.95, 0.8, 0.5, 0.0});
  out.push_back({"tabulated", table});

  ContactPatch slip = uniform;
  slip.slip_speed_friction = SlipSpeedFriction<double>{0.5, 0.3, 2.0, 1.0};
  out.push_back({"slip_speed", slip});
  return out;
}

// (vx, vy, omega): pure spin, pure sliding, rest, centre of sliding inside, on and outside the
// rim, oblique sliding with spin of either sign.
const std::vector<Kinematics<double>> kKinematics = {
    {0.0, 0.0, 10.0}, {0.5, 0.0, 0.0},  {0.0, 0.0, 0.0},   {0.3, 0.0, 10.0},
    {1.0, 0.0, 10.0}, {2.0, 0.5, 10.0}, {-0.4, 0.7, -6.0}, {0.05, -0.02, 30.0}};

}  // namespace

int main() {
  std::printf(
      "kind,case,vx,vy,omega,Fx,Fy,Mz,e_Fx,e_Fy,e_Mz,J00,J01,J02,J10,J11,J12,J20,J21,J22\n");
  for (const Case& c : cases()) {
    const ExactModel<double> model = make_exact_model(c.patch);
    for (double tol : {1e-10, 1e-6}) {
      for (const Kinematics<double>& k : kKinematics) {
        const ExactResult<double> r = exact_resultants(model, k, ExactOptions{tol});
        std::printf("exact%s,%s,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g",
                    tol == 1e-6 ? "_1e-6" : "", c.name.c_str(), k.vx, k.vy, k.omega,
                    r.resultants.Fx, r.resultants.Fy, r.resultants.Mz, r.error.Fx, r.error.Fy,
                    r.error.Mz);
        for (int i = 0; i < 9; ++i) std::printf(",");
        std::printf("\n");
      }
    }
    if (c.patch.slip_speed_friction) continue;  // the law has no f(w)
    for (const bool fitted : {false, true}) {
      const FractionalLaw<double> law =
          fitted ? fractional_law_fitted(c.patch) : fractional_law_from_patch(c.patch);
      for (const Kinematics<double>& k : kKinematics) {
        const FractionalWithJacobian r = fractional_resultants_with_jacobian(law, k);
        std::printf("%s,%s,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,,,",
                    fitted ? "fractional_fitted" : "fractional", c.name.c_str(), k.vx, k.vy,
                    k.omega, r.resultants.Fx, r.resultants.Fy, r.resultants.Mz);
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j) std::printf(",%.17g", r.jacobian(i, j));
        std::printf("\n");
      }
    }
  }
  return 0;
}
