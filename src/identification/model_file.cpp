// The identified model as JSON and back (model_file.hpp).
#include "contensou/identification/model_file.hpp"

#include <cmath>
#include <nlohmann/json.hpp>

#include "contensou/friction/error.hpp"

namespace contensou {

namespace {

using Json = nlohmann::json;

Json optional_number(const std::optional<double>& v) {
  return v ? Json(*v) : Json();
}

Json shape_json(const ProfileShape& shape) {
  struct Visit {
    Json operator()(const UniformShape&) const { return {{"shape", "uniform"}}; }
    Json operator()(const HertzShape&) const { return {{"shape", "hertz"}}; }
    Json operator()(const CosineSeriesShape& s) const {
      return {{"shape", "cosine_series"}, {"w", s.w}, {"a", s.a}};
    }
    Json operator()(const TabulatedShape& s) const {
      return {{"shape", "table"}, {"rho", s.rho}, {"p", s.p}};
    }
    Json operator()(const ChebyshevShape& s) const { return {{"shape", "chebyshev"}, {"c", s.c}}; }
  };
  return std::visit(Visit{}, shape);
}

Json profile_json(const std::optional<PressureProfile>& p) {
  if (!p) return Json();
  Json j = shape_json(p->shape);
  j["clip_negative"] = p->clip_negative;
  j["keep_negative"] = p->keep_negative;
  return j;
}

const char* covariate_kind(Covariate::Kind k) {
  switch (k) {
    case Covariate::Kind::load:
      return "load";
    case Covariate::Kind::time:
      return "time";
    case Covariate::Kind::order:
      return "order";
    case Covariate::Kind::recorded:
      break;
  }
  return "recorded";
}

Json dependence_json(const ModelSpec& spec) {
  Json out = Json::array();
  for (const std::optional<Covariate>& c : spec.dependence)
    out.push_back(c ? Json{{"kind", covariate_kind(c->kind)},
                           {"name", c->name},
                           {"unit", c->unit},
                           {"mid", c->mid},
                           {"half_range", c->half_range}}
                    : Json());
  return out;
}

Json patch_json(const std::optional<RigidPatch>& p) {
  if (!p) return Json();
  Json wider;  // null: the bound c <= 1 does not hold the search (rigid_patch.hpp)
  if (p->wider_contact)
    wider = {{"radius_ratio", p->wider_contact->radius_ratio},
             {"exponent", p->wider_contact->exponent},
             {"median_angle_deg", p->wider_contact->median_angle_deg}};
  return {{"radius_m", p->radius_m},
          {"contact_radius_ratio", p->contact_radius_ratio},
          {"exponent", p->exponent},
          {"kx", p->kx},
          {"ky", p->ky},
          {"force_scale_N", p->force_scale_n},
          {"median_angle_deg", p->median_angle_deg},
          {"rows", p->rows},
          {"wider_contact", wider}};
}

}  // namespace

std::string model_to_json(const ModelSpec& s, int indent) {
  Json j;
  j["format"] = kModelFileFormat;
  j["radius_m"] = s.radius_m;
  j["normal_load_N"] = optional_number(s.normal_load_n);
  j["reference_load_N"] = optional_number(s.reference_load_n);
  j["law_constants"] = {{"c", s.c}, {"a_k", s.a_k}, {"mk_ratio", s.mk_ratio}};
  j["profile"] = profile_json(s.profile);
  j["profile_degree"] = s.profile_degree;
  j["profile_corrected"] = s.profile_corrected;
  j["exact_only"] = s.exact_only;
  j["speed_in_exact"] = s.speed_in_exact;
  j["admissible_shape"] = s.admissible_shape;
  j["joint_admissibility"] = s.joint_admissibility;
  j["profile_constants"] = {
      {"a", s.profile_a}, {"m", s.profile_m}, {"m0_ratio", s.profile_m0_ratio}};
  j["exact_tolerance"] = s.exact_tolerance;
  j["regularization_speed_mps"] = s.regularization_speed;
  Json params = Json::object();
  for (int i = 0; i < kModelParameters; ++i) params[parameter_info(i).name] = s.value[i];
  j["parameters"] = params;
  j["dependence"] = dependence_json(s);
  j["motion_patch"] = patch_json(s.motion_patch);
  return j.dump(indent, ' ', false, Json::error_handler_t::replace);
}

namespace {

// Reads members with errors naming them ("model.parameters.kx").
class Reader {
 public:
  explicit Reader(std::string source) : source_(std::move(source)) {}

  const Json& member(const Json& j, const std::string& name, const std::string& where) const {
    if (!j.is_object() || !j.contains(name))
      throw InvalidArgument(source_ + ": " + where + name, "missing",
                            "the model file needs it (model_file.hpp)");
    return j.at(name);
  }
  double number(const Json& j, const std::string& name, const std::string& where = "") const {
    const Json& v = member(j, name, where);
    if (!v.is_number() || !std::isfinite(v.get<double>()))
      throw InvalidArgument(source_ + ": " + where + name, v.dump(), "must be a finite number");
    return v.get<double>();
  }
  std::optional<double> optional(const Json& j, const std::string& name) const {
    if (j.contains(name) && j.at(name).is_null()) return std::nullopt;
    return number(j, name);
  }
  bool flag(const Json& j, const std::string& name) const {
    const Json& v = member(j, name, "");
    if (!v.is_boolean())
      throw InvalidArgument(source_ + ": " + name, v.dump(), "must be true or false");
    return v.get<bool>();
  }
  std::vector<double> numbers(const Json& j, const std::string& name,
                              const std::string& where) const {
    const Json& v = member(j, name, where);
    std::vector<double> out;
    if (v.is_array())
      for (const Json& x : v)
        if (x.is_number() && std::isfinite(x.get<double>())) out.push_back(x.get<double>());
    if (!v.is_array() || out.size() != v.size() || out.empty())
      throw InvalidArgument(source_ + ": " + where + name, "not a list of finite numbers",
                            "must be a non-empty list of finite numbers");
    return out;
  }
  const std::string& source() const { return source_; }

 private:
  std::string source_;
};

PressureProfile read_profile(const Reader& r, const Json& j) {
  const Json& kind = r.member(j, "shape", "profile.");
  const std::string shape = kind.is_string() ? kind.get<std::string>() : kind.dump();
  PressureProfile p;
  if (shape == "uniform") {
    p = uniform_profile();
  } else if (shape == "hertz") {
    p = hertz_profile();
  } else if (shape == "cosine_series") {
    p = cosine_series_profile(r.number(j, "w", "profile."), r.numbers(j, "a", "profile."));
  } else if (shape == "table") {
    p = tabulated_profile(r.numbers(j, "rho", "profile."), r.numbers(j, "p", "profile."));
  } else if (shape == "chebyshev") {
    p.shape = ChebyshevShape{r.numbers(j, "c", "profile.")};
  } else {
    throw InvalidArgument(r.source() + ": profile.shape", shape,
                          "must be uniform, hertz, cosine_series, table or chebyshev");
  }
  p.clip_negative = j.value("clip_negative", false);
  p.keep_negative = j.value("keep_negative", false);
  return p;
}

std::optional<Covariate> read_covariate(const Reader& r, const Json& j) {
  if (j.is_null()) return std::nullopt;
  Covariate c;
  const std::string kind = j.value("kind", std::string());
  if (kind == "load")
    c.kind = Covariate::Kind::load;
  else if (kind == "time")
    c.kind = Covariate::Kind::time;
  else if (kind == "order")
    c.kind = Covariate::Kind::order;
  else if (kind == "recorded")
    c.kind = Covariate::Kind::recorded;
  else
    throw InvalidArgument(r.source() + ": dependence.kind", kind,
                          "must be load, time, order or recorded");
  c.name = j.value("name", std::string());
  c.unit = j.value("unit", std::string());
  c.mid = r.number(j, "mid", "dependence.");
  c.half_range = r.number(j, "half_range", "dependence.");
  return c;
}

void read_parameters(const Reader& r, const Json& j, ModelSpec& s) {
  const Json& params = r.member(j, "parameters", "");
  for (int i = 0; i < kModelParameters; ++i)
    s.value[i] = params.contains(parameter_info(i).name)
                     ? r.number(params, parameter_info(i).name, "parameters.")
                     : parameter_info(i).null_value;
}

// The given profile's exact model and constants, as base_spec_for sets them.
void attach_profile(ModelSpec& s, const PressureProfile& shape) {
  const ContactPatch patch = ContactPatch::from_normal_load(s.radius_m, 1.0, shape, 1.0);
  s.profile = shape;
  s.profile_model = make_exact_model(patch, 1e-6);
  s.exact_laws = std::make_shared<ExactLawCache>(s.radius_m, s.profile_model, s.exact_tolerance);
}

// The rigid patch of the motion (absent or null: none), validated (rigid_patch.hpp).
std::optional<RigidPatch> read_patch(const Reader& r, const Json& j) {
  if (!j.contains("motion_patch") || j.at("motion_patch").is_null()) return std::nullopt;
  const Json& m = j.at("motion_patch");
  RigidPatch p;
  p.radius_m = r.number(m, "radius_m", "motion_patch.");
  p.contact_radius_ratio = r.number(m, "contact_radius_ratio", "motion_patch.");
  const double n = r.number(m, "exponent", "motion_patch.");
  if (!(n >= 0.0 && n <= kMaxPowerProfileExponent) || n != std::floor(n))
    throw InvalidArgument(
        r.source() + ": motion_patch.exponent", format_value(n),
        "must be an even integer in [0, " + std::to_string(kMaxPowerProfileExponent) + "]");
  p.exponent = static_cast<int>(n);
  p.kx = r.number(m, "kx", "motion_patch.");
  p.ky = r.number(m, "ky", "motion_patch.");
  p.force_scale_n = r.number(m, "force_scale_N", "motion_patch.");
  p.median_angle_deg = m.value("median_angle_deg", 0.0);
  p.rows = m.value("rows", 0);
  if (m.contains("wider_contact") && !m.at("wider_contact").is_null()) {
    const Json& w = m.at("wider_contact");
    const std::string where = "motion_patch.wider_contact.";
    const double c = r.number(w, "radius_ratio", where), wn = r.number(w, "exponent", where),
                 angle = r.number(w, "median_angle_deg", where);
    if (!(c > 1.0 && c <= 10.0))
      throw InvalidArgument(r.source() + ": " + where + "radius_ratio", format_value(c),
                            "must be in (1, 10]: a contact wider than the body");
    if (!(wn >= 0.0 && wn <= kMaxPowerProfileExponent) || wn != 2.0 * std::floor(wn / 2.0))
      throw InvalidArgument(
          r.source() + ": " + where + "exponent", format_value(wn),
          "must be an even integer in [0, " + std::to_string(kMaxPowerProfileExponent) + "]");
    if (!(angle >= 0.0 && angle <= 180.0))
      throw InvalidArgument(r.source() + ": " + where + "median_angle_deg", format_value(angle),
                            "must be in [0, 180] deg");
    p.wider_contact = WiderContact{c, static_cast<int>(wn), angle};
  }
  try {
    validate(p);
  } catch (const InvalidArgument& e) {
    throw InvalidArgument(r.source() + ": motion_patch", "invalid", e.what());
  }
  return p;
}

}  // namespace

ModelSpec model_from_json(const std::string& text, const std::string& source) {
  Json j;
  try {
    j = Json::parse(text);
  } catch (const Json::parse_error& e) {
    throw ParseError(source, 0, 0, std::string("not JSON: ") + e.what());
  }
  if (j.is_object() && j.contains("model") && !j.contains("format")) j = j.at("model");
  const Reader r(source);
  const Json& format = r.member(j, "format", "");
  if (format != kModelFileFormat)
    throw InvalidArgument(source + ": format", format.dump(),
                          std::string("must be \"") + kModelFileFormat + "\"");
  const double radius = r.number(j, "radius_m");
  require_positive((source + ": radius_m").c_str(), radius);
  ModelSpec s = base_model_spec(radius, r.optional(j, "normal_load_N"));
  s.reference_load_n = r.optional(j, "reference_load_N");
  const Json& k = r.member(j, "law_constants", "");
  s.c = r.number(k, "c", "law_constants.");
  s.a_k = r.number(k, "a_k", "law_constants.");
  s.mk_ratio = r.number(k, "mk_ratio", "law_constants.");
  const double degree = r.number(j, "profile_degree");
  if (degree != 2.0 && degree != 4.0)
    throw InvalidArgument(source + ": profile_degree", format_value(degree), "must be 2 or 4");
  s.profile_degree = static_cast<int>(degree);
  s.profile_corrected = r.flag(j, "profile_corrected");
  s.exact_only = r.flag(j, "exact_only");
  s.speed_in_exact = r.flag(j, "speed_in_exact");
  s.admissible_shape = r.flag(j, "admissible_shape");
  s.joint_admissibility = j.value("joint_admissibility", false);
  const Json& pc = r.member(j, "profile_constants", "");
  s.profile_a = r.number(pc, "a", "profile_constants.");
  s.profile_m = r.number(pc, "m", "profile_constants.");
  s.profile_m0_ratio = r.number(pc, "m0_ratio", "profile_constants.");
  s.exact_tolerance = r.number(j, "exact_tolerance");
  s.regularization_speed = r.number(j, "regularization_speed_mps");
  s.exact_laws = std::make_shared<ExactLawCache>(s.radius_m, std::nullopt, s.exact_tolerance);
  if (!r.member(j, "profile", "").is_null()) attach_profile(s, read_profile(r, j.at("profile")));
  read_parameters(r, j, s);
  s.free.fill(false);
  const Json& dep = r.member(j, "dependence", "");
  for (int slot = 0;
       slot < kDependenceSlots && dep.is_array() && slot < static_cast<int>(dep.size()); ++slot)
    s.dependence[slot] = read_covariate(r, dep.at(slot));
  s.motion_patch = read_patch(r, j);
  return s;
}

ModelSpec bind_to_data(ModelSpec spec, const MeasuredData& data) {
  for (std::optional<Covariate>& c : spec.dependence) {
    if (!c || c->kind != Covariate::Kind::recorded) continue;
    c->recorded = -1;
    for (std::size_t i = 0; i < data.recorded.size(); ++i)
      if (data.recorded[i].name == c->name || data.recorded[i].header == c->name)
        c->recorded = static_cast<int>(i);
    if (c->recorded < 0)
      throw InvalidArgument("data " + data.source, "no column '" + c->name + "'",
                            "the model's friction follows it: the data must record it");
  }
  return spec;
}

}  // namespace contensou
