// MuJoCo engine plugin "contensou.friction": coupled sliding-spinning friction over a circular
// contact patch (theory.md §1-4) for the geom pairs named in the plugin's configuration, which
// must have condim="1": MuJoCo keeps the normal force, the plugin replaces MuJoCo's friction by
// the patch's wrench (Fx, Fy, Mz), applied to qfrc_passive. Laws: fractional (default), exact
// (exact_law.hpp, built at init), set-valued (a Moreau-Jean projection onto the limit surface,
// limit_surface.hpp). The normal force is the previous step's contact solution, stored in
// `advance`.
// Contract: the configuration keys, their ranges and the errors at init (a value outside its
// range, a pair named twice or never colliding, a plane as the tire, a tolerance the exact law
// cannot reach) are documented in docs/mujoco.md, "The plugin"; the per-step algorithm, the
// set-valued step and the state layout per pair (kStateSize numbers) in docs/mujoco.md,
// "Inside the plugin". An exception of the library becomes mju_error naming the plugin (fail).
#include <mujoco/mujoco.h>

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <unordered_map>
#include <vector>

#include "contensou/friction/contact_patch.hpp"
#include "contensou/friction/exact_law.hpp"
#include "contensou/friction/exact_resultants.hpp"
#include "contensou/friction/fractional_law.hpp"
#include "contensou/friction/limit_surface.hpp"
#include "contensou/friction/pressure_profile.hpp"
#include "plugin_config.hpp"

namespace contensou::mujoco_plugin {
namespace {

// State layout per pair (header comment).
constexpr int kN = 0, kNUsed = 1, kRadius = 2, kTwist = 3, kWrench = 6, kStick = 9, kIter = 10,
              kContact = 11, kCentre = 12, kVel = 15, kForce = 21, kOther = 27, kOtherValid = 33;
constexpr int kStateSize = 34;
constexpr std::array<const char*, 10> kAttributes = {
    "pairs",     "profile", "friction", "kappa",          "radius",
    "stiffness", "law",     "surface",  "regularization", "tolerance"};

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;

struct Pair {
  int tire = -1, road = -1;  // geom ids
  double widest = 0.0;       // the largest patch radius [m]: the tire geom's bounding radius
};

// The key of a geom pair in either order: (min id) * 2^32 + max id.
std::uint64_t pair_key(int a, int b) {
  const auto lo = static_cast<std::uint32_t>(std::min(a, b));
  const auto hi = static_cast<std::uint32_t>(std::max(a, b));
  return (std::uint64_t{lo} << 32) | hi;
}

// A pair's contacts in this step, gathered by one pass over d->contact in MuJoCo's order.
struct PairContacts {
  int count = 0;
  mjtNum normal[3] = {0, 0, 0};  // the first contact's normal, from road into tire
  mjtNum t1[3] = {0, 0, 0};      // the first contact's first tangent
  mjtNum point[3] = {0, 0, 0};   // sum of the contact points
};

// nv as the int that mju_* and mj_solveM take (mjtSize in MuJoCo 4).
int dofs(const mjModel* m) {
  return static_cast<int>(m->nv);
}

// Work arrays of the set-valued law (nv = degrees of freedom).
struct Scratch {
  std::vector<mjtNum> jp_tire, jr_tire, jp_road, jr_road;  // 3 x nv each
  std::vector<mjtNum> jw;                                  // 6 x nv: relative, world frame
  std::vector<mjtNum> j, x;                                // 3 x nv: contact rows, M^-1 rows
  std::vector<mjtNum> q, y;                                // nv
  void resize(int nv) {
    for (auto* v : {&jp_tire, &jr_tire, &jp_road, &jr_road, &j, &x})
      v->assign(3 * static_cast<std::size_t>(nv), 0.0);
    jw.assign(6 * static_cast<std::size_t>(nv), 0.0);
    q.assign(nv, 0.0);
    y.assign(nv, 0.0);
  }
};

// The instance: the law for a unit patch (R = 1 m, N = 1 N), scaled per contact. Coulomb
// friction with constant f is homogeneous of degree 0 in the velocities, so the exact resultants
// are F = N F_1(v/R, omega), Mz = N R Mz_1(v/R, omega) (theory.md section 3 uses the same
// scaling; the exact law's error bound, relative to f N and f N R, scales with them); the
// fractional law scales F0 = f N and M0 = f N R A^2/A^1 (theory.md section 4:
// M0 = 2 pi f R^3 p* A^2 with N = 2 pi R^2 p* A^1); the limit surface scales as
// C(N, R) = N diag(1, 1, R) C_1 (the same homogeneity: its points are exact resultants).
struct Instance {
  Config config;
  std::vector<Pair> pairs;
  std::unordered_map<std::uint64_t, int> pair_of;  // pair_key(tire, road) -> index in pairs
  std::vector<PairContacts> contacts;              // per pair, this step
  FractionalLaw<double> unit_law;
  std::shared_ptr<const ExactLaw> unit_exact;             // read only: shared by copies
  std::unique_ptr<LimitSurface> unit_surface;             // set-valued, exact surface
  std::optional<EllipsoidalLimitSurface> unit_ellipsoid;  // set-valued, ellipsoid
  Scratch scratch;

  // Index in `pairs` of a contact's geom pair, -1 if none.
  int pair_index(const mjContact& c) const {
    const auto it = pair_of.find(pair_key(c.geom[0], c.geom[1]));
    return it == pair_of.end() ? -1 : it->second;
  }

  Resultants<double> wrench(double N, double R, double vx, double vy, double omega) const {
    if (!(N > 0)) return {};
    if (unit_exact) {
      const Kinematics<double> k{vx / R, vy / R, omega};
      const Resultants<double> r = exact_law_resultants(*unit_exact, k);
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

  Projection project_unit(const Vec3& trial, const Mat3& metric) const {
    return unit_ellipsoid ? project(*unit_ellipsoid, trial, metric)
                          : project(*unit_surface, trial, metric);
  }
};

// The unit patch, R = 1 m and N = 1 N: the law is scaled per step by the pair's R and by the
// normal force MuJoCo's solver gives (no load or pressure in the configuration).
ContactPatch unit_patch(const Config& c) {
  const PressureProfile profile = c.profile == "hertz"       ? hertz_profile()
                                  : c.profile == "seed-tire" ? seed_tire_profile()
                                                             : uniform_profile();
  return ContactPatch::from_normal_load(1.0, 1.0, profile, c.friction, c.kappa);
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

// Why MuJoCo never makes a contact between geoms a and b ("" if it may). Its broad phase skips
// geoms of one weld body, of a weld body and its parent's (unless filterparent is disabled; not
// with the world) and geoms whose contype and conaffinity do not match (contype_a & conaffinity_b
// and contype_b & conaffinity_a both 0); a <contact><pair> bypasses these filters.
std::string never_collides(const mjModel* m, int a, int b) {
  if (a == b) return "a geom has no contact with itself";
  for (int i = 0; i < static_cast<int>(m->npair); ++i)
    if (pair_key(m->pair_geom1[i], m->pair_geom2[i]) == pair_key(a, b)) return "";
  const int wa = m->body_weldid[m->geom_bodyid[a]], wb = m->body_weldid[m->geom_bodyid[b]];
  if (wa == wb) return "both geoms are on one body (or bodies welded together)";
  const int pa = m->body_weldid[m->body_parentid[wa]], pb = m->body_weldid[m->body_parentid[wb]];
  if (!(m->opt.disableflags & mjDSBL_FILTERPARENT) && wa != 0 && wb != 0 && (wa == pb || wb == pa))
    return "one geom's body is the other's parent (MuJoCo filters parent-child contacts)";
  if (!(m->geom_contype[a] & m->geom_conaffinity[b]) &&
      !(m->geom_contype[b] & m->geom_conaffinity[a]))
    return "their contype and conaffinity do not match";
  return "";
}

// A pair whose friction would be lost or misplaced is an error (item: "'tire road'").
void check_pair(const mjModel* m, const std::string& item, const Pair& p) {
  const std::string why = never_collides(m, p.tire, p.road);
  if (!why.empty()) fail("config 'pairs': " + item + " never touch: " + why);
  const int type = m->geom_type[p.tire];
  if (type == mjGEOM_PLANE || type == mjGEOM_HFIELD)
    fail("config 'pairs': " + item + ": the tire (first) geom is a " +
         (type == mjGEOM_PLANE ? "plane" : "height field") +
         ", whose centre is no patch centre; name the tire first, then the road");
}

// A pair of this instance that another instance of the plugin also names is an error.
void check_other_instances(const mjModel* m, int instance, const Instance& inst) {
  for (int i = 0; i < static_cast<int>(m->nplugin); ++i) {
    if (i == instance || m->plugin[i] != m->plugin[instance]) continue;
    for (const auto& [a, b] : read_pair_names(m, i)) {
      const int ga = mj_name2id(m, mjOBJ_GEOM, a.c_str()),
                gb = mj_name2id(m, mjOBJ_GEOM, b.c_str());
      if (ga < 0 || gb < 0 || !inst.pair_of.count(pair_key(ga, gb))) continue;
      fail("config 'pairs': '" + a + " " + b + "' is also a pair of plugin instance '" +
           std::string(m->names + m->name_pluginadr[i]) + "': its friction would be applied twice");
    }
  }
}

// The patch of a pair lies in [kShortest, widest] (Pair::widest: the tire geom's bounding
// radius, at most kLongest): a 'radius' outside is an error naming the pair; a 'stiffness' k is
// an error when the patch R = (W / k)^(1/3) under the weight W of the tire's mechanism (the
// subtree mass of its root body times |g|; without gravity, any force MuJoCo holds, 1e-15 to
// 1e10 N) is outside that range: k in [W / widest^3, W / kShortest^3].
void check_patch_size(const mjModel* m, int instance, const std::string& item, const Config& c,
                      Pair& p) {
  p.widest = std::min(static_cast<double>(m->geom_rbound[p.tire]), kLongest);
  const std::string geom = "the tire geom's bounding radius (pair " + item + ")";
  if (c.radius > 0) {
    require_within("radius", attribute(m, instance, "radius"), c.radius, kShortest, p.widest, "m",
                   "a patch no narrower than mjMINVAL and no wider than " + geom);
    return;
  }
  const int root = m->body_rootid[m->geom_bodyid[p.tire]];
  const double weight = m->body_subtreemass[root] * mju_norm3(m->opt.gravity);
  const double low = weight > 0 ? weight : mjMINVAL, high = weight > 0 ? weight : mjMAXVAL;
  const double wide = p.widest * p.widest * p.widest, narrow = kShortest * kShortest * kShortest;
  require_within("stiffness", attribute(m, instance, "stiffness"), c.stiffness, low / wide,
                 high / narrow, "N/m^3",
                 weight > 0 ? "the patch (W / k)^(1/3) under the weight W = " + format(weight) +
                                  " N of the tire's mechanism must lie between mjMINVAL and " + geom
                            : "with no weight, the patch (N / k)^(1/3) must lie between "
                              "mjMINVAL and " +
                                  geom + " for some force N from 1e-15 to 1e10 N");
}

// The geom ids of the configured pairs and their index by geom pair (Instance::pair_of).
void resolve_pairs(const mjModel* m, int instance, Instance& inst) {
  const auto& names = inst.config.pair_names;
  for (std::size_t k = 0; k < names.size(); ++k) {
    const Pair p{geom_id(m, names[k].first), geom_id(m, names[k].second)};
    const std::string item = "'" + names[k].first + " " + names[k].second + "'";
    check_pair(m, item, p);
    const auto [it, fresh] = inst.pair_of.emplace(pair_key(p.tire, p.road), static_cast<int>(k));
    if (!fresh) {
      const auto& [a, b] = names[it->second];
      fail("config 'pairs': " + item + " and '" + a + " " + b +
           "' are the same geom pair: its friction would be applied twice");
    }
    inst.pairs.push_back(p);
  }
  check_other_instances(m, instance, inst);
  inst.contacts.assign(inst.pairs.size(), PairContacts{});
  for (std::size_t k = 0; k < names.size(); ++k)
    check_patch_size(m, instance, "'" + names[k].first + " " + names[k].second + "'", inst.config,
                     inst.pairs[k]);
}

// The unit patch's law of the configured kind (Instance).
void build_law(Instance& inst) {
  try {
    const ContactPatch patch = unit_patch(inst.config);
    switch (inst.config.law) {
      case Law::exact:
        inst.unit_exact = std::make_shared<const ExactLaw>(
            make_exact_law(make_exact_model(patch), ExactLawOptions{inst.config.tolerance}));
        break;
      case Law::fractional:
        inst.unit_law = fractional_law_from_patch(patch);
        break;
      case Law::set_valued: {
        auto surface =
            std::make_unique<LimitSurface>(make_limit_surface(patch, inst.config.tolerance));
        if (inst.config.ellipsoid)
          inst.unit_ellipsoid = fit_ellipsoid(*surface);
        else
          inst.unit_surface = std::move(surface);
        break;
      }
    }
  } catch (const std::exception& e) {
    fail(e.what());
  }
  if (inst.unit_exact && !inst.unit_exact->reached)
    fail("config 'tolerance' = " + format(inst.config.tolerance) + ": the exact law reached " +
         format(inst.unit_exact->achieved) + " (relative to f N), not the tolerance; use a " +
         "larger tolerance" +
         (inst.config.kappa > 1.0
              ? " (the error relative to f N grows with kappa = " + format(inst.config.kappa) +
                    ": about 1.6e-13 kappa is reached)"
              : std::string()));
}

int init(const mjModel* m, mjData* d, int instance) {
  auto inst = std::make_unique<Instance>();
  inst->config = read_config(m, instance);
  resolve_pairs(m, instance, *inst);
  build_law(*inst);
  inst->scratch.resize(dofs(m));
  d->plugin_data[instance] = reinterpret_cast<uintptr_t>(inst.release());
  return 0;
}

void destroy(mjData* d, int instance) {
  delete instance_of(d, instance);
  d->plugin_data[instance] = 0;
}

void copy(mjData* dest, const mjModel* m, const mjData* src, int instance) {
  const Instance* from = instance_of(src, instance);
  auto to = std::make_unique<Instance>();
  to->config = from->config;
  to->pairs = from->pairs;
  to->pair_of = from->pair_of;
  to->contacts = from->contacts;
  to->unit_law = from->unit_law;
  to->unit_exact = from->unit_exact;
  if (from->unit_surface) to->unit_surface = std::make_unique<LimitSurface>(*from->unit_surface);
  to->unit_ellipsoid = from->unit_ellipsoid;
  to->scratch.resize(dofs(m));
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

// Relative Jacobian (6 x nv, world frame; rows 0-2 linear velocity, 3-5 angular velocity) of
// the tire's material point at `point` with respect to the road's: mj_jac(tire) - mj_jac(road).
void relative_jacobian(const mjModel* m, const mjData* d, const mjtNum point[3], int tire_body,
                       int road_body, Scratch& w) {
  const int nv = dofs(m);
  mj_jac(m, d, w.jp_tire.data(), w.jr_tire.data(), point, tire_body);
  mj_jac(m, d, w.jp_road.data(), w.jr_road.data(), point, road_body);
  for (int k = 0; k < 3 * nv; ++k) {
    w.jw[k] = w.jp_tire[k] - w.jp_road[k];
    w.jw[3 * nv + k] = w.jr_tire[k] - w.jr_road[k];
  }
}

// The generalised force of the applied inputs: qfrc_applied + xfrc_applied (force and torque
// at each body's centre of mass, as MuJoCo applies them).
void applied_force(const mjModel* m, mjData* d, mjtNum* q) {
  mju_copy(q, d->qfrc_applied, dofs(m));
  for (int b = 1; b < m->nbody; ++b) {
    const mjtNum* f = d->xfrc_applied + 6 * b;
    if (!mju_isZero(f, 6)) mj_applyFT(m, d, f, f + 3, d->xipos + 3 * b, b, q);
  }
}

// The set-valued law at one pair (header comment): fills the wrench, stick flag and iterations.
// s: this step's state block of the pair; ex, ey, normal: the contact frame.
Vec3 set_valued_wrench(const mjModel* m, mjData* d, Instance& inst, mjtNum* s, double N, double R,
                       const mjtNum ex[3], const mjtNum ey[3], const mjtNum normal[3]) {
  const int nv = dofs(m);
  const double h = m->opt.timestep;
  Scratch& w = inst.scratch;
  // Contact rows of the Jacobian: ex.Jp, ey.Jp, n.Jr.
  for (int j = 0; j < nv; ++j) {
    mjtNum p[3] = {w.jw[j], w.jw[nv + j], w.jw[2 * nv + j]};
    mjtNum r[3] = {w.jw[3 * nv + j], w.jw[4 * nv + j], w.jw[5 * nv + j]};
    w.j[j] = mju_dot3(ex, p);
    w.j[nv + j] = mju_dot3(ey, p);
    w.j[2 * nv + j] = mju_dot3(normal, r);
  }
  // A = h J M^-1 J^T (rows of X = M^-1 J_i^T).
  mj_solveM(m, d, w.x.data(), w.j.data(), 3);
  Mat3 A;
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) A(a, b) = h * mju_dot(w.j.data() + a * nv, w.x.data() + b * nv, nv);
  A = 0.5 * (A + A.transpose());
  const Vec3 twist(s[kTwist], s[kTwist + 1], s[kTwist + 2]);
  // s_free = s + h (c projected on the contact frame + J M^-1 f_app); c from the previous step.
  Vec3 s_free = twist;
  if (s[kOtherValid] != 0.0) {
    applied_force(m, d, w.q.data());
    mj_solveM(m, d, w.y.data(), w.q.data(), 1);
    const mjtNum* c = s + kOther;
    Vec3 a_other(mju_dot3(ex, c), mju_dot3(ey, c), mju_dot3(normal, c + 3));
    for (int a = 0; a < 3; ++a) a_other[a] += mju_dot(w.j.data() + a * nv, w.y.data(), nv);
    s_free += h * a_other;
  }
  // Scaled: u = S^-1 w / N, S = diag(1, 1, R); metric G = S A S; u_t = -G^-1 S s_free / N.
  const Vec3 Sd(1.0, 1.0, R);
  Mat3 G = Sd.asDiagonal() * A * Sd.asDiagonal();
  const Eigen::SelfAdjointEigenSolver<Mat3> eig(G, Eigen::EigenvaluesOnly);
  const double lmax = eig.eigenvalues().maxCoeff(), lmin = eig.eigenvalues().minCoeff();
  if (!(lmax > 0.0)) return Vec3::Zero();  // the pair cannot move relative to the road
  if (lmin < 1e-12 * lmax) G.diagonal().array() += 1e-12 * lmax - std::min(lmin, 0.0);
  const Vec3 u_t = -G.llt().solve(Sd.cwiseProduct(s_free)) / N;
  Projection p;
  try {
    p = inst.project_unit(u_t, G);
  } catch (const std::exception& e) {
    fail(e.what());
  }
  s[kStick] = p.inside ? 1.0 : 0.0;
  s[kIter] = p.iterations;
  return N * Sd.cwiseProduct(p.wrench);
}

// One pass over d->contact: each contact of a configured pair adds to that pair's
// PairContacts, in MuJoCo's order (the first contact gives the normal and tangent).
void gather_contacts(const mjData* d, Instance& inst) {
  std::fill(inst.contacts.begin(), inst.contacts.end(), PairContacts{});
  for (int i = 0; i < d->ncon; ++i) {
    const mjContact& c = d->contact[i];
    const int k = c.exclude ? -1 : inst.pair_index(c);
    if (k < 0) continue;
    PairContacts& pc = inst.contacts[k];
    if (pc.count == 0) {
      mju_scl3(pc.normal, c.frame, orientation(c, inst.pairs[k]));
      mju_copy3(pc.t1, c.frame + 3);
    }
    mju_addTo3(pc.point, c.pos);
    ++pc.count;
  }
}

// The patch centre (the tire geom's centre projected onto the contact plane through the mean
// contact point) and frame: z = normal (road into tire), x = the tire geom's x axis projected
// onto the contact plane (the longitudinal direction of kappa, theory.md section 2; its y axis
// if x is within 0.1 degree of the normal, MuJoCo's first contact tangent if both are),
// y = z x x.
void patch_frame(const mjData* d, const Pair& p, const PairContacts& pc, mjtNum centre[3],
                 mjtNum ex[3], mjtNum ey[3]) {
  mjtNum point[3], rel[3];
  mju_scl3(point, pc.point, 1.0 / pc.count);
  mju_sub3(rel, d->geom_xpos + 3 * p.tire, point);
  mju_addScl3(centre, d->geom_xpos + 3 * p.tire, pc.normal, -mju_dot3(rel, pc.normal));
  const mjtNum* xmat = d->geom_xmat + 9 * p.tire;  // row-major: column j is the geom's axis j
  bool found = false;
  for (int j = 0; j < 2 && !found; ++j) {
    const mjtNum axis[3] = {xmat[j], xmat[3 + j], xmat[6 + j]};
    mju_addScl3(ex, axis, pc.normal, -mju_dot3(axis, pc.normal));
    found = mju_norm3(ex) > 2e-3;
  }
  if (!found) mju_addScl3(ex, pc.t1, pc.normal, -mju_dot3(pc.t1, pc.normal));
  mju_normalize3(ex);
  mju_cross(ey, pc.normal, ex);
}

// The wrench (Fx, Fy, Mz) in the patch frame on the tire at the centre, and its opposite on the
// road, into qfrc_passive (J^T f of each body; skipped for a body welded to the world, whose
// Jacobian is 0); the tire's (world frame) into the state block s.
void apply_wrench(const mjModel* m, mjData* d, const Pair& p, const Resultants<double>& w,
                  const mjtNum centre[3], const mjtNum ex[3], const mjtNum ey[3],
                  const mjtNum normal[3], mjtNum* s) {
  mjtNum force[3], torque[3];
  mju_scl3(force, ex, w.Fx);
  mju_addToScl3(force, ey, w.Fy);
  mju_scl3(torque, normal, w.Mz);
  mju_copy3(s + kForce, force);
  mju_copy3(s + kForce + 3, torque);
  const int tire_body = m->geom_bodyid[p.tire], road_body = m->geom_bodyid[p.road];
  if (m->body_weldid[tire_body] != 0)
    mj_applyFT(m, d, force, torque, centre, tire_body, d->qfrc_passive);
  if (m->body_weldid[road_body] == 0) return;
  mju_scl3(force, force, -1.0);
  mju_scl3(torque, torque, -1.0);
  mj_applyFT(m, d, force, torque, centre, road_body, d->qfrc_passive);
}

// One pair's step (header comment): twist, law, wrench; s is its state block.
void pair_step(const mjModel* m, mjData* d, Instance& inst, std::size_t k, mjtNum* s) {
  const Pair& p = inst.pairs[k];
  const PairContacts& pc = inst.contacts[k];
  const bool set_valued = inst.config.law == Law::set_valued;
  const double N = s[kN];
  std::fill(s + kNUsed, s + kOther, 0.0);  // keeps N and c, written by `advance`
  // The set-valued law keeps a history (c) of every step with contacts, even at N = 0.
  if (pc.count == 0 || (!(N > 0) && !set_valued)) return;
  mjtNum centre[3], ex[3], ey[3];
  patch_frame(d, p, pc, centre, ex, ey);
  const int tire_body = m->geom_bodyid[p.tire], road_body = m->geom_bodyid[p.road];
  mjtNum dv[3], dw[3];
  if (set_valued) {
    // The twist from the Jacobian (J qvel), the same J as the Delassus matrix's.
    relative_jacobian(m, d, centre, tire_body, road_body, inst.scratch);
    mju_mulMatVec(s + kVel, inst.scratch.jw.data(), d->qvel, 6, dofs(m));
    mju_copy3(dv, s + kVel);
    mju_copy3(dw, s + kVel + 3);
    mju_copy3(s + kCentre, centre);
    s[kContact] = 1.0;
  } else {
    mjtNum vt[3], wt[3], vr[3], wr[3];
    point_velocity(m, d, tire_body, centre, vt, wt);
    point_velocity(m, d, road_body, centre, vr, wr);
    mju_sub3(dv, vt, vr);
    mju_sub3(dw, wt, wr);
  }
  const double vx = mju_dot3(dv, ex), vy = mju_dot3(dv, ey), omega = mju_dot3(dw, pc.normal);
  s[kTwist] = vx;
  s[kTwist + 1] = vy;
  s[kTwist + 2] = omega;
  if (!(N > 0)) return;
  // Patch radius: given, or Hertz-like R = (N / k)^(1/3) (a sphere on a plane:
  // a = (3 N R_s / 4 E*)^(1/3), Johnson, Contact Mechanics, eq. 4.22, so k = 4 E* / 3 R_s),
  // kept within [kShortest, the tire geom's bounding radius] (a patch covers at most its tire).
  const double R = inst.config.radius > 0
                       ? inst.config.radius
                       : std::clamp(std::cbrt(N / inst.config.stiffness), kShortest, p.widest);
  Resultants<double> w;
  if (set_valued) {
    const Vec3 ws = set_valued_wrench(m, d, inst, s, N, R, ex, ey, pc.normal);
    w = {ws[0], ws[1], ws[2]};
  } else {
    try {
      w = inst.wrench(N, R, vx, vy, omega);
    } catch (const std::exception& e) {
      fail(e.what());
    }
  }
  apply_wrench(m, d, p, w, centre, ex, ey, pc.normal, s);
  s[kNUsed] = N;
  s[kRadius] = R;
  s[kWrench] = w.Fx;
  s[kWrench + 1] = w.Fy;
  s[kWrench + 2] = w.Mz;
}

void compute(const mjModel* m, mjData* d, int instance, int) {
  Instance* inst = instance_of(d, instance);
  mjtNum* state = d->plugin_state + m->plugin_stateadr[instance];
  gather_contacts(d, *inst);
  for (std::size_t k = 0; k < inst->pairs.size(); ++k)
    pair_step(m, d, *inst, k, state + kStateSize * k);
}

// The set-valued law's history (header comment): after the step, the patch acceleration from
// everything but this pair's friction and the applied inputs,
//   c = (J qvel+ - s) / h - J M^-1 (J^T w + f_app),
// with this step's J (kinematics are not yet updated), qLD and wrench w.
void store_other_acceleration(const mjModel* m, mjData* d, Instance& inst, const Pair& p,
                              mjtNum* s) {
  s[kOtherValid] = 0.0;
  if (s[kContact] == 0.0) return;
  const int nv = dofs(m);
  const int tire_body = m->geom_bodyid[p.tire], road_body = m->geom_bodyid[p.road];
  Scratch& w = inst.scratch;
  relative_jacobian(m, d, s + kCentre, tire_body, road_body, w);
  applied_force(m, d, w.q.data());
  mjtNum neg[6];
  mj_applyFT(m, d, s + kForce, s + kForce + 3, s + kCentre, tire_body, w.q.data());
  mju_scl(neg, s + kForce, -1.0, 6);
  mj_applyFT(m, d, neg, neg + 3, s + kCentre, road_body, w.q.data());
  mj_solveM(m, d, w.y.data(), w.q.data(), 1);
  mjtNum after[6], known[6];
  mju_mulMatVec(after, w.jw.data(), d->qvel, 6, nv);
  mju_mulMatVec(known, w.jw.data(), w.y.data(), 6, nv);
  const double h = m->opt.timestep;
  for (int i = 0; i < 6; ++i) s[kOther + i] = (after[i] - s[kVel + i]) / h - known[i];
  s[kOtherValid] = 1.0;
}

// After MuJoCo's constraint solver: store this step's normal force of each pair for the next
// (and, set-valued, the other acceleration c).
// (One pass over d->contact, as gather_contacts: N = sum of the pair's contact normal forces.)
void advance(const mjModel* m, mjData* d, int instance) {
  Instance* inst = instance_of(d, instance);
  mjtNum* state = d->plugin_state + m->plugin_stateadr[instance];
  for (std::size_t k = 0; k < inst->pairs.size(); ++k) state[kStateSize * k + kN] = 0.0;
  for (int i = 0; i < d->ncon; ++i) {
    const mjContact& c = d->contact[i];
    if (c.exclude || c.efc_address < 0) continue;
    const int k = inst->pair_index(c);
    if (k < 0) continue;
    mjtNum f6[6];
    mj_contactForce(m, d, i, f6);
    state[kStateSize * k + kN] += f6[0];
  }
  if (inst->config.law == Law::set_valued)
    for (std::size_t k = 0; k < inst->pairs.size(); ++k)
      store_other_acceleration(m, d, *inst, inst->pairs[k], state + kStateSize * k);
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
