/// \file
/// Quadrature rules: Gauss-Legendre nodes of any order and the Gauss-Kronrod G10K21 pair.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <vector>

namespace contensou {

/// A Gauss-Legendre rule on [-1, 1].
struct GaussLegendreRule {
  std::vector<double> nodes;    ///< in [-1, 1], ascending
  std::vector<double> weights;  ///< summing to 2
};

/// n-point Gauss-Legendre rule (exact for polynomials of degree 2n-1), computed by Newton's
/// method on the three-term recurrence of P_n; accurate to a few ulp for n <= 1000. Throws
/// InvalidArgument for n outside [1, 1000].
GaussLegendreRule gauss_legendre(int n);

namespace detail {

struct KronrodNode {
  double x;        ///< node in [0, 1]
  double kronrod;  ///< weight in the 21-point Kronrod rule
  double gauss;    ///< weight in the embedded 10-point Gauss rule (0 if Kronrod-only)
};

/// Gauss-Kronrod G7K15 on [-1, 1]; the symmetric half (same generator): the rule of the many
/// short intervals between a table's knot crossings (exact_resultants.hpp).
inline constexpr KronrodNode kGK15[8] = {
    {9.9145537112081263921e-1, 0.022935322010529224964, 0.0},
    {9.4910791234275852453e-1, 0.063092092629978553291, 0.12948496616886969327},
    {8.6486442335976907279e-1, 0.10479001032225018384, 0.0},
    {7.4153118559939443986e-1, 0.14065325971552591875, 0.2797053914892766679},
    {5.8608723546769113029e-1, 0.16900472663926790283, 0.0},
    {4.0584515137739716691e-1, 0.19035057806478540991, 0.38183005050511894495},
    {2.077849550078984676e-1, 0.20443294007529889241, 0.0},
    {0.0, 0.20948214108472782801, 0.41795918367346938776},
};

/// Gauss-Kronrod G10K21 on [-1, 1]; the symmetric half. Generated to 20 digits by
/// scripts/gen_kronrod.py (zeros of the Stieltjes polynomial E_11).
inline constexpr KronrodNode kGK21[11] = {
    {9.9565716302580808074e-1, 0.011694638867371874278, 0.0},
    {9.7390652851717172008e-1, 0.032558162307964727479, 0.066671344308688137594},
    {9.30157491355708226e-1, 0.054755896574351996031, 0.0},
    {8.6506336668898451073e-1, 0.075039674810919952767, 0.14945134915058059315},
    {7.8081772658641689706e-1, 0.093125454583697605535, 0.0},
    {6.7940956829902440623e-1, 0.1093871588022976419, 0.219086362515982044},
    {5.6275713466860468334e-1, 0.12349197626206585108, 0.0},
    {4.333953941292471908e-1, 0.13470921731147332593, 0.26926671930999635509},
    {2.9439286270146019813e-1, 0.1427759385770600808, 0.0},
    {1.4887433898163121088e-1, 0.14773910490133849137, 0.29552422471475287017},
    {0.0, 0.14944555400291690566, 0.0},
};

/// Gauss-Kronrod G15K31 on [-1, 1]; the symmetric half (same generator).
inline constexpr KronrodNode kGK31[16] = {
    {9.9800229869339706029e-1, 0.0053774798729233489878, 0.0},
    {9.8799251802048542849e-1, 0.015007947329316122538, 0.030753241996117268355},
    {9.6773907567913913426e-1, 0.025460847326715320187, 0.0},
    {9.3727339240070590431e-1, 0.035346360791375846222, 0.070366047488108124709},
    {8.9726453234408190088e-1, 0.044589751324764876608, 0.0},
    {8.482065834104272162e-1, 0.053481524690928087265, 0.10715922046717193501},
    {7.9041850144246593297e-1, 0.062009567800670640285, 0.0},
    {7.2441773136017004742e-1, 0.06985412131872825871, 0.13957067792615431445},
    {6.5099674129741697053e-1, 0.076849680757720378894, 0.0},
    {5.7097217260853884754e-1, 0.083080502823133021038, 0.16626920581699393355},
    {4.8508186364023968069e-1, 0.088564443056211770647, 0.0},
    {3.941513470775633699e-1, 0.093126598170825321225, 0.18616100001556221103},
    {2.9918000715316881217e-1, 0.096642726983623678505, 0.0},
    {2.011940939974345223e-1, 0.099173598721791959332, 0.19843148532711157646},
    {1.0114206691871749903e-1, 0.10076984552387559504, 0.0},
    {0.0, 0.10133000701479154902, 0.20257824192556127288},
};

/// Number of points of a Kronrod rule given its symmetric half (node 0 last).
template <std::size_t Half>
constexpr int kronrod_points(const KronrodNode (&)[Half]) {
  return 2 * static_cast<int>(Half) - 1;
}

/// QUADPACK's error heuristic: scale |K - G| by the integrand's variation (Piessens et al. 1983).
inline double kronrod_error(double kronrod_minus_gauss, double abs_dev) {
  double err = std::abs(kronrod_minus_gauss);
  if (abs_dev != 0.0 && err != 0.0) {
    err = abs_dev * std::min(1.0, std::pow(200.0 * err / abs_dev, 1.5));
  }
  return err;
}

}  // namespace detail
}  // namespace contensou
