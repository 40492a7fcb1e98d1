// MuJoCo engine plugin "contensou.friction": coupled sliding-spinning friction over a circular
// contact patch (theory.md sections 1-4) for the geom pairs named in the plugin's configuration.
//
// MJCF:
//   <extension><plugin plugin="contensou.friction"><instance name="patch">
//     <config key="pairs" value="disk floor"/>      tire geom, road geom [; tire road ...]
//     <config key="profile" value="uniform"/>       uniform | hertz | seed-tire
//     <config key="friction" value="0.5"/>          f
//     <config key="radius" value="0.05"/>           patch radius R [m], or instead:
//     <config key="stiffness" value="1e7"/>         k [N/m^3]: R = (N / k)^(1/3) (Hertz-like)
//     <config key="law" value="fractional"/>        fractional (default) | exact
//     <config key="regularization" value="1e-4"/>   eps [m/s] of the fractional law
//     <config key="tolerance" value="1e-8"/>        of the exact integrals (relative to f N)
//   </instance></plugin></extension>
// The named geoms must have condim="1": MuJoCo keeps the normal force (its constraint solver)
// and the plugin replaces MuJoCo's friction by the wrench (Fx, Fy, Mz) of the patch.
//
// Per step and pair: the contacts of the pair (d->contact) give the normal n (from road into
// tire, theory.md section 1) and a point; the patch centre is the tire geom's centre projected
// onto the contact plane. The sliding velocity (tire relative to road at that point) and the
// spin (relative angular velocity about n) in MuJoCo's contact frame enter the law; the wrench
// on the tire (and its opposite on the road) goes to qfrc_passive by mj_applyFT.
//
// The normal force: passive forces are computed before MuJoCo's constraint solver, so the
// contact solution of this step does not exist yet. The plugin uses the PREVIOUS step's
// solution: in `advance` (after the solver) it stores N = sum over the pair's contacts of the
// normal component of mj_contactForce, and the next step's friction uses it. A contact that is
// new this step has N = 0 (no friction in its first step). State per pair (kStateSize numbers):
// [0] N stored for the next step, [1] N used this step, [2] R, [3..5] vx vy omega, [6..8] Fx Fy Mz.
#include <mujoco/mujoco.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <exception>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "contensou/friction/contact_patch.hpp"
#include "contensou/friction/exact_resultants.hpp"
#include "contensou/friction/fractional_law.hpp"
#include "contensou/friction/pressure_profile.hpp"

namespace contensou::mujoco_plugin {
namespace {

constexpr int kStateSize = 9;
constexpr const char* kName = "contensou.friction";
constexpr std::array<const char*, 8> kAttributes = {
    "pairs", "profile", "friction", "radius", "stiffness", "law", "regularization", "tolerance"};

struct Pair {
  int tire = -1, road = -1;  // geom ids
};

struct Config {
  std::vector<std::pair<std::string, std::string>> pair_names;
  std::string profile = "uniform";
  double friction = 0.0;
  double radius = 0.0;     // 0: from the stiffness
  double stiffness = 0.0;  // N/m^3
  bool exact = false;
  double regularization = 1e-4;
  double tolerance = 1e-8;
};

[[noreturn]] void fail(const std::string& message) {
  mju_error("%s", (std::string(kName) + ": " + message).c_str());
  std::abort();  // mju_error does not return
}

std::string attribute(const mjModel* m, int instance, const char* key) {
  const char* v = mj_getPluginConfig(m, instance, key);
  return v ? std::string(v) : std::string();
}

double number(const mjModel* m, int instance, const char* key, double fallback, bool positive) {
  const std::string s = attribute(m, instance, key);
  if (s.empty()) return fallback;
  char* end = nullptr;
  const double x = std::strtod(s.c_str(), &end);
  if (end == s.c_str() || *end != '\0' || !std::isfinite(x) || (positive && !(x > 0)))
    fail(std::string("config '") + key + "' = '" + s + "' is not a " +
         (positive ? "positive " : "") + "number");
  return x;
}

Config read_config(const mjModel* m, int instance) {
  Config c;
  std::stringstream pairs(attribute(m, instance, "pairs"));
  std::string item;
  while (std::getline(pairs, item, ';')) {
    std::stringstream words(item);
    std::string a, b, extra;
    if (!(words >> a)) continue;
    if (!(words >> b) || (words >> extra))
      fail("config 'pairs': '" + item + "' is not two geom names (tire road)");
    c.pair_names.emplace_back(a, b);
  }
  if (c.pair_names.empty()) fail("config 'pairs' is empty: name the geom pairs (tire road; ...)");
  const std::string profile = attribute(m, instance, "profile");
  if (!profile.empty()) c.profile = profile;
  if (c.profile != "uniform" && c.profile != "hertz" && c.profile != "seed-tire")
    fail("config 'profile' = '" + c.profile + "': use uniform, hertz or seed-tire");
  c.friction = number(m, instance, "friction", 0.0, true);
  if (attribute(m, instance, "friction").empty()) fail("config 'friction' (f) is required");
  c.radius = number(m, instance, "radius", 0.0, true);
  c.stiffness = number(m, instance, "stiffness", 0.0, true);
  if ((c.radius > 0) == (c.stiffness > 0))
    fail("give exactly one of config 'radius' [m] and 'stiffness' [N/m^3]");
  const std::string law = attribute(m, instance, "law");
  if (!law.empty() && law != "fractional" && law != "exact")
    fail("config 'law' = '" + law + "': use fractional or exact");
  c.exact = law == "exact";
  c.regularization = number(m, instance, "regularization", 1e-4, true);
  c.tolerance = number(m, instance, "tolerance", 1e-8, true);
  return c;
}

// The instance: the law for a unit patch (R = 1 m, N = 1 N), scaled per contact. Coulomb
// friction with constant f is homogeneous of degree 0 in the velocities, so the exact resultants
// are F = N F_1(v/R, omega), Mz = N R Mz_1(v/R, omega) (theory.md section 3 uses the same
// scaling); the fractional law scales F0 = f N and M0 = f N R A^2/A^1 (theory.md section 4:
// M0 = 2 pi f R^3 p* A^2 with N = 2 pi R^2 p* A^1).
struct Instance {
  Config config;
  std::vector<Pair> pairs;
  FractionalLaw<double> unit_law;
  std::unique_ptr<ExactModel<double>> unit_exact;

  Resultants<double> wrench(double N, double R, double vx, double vy, double omega) const {
    if (!(N > 0)) return {};
    if (unit_exact) {
      const Kinematics<double> k{vx / R, vy / R, omega};
      Resultants<double> r = exact_resultants(*unit_exact, k, {config.tolerance}).resultants;
      return {N * r.Fx, N * r.Fy, N * R * r.Mz};
    }
    FractionalLaw<double> law = unit_law;
    law.F0 *= N;
    law.M0 *= N * R;
    law.Mk *= N * R;
    law.radius = R;
    law.regularization_speed = config.regularization;
    return fractional_resultants(law, Kinematics<double>{vx, vy, omega});
  }
};

ContactPatch unit_patch(const Config& c) {
  ContactPatch p;
  p.radius_m = 1.0;
  p.friction = c.friction;
  p.profile = c.profile == "hertz"       ? hertz_profile()
              : c.profile == "seed-tire" ? seed_tire_patch().profile
                                         : uniform_profile();
  p.reference_pressure_pa = 1.0;
  p.reference_pressure_pa = 1.0 / normal_load(p);  // N = 1
  return p;
}

Instance* instance_of(const mjData* d, int instance) {
  return reinterpret_cast<Instance*>(d->plugin_data[instance]);
}

int geom_id(const mjModel* m, const std::string& name) {
  const int id = mj_name2id(m, mjOBJ_GEOM, name.c_str());
  if (id < 0) fail("config 'pairs': no geom named '" + name + "'");
  if (m->geom_condim[id] != 1)
    fail("geom '" + name + "' has condim " + std::to_string(m->geom_condim[id]) +
         ": set condim=\"1\" so that MuJoCo's own friction is off on the pairs of the plugin");
  return id;
}

int nstate(const mjModel* m, int instance) {
  return kStateSize * static_cast<int>(read_config(m, instance).pair_names.size());
}

int init(const mjModel* m, mjData* d, int instance) {
  auto inst = std::make_unique<Instance>();
  inst->config = read_config(m, instance);
  for (const auto& [tire, road] : inst->config.pair_names)
    inst->pairs.push_back({geom_id(m, tire), geom_id(m, road)});
  try {
    const ContactPatch patch = unit_patch(inst->config);
    if (inst->config.exact)
      inst->unit_exact = std::make_unique<ExactModel<double>>(make_exact_model(patch));
    else
      inst->unit_law = fractional_law_from_patch(patch);
  } catch (const std::exception& e) {
    fail(e.what());
  }
  d->plugin_data[instance] = reinterpret_cast<uintptr_t>(inst.release());
  return 0;
}

void destroy(mjData* d, int instance) {
  delete instance_of(d, instance);
  d->plugin_data[instance] = 0;
}

void copy(mjData* dest, const mjModel*, const mjData* src, int instance) {
  const Instance* from = instance_of(src, instance);
  auto to = std::make_unique<Instance>();
  to->config = from->config;
  to->pairs = from->pairs;
  to->unit_law = from->unit_law;
  if (from->unit_exact) to->unit_exact = std::make_unique<ExactModel<double>>(*from->unit_exact);
  delete instance_of(dest, instance);
  dest->plugin_data[instance] = reinterpret_cast<uintptr_t>(to.release());
}

void reset(const mjModel* m, mjtNum* state, void*, int instance) {
  std::fill(state, state + m->plugin_statenum[instance], 0.0);
}

// +1 if contact c is (road, tire) in MuJoCo's order (its normal points from geom[0] to geom[1],
// so from road into tire as theory.md section 1 wants), -1 if (tire, road), 0 if not this pair.
int orientation(const mjContact& c, const Pair& p) {
  if (c.geom[0] == p.road && c.geom[1] == p.tire) return 1;
  if (c.geom[0] == p.tire && c.geom[1] == p.road) return -1;
  return 0;
}

// Velocity of the material point of `body` at `point` (world frame).
void point_velocity(const mjModel* m, const mjData* d, int body, const mjtNum point[3],
                    mjtNum lin[3], mjtNum rot[3]) {
  mjtNum v6[6];
  mj_objectVelocity(m, d, mjOBJ_BODY, body, v6, 0);  // at xpos[body], world orientation
  mjtNum r[3], wxr[3];
  mju_sub3(r, point, d->xpos + 3 * body);
  mju_cross(wxr, v6, r);
  mju_add3(lin, v6 + 3, wxr);
  mju_copy3(rot, v6);
}

void compute(const mjModel* m, mjData* d, int instance, int) {
  Instance* inst = instance_of(d, instance);
  mjtNum* state = d->plugin_state + m->plugin_stateadr[instance];
  for (std::size_t k = 0; k < inst->pairs.size(); ++k) {
    const Pair& p = inst->pairs[k];
    mjtNum* s = state + kStateSize * k;
    const double N = s[0];
    std::fill(s + 1, s + kStateSize, 0.0);
    int count = 0;
    mjtNum normal[3] = {0, 0, 0}, t1[3] = {0, 0, 0}, point[3] = {0, 0, 0};
    for (int i = 0; i < d->ncon; ++i) {
      const mjContact& c = d->contact[i];
      const int o = orientation(c, p);
      if (!o || c.exclude) continue;
      if (count == 0) {
        mju_scl3(normal, c.frame, o);
        mju_copy3(t1, c.frame + 3);
      }
      mju_addTo3(point, c.pos);
      ++count;
    }
    if (count == 0 || !(N > 0)) continue;
    mju_scl3(point, point, 1.0 / count);
    // Patch centre: the tire geom's centre projected onto the contact plane through `point`.
    mjtNum centre[3], rel[3];
    mju_sub3(rel, d->geom_xpos + 3 * p.tire, point);
    mju_addScl3(centre, d->geom_xpos + 3 * p.tire, normal, -mju_dot3(rel, normal));
    // Frame: x = first tangent of MuJoCo's contact frame, z = normal (road into tire), y = z x x.
    mjtNum ex[3], ey[3];
    mju_addScl3(ex, t1, normal, -mju_dot3(t1, normal));
    mju_normalize3(ex);
    mju_cross(ey, normal, ex);
    const int tire_body = m->geom_bodyid[p.tire], road_body = m->geom_bodyid[p.road];
    mjtNum vt[3], wt[3], vr[3], wr[3], dv[3], dw[3];
    point_velocity(m, d, tire_body, centre, vt, wt);
    point_velocity(m, d, road_body, centre, vr, wr);
    mju_sub3(dv, vt, vr);
    mju_sub3(dw, wt, wr);
    const double vx = mju_dot3(dv, ex), vy = mju_dot3(dv, ey), omega = mju_dot3(dw, normal);
    // Patch radius: given, or Hertz-like R = (N / k)^(1/3) (a sphere on a plane:
    // a = (3 N R_s / 4 E*)^(1/3), Johnson, Contact Mechanics, eq. 4.22, so k = 4 E* / 3 R_s).
    const double R =
        inst->config.radius > 0 ? inst->config.radius : std::cbrt(N / inst->config.stiffness);
    Resultants<double> w;
    try {
      w = inst->wrench(N, R, vx, vy, omega);
    } catch (const std::exception& e) {
      fail(e.what());
    }
    mjtNum force[3], torque[3];
    mju_scl3(force, ex, w.Fx);
    mju_addToScl3(force, ey, w.Fy);
    mju_scl3(torque, normal, w.Mz);
    mj_applyFT(m, d, force, torque, centre, tire_body, d->qfrc_passive);
    mju_scl3(force, force, -1.0);
    mju_scl3(torque, torque, -1.0);
    mj_applyFT(m, d, force, torque, centre, road_body, d->qfrc_passive);
    s[1] = N;
    s[2] = R;
    s[3] = vx;
    s[4] = vy;
    s[5] = omega;
    s[6] = w.Fx;
    s[7] = w.Fy;
    s[8] = w.Mz;
  }
}

// After MuJoCo's constraint solver: store this step's normal force of each pair for the next.
void advance(const mjModel* m, mjData* d, int instance) {
  Instance* inst = instance_of(d, instance);
  mjtNum* state = d->plugin_state + m->plugin_stateadr[instance];
  for (std::size_t k = 0; k < inst->pairs.size(); ++k) {
    double N = 0.0;
    for (int i = 0; i < d->ncon; ++i) {
      const mjContact& c = d->contact[i];
      if (!orientation(c, inst->pairs[k]) || c.exclude || c.efc_address < 0) continue;
      mjtNum f6[6];
      mj_contactForce(m, d, i, f6);
      N += f6[0];
    }
    state[kStateSize * k] = N;
  }
}

}  // namespace
}  // namespace contensou::mujoco_plugin

mjPLUGIN_LIB_INIT(contensou_friction) {
  using namespace contensou::mujoco_plugin;
  mjpPlugin plugin;
  mjp_defaultPlugin(&plugin);
  plugin.name = kName;
  plugin.capabilityflags |= mjPLUGIN_PASSIVE;
  plugin.nattribute = static_cast<int>(kAttributes.size());
  plugin.attributes = kAttributes.data();
  plugin.nstate = nstate;
  plugin.init = init;
  plugin.destroy = destroy;
  plugin.copy = copy;
  plugin.reset = reset;
  plugin.compute = compute;
  plugin.advance = advance;
  mjp_registerPlugin(&plugin);
}
