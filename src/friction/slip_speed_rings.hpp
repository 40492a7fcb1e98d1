// The ring integrals of the slip-speed quadrature (slip_speed_measure.hpp): the half rings
// m_i(s) / (2 s) about the centre of sliding, closed form for a constant profile, lane by lane
// for a table's rings that cross knots, adaptively otherwise. Internal to the friction module.
#pragma once

#include <vector>

#include "contensou/friction/exact_model.hpp"
#include "contensou/friction/quadrature.hpp"
#include "contensou/friction/slip_speed_measure.hpp"

namespace contensou::detail {

// The rules of a table's ring pieces (half_rings_table): Gauss-Legendre of 1..coarse_max nodes
// (gauss[n] has n) for the pieces away from both ends of the ring's range, `fine` for the others.
struct RingRules {
  std::vector<GaussLegendreRule> gauss;
  std::vector<double> reach;  // piece_lanes
  GaussLegendreRule fine;
  int coarse_min = 3, coarse_max = 6;
};

// The rules of options.ring_nodes and options.ring_tolerance (piece_lanes: B^(-2n) = 1e-2
// ring_tolerance, the default about 1e-15, gives r = cosh(-ln(B^(-2n)) / (2 n))).
RingRules ring_rules(const SlipSpeedMeasureOptions& options);

// The half rings m_i(s) / (2 s) at radii s (value[j] for s[j]): a table's rings that cross a
// knot kLanes at a time in the order given (neighbours cross nearly the same knots), the others
// one by one (half_ring).
void half_rings(const ExactModel<double>& m, double eps, double tol, const RingRules& rules,
                const std::vector<double>& s, std::vector<SlipMoments>& value);

}  // namespace contensou::detail
