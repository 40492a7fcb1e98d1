// A fit holds the law's shapes a and m to what a non-negative pressure gives (a <= 4, m >= 4,
// theory.md section 4): on data from a law no patch produces, the estimate ends on its bound,
// is named there with its meaning, its interval does not reach past the bound, and the report's
// cautions say so; with admissible_shape off the same data give the law back.
#include <gtest/gtest.h>

#include <string>

#include "contensou/friction/admissible_shape.hpp"
#include "contensou/identification/fit.hpp"
#include "contensou/identification/report_text.hpp"
#include "contensou/identification/simulation.hpp"

using namespace contensou;

namespace {

// A law of a disk (R = 5 cm) whose torque persists under sliding as no patch's does (m = 1).
FractionalLaw<double> law_with(double m) {
  FractionalLaw<double> law;
  law.F0 = 3.0;
  law.M0 = 0.09;
  law.a = 1.0;
  law.m = m;
  law.kx = 0.0;
  law.Mk = 0.0;
  law.radius = 0.05;
  return law;
}

MeasuredData diagrams_of(const FractionalLaw<double>& law) {
  DiagramSpec spec;
  spec.radius_m = law.radius;
  spec.points = 120;
  spec.psi_min = 0.02;
  spec.psi_max = 50.0;
  spec.spin_speed_mps = 0.02;
  spec.noise_level = 0.005;
  return simulate_diagrams(law, spec);
}

IdentificationOptions options() {
  IdentificationOptions o;
  o.radius_m = 0.05;
  o.normal_load_n = 10.0;
  return o;
}

bool contains(const std::vector<std::string>& lines, const std::string& text) {
  for (const std::string& l : lines)
    if (l.find(text) != std::string::npos) return true;
  return false;
}

}  // namespace

// Oracle: the truth m = 1 lies below the bound 4, so the constrained optimum is on the bound
// (the cost rises toward the interior: the Karush-Kuhn-Tucker condition the fit checks).
TEST(AdmissibleFit, ALawNoPatchGivesEndsOnTheBoundAndIsNamed) {
  const MeasuredData data = diagrams_of(law_with(1.0));
  const FitReport fit = fit_fractional_law(data, options());
  const ParameterEstimate* m = fit.parameter("m");
  ASSERT_NE(m, nullptr);
  EXPECT_DOUBLE_EQ(m->value, 4.0);
  EXPECT_EQ(m->on_bound, "lower");
  EXPECT_NE(m->bound_meaning.find("least any non-negative pressure"), std::string::npos);
  if (m->ci95) {
    EXPECT_GE((*m->ci95)[0], 4.0);
  }
  const std::vector<std::string> cautions = shape_cautions(fit);
  EXPECT_TRUE(contains(cautions, "m = 4 ends on its lower bound"))
      << ::testing::PrintToString(cautions);
  // Every reported interval lies within its parameter's bounds.
  for (const ParameterEstimate& p : fit.parameters) {
    const int i = parameter_index_by_name(p.name);
    if (i < 0 || !p.ci95) continue;
    EXPECT_GE((*p.ci95)[0], parameter_bounds(i).lower) << p.name;
    EXPECT_LE((*p.ci95)[1], parameter_bounds(i).upper) << p.name;
  }
  // The report's first line is the caution.
  const std::string text = fit_report_text_with_cautions(ReportInput{}, fit);
  EXPECT_EQ(text.rfind("CAUTION (the law): m = 4 ends on its lower bound", 0), 0u) << text;
}

// Oracle: the truth. Without the bounds (the seed's own fits) the data give m = 1 back; with an
// admissible truth (m = 8) nothing is on a bound and nothing is cautioned.
TEST(AdmissibleFit, OffOrAdmissibleTheLawComesBack) {
  IdentificationOptions open = options();
  open.admissible_shape = false;
  const FitReport free = fit_fractional_law(diagrams_of(law_with(1.0)), open);
  EXPECT_NEAR(free.parameter("m")->value, 1.0, 0.05);
  EXPECT_TRUE(free.parameter("m")->on_bound.empty());
  const FitReport fit = fit_fractional_law(diagrams_of(law_with(8.0)), options());
  EXPECT_NEAR(fit.parameter("m")->value, 8.0, 0.4);
  EXPECT_TRUE(shape_cautions(fit).empty()) << ::testing::PrintToString(shape_cautions(fit));
}

// A fixed shape no patch gives is refused, naming the bound's reason.
TEST(AdmissibleFit, AFixedShapeOutsideTheBoundsIsRefused) {
  IdentificationOptions o = options();
  o.fixed = {{"m", 2.0}};
  try {
    fit_fractional_law(diagrams_of(law_with(8.0)), o);
    FAIL() << "m = 2 was accepted";
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("m = (2 A^2 / A^3)^2 >= 4"), std::string::npos)
        << e.what();
  }
  o.admissible_shape = false;
  EXPECT_NO_THROW(fit_fractional_law(diagrams_of(law_with(8.0)), o));
}

// Oracle: the moment conditions (admissible_shape.hpp). Data from a law whose a and m are each
// within their bounds but not together (a m = 24 > 16) are fitted by a law that is: the fit ends
// on the edge a m = 16 (within the penalty's 1e-6), and the report says it is held there.
TEST(AdmissibleFit, ALawInadmissibleOnlyJointlyIsHeldOnTheEdge) {
  FractionalLaw<double> law = law_with(8.0);
  law.a = 3.0;  // a m = 24
  // By default only a and m on their own are held: the fit says the law is no patch's.
  const FitReport plain = fit_fractional_law(diagrams_of(law), options());
  EXPECT_TRUE(contains(shape_cautions(plain), "no non-negative pressure on the patch gives"))
      << ::testing::PrintToString(shape_cautions(plain));
  IdentificationOptions joint = options();
  joint.joint_admissibility = true;
  const FitReport fit = fit_fractional_law(diagrams_of(law), joint);
  const double a = fit.parameter("a")->value, m = fit.parameter("m")->value;
  const double q = fit.parameter("M0_Nm")->value / (fit.parameter("F0_N")->value * 0.05);
  const ShapeAdmissibility s = shape_admissibility(a, m, q);
  EXPECT_TRUE(s.admissible) << s.reason;
  EXPECT_FALSE(s.edge.empty()) << "a = " << a << ", m = " << m << ", q = " << q;
  EXPECT_TRUE(contains(shape_cautions(fit), "held on the edge"))
      << ::testing::PrintToString(shape_cautions(fit));
  IdentificationOptions open = options();
  open.admissible_shape = false;  // the law itself comes back without the conditions
  const FitReport free = fit_fractional_law(diagrams_of(law), open);
  EXPECT_NEAR(free.parameter("a")->value * free.parameter("m")->value, 24.0, 1.5);
}

// A parametric profile's weight at zero is an ordinary shape (the pressure vanishes at the rim):
// marked in the table, no caution; a pressure shift on its bound is cautioned with its meaning.
TEST(AdmissibleFit, AProfileWeightAtZeroIsNoCaution) {
  FitReport fit;
  ParameterEstimate w;
  w.name = "profile_w2";
  w.on_bound = "lower";
  w.bound_meaning = bound_meaning(kProfileW2, false);
  fit.parameters = {w};
  EXPECT_TRUE(shape_cautions(fit).empty()) << ::testing::PrintToString(shape_cautions(fit));
  ParameterEstimate k;
  k.name = "kx";
  k.value = 0.95;
  k.on_bound = "upper";
  k.bound_meaning = bound_meaning(kKx, true);
  fit.parameters.push_back(k);
  ASSERT_EQ(shape_cautions(fit).size(), 1u);
  EXPECT_TRUE(contains(shape_cautions(fit), "kx = 0.95 ends on its upper bound: |k| = 0.95"));
}
