#include "contensou/friction/pressure_profile.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <numbers>

#include "contensou/friction/csv.hpp"
#include "contensou/friction/error.hpp"
#include "contensou/friction/quadrature.hpp"
#include "contensou/friction/units.hpp"

namespace contensou {
namespace {

template <class... Ts>
struct Overloaded : Ts... {
  using Ts::operator()...;
};
template <class... Ts>
Overloaded(Ts...) -> Overloaded<Ts...>;

// integral_0^b cos(c x) x^n dx, c >= 0, closed form: the power series for small c b, and the
// integration-by-parts recurrence otherwise (both in long double; the recurrence amplifies
// rounding by about n!/(c b)^n, so it is used only for c b > n + 1).
double cos_moment(double c, int n, double b) {
  if (b <= 0.0) return 0.0;
  const long double z = static_cast<long double>(c) * b;
  long double unit;  // integral_0^1 cos(z x) x^n dx
  if (z <= n + 1.0L) {
    long double term = 1.0L, sum = 0.0L;
    for (int j = 0; j < 200; ++j) {
      const long double add = term / (n + 2 * j + 1);
      sum += add;
      if (std::fabs(add) < 1e-22L * std::fabs(sum)) break;
      term *= -z * z / ((2.0L * j + 1.0L) * (2.0L * j + 2.0L));
    }
    unit = sum;
  } else {
    const long double s = std::sin(z), co = std::cos(z);
    long double C = s / z, S = (1.0L - co) / z;
    for (int k = 1; k <= n; ++k) {
      const long double Cn = s / z - k / z * S;
      const long double Sn = -co / z + k / z * C;
      C = Cn;
      S = Sn;
    }
    unit = C;
  }
  return static_cast<double>(unit * std::pow(static_cast<long double>(b), n + 1));
}

// The monotone cubic of a table in t = rho^2 (cubic Hermite on each [t_k, t_k+1], slopes dp/dt).
double pchip_value(const TabulatedShape& t, double rho) {
  const auto& x = t.rho;
  if (rho <= x.front()) return t.p.front();
  if (rho >= x.back()) return t.p.back();
  const std::size_t k = std::upper_bound(x.begin(), x.end(), rho) - x.begin() - 1;
  const double ta = x[k] * x[k], h = x[k + 1] * x[k + 1] - ta;
  const double s = (rho * rho - ta) / h;
  const double h00 = (1 + 2 * s) * (1 - s) * (1 - s), h10 = s * (1 - s) * (1 - s);
  const double h01 = s * s * (3 - 2 * s), h11 = s * s * (s - 1);
  return h00 * t.p[k] + h10 * h * t.slope[k] + h01 * t.p[k + 1] + h11 * h * t.slope[k + 1];
}

// Fritsch-Carlson monotone slopes (weighted harmonic mean inside, shape-preserving
// three-point formula at the ends, as in Fritsch & Butland 1984).
std::vector<double> pchip_slopes(const std::vector<double>& x, const std::vector<double>& y) {
  const std::size_t n = x.size();
  std::vector<double> d(n, 0.0);
  if (n == 2) {
    d[0] = d[1] = (y[1] - y[0]) / (x[1] - x[0]);
    return d;
  }
  std::vector<double> h(n - 1), del(n - 1);
  for (std::size_t k = 0; k + 1 < n; ++k) {
    h[k] = x[k + 1] - x[k];
    del[k] = (y[k + 1] - y[k]) / h[k];
  }
  for (std::size_t k = 1; k + 1 < n; ++k) {
    if (del[k - 1] * del[k] <= 0.0) continue;
    const double w1 = 2 * h[k] + h[k - 1], w2 = h[k] + 2 * h[k - 1];
    d[k] = (w1 + w2) / (w1 / del[k - 1] + w2 / del[k]);
  }
  auto end_slope = [](double h0, double h1, double d0, double d1) {
    double s = ((2 * h0 + h1) * d0 - h0 * d1) / (h0 + h1);
    if (s * d0 <= 0.0) return 0.0;
    if (d0 * d1 < 0.0 && std::abs(s) > 3 * std::abs(d0)) return 3 * d0;
    return s;
  };
  d[0] = end_slope(h[0], h[1], del[0], del[1]);
  d[n - 1] = end_slope(h[n - 2], h[n - 3], del[n - 2], del[n - 3]);
  return d;
}

// sum_k c_k T_k(2 t - 1) by Clenshaw.
double chebyshev_in_t(const std::vector<double>& c, double t) {
  const double z = 2.0 * t - 1.0;
  double b1 = 0.0, b2 = 0.0;
  for (std::size_t k = c.size(); k-- > 1;) {
    const double b0 = c[k] + 2.0 * z * b1 - b2;
    b2 = b1;
    b1 = b0;
  }
  return c[0] + z * b1 - b2;
}

double raw_value(const PressureProfile& profile, double rho) {
  return std::visit(
      Overloaded{[](const UniformShape&) { return 1.0; },
                 [&](const HertzShape&) { return std::sqrt(std::max(0.0, 1.0 - rho * rho)); },
                 [&](const CosineSeriesShape& c) {
                   double s = 0.0;
                   for (std::size_t k = 0; k < c.a.size(); ++k)
                     s += c.a[k] * std::cos(std::numbers::pi * static_cast<double>(k) * c.w * rho);
                   return s;
                 },
                 [&](const TabulatedShape& t) { return pchip_value(t, rho); },
                 [&](const ChebyshevShape& c) { return chebyshev_in_t(c.c, rho * rho); }},
      profile.shape);
}

// integral_lo^hi p(rho) rho^n d rho of the unclipped shape, exact for each kind.
double raw_moment(const PressureProfile& profile, int n, double lo, double hi) {
  return std::visit(
      Overloaded{
          [&](const UniformShape&) {
            return (std::pow(hi, n + 1) - std::pow(lo, n + 1)) / (n + 1);
          },
          [&](const HertzShape&) {
            // Only whole-range moments are needed: a Hertz shape never goes negative.
            // integral_0^1 sqrt(1 - r^2) r^n dr = (sqrt(pi)/4) Gamma((n+1)/2) / Gamma(n/2 +
            // 2).
            return std::sqrt(std::numbers::pi) / 4.0 *
                   std::exp(std::lgamma((n + 1) / 2.0) - std::lgamma(n / 2.0 + 2.0));
          },
          [&](const CosineSeriesShape& c) {
            double s = 0.0;
            for (std::size_t k = 0; k < c.a.size(); ++k) {
              const double freq = std::numbers::pi * static_cast<double>(k) * c.w;
              s += c.a[k] * (cos_moment(freq, n, hi) - cos_moment(freq, n, lo));
            }
            return s;
          },
          [&](const TabulatedShape& t) {
            // Gauss-Legendre in rho on each piece (a cubic in rho^2), exact for degree
            // 6 + n.
            const GaussLegendreRule g = gauss_legendre(n / 2 + 4);
            std::vector<double> knots{lo};
            for (double r : t.rho)
              if (r > lo && r < hi) knots.push_back(r);
            knots.push_back(hi);
            double s = 0.0;
            for (std::size_t k = 0; k + 1 < knots.size(); ++k) {
              const double a = knots[k], b = knots[k + 1];
              for (std::size_t i = 0; i < g.nodes.size(); ++i) {
                const double r = 0.5 * (a + b) + 0.5 * (b - a) * g.nodes[i];
                s += 0.5 * (b - a) * g.weights[i] * pchip_value(t, r) * std::pow(r, n);
              }
            }
            return s;
          },
          [&](const ChebyshevShape& c) {
            // A polynomial of degree 2 (K - 1) + n in rho: Gauss-Legendre, exact.
            const GaussLegendreRule g = gauss_legendre(static_cast<int>(c.c.size()) + n / 2 + 1);
            double s = 0.0;
            for (std::size_t i = 0; i < g.nodes.size(); ++i) {
              const double r = 0.5 * (lo + hi) + 0.5 * (hi - lo) * g.nodes[i];
              s += 0.5 * (hi - lo) * g.weights[i] * chebyshev_in_t(c.c, r * r) * std::pow(r, n);
            }
            return s;
          }},
      profile.shape);
}

// Sign changes of the unclipped shape on [0, 1], by a fine scan and bisection.
std::vector<double> sign_changes(const PressureProfile& profile) {
  std::vector<double> roots;
  constexpr int kScan = 4096;
  double x0 = 0.0, f0 = raw_value(profile, 0.0);
  for (int i = 1; i <= kScan; ++i) {
    const double x1 = static_cast<double>(i) / kScan;
    const double f1 = raw_value(profile, x1);
    if ((f0 < 0.0) != (f1 < 0.0)) {
      double a = x0, b = x1;
      const bool neg_a = f0 < 0.0;
      for (int it = 0; it < 80 && b - a > 1e-16; ++it) {
        const double m = 0.5 * (a + b);
        if ((raw_value(profile, m) < 0.0) == neg_a)
          a = m;
        else
          b = m;
      }
      roots.push_back(0.5 * (a + b));
    }
    x0 = x1;
    f0 = f1;
  }
  return roots;
}

// Knots at rho a < b are far enough apart: b - a >= kMinProfileKnotStep up to the rounding of
// the two (a relative 1e-6 of the step: 0.999999999 and 1 are 1e-9 apart).
bool knots_apart(double a, double b) {
  return b - a >= kMinProfileKnotStep * (1.0 - 1e-6);
}

// Why a table of more than kMaxProfilePoints points is refused, and what to do instead.
std::string too_many_points_advice() {
  return "a tabulated profile takes at most " + std::to_string(kMaxProfilePoints) +
         " points (its exact model and law take about 1.7 KB a point to build): resample it, "
         "or fit smoothed_profile";
}

// The knots of a table (tabulated_profile's checks), with a first rho within 1e-9 of the
// centre set to 0 and a last within 1e-9 of the rim set to 1; errors name the knot.
std::vector<double> checked_knots(std::vector<double> rho, const std::vector<double>& p) {
  if (rho.size() < 2)
    throw InvalidArgument("rho", "(" + std::to_string(rho.size()) + " points)",
                          "a tabulated profile needs at least 2 points");
  if (rho.size() > kMaxProfilePoints)
    throw InvalidArgument("rho", "(" + std::to_string(rho.size()) + " points)",
                          too_many_points_advice());
  if (rho.size() != p.size())
    throw InvalidArgument("p", "(" + std::to_string(p.size()) + " values)",
                          "must have as many values as rho (" + std::to_string(rho.size()) + ")");
  for (std::size_t k = 0; k < rho.size(); ++k) {
    const std::string name = "rho[" + std::to_string(k) + "]";
    require_finite(name.c_str(), rho[k]);
    require_finite(("p[" + std::to_string(k) + "]").c_str(), p[k]);
    if (rho[k] < 0.0 || rho[k] > 1.0 + 1e-12)
      throw InvalidArgument(name, format_value(rho[k]), "must lie in [0, 1]");
    rho[k] = std::min(rho[k], 1.0);  // past the rim by rounding: on it (then check increase)
    if (k > 0 && !(rho[k] > rho[k - 1]))
      throw InvalidArgument(
          name, format_value(rho[k]),
          "rho must be strictly increasing (previous " + format_value(rho[k - 1]) + ")");
  }
  if (rho.front() > 1e-9)
    throw InvalidArgument("rho[0]", format_value(rho.front()),
                          "a tabulated profile must start at the centre, rho = 0: it is not "
                          "extended below its first knot (add the knot rho = 0 with the "
                          "centre's pressure)");
  if (rho.back() < 1.0 - 1e-9)
    throw InvalidArgument("rho[last]", format_value(rho.back()),
                          "a tabulated profile must reach the rim, rho = 1");
  rho.front() = 0.0;
  rho.back() = 1.0;
  for (std::size_t k = 1; k < rho.size(); ++k)
    if (!knots_apart(rho[k - 1], rho[k]))
      throw InvalidArgument(
          "rho[" + std::to_string(k) + "]", format_value(rho[k]),
          "knots " + std::to_string(k - 1) + " (rho = " + format_value(rho[k - 1]) + ") and " +
              std::to_string(k) + " are " + format_value(rho[k] - rho[k - 1]) +
              " apart, closer than 1e-9 (of the radius): the interpolant's slope between them "
              "is not defined to a double's precision; merge the two knots");
  return rho;
}

// Each piece of the table's cubic in t = rho^2 (the Hermite form of set_table_pieces: p_k,
// d_k, (3 del - 2 d_k - d_k+1) / h, (d_k + d_k+1 - 2 del) / h^2, del = (p_k+1 - p_k) / h)
// must be finite: values too large for their knot step are refused naming the two knots.
void check_pieces(const TabulatedShape& t) {
  for (std::size_t k = 0; k + 1 < t.rho.size(); ++k) {
    const double h = t.rho[k + 1] * t.rho[k + 1] - t.rho[k] * t.rho[k];
    const double del = (t.p[k + 1] - t.p[k]) / h, d0 = t.slope[k], d1 = t.slope[k + 1];
    const double c2 = (3.0 * del - 2.0 * d0 - d1) / h, c3 = (d0 + d1 - 2.0 * del) / (h * h);
    if (std::isfinite(d0) && std::isfinite(d1) && std::isfinite(c2) && std::isfinite(c3)) continue;
    throw InvalidArgument(
        "p[" + std::to_string(k) + "], p[" + std::to_string(k + 1) + "]",
        format_value(t.p[k]) + ", " + format_value(t.p[k + 1]) +
            " at rho = " + format_value(t.rho[k]) + ", " + format_value(t.rho[k + 1]),
        "the interpolant between these knots overflows a double (its slope in rho^2 is " +
            format_value(del) + "): give the values in other units, or the knots farther apart");
  }
}

// A row of a profile CSV after its predecessor (nullptr for the first row): the first must be
// the centre (rho within 1e-9 of 0), each next at least kMinProfileKnotStep past the previous.
void check_profile_row(const CsvTable& table, int line, int column, double rho,
                       const double* previous) {
  if (!previous) {
    if (rho > 1e-9)
      throw table.cell_error(line, column,
                             "rho = " + format_value(rho) +
                                 ": the first row must be the centre, rho = 0 (the profile is "
                                 "not extended below its first row; add a row at rho = 0)");
    return;
  }
  if (!(rho > *previous))
    throw table.cell_error(line, column,
                           "rho = " + format_value(rho) + " not increasing (previous " +
                               format_value(*previous) + ")");
  if (!knots_apart(*previous, rho))
    throw table.cell_error(line, column,
                           "rho = " + format_value(rho) + " is " + format_value(rho - *previous) +
                               " past the previous row's " + format_value(*previous) +
                               ", closer than 1e-9 (of the radius): the interpolant's slope "
                               "between them is not defined to a double's precision; merge the "
                               "two rows");
}

}  // namespace

PressureProfile uniform_profile() {
  return {};
}

PressureProfile hertz_profile() {
  PressureProfile p;
  p.shape = HertzShape{};
  return p;
}

PressureProfile cosine_series_profile(double w, std::vector<double> a) {
  require_positive("w", w);
  if (a.empty()) throw InvalidArgument("a", "[]", "cosine series needs at least one coefficient");
  for (std::size_t k = 0; k < a.size(); ++k)
    require_finite(("a[" + std::to_string(k) + "]").c_str(), a[k]);
  PressureProfile p;
  p.shape = CosineSeriesShape{w, std::move(a)};
  return p;
}

PressureProfile tabulated_profile(std::vector<double> rho, std::vector<double> p) {
  rho = checked_knots(std::move(rho), p);
  TabulatedShape t;
  std::vector<double> knots_t(rho.size());
  for (std::size_t k = 0; k < rho.size(); ++k) knots_t[k] = rho[k] * rho[k];
  t.slope = pchip_slopes(knots_t, p);
  t.rho = std::move(rho);
  t.p = std::move(p);
  check_pieces(t);
  PressureProfile out;
  out.shape = std::move(t);
  return out;
}

PressureProfile power_profile(int n) {
  if (n < 0 || n > kMaxPowerProfileExponent || n % 2 != 0)
    throw InvalidArgument(
        "n", std::to_string(n),
        "must be an even exponent in [0, " + std::to_string(kMaxPowerProfileExponent) + "]");
  // t^k in z = 2 t - 1: k times c <- c (1 + z) / 2, with z T_0 = T_1 and
  // z T_j = (T_(j+1) + T_(j-1)) / 2 (j >= 1).
  std::vector<double> c{1.0};
  for (int k = 0; k < n / 2; ++k) {
    std::vector<double> next(c.size() + 1, 0.0);
    for (std::size_t j = 0; j < c.size(); ++j) {
      next[j] += 0.5 * c[j];
      if (j == 0) {
        next[1] += 0.5 * c[0];
      } else {
        next[j + 1] += 0.25 * c[j];
        next[j - 1] += 0.25 * c[j];
      }
    }
    c = std::move(next);
  }
  PressureProfile p;
  p.shape = ChebyshevShape{std::move(c)};
  return p;
}

PressureProfile seed_tire_profile() {
  PressureProfile p =
      cosine_series_profile(0.848, {0.685, 0.398, -0.831, 0.230, 0.161, -0.027, -0.133, 0.101});
  // The published series dips below zero on (0.9936, 1] (1.8e-4 of its load). Kept as
  // published, explicitly, so that its moments are theory.md's (section 5); clip_negative = true
  // clips it at zero instead (A^n change by about 8e-5).
  p.keep_negative = true;
  return p;
}

namespace {

// The profile table's pressure column: "pressure_Pa", or a column named "pressure" (or "p")
// in any pressure unit ("pressure [kPa]", "p_bar"); -1 if none. `to_si` gets its factor.
int pressure_column(const CsvTable& table, double& to_si) {
  to_si = 1.0;
  for (std::size_t c = 0; c < table.header.size(); ++c) {
    const NameAndUnit nu = split_name_and_unit(table.header[c]);
    std::string name = nu.name;
    for (char& ch : name) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
    if (name != "pressure" && name != "p") continue;
    const Unit* u = find_unit(nu.unit);
    if (u == nullptr || u->dimension != Dimension::pressure)
      throw table.cell_error(table.header_line, static_cast<int>(c),
                             "'" + table.header[c] + "' is not in a pressure unit (" +
                                 units_of(Dimension::pressure) + ")");
    to_si = u->to_si;
    return static_cast<int>(c);
  }
  return -1;
}

}  // namespace

ProfileTable read_profile_table(const std::string& path) {
  CsvLimits limits;  // reading stops at the first row past the table's limit
  limits.max_rows = kMaxProfilePoints;
  limits.rows_advice = too_many_points_advice();
  const CsvTable table = read_csv(path, limits);
  double to_pa = 1.0;
  const int ir = table.column("rho"), ip = pressure_column(table, to_pa);
  if (ir < 0 || ip < 0) {
    const std::string missing = ir < 0 ? "rho" : "pressure_Pa";
    const std::string close = table.closest_column(missing);
    throw ParseError(path, table.header_line, 0,
                     "missing column '" + missing +
                         "' (need rho and the pressure, pressure_Pa or in another unit as "
                         "'pressure [kPa]'" +
                         (close.empty() ? "" : "; did you mean '" + close + "'?") + ")");
  }
  ProfileTable out;
  for (const CsvRow& row : table.rows) {
    double v[2];
    for (int k = 0; k < 2; ++k) {
      const int c = k == 0 ? ir : ip;
      const std::optional<double> x = table.number(row, c);
      if (!x) throw table.cell_error(row.line, c, "empty cell");
      v[k] = *x;
    }
    if (v[0] < 0.0 || v[0] > 1.0 + 1e-12)
      throw table.cell_error(row.line, ir, "rho = " + format_value(v[0]) + " outside [0, 1]");
    const double r = std::min(v[0], 1.0);  // past the rim by rounding: on it
    check_profile_row(table, row.line, ir, r, out.rho.empty() ? nullptr : &out.rho.back());
    out.rho.push_back(out.rho.empty() ? 0.0 : r);  // within 1e-9 of the centre: the centre
    out.pressure_pa.push_back(v[1] * to_pa);
  }
  if (out.rho.size() < 2)
    throw ParseError(
        path, table.header_line, 0,
        "a profile needs at least 2 rows (found " + std::to_string(out.rho.size()) + ")");
  if (out.rho.back() < 1.0 - 1e-9)
    throw table.cell_error(table.rows.back().line, ir, "the last rho must be 1 (the rim)");
  out.rho.back() = 1.0;  // snapping the ends only widens their steps
  return out;
}

MeasuredProfile read_profile_csv(const std::string& path, bool clip_negative) {
  ProfileTable t = read_profile_table(path);
  // The pressures scaled by a power of two, 2^-e, so that the largest is below 1: exact, and
  // the interpolant is homogeneous in p, so the shape divided by the mean is the same to the
  // bit, while slopes of pressures near the largest double stay finite.
  double largest = 0.0;
  for (double x : t.pressure_pa) largest = std::max(largest, std::abs(x));
  int e = 0;
  std::frexp(largest, &e);
  for (double& x : t.pressure_pa) x = std::ldexp(x, -e);
  MeasuredProfile out;
  out.profile = tabulated_profile(t.rho, t.pressure_pa);
  out.profile.clip_negative = clip_negative;
  // Mean pressure = 2 integral_0^1 p rho d rho (theory.md section 4: N = pi R^2 p_mean).
  const double mean = 2.0 * moment(out.profile, 1), mean_pa = std::ldexp(mean, e);
  if (!(mean > 0.0 && std::isfinite(mean_pa)))
    throw ParseError(path, 0, 0,
                     std::string("the profile's mean pressure") +
                         (clip_negative ? " clipped at zero, " : ", ") + format_value(mean_pa) +
                         " Pa, is not positive and finite");
  auto& tab = std::get<TabulatedShape>(out.profile.shape);
  for (double& x : tab.p) x /= mean;
  for (double& x : tab.slope) x /= mean;
  out.reference_pressure_pa = mean_pa;
  return out;
}

SmoothedProfile smoothed_profile(const std::vector<double>& rho, const std::vector<double>& p,
                                 int terms) {
  const PressureProfile checked = tabulated_profile(rho, p);  // validates rho and p
  const auto& tab = std::get<TabulatedShape>(checked.shape);
  const int n = static_cast<int>(tab.rho.size());
  if (terms < 1 || terms > n - 1)
    throw InvalidArgument(
        "terms", std::to_string(terms),
        "a smoothing fit needs 1 to (points - 1) = " + std::to_string(n - 1) + " terms");
  // Least squares in t = rho^2 by QR of the Chebyshev design matrix (Householder, in place).
  std::vector<std::vector<double>> A(static_cast<std::size_t>(n),
                                     std::vector<double>(static_cast<std::size_t>(terms)));
  std::vector<double> y = tab.p;
  for (int i = 0; i < n; ++i) {
    const double z = 2.0 * tab.rho[i] * tab.rho[i] - 1.0;
    double tp = 1.0, tc = z;
    for (int k = 0; k < terms; ++k) {
      const double tk = k == 0 ? 1.0 : (k == 1 ? z : 2.0 * z * tc - tp);
      if (k >= 2) {
        tp = tc;
        tc = tk;
      }
      A[i][k] = tk;
    }
  }
  for (int k = 0; k < terms; ++k) {
    double norm = 0.0;
    for (int i = k; i < n; ++i) norm += A[i][k] * A[i][k];
    norm = std::sqrt(norm);
    if (!(norm > 0.0)) continue;
    const double alpha = A[k][k] > 0.0 ? -norm : norm;
    std::vector<double> v(static_cast<std::size_t>(n - k));
    for (int i = k; i < n; ++i) v[i - k] = A[i][k];
    v[0] -= alpha;
    double vv = 0.0;
    for (double x : v) vv += x * x;
    if (!(vv > 0.0)) continue;
    auto reflect = [&](auto get, auto set) {
      double d = 0.0;
      for (int i = k; i < n; ++i) d += v[i - k] * get(i);
      d = 2.0 * d / vv;
      for (int i = k; i < n; ++i) set(i, get(i) - d * v[i - k]);
    };
    for (int j = k; j < terms; ++j)
      reflect([&](int i) { return A[i][j]; }, [&](int i, double x) { A[i][j] = x; });
    reflect([&](int i) { return y[i]; }, [&](int i, double x) { y[i] = x; });
  }
  std::vector<double> c(static_cast<std::size_t>(terms), 0.0);
  for (int k = terms - 1; k >= 0; --k) {
    double s = y[k];
    for (int j = k + 1; j < terms; ++j) s -= A[k][j] * c[j];
    if (A[k][k] == 0.0)
      throw InvalidArgument("terms", std::to_string(terms),
                            "the points do not determine that many terms");
    c[k] = s / A[k][k];
  }
  SmoothedProfile out;
  out.profile.shape = ChebyshevShape{c};
  double ss = 0.0;
  for (int i = 0; i < n; ++i) {
    const double e = tab.p[i] - chebyshev_in_t(c, tab.rho[i] * tab.rho[i]);
    ss += e * e;
    out.max_residual = std::max(out.max_residual, std::abs(e));
  }
  out.rms_residual = std::sqrt(ss / n);
  return out;
}

double shape_value(const PressureProfile& profile, double rho) {
  const double v = raw_value(profile, rho);
  return profile.clip_negative ? std::max(v, 0.0) : v;
}

double moment(const PressureProfile& profile, int n) {
  if (n < 0) throw InvalidArgument("n", std::to_string(n), "moment order must be >= 0");
  if (!profile.clip_negative) return raw_moment(profile, n, 0.0, 1.0);
  double sum = 0.0;
  for (const auto& [lo, hi] : [&] {
         std::vector<std::pair<double, double>> positive;
         std::vector<double> cuts{0.0};
         for (double r : sign_changes(profile)) cuts.push_back(r);
         cuts.push_back(1.0);
         for (std::size_t k = 0; k + 1 < cuts.size(); ++k)
           if (raw_value(profile, 0.5 * (cuts[k] + cuts[k + 1])) > 0.0)
             positive.emplace_back(cuts[k], cuts[k + 1]);
         return positive;
       }())
    sum += raw_moment(profile, n, lo, hi);
  return sum;
}

std::vector<std::pair<double, double>> negative_intervals(const PressureProfile& profile) {
  std::vector<double> cuts{0.0};
  for (double r : sign_changes(profile)) cuts.push_back(r);
  cuts.push_back(1.0);
  std::vector<std::pair<double, double>> out;
  for (std::size_t k = 0; k + 1 < cuts.size(); ++k)
    if (raw_value(profile, 0.5 * (cuts[k] + cuts[k + 1])) < 0.0)
      out.emplace_back(cuts[k], cuts[k + 1]);
  return out;
}

double negative_load_share(const PressureProfile& profile) {
  // Gauss-Legendre on each interval between sign changes (the profile is smooth there, or
  // piecewise cubic for a table: 40 points per interval are ample for a share).
  const GaussLegendreRule g = gauss_legendre(40);
  std::vector<double> cuts{0.0};
  for (double r : sign_changes(profile)) cuts.push_back(r);
  cuts.push_back(1.0);
  double negative = 0.0, total = 0.0;
  for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
    const double h = 0.5 * (cuts[k + 1] - cuts[k]), c = 0.5 * (cuts[k + 1] + cuts[k]);
    for (std::size_t i = 0; i < g.nodes.size(); ++i) {
      const double r = c + h * g.nodes[i], w = h * g.weights[i] * r;
      const double p = raw_value(profile, r);
      total += w * std::abs(p);
      if (p < 0.0) negative -= w * p;
    }
  }
  return total > 0.0 ? negative / total : 0.0;
}

std::string describe(const PressureProfile& profile) {
  std::string s = std::visit(
      Overloaded{[](const UniformShape&) { return std::string("uniform"); },
                 [](const HertzShape&) { return std::string("Hertz"); },
                 [](const CosineSeriesShape& c) {
                   return "cosine series (" + std::to_string(c.a.size()) + " terms)";
                 },
                 [](const TabulatedShape& t) {
                   return "tabulated (" + std::to_string(t.rho.size()) + " points, PCHIP)";
                 },
                 [](const ChebyshevShape& c) {
                   return "Chebyshev series in rho^2 (" + std::to_string(c.c.size()) + " terms)";
                 }},
      profile.shape);
  if (profile.clip_negative) s += ", clipped at 0";
  if (profile.keep_negative && !profile.clip_negative) s += ", negative part kept";
  return s;
}

}  // namespace contensou
