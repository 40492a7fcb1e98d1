#include "contensou/identification/exact_law_cache.hpp"

namespace contensou {

ExactLawCache::ExactLawCache(double radius_m, std::optional<ExactModel<double>> profile,
                             double tolerance)
    : radius_m_(radius_m), tolerance_(tolerance), profile_(std::move(profile)) {}

const std::vector<ExactLaw>& ExactLawCache::laws(bool slip_speed, const StopRequest& stop,
                                                 int degree) const {
  // The given profile's one law ignores the degree; the parametric profile's degree 4 reuses
  // the three laws of degree 2 and adds 1 + T3, 1 + T4.
  const int which = (slip_speed ? 1 : 0) + (!profile_ && degree == 4 ? 2 : 0);
  std::call_once(once_[which], [this, which, slip_speed, &stop] {
    // Any f_s != f_k builds the falling table; the fit sets f_s = 1, f_k = 1 - beta, w_s.
    std::optional<SlipSpeedFriction<double>> slip;
    if (slip_speed) slip = SlipSpeedFriction<double>{1.0, 0.5, 1.0, 1.0};
    ExactLawOptions options{tolerance_};
    options.stop = stop;
    std::vector<ExactLaw> laws;  // moved in when complete: an interrupted build leaves none
    if (profile_) {
      ExactModel<double> m = *profile_;
      m.slip_speed = slip;
      m.friction = 1.0;
      m.friction_scale = 1.0;
      laws.push_back(make_exact_law(m, options));
      laws_[which] = std::move(laws);
      return;
    }
    std::size_t first = 0;
    if (which >= 2) {
      laws = this->laws(slip_speed, stop, 2);
      first = laws.size();
    }
    const std::vector<std::vector<double>> basis = {
        {1.0}, {1.0, 1.0}, {1.0, 0.0, 1.0}, {1.0, 0.0, 0.0, 1.0}, {1.0, 0.0, 0.0, 0.0, 1.0}};
    const std::size_t count = which >= 2 ? 5 : 3;
    for (std::size_t b = first; b < count; ++b) {
      ContactPatch patch;
      patch.radius_m = radius_m_;
      patch.reference_pressure_pa = 1.0;
      patch.friction = 1.0;
      patch.profile.shape = ChebyshevShape{basis[b]};
      patch.slip_speed_friction = slip;
      laws.push_back(make_exact_law(make_exact_model(patch), options));
    }
    laws_[which] = std::move(laws);
  });
  return laws_[which];
}

}  // namespace contensou
